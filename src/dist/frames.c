/* Camera paths for animations and the names of their frames. */
#define _POSIX_C_SOURCE 200809L
#include <ctype.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "base/alloc.h"
#include "base/file.h"
#include "base/number.h"
#include "whitted/frames.h"

#define FRAMES_MAX_PATH_BYTES (16L << 20)

void frames_orbit(const struct camera_params *base, int k, int n, struct camera_params *out)
{
	const double pi = 3.14159265358979323846;
	double angle = 2.0 * pi * (double)(k - 1) / (double)n;
	double c = cos(angle), s = sin(angle);
	struct vec3 u, v;

	*out = *base;
	if (k == 1)
		return;
	/* Rodrigues' rotation of v = eye - look about the unit axis u:
	 * v' = v cos a + (u x v) sin a + u (u . v)(1 - cos a). */
	u = vec3_scale(base->up, 1.0 / vec3_length(base->up));
	v = vec3_sub(base->eye, base->look);
	v = vec3_add(vec3_add(vec3_scale(v, c), vec3_scale(vec3_cross(u, v), s)),
		     vec3_scale(u, vec3_dot(u, v) * (1.0 - c)));
	out->eye = vec3_add(base->look, v);
}

static struct vec3 frames_lerp3(struct vec3 a, struct vec3 b, double f)
{
	return vec3_add(a, vec3_scale(vec3_sub(b, a), f));
}

void frames_on_path(const struct frame_path *p, int k, int n, struct camera_params *out)
{
	long long m = (long long)p->n_keys - 1, num;
	size_t i;
	double f;

	if (n <= 1 || m == 0) {
		*out = p->keys[0];
		return;
	}
	/* Frame k sits at key position (k - 1) * m / (n - 1) = i + f. */
	num = (long long)(k - 1) * m;
	i = (size_t)(num / (n - 1));
	f = (double)(num % (n - 1)) / (double)(n - 1);
	if (f == 0.0) {
		*out = p->keys[i];
		return;
	}
	out->eye = frames_lerp3(p->keys[i].eye, p->keys[i + 1].eye, f);
	out->look = frames_lerp3(p->keys[i].look, p->keys[i + 1].look, f);
	out->up = frames_lerp3(p->keys[i].up, p->keys[i + 1].up, f);
	out->fov_deg = p->keys[i].fov_deg + (p->keys[i + 1].fov_deg - p->keys[i].fov_deg) * f;
}

void frames_path_free(struct frame_path *p)
{
	rt_free(p->keys);
	p->keys = NULL;
	p->n_keys = 0;
}

/* The next whitespace-separated word of the line at *s (cut in place), or
 * NULL at its end. */
static char *frames_word(char **s)
{
	char *w = *s;

	while (*w && isspace((unsigned char)*w))
		w++;
	if (*w == '\0')
		return NULL;
	*s = w;
	while (**s && !isspace((unsigned char)**s))
		(*s)++;
	if (**s)
		*(*s)++ = '\0';
	return w;
}

/* One keyframe line, over a copy of the previous keyframe. */
static int frames_parse_line(const char *path, int line, char *s, struct camera_params *key,
			     struct diag *d)
{
	char *word, *value;
	double v[3];
	int seen = 0, bit, rc;

	while ((word = frames_word(&s)) != NULL) {
		bit = strcmp(word, "eye") == 0 ? 1 : strcmp(word, "look") == 0 ? 2 :
		      strcmp(word, "up") == 0 ? 4 : strcmp(word, "fov") == 0 ? 8 : 0;
		if (bit == 0)
			return diag_set(d, RT_E_SYNTAX, path, line, 0,
					"expected eye, look, up or fov, found '%s'", word);
		if (seen & bit)
			return diag_set(d, RT_E_SYNTAX, path, line, 0, "'%s' given twice", word);
		seen |= bit;
		value = frames_word(&s);
		if (!value)
			return diag_set(d, RT_E_SYNTAX, path, line, 0, "'%s' needs a value", word);
		if (bit == 8) {
			rc = number_parse_double("fov", value, &v[0], d);
			if (rc == 0 && !(v[0] > 0.0 && v[0] < 180.0))
				rc = diag_fail(d, RT_E_RANGE,
					      "fov: expected degrees between 0 and 180 (exclusive), found '%s'",
					      value);
			key->fov_deg = v[0];
		} else {
			rc = number_parse_list(word, value, v, 3, d);
			if (rc == 0) {
				struct vec3 x = vec3_make(v[0], v[1], v[2]);
				if (bit == 1)
					key->eye = x;
				else if (bit == 2)
					key->look = x;
				else
					key->up = x;
			}
		}
		if (rc < 0) {
			/* Keep the message, give it the file and line. */
			snprintf(d->file, sizeof(d->file), "%s", path);
			d->line = line;
			return -RT_E_SYNTAX;
		}
	}
	return 0;
}

static int frames_read(const char *path, char **out, struct diag *d)
{
	size_t len;
	int rc = file_read_all(path, "keyframe file", FRAMES_MAX_PATH_BYTES, out, &len, d);

	if (rc == 0 && memchr(*out, '\0', len)) {
		rt_free(*out);
		*out = NULL;
		rc = diag_set(d, RT_E_SYNTAX, path, 0, 0, "a NUL byte in a text file");
	}
	return rc;
}

int frames_path_load(const char *path, const struct camera_params *base,
		     struct frame_path *out, struct diag *d)
{
	struct camera_params key = *base, *grown;
	size_t cap = 0;
	char *text = NULL, *line, *next, *hash;
	int lineno = 0, rc = 0;

	out->keys = NULL;
	out->n_keys = 0;
	if ((rc = frames_read(path, &text, d)) < 0)
		return rc;
	for (line = text; line; line = next) {
		next = strchr(line, '\n');
		if (next)
			*next++ = '\0';
		lineno++;
		hash = strchr(line, '#');
		if (hash)
			*hash = '\0';
		line += strspn(line, " \t\r\f\v");
		if (*line == '\0')
			continue;
		if ((rc = frames_parse_line(path, lineno, line, &key, d)) < 0)
			goto out_free;
		if (out->n_keys == (size_t)RT_MAX_KEYFRAMES) {
			rc = diag_set(d, RT_E_RANGE, path, lineno, 0, "more than %d keyframes",
				      RT_MAX_KEYFRAMES);
			goto out_free;
		}
		if (out->n_keys == cap) {
			cap = cap ? cap * 2 : 16;
			grown = rt_reallocarray(out->keys, cap, sizeof(*grown));
			if (!grown) {
				rc = diag_set(d, RT_E_NOMEM, path, 0, 0, "out of memory");
				goto out_free;
			}
			out->keys = grown;
		}
		out->keys[out->n_keys++] = key;
	}
	if (out->n_keys == 0)
		rc = diag_set(d, RT_E_SYNTAX, path, 0, 0,
			      "no keyframes (lines such as 'eye 0,-200,10 look 0,0,0 up 0,0,1 fov 80')");
out_free:
	rt_free(text);
	if (rc < 0)
		frames_path_free(out);
	return rc;
}

/* Length of the conversion at p ("%d" or "%0Wd"), or 0. */
static size_t frames_conversion(const char *p)
{
	size_t i = 1;

	if (p[i] == '0') {
		i++;
		if (p[i] < '1' || p[i] > '9')
			return 0;
		i++;
	}
	return p[i] == 'd' ? i + 1 : 0;
}

int frames_pattern_check(const char *pattern, bool *numbered, struct diag *d)
{
	const char *p;
	size_t len;

	*numbered = false;
	for (p = pattern; *p; p++) {
		if (*p != '%')
			continue;
		if (p[1] == '%') {
			p++;
			continue;
		}
		len = frames_conversion(p);
		if (len == 0)
			return diag_fail(d, RT_E_INVALID,
					"'%s': a frame pattern takes %%d or %%0Wd (W 1..9) and %%%% only",
					pattern);
		if (*numbered)
			return diag_fail(d, RT_E_INVALID,
					"'%s': more than one frame number in the pattern", pattern);
		*numbered = true;
		p += len - 1;
	}
	return 0;
}

int frames_name(const char *pattern, int k, char *buf, size_t size, struct diag *d)
{
	size_t used = 0, len;
	const char *p;
	char num[32];
	int n;

	for (p = pattern; *p; p++) {
		if (*p == '%' && p[1] == '%') {
			p++;
			n = snprintf(num, sizeof(num), "%%");
		} else if (*p == '%' && (len = frames_conversion(p)) != 0) {
			n = snprintf(num, sizeof(num), "%0*d", len == 2 ? 1 : p[2] - '0', k);
			p += len - 1;
		} else {
			n = snprintf(num, sizeof(num), "%c", *p);
		}
		if ((size_t)n >= size - used)
			return diag_fail(d, RT_E_RANGE, "'%s': the file name is too long", pattern);
		memcpy(buf + used, num, (size_t)n);
		used += (size_t)n;
	}
	if (used >= size)
		return diag_fail(d, RT_E_RANGE, "'%s': the file name is too long", pattern);
	buf[used] = '\0';
	return 0;
}
