/* The tile record: what a tile says about itself (struct tile_info), the
 * checks of a region against its image, and the text of the whitted-tile
 * chunk that carries the record in the PNG (written and read in
 * tile_png.c).  The reading is strict: the text must be exactly what
 * tile_text_format writes, so that two tiles with equal records have equal
 * text. */
#include <inttypes.h>
#include <stdbool.h>
#include <stdio.h>
#include <string.h>

#include "base/hash.h"
#include "dist/tile_text.h"

void tile_info_init(struct tile_info *info, const struct settings *s, uint64_t scene_hash,
		    int x0, int y0, int x1, int y1)
{
	memset(info, 0, sizeof(*info));
	info->full_width = info->full_height = s->size;
	info->x0 = x0;
	info->y0 = y0;
	info->x1 = x1;
	info->y1 = y1;
	info->scene_hash = scene_hash;
	settings_format(s, info->options, sizeof(info->options));
	info->options_hash = hash_bytes(RT_HASH_INIT, info->options, strlen(info->options));
}

int tile_check_region(int x0, int y0, int x1, int y1, int full_width, int full_height,
		      struct diag *d)
{
	if (x0 >= x1 || y0 >= y1)
		return diag_fail(d, RT_E_INVALID,
				"region %d,%d,%d,%d is empty or inverted (X0,Y0,X1,Y1 are end-exclusive: X0 < X1, Y0 < Y1)",
				x0, y0, x1, y1);
	if (x0 < 0 || y0 < 0 || x1 > full_width || y1 > full_height)
		return diag_fail(d, RT_E_INVALID,
				"region %d,%d,%d,%d is outside the %dx%d image (pixels 0..%d, 0..%d)",
				x0, y0, x1, y1, full_width, full_height, full_width - 1, full_height - 1);
	return 0;
}

/* The text of the whitted-tile chunk, one "key value" per line. */
void tile_text_format(const struct tile_info *t, char *buf, size_t size)
{
	snprintf(buf, size,
		 "version %d\n"
		 "full-size %d %d\n"
		 "region %d %d %d %d\n"
		 "scene-hash %016" PRIx64 "\n"
		 "options-hash %016" PRIx64 "\n"
		 "options %s",
		 RT_TILE_VERSION, t->full_width, t->full_height, t->x0, t->y0, t->x1, t->y1,
		 t->scene_hash, t->options_hash, t->options);
}

struct tile_cursor {
	const char *p;
	bool ok;
};

static void tile_expect(struct tile_cursor *c, const char *lit)
{
	size_t n = strlen(lit);

	if (c->ok && strncmp(c->p, lit, n) == 0)
		c->p += n;
	else
		c->ok = false;
}

/* The literal lit (what comes before the number in the text), then 1 to
 * 9 decimal digits. */
static int tile_int(struct tile_cursor *c, const char *lit)
{
	int v = 0, n = 0;

	tile_expect(c, lit);
	while (c->ok && *c->p >= '0' && *c->p <= '9' && n < 9) {
		v = v * 10 + (*c->p++ - '0');
		n++;
	}
	if (n == 0)
		c->ok = false;
	return v;
}

/* The literal lit, then exactly 16 lower-case hex digits. */
static uint64_t tile_hex64(struct tile_cursor *c, const char *lit)
{
	uint64_t v = 0;
	int i;

	tile_expect(c, lit);
	for (i = 0; i < 16 && c->ok; i++, c->p++) {
		if (*c->p >= '0' && *c->p <= '9')
			v = v << 4 | (uint64_t)(*c->p - '0');
		else if (*c->p >= 'a' && *c->p <= 'f')
			v = v << 4 | (uint64_t)(*c->p - 'a' + 10);
		else
			c->ok = false;
	}
	return v;
}

int tile_text_parse(const char *path, const char *text, size_t len, struct tile_info *t,
		    struct diag *d)
{
	char buf[RT_TILE_TEXT_MAX], again[RT_TILE_TEXT_MAX];
	struct tile_cursor c;
	int version;
	size_t n;

	memset(t, 0, sizeof(*t));
	if (len >= sizeof(buf) || memchr(text, '\0', len))
		goto out_bad;
	memcpy(buf, text, len);
	buf[len] = '\0';
	c.p = buf;
	c.ok = true;
	version = tile_int(&c, "version ");
	if (c.ok && version != RT_TILE_VERSION)
		return diag_set(d, RT_E_SYNTAX, path, 0, 0,
				"whitted-tile version %d, this whitted reads version %d", version,
				RT_TILE_VERSION);
	t->full_width = tile_int(&c, "\nfull-size ");
	t->full_height = tile_int(&c, " ");
	t->x0 = tile_int(&c, "\nregion ");
	t->y0 = tile_int(&c, " ");
	t->x1 = tile_int(&c, " ");
	t->y1 = tile_int(&c, " ");
	t->scene_hash = tile_hex64(&c, "\nscene-hash ");
	t->options_hash = tile_hex64(&c, "\noptions-hash ");
	tile_expect(&c, "\noptions ");
	if (!c.ok)
		goto out_bad;
	n = strlen(c.p);
	if (n >= sizeof(t->options) || strchr(c.p, '\n'))
		goto out_bad;
	memcpy(t->options, c.p, n + 1);
	tile_text_format(t, again, sizeof(again));
	if (strcmp(again, buf) != 0)
		goto out_bad;
	if (t->full_width < 1 || t->full_height < 1 ||
	    tile_check_region(t->x0, t->y0, t->x1, t->y1, t->full_width, t->full_height, d) < 0)
		return diag_set(d, RT_E_SYNTAX, path, 0, 0,
				"whitted-tile chunk: region %d,%d,%d,%d does not fit the %dx%d image",
				t->x0, t->y0, t->x1, t->y1, t->full_width, t->full_height);
	if (hash_bytes(RT_HASH_INIT, t->options, n) != t->options_hash)
		return diag_set(d, RT_E_SYNTAX, path, 0, 0,
				"whitted-tile chunk: the options hash does not match the options text");
	return 0;
out_bad:
	return diag_set(d, RT_E_SYNTAX, path, 0, 0, "malformed whitted-tile chunk");
}
