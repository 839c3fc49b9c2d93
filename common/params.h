#ifndef VSPH_COMMON_PARAMS_H
#define VSPH_COMMON_PARAMS_H

#include <stddef.h>

/** @file params.h
 *  @brief Run parameters as "Section:key" -> value, from a YAML-subset file
 *  (SWIFT shape: `Section:` then `key: value`, scalars and [a, b] lists,
 *  # comments; parsed with libyaml) and from command-line overrides. Getters
 *  return a status, record every value used (defaults filled in) and mark
 *  the key, so a run can reject unknown keys and list what it used (STYLE
 *  B8). No I/O other than reading the file. */

/** Opaque parameter store. */
struct vsph_params;

/** @brief Empty store. NULL on failure. */
struct vsph_params *vsph_params_alloc(void);

/** @brief Free; NULL is a no-op. */
void vsph_params_free(struct vsph_params *prm);

/** @brief Read a parameter file; later values override earlier ones.
 *  @return VSPH_OK, VSPH_EIO (cannot open), VSPH_EINVAL (outside the
 *  subset: anchors, aliases, deeper nesting, several documents, a key
 *  given twice, a malformed file), VSPH_ENOMEM. */
int vsph_params_read(struct vsph_params *prm, const char *path);

/** @brief Set "Section:key" to @p value (overrides the file).
 *  @return VSPH_OK or VSPH_EINVAL (key not of the form Section:key). */
int vsph_params_set(struct vsph_params *prm, const char *key,
                    const char *value);

/** @brief Required number. @return VSPH_OK or VSPH_EINVAL (missing or not
 *  a finite number). */
int vsph_params_get_double(struct vsph_params *prm, const char *key,
                           double *out);

/** @brief Optional number with a default (recorded as used). */
int vsph_params_get_double_or(struct vsph_params *prm, const char *key,
                              double def, double *out);

/** @brief Optional string with a default (recorded as used).
 *  @note The pointer lives as long as the store. */
int vsph_params_get_string_or(struct vsph_params *prm, const char *key,
                              const char *def, const char **out);

/** @brief The first key given but never read, or NULL. */
const char *vsph_params_unused(const struct vsph_params *prm);

/** @brief Number of entries (given or used). */
size_t vsph_params_count(const struct vsph_params *prm);

/** @brief Entry @p i in insertion order: key, value, and whether it was
 *  read (used). */
void vsph_params_entry(const struct vsph_params *prm, size_t i,
                       const char **key, const char **value, int *used);

#endif /* VSPH_COMMON_PARAMS_H */
