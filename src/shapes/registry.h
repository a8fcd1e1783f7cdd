/* Adding tables to the registry and taking them out again: the one path
 * by which the built-in tables (at the first look-up) and the plugins'
 * (src/plugin/) come in.  The look-ups are in whitted/shape.h. */
#ifndef RT_SHAPES_REGISTRY_H
#define RT_SHAPES_REGISTRY_H

#include <stdbool.h>
#include <stddef.h>

#include "whitted/diag.h"
#include "whitted/shape.h"

/* Room for this many tables, built-in ones included. */
#define RT_REGISTRY_MAX 128
/* The longest keyword a table may have. */
#define RT_SHAPE_KEYWORD_MAX 64
/* The longest keyword list (shape_keywords): every table's keyword, each
 * with its ", ", and the terminating NUL; never cut short. */
#define RT_KEYWORD_LIST_MAX (RT_REGISTRY_MAX * (RT_SHAPE_KEYWORD_MAX + 2) + 1)

/* Adds the NULL-terminated tables, all or none, as coming from origin (a
 * plugin's path, copied; NULL for the built-ins).  Fails with RT_E_INVALID
 * and a message naming the keyword when a table lacks a required member or
 * has a keyword that is no word, or when its keyword is already registered
 * from another origin or with dialects that meet its own (the built-in
 * pyramid's two tables share a keyword with disjoint dialects); with
 * RT_E_RANGE when the registry is full.  Thread-safe; lists returned
 * earlier by shape_keywords_in stay valid but may be out of date. */
int shape_registry_add(const struct shape_ops *const *tables, const char *origin,
		       struct diag *d);
/* Takes out every table of that origin (a plugin being unloaded). */
void shape_registry_remove(const char *origin);
/* Whether a table of that keyword is registered from that origin (a
 * plugin's path). */
bool shape_registry_has(const char *keyword, const char *origin);
/* Where the table came from: NULL for a built-in, else the plugin's path as
 * given to shape_registry_add; NULL for a table not registered. */
const char *shape_registry_origin(const struct shape_ops *ops);

#endif
