/* The options of a whitted render (a still image, a region, a grid tile or
 * the frames of an animation) and their reading from argv. */
#ifndef RT_CLI_RENDER_ARGS_H
#define RT_CLI_RENDER_ARGS_H

#include <stdbool.h>
#include <stdint.h>

#include "cli/scene_opts.h"
#include "whitted/image.h"


enum {
	OPT_STATS = CLI_OPT_FIRST_PRIVATE,
	OPT_PROGRESS,
	OPT_FORMAT,
	OPT_REGION,
	OPT_FRAMES,
	OPT_FRAME,
	OPT_PATH,
	OPT_GRID,
	OPT_TILE,
	OPT_LIST_SHAPES,
	OPT_MAX_RAYS,
};

#define NAME_MAX_LEN 4096

enum progress_mode { PROGRESS_AUTO, PROGRESS_ALWAYS, PROGRESS_NEVER };

struct options {
	struct cli_scene scene;
	const char *scene_path;
	const char *output;
	char *output_owned;
	enum image_format format;
	int threads;
	bool stats;
	enum progress_mode progress;
	bool region;
	int x0, y0, x1, y1;		/* the region, end-exclusive */
	int frames;			/* 0: a still image */
	int frame;			/* 0: every frame */
	const char *path_file;		/* keyframes; NULL: the orbit */
	bool numbered;			/* output is a pattern with a frame number */
	int grid_cols, grid_rows;	/* --grid; 0: none */
	int tile;			/* --tile K of the grid, 1-based */
	uint64_t max_rays;		/* --max-rays; 0: the default */
};


/* Fills o from argv.  Returns 0, or the exit status to stop with: a usage
 * error has been printed (2), or --help or --version answered (-1: exit 0).
 * o->output_owned is to be freed in any case. */
int render_args_parse(int argc, char **argv, struct options *o);

#endif
