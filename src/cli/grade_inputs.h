/* What whitted grade grades: the images among its operands, which may be
 * image files, folders of them (a class's Moodle download, folder by
 * folder) or zip files of either; each with the student it belongs to and
 * the scene it is a render of. */
#ifndef RT_CLI_GRADE_INPUTS_H
#define RT_CLI_GRADE_INPUTS_H

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

/* Adds an input (copies the strings; takes data); NULL path with data. */
int grade_inputs_add(struct grade_inputs *in, const char *label, const char *path,
		     unsigned char *data, size_t len, struct diag *d);

#endif
