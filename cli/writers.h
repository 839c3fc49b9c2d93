#ifndef VSPH_CLI_WRITERS_H
#define VSPH_CLI_WRITERS_H

#include <cjson/cJSON.h>
#include <stddef.h>
#include <stdio.h>

struct vsph_moments;

/** @file writers.h
 *  @brief The only code that writes results: JSON through cJSON, CSV and
 *  Markdown text, each file written to a temporary name and renamed into
 *  place so nothing is ever left half-written. */

/** @brief Array of n doubles (NaN becomes null). */
cJSON *vsph_writers_array(const double *v, size_t n);

/** @brief The tensors as nested arrays: F d x d x d, G d^4, N d, M d x d,
 *  added to @p obj under the keys "F", "G", "N", "M". */
void vsph_writers_moments(cJSON *obj, const struct vsph_moments *m);

/** @brief Add a number, or null when it is not finite. */
void vsph_writers_number(cJSON *obj, const char *key, double v);

/** @brief Print a JSON object to stdout with a newline; frees it. */
int vsph_writers_print_json(cJSON *obj);

/** @brief Open DIR/NAME.tmp for writing; NULL after reporting on failure. */
FILE *vsph_writers_open(const char *dir, const char *name);

/** @brief Close a file from vsph_writers_open and rename it into place.
 *  @return 0 on success, VSPH_EIO otherwise (the temporary is removed). */
int vsph_writers_close(FILE *f, const char *dir, const char *name);

/** @brief Write a JSON object to DIR/NAME atomically; frees it. */
int vsph_writers_json_file(cJSON *obj, const char *dir, const char *name);

struct vsph_particles;

/** @brief Legacy VTK (POLYDATA) snapshot of the particles with id <
 *  n_fluid, in id order: points, velocity, density, pressure, id. ParaView
 *  and VisIt open it directly. Atomic. */
int vsph_writers_vtk(const char *dir, const char *name,
                     const struct vsph_particles *p, size_t n_fluid, double t);

/** @brief A whole file as a NUL-terminated string (caller frees), its
 *  length in @p len if not NULL; NULL if it cannot be read. */
char *vsph_writers_slurp(const char *path, size_t *len);

/** @brief Create directory @p dir and its parents. 0 or VSPH_EIO. */
int vsph_writers_mkdir(const char *dir);

#endif /* VSPH_CLI_WRITERS_H */
