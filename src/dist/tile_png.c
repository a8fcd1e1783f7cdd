/* Tile PNGs through libpng's full API, which writes and reads the chunks
 * that place a tile: oFFs (png_set_oFFs, png_get_oFFs), the whitted-tile
 * tEXt (png_set_text, png_get_text) and ImageMagick's vpAg, which libpng
 * does not know (png_set_unknown_chunks on writing; on reading
 * png_set_keep_unknown_chunks keeps it for png_get_unknown_chunks).  The
 * writing is image/png_idat.c's, the writer of whole images, with these
 * chunks added.  The reading's setjmp, which STYLE.md otherwise avoids, is
 * confined to tile_png_guard: every libpng call that can fail runs in a
 * step function called from there, and everything a step changes lives in
 * a struct of the caller's, never in a local of the function that called
 * setjmp, so nothing needs to be volatile.  libpng's messages go into the
 * diag; nothing is printed. */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <png.h>
#include <stdio.h>
#include <string.h>

#include "base/alloc.h"
#include "base/file.h"
#include "dist/tile_text.h"
#include "image/png_check.h"
#include "image/png_idat.h"
#include "whitted/tile.h"

/* Larger files are refused: a full tile of the largest image is ~800 MB
 * uncompressed, and PNG never grows it by much. */
#define TILE_MAX_FILE_BYTES (1L << 30)

/* One libpng structure, read or write, and the message of its error. */
struct tile_png {
	png_structp png;
	png_infop info;
	struct png_message msg;
};

typedef void tile_png_step(struct tile_png *p, void *ctx);

/* Runs step(p, ctx); false when libpng failed in it (p->msg says why). */
static bool tile_png_guard(struct tile_png *p, tile_png_step *step, void *ctx)
{
	if (setjmp(png_jmpbuf(p->png)))
		return false;
	step(p, ctx);
	return true;
}

/* The vpAg chunk: full width and height (4 bytes each, big-endian) and a
 * unit byte, 0 for pixels. */
static const png_byte tile_vpag_name[5] = "vpAg";
#define TILE_VPAG_SIZE 9

/* What a tile's writing needs while libpng runs. */
struct tile_writer {
	const struct image *img;
	const struct tile_info *info;
	char key[sizeof(RT_TILE_KEYWORD)];
	char text[RT_TILE_TEXT_MAX];
	png_byte vpag[TILE_VPAG_SIZE];
};

/* The chunks that place a tile, added by png_idat_write_file (the writer
 * of whole images, so that tiles have the very same image data). */
static void tile_write_chunks(png_structp png, png_infop info, void *ctx)
{
	struct tile_writer *w = ctx;
	const struct tile_info *t = w->info;
	png_unknown_chunk vpag;
	png_text text;

	png_set_oFFs(png, info, t->x0, t->y0, PNG_OFFSET_PIXEL);
	memset(&vpag, 0, sizeof(vpag));
	memcpy(vpag.name, tile_vpag_name, sizeof(tile_vpag_name));
	vpag.data = w->vpag;
	vpag.size = sizeof(w->vpag);
	vpag.location = PNG_HAVE_IHDR;	/* right after IHDR, before oFFs */
	png_set_keep_unknown_chunks(png, PNG_HANDLE_CHUNK_ALWAYS, tile_vpag_name, 1);
	png_set_unknown_chunks(png, info, &vpag, 1);
	memset(&text, 0, sizeof(text));
	text.compression = PNG_TEXT_COMPRESSION_NONE;
	text.key = w->key;
	text.text = w->text;
	text.text_length = strlen(w->text);
	png_set_text(png, info, &text, 1);
}

/* image_write_file's fill: the whole PNG into f. */
static int tile_fill(void *ctx, FILE *f, struct diag *d)
{
	struct tile_writer *w = ctx;

	return png_idat_write_file(w->img, f, tile_write_chunks, w, d);
}

int tile_write(const char *path, const struct image *img, const struct tile_info *info,
	       const volatile sig_atomic_t *cancel, struct diag *d)
{
	struct tile_writer w;

	if (img->width != info->x1 - info->x0 || img->height != info->y1 - info->y0)
		return diag_fail(d, RT_E_INVALID, "the tile image does not have its region's size");
	memset(&w, 0, sizeof(w));
	w.img = img;
	w.info = info;
	memcpy(w.key, RT_TILE_KEYWORD, sizeof(w.key));
	tile_text_format(info, w.text, sizeof(w.text));
	png_save_uint_32(w.vpag, (png_uint_32)info->full_width);
	png_save_uint_32(w.vpag + 4, (png_uint_32)info->full_height);
	w.vpag[8] = 0;
	return image_write_file(path, tile_fill, &w, cancel, d);
}

/* What a tile's reading needs while libpng runs, and what it found. */
struct tile_reader {
	const unsigned char *data;	/* the whole file */
	size_t len, pos;
	bool truncated;
	png_uint_32 width, height;	/* IHDR */
	int bit_depth, color_type;
	bool have_offs, have_vpag;
	png_int_32 off_x, off_y;	/* oFFs */
	int off_unit;
	png_uint_32 page_width, page_height;	/* vpAg */
	int page_unit;
	const char *text;		/* the whitted-tile text (libpng's), or NULL */
	size_t text_len;
	int texts;			/* whitted-tile chunks seen */
	struct image *img;		/* for the pixels */
};

/* libpng's read callback, from the file in memory. */
static void tile_png_read_fn(png_structp png, png_bytep out, size_t n)
{
	struct tile_reader *r = png_get_io_ptr(png);

	if (n > r->len - r->pos) {
		r->truncated = true;
		png_error(png, "truncated PNG file");
	}
	memcpy(out, r->data + r->pos, n);
	r->pos += n;
}

/* The chunks that place a tile, from libpng's info. */
static void tile_read_chunks(struct tile_png *p, struct tile_reader *r)
{
	png_unknown_chunkp unknown;
	png_textp text;
	int i, n;

	r->have_offs = png_get_oFFs(p->png, p->info, &r->off_x, &r->off_y, &r->off_unit) != 0;
	n = png_get_unknown_chunks(p->png, p->info, &unknown);
	for (i = 0; i < n; i++) {
		if (memcmp(unknown[i].name, tile_vpag_name, 4) != 0 ||
		    unknown[i].size != TILE_VPAG_SIZE)
			continue;
		r->have_vpag = true;
		r->page_width = png_get_uint_32(unknown[i].data);
		r->page_height = png_get_uint_32(unknown[i].data + 4);
		r->page_unit = unknown[i].data[8];
	}
	n = png_get_text(p->png, p->info, &text, NULL);
	for (i = 0; i < n; i++) {
		if (text[i].compression != PNG_TEXT_COMPRESSION_NONE ||
		    strcmp(text[i].key, RT_TILE_KEYWORD) != 0)
			continue;
		r->texts++;
		r->text = text[i].text;
		r->text_len = text[i].text_length;
	}
}

/* Everything before the image data. */
static void tile_read_head(struct tile_png *p, void *ctx)
{
	struct tile_reader *r = ctx;

	png_set_read_fn(p->png, r, tile_png_read_fn);
	/* A bad CRC in any chunk is an error, not only in the critical ones:
	 * the placing chunks are ancillary. */
	png_set_crc_action(p->png, PNG_CRC_DEFAULT, PNG_CRC_ERROR_QUIT);
	png_set_keep_unknown_chunks(p->png, PNG_HANDLE_CHUNK_ALWAYS, tile_vpag_name, 1);
	png_read_info(p->png, p->info);
	r->width = png_get_image_width(p->png, p->info);
	r->height = png_get_image_height(p->png, p->info);
	r->bit_depth = png_get_bit_depth(p->png, p->info);
	r->color_type = png_get_color_type(p->png, p->info);
	tile_read_chunks(p, r);
}

/* The pixels into r->img (the image's size), then the chunks up to IEND. */
static void tile_read_rows(struct tile_png *p, void *ctx)
{
	struct tile_reader *r = ctx;
	size_t stride = (size_t)r->img->width * 3;
	int passes = png_set_interlace_handling(p->png), pass, y;

	png_read_update_info(p->png, p->info);
	if (png_get_rowbytes(p->png, p->info) != stride)
		png_error(p->png, "unexpected row size");
	for (pass = 0; pass < passes; pass++)
		for (y = 0; y < r->img->height; y++)
			png_read_row(p->png, r->img->pixels + (size_t)y * stride, NULL);
	png_read_end(p->png, NULL);
}

/* The diag for a failure inside libpng. */
static int tile_png_failed(const char *path, const struct tile_png *p, const struct tile_reader *r,
			   struct diag *d)
{
	png_uint_32 c;

	if (r->truncated)
		return diag_set(d, RT_E_SYNTAX, path, 0, 0, "truncated PNG file");
	if (strstr(p->msg.text, "CRC error")) {
		c = png_get_io_chunk_type(p->png);
		return diag_set(d, RT_E_SYNTAX, path, 0, 0,
				"damaged PNG file (bad CRC in its %c%c%c%c chunk)",
				(char)(c >> 24 & 0xff), (char)(c >> 16 & 0xff), (char)(c >> 8 & 0xff),
				(char)(c & 0xff));
	}
	if (strstr(p->msg.text, "memory"))
		return diag_set(d, RT_E_NOMEM, path, 0, 0, "cannot read PNG: %s", p->msg.text);
	return diag_set(d, RT_E_SYNTAX, path, 0, 0, "damaged PNG file (%s)", p->msg.text);
}

/* The record against the PNG's own header and placing chunks. */
static int tile_check_head(const char *path, const struct tile_reader *r, struct tile_info *info,
			   struct diag *d)
{
	int rc;

	if (r->texts == 0)
		return diag_set(d, RT_E_SYNTAX, path, 0, 0,
				"not a whitted tile (a PNG without the whitted-tile text chunk that whitted --region writes)");
	if (r->texts > 1)
		return diag_set(d, RT_E_SYNTAX, path, 0, 0, "two whitted-tile chunks");
	if ((rc = tile_text_parse(path, r->text, r->text_len, info, d)) < 0)
		return rc;
	if (r->width != (png_uint_32)(info->x1 - info->x0) ||
	    r->height != (png_uint_32)(info->y1 - info->y0))
		return diag_set(d, RT_E_SYNTAX, path, 0, 0,
				"the image is %lux%lu but its whitted-tile region %d,%d,%d,%d is %dx%d",
				(unsigned long)r->width, (unsigned long)r->height, info->x0, info->y0,
				info->x1, info->y1, info->x1 - info->x0, info->y1 - info->y0);
	if ((r->have_offs && (r->off_unit != PNG_OFFSET_PIXEL || r->off_x != info->x0 ||
			      r->off_y != info->y0)) ||
	    (r->have_vpag && (r->page_unit != 0 || r->page_width != (png_uint_32)info->full_width ||
			      r->page_height != (png_uint_32)info->full_height)))
		return diag_set(d, RT_E_SYNTAX, path, 0, 0,
				"its oFFs or vpAg chunk disagrees with its whitted-tile chunk");
	/* What whitted writes; the pixels are then the file's bytes. */
	if (r->bit_depth != 8 || r->color_type != PNG_COLOR_TYPE_RGB)
		return diag_set(d, RT_E_SYNTAX, path, 0, 0,
				"a whitted tile is an 8-bit RGB PNG, this one has bit depth %d and colour type %d",
				r->bit_depth, r->color_type);
	return 0;
}

int tile_read_memory(const unsigned char *b, size_t n, const char *path, struct tile_info *info,
		     struct image *img, struct diag *d)
{
	struct tile_reader r;
	struct tile_png p;
	int rc;

	struct png_facts facts;

	if (n < 8 || png_sig_cmp(b, 0, 8) != 0)
		return diag_set(d, RT_E_SYNTAX, path, 0, 0, "not a PNG file");
	/* Before libpng allocates or inflates anything: the CRCs, a size
	 * within the limit and the file's means, no more data than the
	 * header's, nothing after IEND. */
	if ((rc = png_check(b, n, path, RT_MAX_PIXELS, img != NULL, &facts, d)) < 0)
		return rc;
	if (facts.end != n)
		return diag_set(d, RT_E_SYNTAX, path, 0, 0,
				"junk after the end of the PNG (%zu bytes after its IEND chunk): "
				"damaged, or not the file whitted wrote", n - facts.end);
	memset(&r, 0, sizeof(r));
	r.data = b;
	r.len = n;
	memset(&p, 0, sizeof(p));
	p.png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &p.msg, png_message_error, png_message_warning);
	if (p.png)
		p.info = png_create_info_struct(p.png);
	if (!p.info) {
		png_destroy_read_struct(&p.png, NULL, NULL);
		return diag_fail(d, RT_E_NOMEM, "out of memory for a tile's PNG");
	}
	if (!tile_png_guard(&p, tile_read_head, &r)) {
		rc = tile_png_failed(path, &p, &r, d);
		goto out_destroy;
	}
	if ((rc = tile_check_head(path, &r, info, d)) < 0 || !img)
		goto out_destroy;
	if ((rc = image_alloc(img, (int)r.width, (int)r.height, d)) < 0)
		goto out_destroy;
	r.img = img;
	if (!tile_png_guard(&p, tile_read_rows, &r)) {
		rc = tile_png_failed(path, &p, &r, d);
		image_free(img);
	}
out_destroy:
	png_destroy_read_struct(&p.png, &p.info, NULL);
	return rc;
}

int tile_read(const char *path, struct tile_info *info, struct image *img, struct diag *d)
{
	char *buf;
	size_t n = 0;
	int rc = file_read_all(path, "tile", TILE_MAX_FILE_BYTES, &buf, &n, d);

	if (rc < 0)
		return rc;
	rc = tile_read_memory((const unsigned char *)buf, n, path, info, img, d);
	rt_free(buf);
	return rc;
}
