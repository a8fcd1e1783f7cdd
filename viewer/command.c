/* The reproducing command of a capture.  Exactness rests on two facts:
 * %.17g prints a double so that strtod reads back the same double, and
 * whitted builds its camera from eye, look and up with the same
 * camera_init that the viewer's capture used on the same numbers. */
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#include "command.h"
#include "diag.h"

struct out {
	char *buf;
	size_t size, len;
	bool full;
};

static void out_printf(struct out *o, const char *fmt, ...)
{
	va_list ap;
	int n;

	if (o->full)
		return;
	va_start(ap, fmt);
	n = vsnprintf(o->buf + o->len, o->size - o->len, fmt, ap);
	va_end(ap);
	if (n < 0 || (size_t)n >= o->size - o->len)
		o->full = true;
	else
		o->len += (size_t)n;
}

static void out_vec3(struct out *o, const char *opt, struct vec3 v)
{
	out_printf(o, " %s %.17g,%.17g,%.17g", opt, v.x, v.y, v.z);
}

int command_quote(char *buf, size_t size, const char *s)
{
	static const char safe[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz"
				   "0123456789_./+,=:@%-";
	struct out o = { buf, size, 0, false };
	const char *p;

	if (size == 0)
		return -RT_E_RANGE;
	buf[0] = '\0';
	/* A word starting with '-' would be read as an option. */
	if (s[0] == '-')
		out_printf(&o, "./");
	if (s[0] != '\0' && s[strspn(s, safe)] == '\0') {
		out_printf(&o, "%s", s);
		return o.full ? -RT_E_RANGE : 0;
	}
	out_printf(&o, "'");
	for (p = s; *p; p++) {
		if (*p == '\'')
			out_printf(&o, "'\\''");
		else
			out_printf(&o, "%c", *p);
	}
	out_printf(&o, "'");
	return o.full ? -RT_E_RANGE : 0;
}

int command_format(char *buf, size_t size, const char *scene_path,
		   const struct cli_scene *given, const struct camera_params *cam,
		   int image_size)
{
	struct out o = { buf, size, 0, false };
	int rc;

	if (size == 0)
		return -RT_E_RANGE;
	out_printf(&o, "whitted ");
	if (scene_path) {
		if ((rc = command_quote(buf + o.len, size - o.len, scene_path)) < 0)
			return rc;
		o.len += strlen(buf + o.len);
	} else {
		out_printf(&o, "--test-scene");
	}
	out_vec3(&o, "--eye", cam->eye);
	out_vec3(&o, "--look", cam->look);
	out_vec3(&o, "--up", cam->up);
	out_printf(&o, " --fov %.17g --size %d", cam->fov_deg, image_size);
	if (given->recursion)
		out_printf(&o, " --recursion %d", given->recursion);
	if (given->no_floor)
		out_printf(&o, " --no-floor");
	else if (given->floor_width != RT_FLOOR_WIDTH || given->floor_tile != RT_FLOOR_TILE)
		out_printf(&o, " --floor %.17g,%.17g", given->floor_width, given->floor_tile);
	if (given->clamp == RT_CLAMP_FINAL)
		out_printf(&o, " --clamp final");
	return o.full ? -RT_E_RANGE : 0;
}
