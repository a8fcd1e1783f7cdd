/* Animations: the camera of frame k of n along an orbit or a keyframe
 * path, and the output file name of each frame.  Frames are numbered from
 * 1, as their file names (frame-0001.png ...). */
#ifndef RT_FRAMES_H
#define RT_FRAMES_H

#include <stdbool.h>
#include <stddef.h>

#include "camera.h"
#include "diag.h"

#define RT_MAX_FRAMES 1000000
#define RT_MAX_KEYFRAMES 100000
/* The default output pattern of --frames. */
#define RT_FRAMES_PATTERN "frame-%04d.png"

/* Keyframes read from a path file (see docs/distributed.md). */
struct frame_path {
	struct camera_params *keys;
	size_t n_keys;			/* >= 1 */
};

/* Frame k of n on a full turn about the axis through base->look along
 * base->up: the eye turned by 360 * (k - 1) / n degrees (counter-clockwise
 * seen from the tip of up), look, up and field of view unchanged.  Frame 1
 * is the base camera exactly. */
void frames_orbit(const struct camera_params *base, int k, int n, struct camera_params *out);

/* Reads a path file.  Each keyframe line holds "eye X,Y,Z", "look X,Y,Z",
 * "up X,Y,Z" and "fov DEGREES" in any order; a missing one is the previous
 * keyframe's (for the first: base's).  '#' starts a comment.  Errors give
 * the file and line. */
int frames_path_load(const char *path, const struct camera_params *base,
		     struct frame_path *out, struct diag *d);
void frames_path_free(struct frame_path *p);

/* Frame k of n on the path: the keyframes spread evenly over the frames,
 * frame 1 at the first and frame n at the last, eye, look, up and field of
 * view interpolated linearly in between. */
void frames_on_path(const struct frame_path *p, int k, int n, struct camera_params *out);

/* Checks an output pattern: at most one number conversion, %d or %0Wd
 * (W from 1 to 9), and "%%" for a percent sign.  Sets *numbered when it has
 * the conversion. */
int frames_pattern_check(const char *pattern, bool *numbered, struct diag *d);

/* The pattern with frame k in place of its conversion (a pattern without
 * one is copied).  RT_E_RANGE when it does not fit buf. */
int frames_name(const char *pattern, int k, char *buf, size_t size, struct diag *d);

#endif
