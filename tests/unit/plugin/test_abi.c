/* The plugin ABI pinned: the size and the place of every member of every
 * type a plugin sees (whitted/plugin.h lists them), and the values of the
 * enumerations and macros it compiles in, for the current
 * WHITTED_PLUGIN_ABI.  Any change of them breaks plugins built before it,
 * which the host would still load if the version stayed: so a mismatch
 * here means "bump WHITTED_PLUGIN_ABI", then pin the new layout in the
 * new version's table (only the current version's is checked, so the old
 * one goes).  The numbers are worked out by hand from the declarations for
 * LP64 (8-byte pointers, size_t and double, 4-byte int and unsigned, each
 * member aligned to its size), not read from the compiler.  And the
 * loader refuses plugins of the versions beside this one. */
#include <stddef.h>
#include <stdio.h>
#include <string.h>

#include "plugin/loader.h"
#include "support.h"
#include "whitted/mesh.h"
#include "whitted/plugin.h"
#include "whitted/pov.h"
#include "whitted/scene.h"

struct abi_pin {
	const char *what;
	size_t actual, pinned;
};

#define PIN_SIZE(type, n) { "sizeof(" #type ")", sizeof(type), n }
#define PIN_AT(type, member, n) { "offsetof(" #type ", " #member ")", offsetof(type, member), n }
#define PIN_VALUE(expr, n) { #expr, (size_t)(expr), n }

/* ABI 5 on LP64 (ABI 4 was this without struct shape_ops' normal_packet
 * and color_packet at its end; ABI 3 also had intersect_packet taking an
 * array of struct ray, and no struct ray_packet and RT_PACKET_RUN; ABI 2
 * no intersect_packet). */
static const struct abi_pin abi_5[] = {
	PIN_SIZE(struct vec3, 24),
	PIN_AT(struct vec3, x, 0), PIN_AT(struct vec3, y, 8), PIN_AT(struct vec3, z, 16),
	PIN_SIZE(struct color, 24),
	PIN_AT(struct color, r, 0), PIN_AT(struct color, g, 8), PIN_AT(struct color, b, 16),
	PIN_SIZE(struct ray, 48),
	PIN_AT(struct ray, origin, 0), PIN_AT(struct ray, dir, 24),
	PIN_SIZE(struct aabb, 48),
	PIN_AT(struct aabb, min, 0), PIN_AT(struct aabb, max, 24),
	PIN_SIZE(struct material, 80),
	PIN_AT(struct material, color, 0), PIN_AT(struct material, ka, 24),
	PIN_AT(struct material, kd, 32), PIN_AT(struct material, ks, 40),
	PIN_AT(struct material, kr, 48), PIN_AT(struct material, shininess, 56),
	PIN_AT(struct material, kt, 64), PIN_AT(struct material, ior, 72),
	PIN_SIZE(struct shape, 88),
	PIN_AT(struct shape, ops, 0), PIN_AT(struct shape, mat, 8),
	PIN_SIZE(struct shape_ops, 128),
	PIN_AT(struct shape_ops, keyword, 0), PIN_AT(struct shape_ops, dialects, 8),
	PIN_AT(struct shape_ops, parse, 16), PIN_AT(struct shape_ops, intersect, 24),
	PIN_AT(struct shape_ops, normal, 32), PIN_AT(struct shape_ops, export_pov, 40),
	PIN_AT(struct shape_ops, destroy, 48), PIN_AT(struct shape_ops, color_at, 56),
	PIN_AT(struct shape_ops, bounds, 64), PIN_AT(struct shape_ops, degenerate, 72),
	PIN_AT(struct shape_ops, tessellate, 80),
	PIN_AT(struct shape_ops, specular_color_at, 88), PIN_AT(struct shape_ops, closed, 96),
	PIN_AT(struct shape_ops, intersect_packet, 104),
	PIN_AT(struct shape_ops, normal_packet, 112), PIN_AT(struct shape_ops, color_packet, 120),
	PIN_VALUE(RT_PACKET_MAX, 32),
	PIN_VALUE(RT_PACKET_RUN, 8),
	PIN_SIZE(struct ray_packet, 6 * 32 * 8),
	PIN_AT(struct ray_packet, ox, 0), PIN_AT(struct ray_packet, oy, 256),
	PIN_AT(struct ray_packet, oz, 512), PIN_AT(struct ray_packet, dx, 768),
	PIN_AT(struct ray_packet, dy, 1024), PIN_AT(struct ray_packet, dz, 1280),
	PIN_SIZE(struct pov_options, 24),
	PIN_AT(struct pov_options, finish, 0), PIN_AT(struct pov_options, shadow_twin, 4),
	PIN_AT(struct pov_options, floor_texture, 8),
	PIN_SIZE(struct mesh_texture, 8 + 1024 * 24),
	PIN_AT(struct mesh_texture, width, 0), PIN_AT(struct mesh_texture, height, 4),
	PIN_AT(struct mesh_texture, texels, 8),
	PIN_SIZE(struct mesh, 24 + 8 + 1024 * 24),
	PIN_AT(struct mesh, data, 0), PIN_AT(struct mesh, n_vertices, 8),
	PIN_AT(struct mesh, cap_vertices, 16), PIN_AT(struct mesh, texture, 24),
	PIN_SIZE(struct mesh_uv, 16),
	PIN_AT(struct mesh_uv, u, 0), PIN_AT(struct mesh_uv, v, 8),
	PIN_SIZE(struct mesh_options, 56),
	PIN_AT(struct mesh_options, around, 0), PIN_AT(struct mesh_options, segments, 48),
	PIN_VALUE(RT_MESH_TEXELS_MAX, 1024),
	PIN_VALUE(RT_MESH_FLOATS_PER_VERTEX, 8),
	PIN_SIZE(struct whitted_plugin, 24),
	PIN_AT(struct whitted_plugin, name, 0), PIN_AT(struct whitted_plugin, version, 8),
	PIN_AT(struct whitted_plugin, shapes, 16),
	PIN_SIZE(struct whitted_plugin_host, 144),
	PIN_AT(struct whitted_plugin_host, abi, 0), PIN_AT(struct whitted_plugin_host, size, 8),
	PIN_AT(struct whitted_plugin_host, register_plugin, 16),
	PIN_AT(struct whitted_plugin_host, number, 24),
	PIN_AT(struct whitted_plugin_host, integer, 32),
	PIN_AT(struct whitted_plugin_host, vec3, 40),
	PIN_AT(struct whitted_plugin_host, color, 48),
	PIN_AT(struct whitted_plugin_host, material, 56),
	PIN_AT(struct whitted_plugin_host, fail, 64),
	PIN_AT(struct whitted_plugin_host, alloc, 72),
	PIN_AT(struct whitted_plugin_host, free, 80),
	PIN_AT(struct whitted_plugin_host, pov_number, 88),
	PIN_AT(struct whitted_plugin_host, pov_vector, 96),
	PIN_AT(struct whitted_plugin_host, pov_texture, 104),
	PIN_AT(struct whitted_plugin_host, mesh_triangle, 112),
	PIN_AT(struct whitted_plugin_host, mesh_box, 120),
	PIN_AT(struct whitted_plugin_host, solve_quadratic, 128),
	PIN_AT(struct whitted_plugin_host, ray_triangle, 136),
	PIN_VALUE(RT_OK, 0), PIN_VALUE(RT_E_SYNTAX, 1), PIN_VALUE(RT_E_RANGE, 2),
	PIN_VALUE(RT_E_NOMEM, 3), PIN_VALUE(RT_E_IO, 4), PIN_VALUE(RT_E_INVALID, 5),
	PIN_VALUE(RT_E_INTERRUPTED, 6),
	PIN_VALUE(RT_DIALECT_AUTO, 0), PIN_VALUE(RT_DIALECT_CLASSIC, 1),
	PIN_VALUE(RT_DIALECT_SPOT, 2), PIN_VALUE(RT_DIALECT_PYRAMID, 3),
	PIN_VALUE(RT_DIALECT_NEARFAR, 4),
	PIN_VALUE(RT_DIALECT_BIT(RT_DIALECT_CLASSIC), 2),
	PIN_VALUE(RT_DIALECT_BIT(RT_DIALECT_NEARFAR), 16),
};

static const struct {
	unsigned abi;
	const struct abi_pin *pins;
	size_t n;
} tables[] = {
	{ 5, abi_5, sizeof(abi_5) / sizeof(abi_5[0]) },
};

static void test_abi_layout_is_pinned(void **state)
{
	size_t i, k, bad = 0;

	(void)state;
	if (sizeof(void *) != 8 || sizeof(size_t) != 8 || sizeof(int) != 4 || sizeof(double) != 8)
		fail_msg("the pinned layouts are for LP64: add the tables of this data model");
	for (k = 0; k < sizeof(tables) / sizeof(tables[0]); k++)
		if (tables[k].abi == WHITTED_PLUGIN_ABI)
			break;
	if (k == sizeof(tables) / sizeof(tables[0]))
		fail_msg("no pinned layout for plugin ABI %d: after bumping WHITTED_PLUGIN_ABI, add the new version's table here",
			 WHITTED_PLUGIN_ABI);
	for (i = 0; i < tables[k].n; i++) {
		const struct abi_pin *p = &tables[k].pins[i];

		if (p->actual != p->pinned) {
			print_error("%s is %zu, pinned at %zu for plugin ABI %u\n", p->what, p->actual,
				    p->pinned, tables[k].abi);
			bad++;
		}
	}
	if (bad)
		fail_msg("%zu of the types plugins see changed: bump WHITTED_PLUGIN_ABI (whitted/plugin.h) and pin the new layout here",
			 bad);
}

/* The host the loader gives plugins is of this version and this size. */
static void test_abi_host_is_this_version(void **state)
{
	(void)state;
	assert_int_equal(plugin_host()->abi, WHITTED_PLUGIN_ABI);
	assert_int_equal(plugin_host()->size, sizeof(struct whitted_plugin_host));
	assert_non_null(plugin_host()->solve_quadratic);
	assert_non_null(plugin_host()->ray_triangle);
}

/* A plugin built for the version before this one (whose layout is the
 * nearest) or after it is refused before its init runs, with the message
 * naming both versions: there is no compatibility range (plugin.h).  The
 * Makefile builds them from tests/plugins/bad_abi.c. */
static void test_abi_neighbour_versions_refused(void **state)
{
	static const struct {
		const char *path;
		unsigned abi;
	} cases[] = {
		{ RT_TEST_PLUGIN_DIR "/../test-plugins/abi_prev.so", WHITTED_PLUGIN_ABI - 1 },
		{ RT_TEST_PLUGIN_DIR "/../test-plugins/abi_next.so", WHITTED_PLUGIN_ABI + 1 },
	};
	size_t k;

	(void)state;
	for (k = 0; k < sizeof(cases) / sizeof(cases[0]); k++) {
		char want[1024];
		struct diag d;

		snprintf(want, sizeof(want),
			 "plugin %s: built for plugin ABI version %u, but this whitted supports version %u only",
			 cases[k].path, cases[k].abi, WHITTED_PLUGIN_ABI);
		assert_int_equal(plugin_load(cases[k].path, &d), -RT_E_RANGE);
		if (!strstr(d.msg, want))
			fail_msg("'%s' lacks '%s'", d.msg, want);
		assert_int_equal(plugin_count(), 0);
	}
}

SUPPORT_MAIN(SUPPORT_TESTS(test_abi_layout_is_pinned, test_abi_host_is_this_version,
			   test_abi_neighbour_versions_refused))
