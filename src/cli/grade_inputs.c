/* The operands of whitted grade into images, students and scenes. */
#define _POSIX_C_SOURCE 200809L
#include <ctype.h>
#include <dirent.h>
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "base/alloc.h"
#include "base/platform.h"
#include "cli/grade_inputs.h"
#include "whitted/image.h"

/* How deep a folder of submissions is walked. */
#define GRADE_MAX_DEPTH 8

static int grade_name_cmp(const void *a, const void *b)
{
	return strcmp(*(char *const *)a, *(char *const *)b);
}

static int grade_operand(const char *path, int depth, struct grade_inputs *out, struct diag *d);

/* A folder's entries in name order (no hidden ones), each walked. */
static int grade_folder(const char *path, int depth, struct grade_inputs *out, struct diag *d)
{
	DIR *dir;
	struct dirent *e;
	char **names = NULL;
	size_t n = 0, cap = 0, k;
	int rc = 0;

	if (depth > GRADE_MAX_DEPTH)
		return 0;
	if (!(dir = opendir(path)))
		return diag_fail(d, RT_E_IO, "%s: cannot read the folder: %s", path, strerror(errno));
	while ((e = readdir(dir)) != NULL && rc == 0) {
		char *full;
		if (e->d_name[0] == '.')
			continue;
		if (n == cap) {
			char **v = rt_reallocarray(names, cap ? 2 * cap : 32, sizeof(*v));
			if (!v) {
				rc = diag_fail(d, RT_E_NOMEM, "out of memory for %s", path);
				break;
			}
			names = v;
			cap = cap ? 2 * cap : 32;
		}
		if (!(full = rt_malloc(strlen(path) + strlen(e->d_name) + 2))) {
			rc = diag_fail(d, RT_E_NOMEM, "out of memory for %s", path);
			break;
		}
		sprintf(full, "%s%s%s", path, grade_ends_with(path, "/") ? "" : "/", e->d_name);
		names[n++] = full;
	}
	closedir(dir);
	if (rc == 0)
		qsort(names, n, sizeof(*names), grade_name_cmp);
	for (k = 0; k < n; k++) {
		if (rc == 0)
			rc = grade_operand(names[k], depth + 1, out, d);
		rt_free(names[k]);
	}
	rt_free(names);
	return rc;
}

/* An operand, or a folder's entry (depth > 0: what is neither an image
 * nor a zip nor a folder is passed over, not an error). */
static int grade_operand(const char *path, int depth, struct grade_inputs *out, struct diag *d)
{
	struct stat st;

	if ((depth > 0 ? rt_lstat(path, &st) : stat(path, &st)) != 0) {
		if (depth > 0)
			return 0;
		/* Not there: a row that says so, as grade always did. */
		return grade_inputs_add(out, path, path, NULL, 0, d);
	}
	if (S_ISDIR(st.st_mode))
		return grade_folder(path, depth, out, d);
	if (grade_ends_with(path, ".zip") && S_ISREG(st.st_mode))
		return grade_zip_read(path, out, d);
	if (depth > 0 && (!S_ISREG(st.st_mode) || !grade_is_image_name(path)))
		return 0;
	return grade_inputs_add(out, path, path, NULL, 0, d);
}

/* The stem of the last component of s up to end: "a/b/out.bmp" -> "out". */
static void grade_stem(const char *s, const char *end, char *buf, size_t size)
{
	const char *start = s, *dot = NULL, *p;
	size_t n;

	for (p = s; p < end; p++)
		if (*p == '/' || *p == ':')
			start = p + 1;
	for (p = start; p < end; p++)
		if (*p == '.')
			dot = p;
	n = (size_t)((dot && dot > start ? dot : end) - start);
	n = n < size - 1 ? n : size - 1;
	memcpy(buf, start, n);
	buf[n] = '\0';
}

/* Moodle's folder of one student's submission: NAME_ID_assignsubmission_...
 * somewhere in the path: the name and the id. */
static bool grade_moodle(const char *label, char *name, char *id, size_t size)
{
	const char *m = strstr(label, "_assignsubmission_"), *start, *sep;
	size_t n;

	if (!m)
		return false;
	for (sep = m - 1; sep > label && isdigit((unsigned char)*sep); sep--)
		;
	if (sep <= label || *sep != '_' || sep == m - 1)
		return false;
	for (start = sep; start > label && start[-1] != '/' && start[-1] != ':'; start--)
		;
	n = (size_t)(sep - start) < size - 1 ? (size_t)(sep - start) : size - 1;
	memcpy(name, start, n);
	name[n] = '\0';
	n = (size_t)(m - sep - 1) < size - 1 ? (size_t)(m - sep - 1) : size - 1;
	memcpy(id, sep + 1, n);
	id[n] = '\0';
	return true;
}

/* The student of an input: Moodle's name and id; else the folder (or zip)
 * under the operand it was found in; else the file's own name. */
static int grade_student(struct grade_input *g, const char *operand, bool multi, struct diag *d)
{
	char name[256], id[64] = "";
	const char *rel = g->label, *slash;
	size_t on = strlen(operand);

	if (!grade_moodle(g->label, name, id, sizeof(name))) {
		if (strncmp(g->label, operand, on) == 0 && g->label[on] != '\0' && strcmp(g->label, operand) != 0)
			rel = g->label + on + (g->label[on] == '/' || g->label[on] == ':');
		slash = strpbrk(rel, "/:");
		if (slash && slash > rel)
			grade_stem(rel, slash, name, sizeof(name));
		else if (multi && rel == g->label && (slash = strrchr(rel, '/')) != NULL && slash > rel)
			/* A file named alone, of one of several scenes: its
			 * folder is the student's. */
			grade_stem(rel, slash, name, sizeof(name));
		else
			grade_stem(rel, rel + strlen(rel), name, sizeof(name));
	}
	g->student = rt_strdup(name);
	g->id = rt_strdup(id);
	if (!g->student || !g->id)
		return diag_fail(d, RT_E_NOMEM, "out of memory for the submissions");
	return 0;
}

static int grade_input_cmp(const void *a, const void *b)
{
	const struct grade_input *x = a, *y = b;
	int c = strcmp(x->student, y->student);

	return c ? c : strcmp(x->label, y->label);
}

/* Whether s contains t, case folded. */
static bool grade_contains(const char *s, const char *t)
{
	size_t n = strlen(t), i;

	for (; *s; s++) {
		for (i = 0; i < n && tolower((unsigned char)s[i]) == tolower((unsigned char)t[i]); i++)
			;
		if (i == n)
			return true;
	}
	return n == 0;
}

static void grade_assign_scenes(struct grade_inputs *in, const char *const *scenes, int n_scenes)
{
	char stems[16][128];
	size_t a = 0, b, k;
	int s;

	for (s = 0; s < n_scenes && s < 16; s++)
		grade_stem(scenes[s], scenes[s] + strlen(scenes[s]), stems[s], sizeof(stems[s]));
	while (a < in->n) {
		bool used[16] = { false };
		for (b = a; b < in->n && strcmp(in->v[b].student, in->v[a].student) == 0; b++)
			;
		/* By name: the longest scene name the image's name contains. */
		for (k = a; k < b; k++) {
			const char *file = in->v[k].label;
			size_t best = 0;
			if (n_scenes == 1) {
				in->v[k].scene = 0;
				continue;
			}
			for (s = 0; s < n_scenes && s < 16; s++) {
				const char *base = strrchr(file, '/');
				if (strlen(stems[s]) > best && grade_contains(base ? base + 1 : file, stems[s])) {
					best = strlen(stems[s]);
					in->v[k].scene = s;
				}
			}
			if (in->v[k].scene >= 0)
				used[in->v[k].scene] = true;
		}
		/* The rest in order, to the scenes not yet given. */
		for (k = a; k < b; k++) {
			if (in->v[k].scene >= 0)
				continue;
			for (s = 0; s < n_scenes && s < 16 && used[s]; s++)
				;
			in->v[k].scene = s < n_scenes ? s : 0;
			if (s < 16)
				used[s] = true;
		}
		a = b;
	}
}

int grade_inputs_collect(char *const *operands, int n, const char *const *scenes, int n_scenes,
			 struct grade_inputs *out, struct diag *d)
{
	int i, rc = 0;

	memset(out, 0, sizeof(*out));
	for (i = 0; i < n && rc == 0; i++) {
		size_t first = out->n, k;
		rc = grade_operand(operands[i], 0, out, d);
		for (k = first; k < out->n && rc == 0; k++)
			rc = grade_student(&out->v[k], operands[i], n_scenes > 1, d);
		/* The operands in their order; a folder's or a zip's images by
		 * student. */
		if (rc == 0)
			qsort(out->v + first, out->n - first, sizeof(*out->v), grade_input_cmp);
	}
	if (rc < 0) {
		grade_inputs_free(out);
		return rc;
	}
	grade_assign_scenes(out, scenes, n_scenes);
	return 0;
}
