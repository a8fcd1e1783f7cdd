/* The PNG strips' deflate (png_deflate.h), for each library the build
 * has (zlib always, ISA-L where found): a strip inflates (by zlib) to its
 * input, a strip that is not the last leaves the stream open and ends on
 * a byte, strips one after the other make one stream, and a strip's bytes
 * depend neither on what its compressor did before nor on where the rows
 * and the compressor lie (threads share out the strips in any order, and
 * the file must be the same for any count).  The Adler-32 is zlib's. */
#include <stdlib.h>
#include <string.h>
#include <zlib.h>

#include "image/png_deflate.h"
#include "support.h"

#define BIG 300000

static const struct png_deflate_ops *const libraries[] = {
	&png_deflate_zlib,
#ifdef RT_HAVE_ISAL
	&png_deflate_isal,
#endif
};
#define N_LIBRARIES (sizeof(libraries) / sizeof(libraries[0]))

static unsigned char *make_input(size_t n, int kind, unsigned seed)
{
	unsigned char *p = malloc(n);
	size_t i;

	assert_non_null(p);
	for (i = 0; i < n; i++) {
		seed = seed * 1103515245u + 12345u;
		switch (kind) {
		case 0:	/* noise with flat runs, as a filtered render */
			p[i] = (i / 61) % 3 == 0 ? (unsigned char)(seed >> 16) : (unsigned char)(i / 700);
			break;
		case 1:	/* all zero: ISA-L's repeated-byte path */
			p[i] = 0;
			break;
		case 2:
			p[i] = 0xff;
			break;
		default:	/* incompressible */
			p[i] = (unsigned char)(seed >> 16);
			break;
		}
	}
	return p;
}

static unsigned char *deflate_strip(const struct png_deflate_ops *ops, void *c,
				    const unsigned char *in, size_t n, bool last, size_t *len)
{
	size_t cap = png_deflate_bound(n);
	unsigned char *out = malloc(cap);

	assert_non_null(out);
	assert_int_equal(ops->strip(c, in, n, last, out, cap, len), 0);
	assert_true(*len > 0 && *len <= cap);
	return out;
}

static void *make_coder(const struct png_deflate_ops *ops)
{
	void *c = NULL;

	assert_int_equal(ops->make(&c), 0);
	assert_non_null(c);
	return c;
}

/* Inflates the raw stream s[0, len) into n bytes; whether it ended. */
static bool inflate_all(const unsigned char *s, size_t len, unsigned char *out, size_t n)
{
	z_stream z;
	int rc;

	memset(&z, 0, sizeof(z));
	assert_int_equal(inflateInit2(&z, -15), Z_OK);
	z.next_in = (Bytef *)s;
	z.avail_in = (uInt)len;
	z.next_out = out;
	z.avail_out = (uInt)n + 1;
	rc = inflate(&z, Z_SYNC_FLUSH);
	assert_true(rc == Z_OK || rc == Z_STREAM_END);
	assert_int_equal(z.avail_in, 0);
	assert_int_equal(z.total_out, n);
	inflateEnd(&z);
	return rc == Z_STREAM_END;
}

static void test_png_deflate_round_trip(void **state)
{
	static const size_t sizes[] = {4, 4609, 65535, 65536, 70000, BIG};
	size_t lib, k;
	int kind, last;

	(void)state;
	for (lib = 0; lib < N_LIBRARIES; lib++) {
		const struct png_deflate_ops *ops = libraries[lib];
		void *c = make_coder(ops);

		for (k = 0; k < sizeof(sizes) / sizeof(sizes[0]); k++)
			for (kind = 0; kind < 4; kind++)
				for (last = 0; last < 2; last++) {
					unsigned char *in = make_input(sizes[k], kind, 7u + (unsigned)k);
					unsigned char *back = malloc(sizes[k] + 1);
					size_t len;
					unsigned char *out = deflate_strip(ops, c, in, sizes[k], last, &len);

					assert_non_null(back);
					/* Ends the stream exactly when it is the last. */
					assert_int_equal(inflate_all(out, len, back, sizes[k]), last);
					assert_memory_equal(back, in, sizes[k]);
					free(in);
					free(back);
					free(out);
				}
		ops->free(c);
	}
}

/* Three strips, compressed in the order 2, 0, 1 by one compressor and each
 * by a fresh one from a copy at another address: the same bytes, and one
 * after the other one stream. */
static void test_png_deflate_strips_independent(void **state)
{
	static const int order[3] = {2, 0, 1};
	size_t n[3] = {BIG, 4609 * 3, 70001}, lib;

	(void)state;
	for (lib = 0; lib < N_LIBRARIES; lib++) {
		const struct png_deflate_ops *ops = libraries[lib];
		unsigned char *in[3], *a[3], *b[3], *joined, *back;
		size_t la[3], lb[3], total = 0, pos = 0, sum = 0;
		void *shared = make_coder(ops);
		int i;

		for (i = 0; i < 3; i++)
			in[i] = make_input(n[i], i == 1 ? 1 : 0, 100u + (unsigned)i);
		for (i = 0; i < 3; i++) {
			int s = order[i];

			a[s] = deflate_strip(ops, shared, in[s], n[s], s == 2, &la[s]);
		}
		for (i = 0; i < 3; i++) {
			size_t shift = 4093 * (size_t)(i + 1) + ((size_t)i << 20);
			unsigned char *elsewhere = malloc(n[i] + shift);
			void *fresh = make_coder(ops);

			assert_non_null(elsewhere);
			memcpy(elsewhere + shift, in[i], n[i]);
			b[i] = deflate_strip(ops, fresh, elsewhere + shift, n[i], i == 2, &lb[i]);
			ops->free(fresh);
			free(elsewhere);
			assert_int_equal(la[i], lb[i]);
			assert_memory_equal(a[i], b[i], la[i]);
			total += la[i];
			sum += n[i];
		}
		joined = malloc(total);
		back = malloc(sum + 1);
		assert_non_null(joined);
		assert_non_null(back);
		for (i = 0; i < 3; i++) {
			memcpy(joined + pos, a[i], la[i]);
			pos += la[i];
		}
		assert_true(inflate_all(joined, total, back, sum));
		for (i = 0, pos = 0; i < 3; pos += n[i], i++) {
			assert_memory_equal(back + pos, in[i], n[i]);
			free(in[i]);
			free(a[i]);
			free(b[i]);
		}
		free(joined);
		free(back);
		ops->free(shared);
	}
}

/* Many small strips of few symbols, each compressed by two compressors
 * from two copies far apart: the same bytes every time.  (ISA-L's level 1
 * failed this at strip 3068: it is not used.) */
static void test_png_deflate_addresses(void **state)
{
	size_t lib;

	(void)state;
	for (lib = 0; lib < N_LIBRARIES; lib++) {
		const struct png_deflate_ops *ops = libraries[lib];
		unsigned char *far = malloc((size_t)8 << 20), *near = malloc(4096 + 3000);
		void *a = make_coder(ops), *b = make_coder(ops);
		unsigned seed = 2026;
		int trial;

		assert_non_null(far);
		assert_non_null(near);
		for (trial = 0; trial < 4000; trial++) {
			size_t n, i, la, lb, at;
			unsigned char *x, *y, *oa, *ob;

			seed = seed * 1103515245u + 12345u;
			n = 50 + (seed >> 8) % 2950;
			x = near + (seed >> 4) % 4096;
			seed = seed * 1103515245u + 12345u;
			at = (size_t)(seed >> 8) % (((size_t)8 << 20) - 3000);
			y = far + at;
			for (i = 0; i < n; i++) {
				seed = seed * 1103515245u + 12345u;
				x[i] = (i / 7) % 5 == 0 ? (unsigned char)((seed >> 16) % 4)
							: (unsigned char)(i / 300);
			}
			memcpy(y, x, n);
			oa = deflate_strip(ops, a, x, n, trial & 1, &la);
			ob = deflate_strip(ops, b, y, n, trial & 1, &lb);
			if (la != lb || memcmp(oa, ob, la) != 0)
				fail_msg("%s: strip %d (%zu bytes) compressed to other bytes elsewhere",
					 ops->name, trial, n);
			free(oa);
			free(ob);
		}
		ops->free(a);
		ops->free(b);
		free(far);
		free(near);
	}
}

static void test_png_deflate_adler32(void **state)
{
	static const size_t sizes[] = {0, 1, 15, 16, 5551, 5552, 5553, 65536, BIG};
	size_t lib, k;

	(void)state;
	for (lib = 0; lib < N_LIBRARIES; lib++)
		for (k = 0; k < sizeof(sizes) / sizeof(sizes[0]); k++) {
			unsigned char *in = make_input(sizes[k] ? sizes[k] : 1, 3, 3u + (unsigned)k);
			uLong want = adler32(adler32(0, Z_NULL, 0), in, (uInt)sizes[k]);

			assert_int_equal(libraries[lib]->adler32(1, in, sizes[k]), (uint32_t)want);
			/* Continued from a running value. */
			assert_int_equal(libraries[lib]->adler32(0x12345678u, in, sizes[k]),
					 (uint32_t)adler32(0x12345678u, in, (uInt)sizes[k]));
			free(in);
		}
}

/* The best is ISA-L exactly where the build has it, and twice the same. */
static void test_png_deflate_best(void **state)
{
	(void)state;
#ifdef RT_HAVE_ISAL
	assert_ptr_equal(png_deflate_best(), &png_deflate_isal);
#else
	assert_ptr_equal(png_deflate_best(), &png_deflate_zlib);
#endif
	assert_ptr_equal(png_deflate_best(), png_deflate_best());
}

SUPPORT_MAIN(SUPPORT_TESTS(test_png_deflate_round_trip, test_png_deflate_strips_independent,
			   test_png_deflate_addresses, test_png_deflate_adler32,
			   test_png_deflate_best))
