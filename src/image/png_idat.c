/* The image data of whitted's PNGs, made for speed.  Each row is filtered
 * with PNG's Up filter (the difference from the row above: a rendered
 * picture is mostly smooth, so most bytes become small or zero) and the
 * rows are compressed by zlib at level 1 in strips of PNG_IDAT_STRIP_ROWS
 * rows, each strip by one of several threads: every strip but the last
 * ends with a sync flush (an empty stored block that ends on a byte), so
 * the raw deflate streams of the strips, one after the other, are one
 * valid stream; their Adler-32 checksums are combined into the stream's.
 * The strips are fixed by the image's height alone, so the file is the
 * same byte for byte whatever the number of threads.  At 1536x1536 this
 * takes a quarter of the time of libpng's fastest setting (no filter, zlib
 * level 3, one thread) for a file about as small.  libpng then writes the
 * chunks; its errors come back through a setjmp confined to
 * png_idat_guard, as in dist/tile_png.c. */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <pthread.h>
#include <setjmp.h>
#include <stdbool.h>
#include <string.h>
#include <unistd.h>
#include <zlib.h>

#include "base/alloc.h"
#include "image/png_idat.h"

#define PNG_IDAT_STRIP_ROWS 64
#define PNG_IDAT_MAX_THREADS 8
/* libpng's own IDAT size for the simplified writer. */
#define PNG_IDAT_CHUNK 8192

struct png_idat_strip {
	unsigned char *out;
	size_t cap, len;
	uLong adler;
	int status;		/* 0, or RT_E_NOMEM when zlib had no memory */
};

struct png_idat_job {
	const struct image *img;
	struct png_idat_strip *strips;
	int n_strips, n_threads;
};

struct png_idat_worker {
	struct png_idat_job *job;
	int first;		/* strips first, first + n_threads, ... */
	unsigned char *filtered;	/* one strip's rows, filtered */
};

static voidpf png_idat_zalloc(voidpf opaque, uInt items, uInt size)
{
	(void)opaque;
	return rt_reallocarray(NULL, items, size);
}

static void png_idat_zfree(voidpf opaque, voidpf p)
{
	(void)opaque;
	rt_free(p);
}

/* Rows [y0, y1) with the Up filter: filtered[x] = row[x] - above[x]
 * (mod 256), the row above the image's first being zero. */
static void png_idat_filter(const struct image *img, unsigned char *filtered, int y0, int y1)
{
	size_t stride = (size_t)img->width * 3, x;
	int y;

	for (y = y0; y < y1; y++) {
		const unsigned char *row = img->pixels + (size_t)y * stride;
		unsigned char *o = filtered + (size_t)(y - y0) * (stride + 1);

		o[0] = 2;
		if (y == 0) {
			memcpy(o + 1, row, stride);
			continue;
		}
		for (x = 0; x < stride; x++)
			o[1 + x] = (unsigned char)(row[x] - row[x - stride]);
	}
}

static void png_idat_strip_run(struct png_idat_job *job, int s, unsigned char *in)
{
	struct png_idat_strip *st = &job->strips[s];
	size_t line = (size_t)job->img->width * 3 + 1;
	int y0 = s * PNG_IDAT_STRIP_ROWS, y1 = y0 + PNG_IDAT_STRIP_ROWS;
	z_stream z;
	int rc;

	if (y1 > job->img->height)
		y1 = job->img->height;
	png_idat_filter(job->img, in, y0, y1);
	st->adler = adler32(adler32(0, Z_NULL, 0), in, (uInt)((size_t)(y1 - y0) * line));
	memset(&z, 0, sizeof(z));
	z.zalloc = png_idat_zalloc;
	z.zfree = png_idat_zfree;
	if (deflateInit2(&z, 1, Z_DEFLATED, -15, 8, Z_DEFAULT_STRATEGY) != Z_OK) {
		st->status = RT_E_NOMEM;
		return;
	}
	z.next_in = in;
	z.avail_in = (uInt)((size_t)(y1 - y0) * line);
	z.next_out = st->out;
	z.avail_out = (uInt)st->cap;
	rc = deflate(&z, s == job->n_strips - 1 ? Z_FINISH : Z_SYNC_FLUSH);
	/* The buffer holds deflateBound's worst case and more, so one call
	 * always finishes. */
	st->status = (rc == Z_STREAM_END || (rc == Z_OK && z.avail_in == 0 && z.avail_out > 0))
			     ? 0 : RT_E_NOMEM;
	st->len = st->cap - z.avail_out;
	deflateEnd(&z);
}

static void *png_idat_worker_main(void *arg)
{
	struct png_idat_worker *w = arg;
	int s;

	for (s = w->first; s < w->job->n_strips; s += w->job->n_threads)
		png_idat_strip_run(w->job, s, w->filtered);
	return NULL;
}

static int png_idat_thread_count(int n_strips)
{
	long cpus = sysconf(_SC_NPROCESSORS_ONLN);
	int n = cpus < 1 ? 1 : cpus > PNG_IDAT_MAX_THREADS ? PNG_IDAT_MAX_THREADS : (int)cpus;

	return n < n_strips ? n : n_strips;
}

/* Compresses every strip, on threads where they can be had (a thread that
 * cannot be started, or has no buffer, leaves its strips to the calling
 * thread). */
static int png_idat_run_strips(struct png_idat_job *job)
{
	struct png_idat_worker workers[PNG_IDAT_MAX_THREADS];
	pthread_t tids[PNG_IDAT_MAX_THREADS];
	bool started[PNG_IDAT_MAX_THREADS];
	size_t bytes = ((size_t)job->img->width * 3 + 1) * PNG_IDAT_STRIP_ROWS;
	int t;

	for (t = 0; t < job->n_threads; t++) {
		workers[t].job = job;
		workers[t].first = t;
		workers[t].filtered = t == 0 ? rt_malloc(bytes) : NULL;
		started[t] = false;
	}
	if (!workers[0].filtered)
		return RT_E_NOMEM;
	for (t = 1; t < job->n_threads; t++) {
		workers[t].filtered = rt_malloc(bytes);
		started[t] = workers[t].filtered &&
			     pthread_create(&tids[t], NULL, png_idat_worker_main, &workers[t]) == 0;
	}
	for (t = 0; t < job->n_threads; t++) {
		if (started[t])
			continue;
		if (t > 0) {
			rt_free(workers[t].filtered);
			workers[t].filtered = workers[0].filtered;
		}
		png_idat_worker_main(&workers[t]);
	}
	for (t = 1; t < job->n_threads; t++) {
		if (started[t]) {
			pthread_join(tids[t], NULL);
			rt_free(workers[t].filtered);
		}
	}
	rt_free(workers[0].filtered);
	return 0;
}

/* The zlib stream: header (deflate, 32 KiB window, fastest), the strips,
 * the Adler-32 of all rows, big-endian. */
static int png_idat_join(const struct png_idat_job *job, struct png_idat *out, struct diag *d)
{
	size_t total = 2 + 4, pos = 2, line = (size_t)job->img->width * 3 + 1;
	uLong adler = adler32(0, Z_NULL, 0);
	int s;

	for (s = 0; s < job->n_strips; s++) {
		if (job->strips[s].status != 0)
			return diag_fail(d, RT_E_NOMEM, "out of memory compressing the PNG");
		total += job->strips[s].len;
	}
	out->data = rt_malloc(total);
	if (!out->data)
		return diag_fail(d, RT_E_NOMEM, "out of memory compressing the PNG");
	out->data[0] = 0x78;
	out->data[1] = 0x01;
	for (s = 0; s < job->n_strips; s++) {
		int rows = job->img->height - s * PNG_IDAT_STRIP_ROWS;

		if (rows > PNG_IDAT_STRIP_ROWS)
			rows = PNG_IDAT_STRIP_ROWS;
		memcpy(out->data + pos, job->strips[s].out, job->strips[s].len);
		pos += job->strips[s].len;
		adler = adler32_combine(adler, job->strips[s].adler, (z_off_t)((size_t)rows * line));
	}
	out->data[pos++] = (unsigned char)(adler >> 24);
	out->data[pos++] = (unsigned char)(adler >> 16);
	out->data[pos++] = (unsigned char)(adler >> 8);
	out->data[pos++] = (unsigned char)adler;
	out->len = pos;
	return 0;
}

int png_idat_compress(const struct image *img, struct png_idat *out, struct diag *d)
{
	struct png_idat_job job;
	size_t line = (size_t)img->width * 3 + 1;
	int s, rc = 0;

	out->data = NULL;
	out->len = 0;
	memset(&job, 0, sizeof(job));
	job.img = img;
	job.n_strips = (img->height + PNG_IDAT_STRIP_ROWS - 1) / PNG_IDAT_STRIP_ROWS;
	job.n_threads = png_idat_thread_count(job.n_strips);
	job.strips = rt_calloc((size_t)job.n_strips, sizeof(*job.strips));
	if (!job.strips) {
		rc = diag_fail(d, RT_E_NOMEM, "out of memory compressing the PNG");
		goto out_free;
	}
	for (s = 0; s < job.n_strips; s++) {
		/* compressBound covers a zlib stream of the strip; the sync
		 * flush's empty stored block needs 5 bytes more. */
		job.strips[s].cap = compressBound((uLong)(line * PNG_IDAT_STRIP_ROWS)) + 16;
		job.strips[s].out = rt_malloc(job.strips[s].cap);
		if (!job.strips[s].out) {
			rc = diag_fail(d, RT_E_NOMEM, "out of memory compressing the PNG");
			goto out_free;
		}
	}
	if (png_idat_run_strips(&job) != 0) {
		rc = diag_fail(d, RT_E_NOMEM, "out of memory compressing the PNG");
		goto out_free;
	}
	rc = png_idat_join(&job, out, d);
out_free:
	if (job.strips)
		for (s = 0; s < job.n_strips; s++)
			rt_free(job.strips[s].out);
	rt_free(job.strips);
	return rc;
}

void png_idat_free(struct png_idat *z)
{
	rt_free(z->data);
	z->data = NULL;
	z->len = 0;
}

/* The libpng side: one write structure and the message of its error. */
struct png_idat_writer {
	png_structp png;
	png_infop info;
	const struct image *img;
	const struct png_idat *z;
	FILE *f;
	png_idat_extra_fn *extra;
	void *ctx;
	char msg[200];
};

static void png_idat_error(png_structp png, png_const_charp msg)
{
	struct png_idat_writer *w = png_get_error_ptr(png);

	snprintf(w->msg, sizeof(w->msg), "%s", msg);
	png_longjmp(png, 1);
}

static void png_idat_warning(png_structp png, png_const_charp msg)
{
	(void)png;
	(void)msg;
}

static void png_idat_steps(struct png_idat_writer *w)
{
	static const png_byte idat[5] = "IDAT", iend[5] = "IEND";
	size_t pos;

	png_init_io(w->png, w->f);
	png_set_IHDR(w->png, w->info, (png_uint_32)w->img->width, (png_uint_32)w->img->height, 8,
		     PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT,
		     PNG_FILTER_TYPE_DEFAULT);
	/* As libpng's simplified writer marks every 8-bit image. */
	png_set_sRGB(w->png, w->info, PNG_sRGB_INTENT_PERCEPTUAL);
	if (w->extra)
		w->extra(w->png, w->info, w->ctx);
	png_write_info(w->png, w->info);
	for (pos = 0; pos < w->z->len; pos += PNG_IDAT_CHUNK) {
		size_t n = w->z->len - pos < PNG_IDAT_CHUNK ? w->z->len - pos : PNG_IDAT_CHUNK;
		png_write_chunk(w->png, idat, w->z->data + pos, n);
	}
	/* png_write_end would refuse: it counts only the IDATs it wrote
	 * itself. */
	png_write_chunk(w->png, iend, NULL, 0);
}

/* Runs the steps; false when libpng failed in them (w->msg says why).
 * Everything the steps change lives in *w, so nothing needs to be
 * volatile. */
static bool png_idat_guard(struct png_idat_writer *w)
{
	if (setjmp(png_jmpbuf(w->png)))
		return false;
	png_idat_steps(w);
	return true;
}

int png_idat_write_file(const struct image *img, FILE *f, png_idat_extra_fn *extra, void *ctx,
			struct diag *d)
{
	struct png_idat_writer w;
	struct png_idat z;
	bool ok;
	int rc;

	rc = png_idat_compress(img, &z, d);
	if (rc != 0)
		return rc;
	memset(&w, 0, sizeof(w));
	w.img = img;
	w.z = &z;
	w.f = f;
	w.extra = extra;
	w.ctx = ctx;
	w.png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &w, png_idat_error, png_idat_warning);
	if (w.png)
		w.info = png_create_info_struct(w.png);
	if (!w.info) {
		png_destroy_write_struct(&w.png, NULL);
		png_idat_free(&z);
		return diag_fail(d, RT_E_NOMEM, "out of memory for a PNG");
	}
	errno = 0;
	ok = png_idat_guard(&w);
	png_destroy_write_struct(&w.png, &w.info);
	png_idat_free(&z);
	/* The caller flushes (image_write_file): a small file fails there. */
	if (ok && !ferror(f))
		return 0;
	/* libpng says only "Write Error" when the stream fails: the reason
	 * (a full disk, a file-size limit) is in errno. */
	if (ferror(f) && errno != 0)
		return diag_fail(d, RT_E_IO, "cannot write PNG: %s", strerror(errno));
	return diag_fail(d, RT_E_IO, "cannot write PNG: %s", ok ? "write error" : w.msg);
}
