/* The image data of whitted's PNGs, made for speed.  Each row is filtered
 * with PNG's Up filter (the difference from the row above: a rendered
 * picture is mostly smooth, so most bytes become small or zero) and the
 * rows are compressed in strips of PNG_IDAT_STRIP_ROWS rows, each strip
 * by one of several threads, on its own (png_deflate.h: ISA-L, or zlib at
 * level 1): every strip but the last ends on a byte and not final, so the
 * raw deflate streams of the strips, one after the other, are one valid
 * stream; their Adler-32 checksums are combined into the stream's.
 * The strips are fixed by the image's height alone, so the file is the
 * same byte for byte whatever the number of threads, and whichever thread
 * compresses a strip: a renderer may hand each strip over as soon as its
 * rows are final (png_idat_strips_band_done, from its own threads), so
 * that the compression runs beside the render; the strips left over are
 * compressed when the file is written.  At 1536x1536 zlib's level 1 so
 * took a quarter of the time of libpng's fastest setting (no filter, zlib
 * level 3, one thread) for a file about as small; ISA-L takes a quarter
 * of zlib's.  libpng then writes the chunks (png_write.c). */
#define _POSIX_C_SOURCE 200809L
#include <pthread.h>
#include <stdbool.h>
#include <stdint.h>
#include <string.h>
#include <unistd.h>
#include <zlib.h>
#if defined(__SSE2__) && !defined(ACCEL_PORTABLE)
#include <emmintrin.h>
#endif

#include "base/alloc.h"
#include "base/platform.h"
#include "base/thread.h"
#include "image/png_deflate.h"
#include "image/png_idat.h"

#define PNG_IDAT_MAX_THREADS 8

struct png_idat_strip {
	unsigned char *out;
	size_t cap, len;
	uint32_t adler;
	int status;		/* 0, or RT_E_NOMEM when the deflate failed */
	bool done;		/* compressed, well or not (status says) */
	int bands_final;	/* how many of the bands it needs are final */
};

/* One thread's compressor, kept from strip to strip, and the buffer of
 * one strip's filtered rows. */
struct png_idat_coder {
	void *def;		/* the library's (png_deflate.h) */
	unsigned char *filtered;
};

struct png_idat_strips {
	const struct image *img;
	struct png_idat_strip *strips;
	int n_strips;
	const struct png_deflate_ops *deflate;
	struct png_idat_coder *coders;
	int n_coders;
	pthread_mutex_t lock;	/* over the strips' bands_final */
	int next;		/* atomic: the next strip a finishing thread looks at */
	/* The strips' outputs, one after the other, each its bound long:
	 * one allocation, where one a strip cost a mapping and its removal
	 * each (the bound is over glibc's mmap threshold). */
	unsigned char *outs;
	unsigned char trailer[4];	/* the stream's Adler-32, once finished */
};

/* Rows [y0, y1) with the Up filter: filtered[x] = row[x] - above[x]
 * (mod 256), the row above the image's first being zero.  Sixteen bytes
 * at a time with SSE2 (x86-64's baseline), else eight at a time in a
 * 64-bit word: (a | H) - (b & ~H) subtracts the low seven bits of each
 * byte with no borrow into the next byte (each byte of it is 128 + a7 -
 * b7, in [1, 255]), and the top bit of the byte's difference is then that
 * bit flipped when a's and b's top bits are equal. */
static void png_idat_filter(const struct image *img, unsigned char *filtered, int y0, int y1)
{
	const uint64_t high = 0x8080808080808080u;
	size_t stride = (size_t)img->width * 3, x;
	int y;

	for (y = y0; y < y1; y++) {
		const unsigned char *row = img->pixels + (size_t)y * stride;
		const unsigned char *above;
		unsigned char *o = filtered + (size_t)(y - y0) * (stride + 1);

		o[0] = 2;
		if (y == 0) {
			memcpy(o + 1, row, stride);
			continue;
		}
		above = row - stride;
		x = 0;
#if defined(__SSE2__) && !defined(ACCEL_PORTABLE)
		for (; x + 16 <= stride; x += 16)
			_mm_storeu_si128((__m128i *)(o + 1 + x),
					 _mm_sub_epi8(_mm_loadu_si128((const __m128i *)(row + x)),
						      _mm_loadu_si128((const __m128i *)(above + x))));
#endif
		for (; x + 8 <= stride; x += 8) {
			uint64_t a, b, diff;

			memcpy(&a, row + x, 8);
			memcpy(&b, above + x, 8);
			diff = ((a | high) - (b & ~high)) ^ ((a ^ ~b) & high);
			memcpy(o + 1 + x, &diff, 8);
		}
		for (; x < stride; x++)
			o[1 + x] = (unsigned char)(row[x] - above[x]);
	}
}

/* The coder ready for a strip of `bytes` filtered bytes. */
static int png_idat_coder_ready(const struct png_deflate_ops *ops, struct png_idat_coder *c,
				size_t bytes)
{
	if (!c->filtered && !(c->filtered = rt_malloc(bytes)))
		return RT_E_NOMEM;
	if (!c->def)
		return ops->make(&c->def);
	return 0;
}

static void png_idat_coder_free(const struct png_deflate_ops *ops, struct png_idat_coder *c)
{
	ops->free(c->def);
	c->def = NULL;
	rt_free(c->filtered);
	c->filtered = NULL;
}

static void png_idat_strip_run(struct png_idat_strips *st, int s, struct png_idat_coder *c)
{
	struct png_idat_strip *strip = &st->strips[s];
	size_t line = (size_t)st->img->width * 3 + 1;
	int y0 = s * PNG_IDAT_STRIP_ROWS, y1 = y0 + PNG_IDAT_STRIP_ROWS;
	size_t bytes;

	if (y1 > st->img->height)
		y1 = st->img->height;
	bytes = (size_t)(y1 - y0) * line;
	strip->done = true;
	if (png_idat_coder_ready(st->deflate, c, line * PNG_IDAT_STRIP_ROWS) != 0) {
		strip->status = RT_E_NOMEM;
		return;
	}
	png_idat_filter(st->img, c->filtered, y0, y1);
	strip->adler = st->deflate->adler32(1, c->filtered, bytes);
	strip->status = st->deflate->strip(c->def, c->filtered, bytes, s == st->n_strips - 1,
					  strip->out, strip->cap, &strip->len);
}

void png_idat_strips_free(struct png_idat_strips *st)
{
	int i;

	if (!st)
		return;
	pthread_mutex_destroy(&st->lock);
	for (i = 0; st->coders && i < st->n_coders; i++)
		png_idat_coder_free(st->deflate, &st->coders[i]);
	rt_free(st->outs);
	rt_free(st->coders);
	rt_free(st->strips);
	rt_free(st);
}

int png_idat_strips_open(const struct image *img, int threads, struct png_idat_strips **out,
			 struct diag *d)
{
	size_t line = (size_t)img->width * 3 + 1, cap;
	struct png_idat_strips *st;
	int s;

	*out = NULL;
	st = rt_calloc(1, sizeof(*st));
	if (!st)
		return diag_fail(d, RT_E_NOMEM, "out of memory compressing the PNG");
	pthread_mutex_init(&st->lock, NULL);
	/* Here, on the thread that starts the ones that compress: the
	 * library is readied before they exist (png_deflate.h). */
	st->deflate = png_deflate_best();
	st->img = img;
	st->n_strips = (img->height + PNG_IDAT_STRIP_ROWS - 1) / PNG_IDAT_STRIP_ROWS;
	/* The compression after the fact (png_idat_strips_seal, for
	 * png_idat_strips_write and png_idat_strips_finish) uses up to
	 * PNG_IDAT_MAX_THREADS of them. */
	st->n_coders = threads > PNG_IDAT_MAX_THREADS ? threads : PNG_IDAT_MAX_THREADS;
	st->strips = rt_calloc((size_t)st->n_strips, sizeof(*st->strips));
	st->coders = rt_calloc((size_t)st->n_coders, sizeof(*st->coders));
	if (!st->strips || !st->coders)
		goto out_nomem;
	cap = png_deflate_bound(line * PNG_IDAT_STRIP_ROWS);
	if (!(st->outs = rt_reallocarray(NULL, (size_t)st->n_strips, cap)))
		goto out_nomem;
	for (s = 0; s < st->n_strips; s++) {
		st->strips[s].cap = cap;
		st->strips[s].out = st->outs + (size_t)s * cap;
	}
	*out = st;
	return 0;
out_nomem:
	png_idat_strips_free(st);
	return diag_fail(d, RT_E_NOMEM, "out of memory compressing the PNG");
}

/* Strip s needs its own rows and the row above them (the Up filter's):
 * band s, and band s - 1 unless it is the first.  Whoever makes the last
 * of them final compresses it, outside the lock; the lock (once a band)
 * makes every row's pixels visible to that thread. */
void png_idat_strips_band_done(struct png_idat_strips *st, int band, int thread)
{
	bool ready[2] = { false, false };
	int s;

	if (thread < 0 || thread >= st->n_coders || band < 0 || band >= st->n_strips)
		return;
	pthread_mutex_lock(&st->lock);
	for (s = band; s <= band + 1 && s < st->n_strips; s++)
		ready[s - band] = ++st->strips[s].bands_final == (s == 0 ? 1 : 2);
	pthread_mutex_unlock(&st->lock);
	for (s = band; s <= band + 1 && s < st->n_strips; s++)
		if (ready[s - band])
			png_idat_strip_run(st, s, &st->coders[thread]);
}

struct png_idat_worker {
	struct png_idat_strips *st;
	struct png_idat_coder *coder;
};

/* The strips not yet done, one at a time, until none are left. */
static void *png_idat_worker_main(void *arg)
{
	struct png_idat_worker *w = arg;
	int s;

	while ((s = __atomic_fetch_add(&w->st->next, 1, __ATOMIC_RELAXED)) < w->st->n_strips)
		if (!w->st->strips[s].done)
			png_idat_strip_run(w->st, s, w->coder);
	return NULL;
}

static int png_idat_thread_count(int n_strips)
{
	int cpus = rt_cpu_count();
	int n = cpus > PNG_IDAT_MAX_THREADS ? PNG_IDAT_MAX_THREADS : cpus;

	return n < n_strips ? n : n_strips;
}

/* Compresses the strips no band_done call compressed, on threads where
 * they can be had (the calling thread takes whatever the others leave,
 * all of it when none can be started). */
static void png_idat_run_rest(struct png_idat_strips *st)
{
	struct png_idat_worker workers[PNG_IDAT_MAX_THREADS];
	int t, n = 0, s;

	for (s = 0; s < st->n_strips; s++)
		n += !st->strips[s].done;
	if (n == 0)
		return;
	n = png_idat_thread_count(n);
	st->next = 0;
	for (t = 0; t < n; t++) {
		workers[t].st = st;
		workers[t].coder = &st->coders[t];
	}
	/* A worker whose thread cannot be started then finds no strip
	 * left. */
	rt_run_parts(workers, sizeof(workers[0]), n, png_idat_worker_main);
}

/* The zlib stream's header: deflate, 32 KiB window, fastest. */
static const unsigned char png_idat_header[2] = { 0x78, 0x01 };

/* The strips compressed (those no band_done call compressed, here), and
 * the stream's trailer: the Adler-32 of all rows, big-endian, from the
 * strips'. */
int png_idat_strips_seal(struct png_idat_strips *st, struct diag *d)
{
	size_t line = (size_t)st->img->width * 3 + 1;
	uLong adler = 1;
	int s;

	png_idat_run_rest(st);
	for (s = 0; s < st->n_strips; s++) {
		int rows = st->img->height - s * PNG_IDAT_STRIP_ROWS;

		if (st->strips[s].status != 0)
			return diag_fail(d, RT_E_NOMEM, "out of memory compressing the PNG");
		if (rows > PNG_IDAT_STRIP_ROWS)
			rows = PNG_IDAT_STRIP_ROWS;
		adler = adler32_combine(adler, st->strips[s].adler, (z_off_t)((size_t)rows * line));
	}
	st->trailer[0] = (unsigned char)(adler >> 24);
	st->trailer[1] = (unsigned char)(adler >> 16);
	st->trailer[2] = (unsigned char)(adler >> 8);
	st->trailer[3] = (unsigned char)adler;
	return 0;
}

int png_idat_piece_count(const struct png_idat_strips *st)
{
	return st->n_strips + 2;
}

const struct image *png_idat_strips_image(const struct png_idat_strips *st)
{
	return st->img;
}

/* Piece k of the sealed stream, k in [0, n_strips + 2): the header, the
 * strips in order, the trailer. */
const unsigned char *png_idat_piece(const struct png_idat_strips *st, int k, size_t *len)
{
	if (k == 0) {
		*len = sizeof(png_idat_header);
		return png_idat_header;
	}
	if (k <= st->n_strips) {
		*len = st->strips[k - 1].len;
		return st->strips[k - 1].out;
	}
	*len = sizeof(st->trailer);
	return st->trailer;
}

/* The sealed stream's length: its pieces'. */
size_t png_idat_stream_len(const struct png_idat_strips *st)
{
	size_t total = 0, len;
	int k;

	for (k = 0; k < st->n_strips + 2; k++) {
		png_idat_piece(st, k, &len);
		total += len;
	}
	return total;
}

/* The sealed stream's pieces joined. */
static int png_idat_join(const struct png_idat_strips *st, struct png_idat *out, struct diag *d)
{
	size_t len;
	int k;

	out->data = rt_malloc(png_idat_stream_len(st));
	if (!out->data)
		return diag_fail(d, RT_E_NOMEM, "out of memory compressing the PNG");
	out->len = 0;
	for (k = 0; k < st->n_strips + 2; k++) {
		const unsigned char *p = png_idat_piece(st, k, &len);

		memcpy(out->data + out->len, p, len);
		out->len += len;
	}
	return 0;
}

int png_idat_strips_finish(struct png_idat_strips *st, struct png_idat *out, struct diag *d)
{
	int rc;

	out->data = NULL;
	out->len = 0;
	if ((rc = png_idat_strips_seal(st, d)) < 0)
		return rc;
	return png_idat_join(st, out, d);
}

int png_idat_compress(const struct image *img, struct png_idat *out, struct diag *d)
{
	struct png_idat_strips *st;
	int rc;

	out->data = NULL;
	out->len = 0;
	if ((rc = png_idat_strips_open(img, 1, &st, d)) < 0)
		return rc;
	rc = png_idat_strips_finish(st, out, d);
	png_idat_strips_free(st);
	return rc;
}

void png_idat_free(struct png_idat *z)
{
	rt_free(z->data);
	z->data = NULL;
	z->len = 0;
}
