/* Which library deflates the PNG strips (png_deflate.h): ISA-L where the
 * build has it, else zlib. */
#include <pthread.h>

#include "image/png_deflate.h"

static pthread_once_t best_once = PTHREAD_ONCE_INIT;

static const struct png_deflate_ops *best_ops(void)
{
#ifdef RT_HAVE_ISAL
	return &png_deflate_isal;
#else
	return &png_deflate_zlib;
#endif
}

static void best_prepare(void)
{
	if (best_ops()->prepare)
		best_ops()->prepare();
}

const struct png_deflate_ops *png_deflate_best(void)
{
	pthread_once(&best_once, best_prepare);
	return best_ops();
}
