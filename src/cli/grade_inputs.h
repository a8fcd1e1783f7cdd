/* What whitted grade grades: the images among its operands, which may be
 * image files, folders of them (a class's Moodle download, folder by
 * folder) or zip files of either; each with the student it belongs to and
 * the scene it is a render of. */
#ifndef RT_CLI_GRADE_INPUTS_H
#define RT_CLI_GRADE_INPUTS_H

#include <stdbool.h>
#include <stddef.h>

#include "whitted/diag.h"

struct grade_input {
	char *label;		/* what its row shows: the path, or ZIP:ENTRY */
	char *student;		/* the student: Moodle's name, a folder's, or the file's */
	char *id;		/* Moodle's id, or "" */
	char *path;		/* the file to read, or NULL: data holds it */
	unsigned char *data;	/* a zip entry's bytes */
	size_t len;
	int scene;		/* the index of the scene (--scene) it renders */
};

struct grade_inputs {
	struct grade_input *v;
	size_t n, cap;
};

/* The images of the operands, students in order of their names and each
 * one's images in order, each given a scene: the one whose base name its
 * file name contains (the longest), else the student's first scene not
 * yet given.  Fails on an operand that cannot be read (RT_E_IO) or a zip
 * file this build cannot open. */
int grade_inputs_collect(char *const *operands, int n, const char *const *scenes, int n_scenes,
			 struct grade_inputs *out, struct diag *d);
void grade_inputs_free(struct grade_inputs *in);

/* The entries of a zip file that are images (by their names), appended
 * as inputs of student "" with their bytes read (grade_zip.c). */
int grade_zip_read(const char *path, struct grade_inputs *out, struct diag *d);

/* Adds an input (copies the strings; takes data); NULL path with data
 * (grade_input_list.c, like the two below). */
int grade_inputs_add(struct grade_inputs *in, const char *label, const char *path,
		     unsigned char *data, size_t len, struct diag *d);
/* Whether s ends with tail, the case of s aside (tail in lower case). */
bool grade_ends_with(const char *s, const char *tail);
/* Whether a file's name is an image's: the formats whitted reads, and
 * JPEG and PNM, which grade reports as such. */
bool grade_is_image_name(const char *name);

#endif
