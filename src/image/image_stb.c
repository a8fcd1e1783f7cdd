/* The decoder of PNG and BMP files: stb_image (Debian's
 * libstb-dev), compiled here and only here, static, with the project's
 * allocator (so that the tests' allocation failures reach it) and its own
 * warnings silenced for this file alone: it is not our code to change. */
#include <stdint.h>
#include <string.h>

#include "base/alloc.h"
#include "image/image_read.h"

#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_STATIC
#define STBI_NO_STDIO
#define STBI_NO_LINEAR
#define STBI_NO_HDR
#define STBI_ONLY_PNG
#define STBI_ONLY_BMP
#define STBI_MAX_DIMENSIONS (1 << 16)
#define STBI_MALLOC(n) rt_malloc(n)
#define STBI_REALLOC(p, n) rt_reallocarray((p), 1, (n))
#define STBI_FREE(p) rt_free(p)
#define STBI_ASSERT(x) ((void)0)
#define STBI_FAILURE_USERMSG
/* Its declarations of the functions left out warn at the end of the file. */
#if defined(__GNUC__)
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wpedantic"
#pragma GCC diagnostic ignored "-Wmissing-prototypes"
#pragma GCC diagnostic ignored "-Wunused-parameter"
#pragma GCC diagnostic ignored "-Wsign-compare"
#pragma GCC diagnostic ignored "-Wimplicit-fallthrough"
#pragma GCC diagnostic ignored "-Wconversion"
#pragma GCC diagnostic ignored "-Wshadow"
#pragma GCC diagnostic ignored "-Wdeclaration-after-statement"
#endif
#include <stb/stb_image.h>
#if defined(__GNUC__)
#pragma GCC diagnostic pop
#endif

int image_stb_decode(const unsigned char *data, size_t len, const char *name,
		     struct image *img, struct diag *d)
{
	int w, h, comp;
	unsigned char *px;

	img->width = img->height = 0;
	img->pixels = NULL;
	if (len > (size_t)INT32_MAX)
		return diag_set(d, RT_E_RANGE, name, 0, 0, "the image file is too large");
	if (!stbi_info_from_memory(data, (int)len, &w, &h, &comp))
		return diag_set(d, RT_E_SYNTAX, name, 0, 0,
				"cannot read the image (%s): it is damaged, truncated or of a kind "
				"not read (PNG, uncompressed BMP, PPM)", stbi_failure_reason());
	if ((long long)w * h > RT_IMAGE_READ_MAX_PIXELS)
		return image_read_over_limit(name, (unsigned long long)w, (unsigned long long)h,
					     RT_IMAGE_READ_MAX_PIXELS, d);
	px = stbi_load_from_memory(data, (int)len, &w, &h, &comp, 3);
	if (!px) {
		const char *why = stbi_failure_reason();
		if (why && strcmp(why, "Out of memory") == 0)
			return diag_set(d, RT_E_NOMEM, name, 0, 0, "out of memory reading the image");
		return diag_set(d, RT_E_SYNTAX, name, 0, 0,
				"cannot read the image (%s): it is damaged or truncated",
				why ? why : "corrupt");
	}
	img->width = w;
	img->height = h;
	img->pixels = px;
	return 0;
}
