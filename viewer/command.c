/* The reproducing command of a capture.  Exactness rests on two facts:
 * settings_format_options prints each double so that strtod reads back
 * the same double, and whitted builds its camera from eye, look and up
 * with the same camera_init that the viewer's capture used on the same
 * numbers.  What the scene file decides (nearfar's near plane and aspect,
 * its floor) whitted reads from the same file again, so the command
 * carries no option for it; a dialect forced with --dialect it does. */
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#include "base/text.h"
#include "command.h"
#include "plugin/loader.h"
#include "whitted/diag.h"

int command_quote(char *buf, size_t size, const char *s)
{
	struct text_buf o;

	if (size == 0)
		return -RT_E_RANGE;
	text_init(&o, buf, size);
	text_shell_word(&o, s);
	return o.full ? -RT_E_RANGE : 0;
}

int command_format(char *buf, size_t size, const char *scene_path, enum scene_dialect dialect,
		   const struct settings *s)
{
	struct text_buf o;
	size_t i;
	int rc;

	if (size == 0)
		return -RT_E_RANGE;
	text_init(&o, buf, size);
	text_printf(&o, "whitted ");
	if (scene_path) {
		if ((rc = command_quote(buf + o.len, size - o.len, scene_path)) < 0)
			return rc;
		o.len += strlen(buf + o.len);
		/* The file is read again, so a dialect forced on it must be
		 * forced again: detection could read it otherwise. */
		if (dialect != RT_DIALECT_AUTO && scene_dialect_name(dialect))
			text_printf(&o, " --dialect %s", scene_dialect_name(dialect));
	} else {
		text_printf(&o, "--test-scene");
	}
	/* The plugins loaded, the option's or $WHITTED_PLUGIN_PATH's: the
	 * command must not depend on the environment it is pasted in. */
	for (i = 0; i < plugin_count() && !o.full; i++) {
		text_printf(&o, " --plugin ");
		if ((rc = command_quote(buf + o.len, size - o.len, plugin_at(i)->path)) < 0)
			return rc;
		o.len += strlen(buf + o.len);
	}
	if (o.full)
		return -RT_E_RANGE;
	return settings_format_options(s, buf + o.len, size - o.len);
}
