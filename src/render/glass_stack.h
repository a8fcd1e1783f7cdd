/* The glass objects a ray is inside, innermost last: what decides whether
 * a hit on glass enters or leaves it and between which indices the ray
 * bends.  The normal's sign cannot say it: a quadric's normal is its
 * gradient, which points inwards when the coefficients are negated (the
 * same sphere), and a ray in nested glass passes from one glass into
 * another, not into air.  As in POV-Ray 3.7 (its ray's interior list): a
 * hit on an object not on the stack enters it (eta = n_top / n_obj, n_top
 * 1 for air), a hit on one on the stack leaves it (eta = n_top / n_rest,
 * n_rest the top once it is taken off; for properly nested solids n_top is
 * n_obj).  Reflected rays keep the stack, transmitted rays carry a copy
 * with the object pushed or removed.
 *
 * Fixed size, on the C stack of render_trace's recursion (no allocation,
 * no locks); only copied at a transmission.  A ray inside more than
 * RT_GLASS_NEST glass objects at once (never in practice) does not record
 * the deeper ones: leaving them is then taken for entering.  Primary rays
 * start with an empty stack: the eye (and a nearfar file's near plane)
 * are taken to be outside every glass object (docs/man/whitted.1). */
#ifndef RT_GLASS_STACK_H
#define RT_GLASS_STACK_H

#include <stdbool.h>

#include "whitted/shape.h"

#define RT_GLASS_NEST 16

struct glass_stack {
	int n;
	const struct shape *obj[RT_GLASS_NEST];
};

/* The index of refraction of the medium the ray is in: the innermost
 * glass's, or 1 (air). */
static inline double glass_stack_ior(const struct glass_stack *g)
{
	return g->n > 0 ? g->obj[g->n - 1]->mat.ior : 1.0;
}

/* Where obj is on the stack, or -1. */
static inline int glass_stack_find(const struct glass_stack *g, const struct shape *obj)
{
	int i;

	for (i = g->n - 1; i >= 0; i--)
		if (g->obj[i] == obj)
			return i;
	return -1;
}

/* The stack of the ray passing through obj's surface, from the stack *g
 * of the ray that hit it, and that passage's eta = n1 / n2 in *eta.  The
 * divisions are those of the single glass object in air (1 / n entering,
 * n / 1 leaving), so such a scene's bits do not depend on the stack. */
static inline void glass_stack_pass(const struct glass_stack *g, const struct shape *obj,
				    struct glass_stack *out, double *eta)
{
	int at = glass_stack_find(g, obj), i, k = 0;
	double n1 = glass_stack_ior(g);

	if (at < 0) {
		/* Only the entries in use: the stack is copied at every
		 * passage through glass. */
		for (i = 0; i < g->n; i++)
			out->obj[i] = g->obj[i];
		out->n = g->n;
		if (out->n < RT_GLASS_NEST)
			out->obj[out->n++] = obj;
		*eta = n1 / obj->mat.ior;
		return;
	}
	for (i = 0; i < g->n; i++)
		if (i != at)
			out->obj[k++] = g->obj[i];
	out->n = k;
	*eta = n1 / glass_stack_ior(out);
}

#endif
