/* Tile PNGs.  libpng's simplified API encodes and decodes the pixels (no
 * setjmp); the chunks that place a tile are written and read here by hand,
 * which PNG's plain chunk layout (length, type, data, CRC-32) makes short:
 * the encoded image is split after its IHDR chunk and oFFs, vpAg and tEXt
 * go in between.  Reading walks the chunk list the same way before handing
 * the whole file to libpng. */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <inttypes.h>
#include <png.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "alloc.h"
#include "file.h"
#include "hash.h"
#include "tile.h"

/* Larger files are refused: a full tile of the largest image is ~800 MB
 * uncompressed, and PNG never grows it by much. */
#define TILE_MAX_FILE_BYTES (1L << 30)
#define TILE_TEXT_MAX (RT_TILE_OPTIONS_MAX + 256)

static const unsigned char tile_png_signature[8] = { 137, 80, 78, 71, 13, 10, 26, 10 };

/* The CRC-32 of PNG and zlib (reflected polynomial 0xedb88320), a bit at a
 * time: it only covers the few small chunks handled here.  Chains like
 * zlib's crc32: tile_crc(tile_crc(0, a), b) is the CRC of a then b. */
static uint32_t tile_crc(uint32_t crc, const unsigned char *p, size_t n)
{
	size_t i;
	int k;

	crc = ~crc;
	for (i = 0; i < n; i++) {
		crc ^= p[i];
		for (k = 0; k < 8; k++)
			crc = (crc >> 1) ^ (UINT32_C(0xedb88320) & (0u - (crc & 1u)));
	}
	return ~crc;
}

static void tile_put32(unsigned char *p, uint32_t v)
{
	p[0] = (unsigned char)(v >> 24);
	p[1] = (unsigned char)(v >> 16);
	p[2] = (unsigned char)(v >> 8);
	p[3] = (unsigned char)v;
}

static uint32_t tile_get32(const unsigned char *p)
{
	return (uint32_t)p[0] << 24 | (uint32_t)p[1] << 16 | (uint32_t)p[2] << 8 | p[3];
}

/* The shortest of %.15g, %.16g and %.17g that reads back as v. */
static void tile_format_double(char *buf, size_t size, double v)
{
	int digits;

	for (digits = 15; digits < 17; digits++) {
		snprintf(buf, size, "%.*g", digits, v);
		if (strtod(buf, NULL) == v)
			return;
	}
	snprintf(buf, size, "%.17g", v);
}

static void tile_format_vec3(char *buf, size_t size, struct vec3 v)
{
	char x[32], y[32], z[32];

	tile_format_double(x, sizeof(x), v.x);
	tile_format_double(y, sizeof(y), v.y);
	tile_format_double(z, sizeof(z), v.z);
	snprintf(buf, size, "%s,%s,%s", x, y, z);
}

void tile_settings_format(const struct tile_settings *s, char *buf, size_t size)
{
	char eye[100], look[100], up[100], fov[32], w[32], t[32], floor[70];

	tile_format_vec3(eye, sizeof(eye), s->camera.eye);
	tile_format_vec3(look, sizeof(look), s->camera.look);
	tile_format_vec3(up, sizeof(up), s->camera.up);
	tile_format_double(fov, sizeof(fov), s->camera.fov_deg);
	if (s->floor) {
		tile_format_double(w, sizeof(w), s->floor_width);
		tile_format_double(t, sizeof(t), s->floor_tile);
		snprintf(floor, sizeof(floor), "%s,%s", w, t);
	} else {
		snprintf(floor, sizeof(floor), "none");
	}
	snprintf(buf, size, "size=%d recursion=%d eye=%s look=%s up=%s fov=%s floor=%s clamp=%s",
		 s->size, s->recursion, eye, look, up, fov, floor,
		 s->clamp == RT_CLAMP_FINAL ? "final" : "level");
}

void tile_info_init(struct tile_info *info, const struct tile_settings *s, uint64_t scene_hash,
		    int x0, int y0, int x1, int y1)
{
	memset(info, 0, sizeof(*info));
	info->full_width = info->full_height = s->size;
	info->x0 = x0;
	info->y0 = y0;
	info->x1 = x1;
	info->y1 = y1;
	info->scene_hash = scene_hash;
	tile_settings_format(s, info->options, sizeof(info->options));
	info->options_hash = hash_bytes(RT_HASH_INIT, info->options, strlen(info->options));
}

int tile_check_region(int x0, int y0, int x1, int y1, int full_width, int full_height,
		      struct diag *d)
{
	if (x0 >= x1 || y0 >= y1)
		return diag_set(d, RT_E_INVALID, "", 0, 0,
				"region %d,%d,%d,%d is empty or inverted (X0,Y0,X1,Y1 are end-exclusive: X0 < X1, Y0 < Y1)",
				x0, y0, x1, y1);
	if (x0 < 0 || y0 < 0 || x1 > full_width || y1 > full_height)
		return diag_set(d, RT_E_INVALID, "", 0, 0,
				"region %d,%d,%d,%d is outside the %dx%d image (pixels 0..%d, 0..%d)",
				x0, y0, x1, y1, full_width, full_height, full_width - 1, full_height - 1);
	return 0;
}

/* The text of the whitted-tile chunk, one "key value" per line. */
static void tile_text_format(const struct tile_info *t, char *buf, size_t size)
{
	snprintf(buf, size,
		 "version %d\n"
		 "full-size %d %d\n"
		 "region %d %d %d %d\n"
		 "scene-hash %016" PRIx64 "\n"
		 "options-hash %016" PRIx64 "\n"
		 "options %s",
		 RT_TILE_VERSION, t->full_width, t->full_height, t->x0, t->y0, t->x1, t->y1,
		 t->scene_hash, t->options_hash, t->options);
}

struct tile_cursor {
	const char *p;
	bool ok;
};

static void tile_expect(struct tile_cursor *c, const char *lit)
{
	size_t n = strlen(lit);

	if (c->ok && strncmp(c->p, lit, n) == 0)
		c->p += n;
	else
		c->ok = false;
}

/* 1 to 9 decimal digits. */
static int tile_int(struct tile_cursor *c)
{
	int v = 0, n = 0;

	while (c->ok && *c->p >= '0' && *c->p <= '9' && n < 9) {
		v = v * 10 + (*c->p++ - '0');
		n++;
	}
	if (n == 0)
		c->ok = false;
	return v;
}

/* Exactly 16 lower-case hex digits. */
static uint64_t tile_hex64(struct tile_cursor *c)
{
	uint64_t v = 0;
	int i;

	for (i = 0; i < 16 && c->ok; i++, c->p++) {
		if (*c->p >= '0' && *c->p <= '9')
			v = v << 4 | (uint64_t)(*c->p - '0');
		else if (*c->p >= 'a' && *c->p <= 'f')
			v = v << 4 | (uint64_t)(*c->p - 'a' + 10);
		else
			c->ok = false;
	}
	return v;
}

/* Parses the chunk text; it must be exactly what tile_text_format writes. */
static int tile_text_parse(const char *path, const unsigned char *text, size_t len,
			   struct tile_info *t, struct diag *d)
{
	char buf[TILE_TEXT_MAX], again[TILE_TEXT_MAX];
	struct tile_cursor c;
	int version;
	size_t n;

	memset(t, 0, sizeof(*t));
	if (len >= sizeof(buf) || memchr(text, '\0', len))
		goto out_bad;
	memcpy(buf, text, len);
	buf[len] = '\0';
	c.p = buf;
	c.ok = true;
	tile_expect(&c, "version ");
	version = tile_int(&c);
	if (c.ok && version != RT_TILE_VERSION)
		return diag_set(d, RT_E_SYNTAX, path, 0, 0,
				"whitted-tile version %d, this whitted reads version %d", version,
				RT_TILE_VERSION);
	tile_expect(&c, "\nfull-size ");
	t->full_width = tile_int(&c);
	tile_expect(&c, " ");
	t->full_height = tile_int(&c);
	tile_expect(&c, "\nregion ");
	t->x0 = tile_int(&c);
	tile_expect(&c, " ");
	t->y0 = tile_int(&c);
	tile_expect(&c, " ");
	t->x1 = tile_int(&c);
	tile_expect(&c, " ");
	t->y1 = tile_int(&c);
	tile_expect(&c, "\nscene-hash ");
	t->scene_hash = tile_hex64(&c);
	tile_expect(&c, "\noptions-hash ");
	t->options_hash = tile_hex64(&c);
	tile_expect(&c, "\noptions ");
	if (!c.ok)
		goto out_bad;
	n = strlen(c.p);
	if (n >= sizeof(t->options) || strchr(c.p, '\n'))
		goto out_bad;
	memcpy(t->options, c.p, n + 1);
	tile_text_format(t, again, sizeof(again));
	if (strcmp(again, buf) != 0)
		goto out_bad;
	if (t->full_width < 1 || t->full_height < 1 ||
	    tile_check_region(t->x0, t->y0, t->x1, t->y1, t->full_width, t->full_height, d) < 0)
		return diag_set(d, RT_E_SYNTAX, path, 0, 0,
				"whitted-tile chunk: region %d,%d,%d,%d does not fit the %dx%d image",
				t->x0, t->y0, t->x1, t->y1, t->full_width, t->full_height);
	if (hash_bytes(RT_HASH_INIT, t->options, n) != t->options_hash)
		return diag_set(d, RT_E_SYNTAX, path, 0, 0,
				"whitted-tile chunk: the options hash does not match the options text");
	return 0;
out_bad:
	return diag_set(d, RT_E_SYNTAX, path, 0, 0, "malformed whitted-tile chunk");
}

/* What the chunk walk found. */
struct tile_chunks {
	uint32_t width, height;			/* IHDR */
	bool have_offs, have_vpag;
	int32_t off_x, off_y;			/* oFFs */
	unsigned off_unit;
	uint32_t page_width, page_height;	/* vpAg */
	unsigned page_unit;
	const unsigned char *text;		/* the whitted-tile text, or NULL */
	size_t text_len;
};

static bool tile_chunk_is(const unsigned char *type, const char *name)
{
	return memcmp(type, name, 4) == 0;
}

static int tile_scan(const char *path, const unsigned char *b, size_t n, struct tile_chunks *c,
		     struct diag *d)
{
	const size_t key_len = sizeof(RT_TILE_KEYWORD);	/* with its NUL */
	size_t pos = 8;
	bool first = true;

	memset(c, 0, sizeof(*c));
	if (n < 8 || memcmp(b, tile_png_signature, 8) != 0)
		return diag_set(d, RT_E_SYNTAX, path, 0, 0, "not a PNG file");
	for (;;) {
		const unsigned char *type, *data;
		uint32_t len;

		if (n - pos < 12)
			return diag_set(d, RT_E_SYNTAX, path, 0, 0, "truncated PNG file");
		len = tile_get32(b + pos);
		if (len > 0x7fffffffu || len > n - pos - 12)
			return diag_set(d, RT_E_SYNTAX, path, 0, 0, "truncated PNG file");
		type = b + pos + 4;
		data = type + 4;
		if ((tile_chunk_is(type, "IHDR") || tile_chunk_is(type, "oFFs") ||
		     tile_chunk_is(type, "vpAg") || tile_chunk_is(type, "tEXt")) &&
		    tile_get32(data + len) != tile_crc(0, type, (size_t)len + 4))
			return diag_set(d, RT_E_SYNTAX, path, 0, 0, "damaged PNG file (bad CRC in its %.4s chunk)",
					(const char *)type);
		if (first != tile_chunk_is(type, "IHDR") || (first && len != 13))
			return diag_set(d, RT_E_SYNTAX, path, 0, 0, "damaged PNG file (no IHDR chunk first)");
		if (first) {
			c->width = tile_get32(data);
			c->height = tile_get32(data + 4);
		} else if (tile_chunk_is(type, "oFFs") && len == 9) {
			c->have_offs = true;
			c->off_x = (int32_t)tile_get32(data);
			c->off_y = (int32_t)tile_get32(data + 4);
			c->off_unit = data[8];
		} else if (tile_chunk_is(type, "vpAg") && len == 9) {
			c->have_vpag = true;
			c->page_width = tile_get32(data);
			c->page_height = tile_get32(data + 4);
			c->page_unit = data[8];
		} else if (tile_chunk_is(type, "tEXt") && len >= key_len &&
			   memcmp(data, RT_TILE_KEYWORD, key_len) == 0) {
			if (c->text)
				return diag_set(d, RT_E_SYNTAX, path, 0, 0, "two whitted-tile chunks");
			c->text = data + key_len;
			c->text_len = len - key_len;
		} else if (tile_chunk_is(type, "IEND")) {
			return 0;
		}
		first = false;
		pos += (size_t)len + 12;
	}
}

/* Reads a whole file into memory. */
static int tile_read_file(const char *path, unsigned char **out, size_t *out_len, struct diag *d)
{
	char *buf;
	int rc = file_read_all(path, "tile", TILE_MAX_FILE_BYTES, &buf, out_len, d);

	*out = (unsigned char *)buf;
	return rc;
}

/* Decodes the pixels with libpng's simplified API. */
static int tile_decode(const char *path, const unsigned char *b, size_t n, const struct tile_info *t,
		       struct image *img, struct diag *d)
{
	png_image png;
	int rc;

	memset(&png, 0, sizeof(png));
	png.version = PNG_IMAGE_VERSION;
	if (!png_image_begin_read_from_memory(&png, b, n))
		return diag_set(d, RT_E_SYNTAX, path, 0, 0, "cannot read PNG: %s", png.message);
	png.format = PNG_FORMAT_RGB;
	if ((rc = image_alloc(img, t->x1 - t->x0, t->y1 - t->y0, d)) < 0) {
		png_image_free(&png);
		return rc;
	}
	if (!png_image_finish_read(&png, NULL, img->pixels, 0, NULL)) {
		rc = diag_set(d, RT_E_SYNTAX, path, 0, 0, "cannot read PNG: %s", png.message);
		image_free(img);
		png_image_free(&png);
		return rc;
	}
	return 0;
}

int tile_read(const char *path, struct tile_info *info, struct image *img, struct diag *d)
{
	struct tile_chunks c;
	unsigned char *b;
	size_t n = 0;
	int rc;

	if ((rc = tile_read_file(path, &b, &n, d)) < 0)
		return rc;
	if ((rc = tile_scan(path, b, n, &c, d)) < 0)
		goto out_free;
	if (!c.text) {
		rc = diag_set(d, RT_E_SYNTAX, path, 0, 0,
			      "not a whitted tile (a PNG without the whitted-tile text chunk that whitted --region writes)");
		goto out_free;
	}
	if ((rc = tile_text_parse(path, c.text, c.text_len, info, d)) < 0)
		goto out_free;
	if (c.width != (uint32_t)(info->x1 - info->x0) || c.height != (uint32_t)(info->y1 - info->y0)) {
		rc = diag_set(d, RT_E_SYNTAX, path, 0, 0,
			      "the image is %lux%lu but its whitted-tile region %d,%d,%d,%d is %dx%d",
			      (unsigned long)c.width, (unsigned long)c.height, info->x0, info->y0,
			      info->x1, info->y1, info->x1 - info->x0, info->y1 - info->y0);
		goto out_free;
	}
	if ((c.have_offs && (c.off_unit != 0 || c.off_x != info->x0 || c.off_y != info->y0)) ||
	    (c.have_vpag && (c.page_unit != 0 || c.page_width != (uint32_t)info->full_width ||
			     c.page_height != (uint32_t)info->full_height))) {
		rc = diag_set(d, RT_E_SYNTAX, path, 0, 0,
			      "its oFFs or vpAg chunk disagrees with its whitted-tile chunk");
		goto out_free;
	}
	if (img)
		rc = tile_decode(path, b, n, info, img, d);
out_free:
	rt_free(b);
	return rc;
}

/* Writes one chunk: length, type, data, CRC of type and data. */
static bool tile_put_chunk(FILE *f, const char *type, const unsigned char *data, size_t len)
{
	unsigned char head[8], crc[4];

	tile_put32(head, (uint32_t)len);
	memcpy(head + 4, type, 4);
	tile_put32(crc, tile_crc(tile_crc(0, head + 4, 4), data, len));
	return fwrite(head, 1, 8, f) == 8 && (len == 0 || fwrite(data, 1, len, f) == len) &&
	       fwrite(crc, 1, 4, f) == 4;
}

struct tile_fill {
	const unsigned char *png;
	size_t len;
	const struct tile_info *info;
};

/* The signature and IHDR chunk, then oFFs, vpAg and tEXt, then the rest. */
static int tile_fill(void *ctx, FILE *f, struct diag *d)
{
	const struct tile_fill *t = ctx;
	const size_t head = 8 + 25;
	unsigned char offs[9], vpag[9], text[sizeof(RT_TILE_KEYWORD) + TILE_TEXT_MAX];
	size_t key_len = sizeof(RT_TILE_KEYWORD);

	tile_put32(offs, (uint32_t)t->info->x0);
	tile_put32(offs + 4, (uint32_t)t->info->y0);
	offs[8] = 0;	/* unit: pixels */
	tile_put32(vpag, (uint32_t)t->info->full_width);
	tile_put32(vpag + 4, (uint32_t)t->info->full_height);
	vpag[8] = 0;
	memcpy(text, RT_TILE_KEYWORD, key_len);
	tile_text_format(t->info, (char *)text + key_len, sizeof(text) - key_len);
	if (fwrite(t->png, 1, head, f) != head || !tile_put_chunk(f, "oFFs", offs, sizeof(offs)) ||
	    !tile_put_chunk(f, "vpAg", vpag, sizeof(vpag)) ||
	    !tile_put_chunk(f, "tEXt", text, key_len + strlen((char *)text + key_len)) ||
	    fwrite(t->png + head, 1, t->len - head, f) != t->len - head)
		return diag_set(d, RT_E_IO, "", 0, 0, "cannot write: %s", strerror(errno));
	return 0;
}

int tile_write(const char *path, const struct image *img, const struct tile_info *info,
	       const volatile sig_atomic_t *cancel, struct diag *d)
{
	struct tile_fill fill;
	png_alloc_size_t size;
	png_image png;
	unsigned char *buf;
	int rc;

	if (img->width != info->x1 - info->x0 || img->height != info->y1 - info->y0)
		return diag_set(d, RT_E_INVALID, "", 0, 0, "the tile image does not have its region's size");
	memset(&png, 0, sizeof(png));
	png.version = PNG_IMAGE_VERSION;
	png.width = (png_uint_32)img->width;
	png.height = (png_uint_32)img->height;
	png.format = PNG_FORMAT_RGB;
	size = PNG_IMAGE_PNG_SIZE_MAX(png);
	buf = rt_malloc(size);
	if (!buf)
		return diag_set(d, RT_E_NOMEM, "", 0, 0, "out of memory for a %dx%d tile",
				img->width, img->height);
	if (!png_image_write_to_memory(&png, buf, &size, 0, img->pixels, 0, NULL)) {
		rc = diag_set(d, RT_E_IO, path, 0, 0, "cannot write PNG: %s", png.message);
		goto out_free;
	}
	if (size < 8 + 25 || memcmp(buf + 12, "IHDR", 4) != 0) {
		rc = diag_set(d, RT_E_IO, path, 0, 0, "cannot write PNG: unexpected libpng output");
		goto out_free;
	}
	fill.png = buf;
	fill.len = size;
	fill.info = info;
	rc = image_write_file(path, tile_fill, &fill, cancel, d);
out_free:
	rt_free(buf);
	return rc;
}
