/* The settings that decide a pixel's value besides the scene text, and the
 * three texts made from them: the canonical text that tiles record (and
 * hash, so that tiles of other settings are refused by the merge), the
 * command-line options that reproduce them (whitted-view's printed
 * command), and the line of whitted --stats.  All three are walks over one
 * table in src/dist/settings.c, so they cannot disagree.
 *
 * A new option that changes pixels is: a member here, one row in that
 * table (its key, which is also its option's name, and its value's text),
 * and filling the member where the programs fill this struct (cli_settings
 * in src/cli/scene_jobs.c, for whitted, the page and the viewer), besides
 * parsing the option itself
 * (src/cli/scene_opts.c).  Tiles, the viewer's command and --stats then
 * carry it with no further edit. */
#ifndef RT_SETTINGS_H
#define RT_SETTINGS_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "camera.h"
#include "material.h"
#include "render.h"

/* Room for the canonical text of any settings, with its NUL: 8192 for the
 * built-in settings (--floor-texture's paths, --glass's list), 2048 more for
 * the plugins' record. */
#define RT_SETTINGS_TEXT_MAX 10240

struct settings {
	int size;			/* the image is size x size */
	int recursion;			/* >= 1 */
	struct camera_params camera;	/* with near and aspect: the nearfar view's */
	bool floor;			/* false: no floor (--no-floor) */
	double floor_width, floor_tile;	/* width INFINITY: nearfar's infinite checkerboard */
	struct material floor_mat;	/* the floor's coefficients (its colour is unused) */
	/* True (the default) when the floor is the one the scene file's view
	 * gives, which whitted adds when neither --floor nor --no-floor is
	 * given; false when --floor chose it. */
	bool floor_from_view;
	enum clamp_mode clamp;
	/* RT_DIALECT_AUTO, or the dialect --dialect forced: the same text read
	 * as another dialect is another scene. */
	enum scene_dialect dialect;
	int samples;			/* --samples N (1: one ray a pixel) */
	const char *floor_texture[2];	/* --floor-texture's paths; NULL: none */
	uint64_t floor_texture_hash;	/* scene_floor_texture_hash: their pixels */
	const char *glass;		/* --glass's canonical list, "" or NULL: none */
	/* NULL or "" when no plugin is loaded, else the record of the plugins
	 * that were (src/plugin/loader.h's plugin_records: name@version#hash
	 * of each, comma-separated): the same scene read with other plugins
	 * may be another image.  In the canonical text as "plugins=...". */
	const char *plugins;
};

/* The built-in defaults: the assignment's camera and floor (the classic
 * view's: RT_FLOOR_WIDTH, RT_FLOOR_TILE, coefficients 0.4 0.2 0.2 0.2,
 * shininess 1), clamping at every level; size and recursion 0, since only
 * a scene file sets them. */
void settings_init(struct settings *s);

/* The canonical one-line text: "size=N recursion=N eye=X,Y,Z look=X,Y,Z
 * up=X,Y,Z fov=F floor=W,T|none clamp=level|final", each number with the
 * fewest of 15, 16 or 17 significant digits that reads back as the same
 * double, so that equal text means equal settings.  Tiles of earlier
 * versions recorded exactly this text: it must not change.  The nearfar
 * view adds rows that are left out at their classic values, so that a
 * classic scene's text stays that: "near=N" and "aspect=A" after fov
 * (left out when 0), the infinite floor as "floor=inf,T", and
 * "floor-finish=KA,KD,KS,KR,SHININESS" after floor (left out with no floor
 * or with the classic coefficients).  A buffer of RT_SETTINGS_TEXT_MAX
 * bytes always holds it; a smaller one gets it cut short, as snprintf
 * does. */
void settings_format(const struct settings *s, char *buf, size_t size);

/* The options that make whitted render with these settings, each with a
 * leading space: " --eye X,Y,Z --look X,Y,Z --up X,Y,Z --fov F --size N
 * --recursion N", then " --floor W,T" or " --no-floor" and " --clamp
 * final" unless they are the built-in defaults.  The numbers are those of
 * settings_format, which whitted reads back as the very same doubles.
 * near, aspect and the floor's finish come from the scene file, so no
 * option carries them; nor the view's floor when floor_from_view (" --floor
 * W,T" is still written for a finite floor of classic coefficients other
 * than 1000,20, which gives the same floor).  Fails with RT_E_RANGE when
 * buf is too small, and with RT_E_INVALID for a floor that only a view can
 * give (infinite, or of other coefficients) when floor_from_view is false. */
int settings_format_options(const struct settings *s, char *buf, size_t size);

#endif
