/* Colours and the Phong material that ends every object in a scene file. */
#ifndef RT_MATERIAL_H
#define RT_MATERIAL_H

struct color {
	double r, g, b;
};

struct material {
	struct color color;	/* each channel in [0, 1] */
	double ka, kd, ks, kr;	/* ambient, diffuse, specular, reflection; >= 0 */
	double shininess;	/* Phong exponent, >= 0 */
	/* Glass (--glass): the transmission coefficient in [0, 1) (0: opaque,
	 * as every object of a scene file) and the index of refraction (> 0)
	 * of the solid's inside, the outside being 1. */
	double kt, ior;
};

static inline struct color color_make(double r, double g, double b)
{
	struct color c = { r, g, b };
	return c;
}

static inline struct color color_add(struct color a, struct color b)
{
	return color_make(a.r + b.r, a.g + b.g, a.b + b.b);
}

static inline struct color color_mul(struct color a, struct color b)
{
	return color_make(a.r * b.r, a.g * b.g, a.b * b.b);
}

static inline struct color color_scale(struct color a, double s)
{
	return color_make(a.r * s, a.g * s, a.b * s);
}

/* NaN (from coordinates near overflow) becomes 0, not an unspecified
 * lround result. */
static inline double color_clamp01(double v)
{
	return v > 1.0 ? 1.0 : v > 0.0 ? v : 0.0;
}

static inline struct color color_clamp(struct color a)
{
	return color_make(color_clamp01(a.r), color_clamp01(a.g), color_clamp01(a.b));
}

#endif
