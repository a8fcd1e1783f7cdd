/* whitted explain's printing: an explanation (whitted/explain.h) as text
 * for a person, or as the JSON object that --json and the web page's
 * window.whitted.explain give. */
#ifndef RT_CLI_EXPLAIN_H
#define RT_CLI_EXPLAIN_H

#include <stdio.h>

#include "whitted/explain.h"
#include "whitted/scene.h"

void explain_print_text(FILE *out, const char *scene_name, const struct scene *s,
			const struct explanation *e);
void explain_print_json(FILE *out, const char *scene_name, const struct scene *s,
			const struct explanation *e);

#endif
