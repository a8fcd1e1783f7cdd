/* The fuzz target of the image readers (stb_image and the checks and the
 * P3 reader around it), shared by libFuzzer and the replay driver. */
#include "grade/grade_impl.h"
#include "harness.h"
#include "whitted/image.h"

int fuzz_image_one(const uint8_t *data, size_t size)
{
	struct image img, t, diff;
	struct grade_figures f;
	struct diag d;

	if (image_read_memory(data, size, "fuzz", &img, NULL, &d) < 0)
		return 0;
	if (grade_transform(&img, RT_CAUSE_MIRRORED, &t, &d) == 0) {
		grade_figures_of(&img, &t, 1, 0, 0, &f);
		if (grade_diff_image(&img, &t, &diff, &d) == 0)
			image_free(&diff);
		image_free(&t);
	}
	image_free(&img);
	return 0;
}
