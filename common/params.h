/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
#ifndef VSPH_COMMON_PARAMS_H
#define VSPH_COMMON_PARAMS_H

#include <stddef.h>

#include "api.h"

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
VSPH_API struct vsph_params *vsph_params_alloc(void);

/** @brief Free; NULL is a no-op. */
VSPH_API void vsph_params_free(struct vsph_params *prm);

/** @brief Read a parameter file (at most 1 MiB): its values override
 *  those of files read before it and of earlier vsph_params_set calls, so
 *  several files apply in order. Linear in the file's size.
 *  @return VSPH_OK, VSPH_EIO (cannot open or read), VSPH_EINVAL (too large;
 *  outside the subset: anchors, aliases, deeper nesting, several
 *  documents, a key given twice in the same file; malformed), VSPH_ENOMEM. */
VSPH_API int vsph_params_read(struct vsph_params *prm, const char *path);

/** @brief The same from @p len bytes of @p text; @p path names it in
 *  messages. */
VSPH_API int vsph_params_read_string(struct vsph_params *prm, const char *text,
                                     size_t len, const char *path);

/** @brief Set "Section:key" to @p value (overrides the file).
 *  @return VSPH_OK or VSPH_EINVAL (key not of the form Section:key). */
VSPH_API int vsph_params_set(struct vsph_params *prm, const char *key,
                             const char *value);

/** @brief The same from one "Section:key=value" setting (the form of
 *  `--set` and of the report's run settings).
 *  @return VSPH_OK or VSPH_EINVAL (not of that form; reported). */
VSPH_API int vsph_params_assign(struct vsph_params *prm, const char *setting);

/** @brief Required number. @return VSPH_OK or VSPH_EINVAL (missing or not
 *  a finite number). */
VSPH_API int vsph_params_get_double(struct vsph_params *prm, const char *key,
                                    double *out);

/** @brief Optional number with a default (recorded as used). */
VSPH_API int vsph_params_get_double_or(struct vsph_params *prm, const char *key,
                                       double def, double *out);

/** @brief Optional string with a default (recorded as used).
 *  @note The pointer lives as long as the store. */
VSPH_API int vsph_params_get_string_or(struct vsph_params *prm, const char *key,
                                       const char *def, const char **out);

/** @brief The first key given but never read, or NULL. */
VSPH_API const char *vsph_params_unused(const struct vsph_params *prm);

/** @brief Of the @p n words @p cand, the one nearest @p word by edit
 *  distance (insertions, deletions, substitutions and swaps of two
 *  neighbours, each one step; letters compared without case), where it is
 *  near enough to be a slip: at most 1 step for a word of up to 4
 *  letters, 2 up to 8, 3 beyond. @return its index, or @p n (none near
 *  enough, or a NULL argument). */
VSPH_API size_t vsph_params_nearest(const char *word, const char *const *cand,
                                    size_t n);

/** @brief The hint for unknown key @p key into @p buf (@p len bytes, one
 *  line): "; did you mean S:k?" where a key the store holds (given, or a
 *  default a table filled in: every key its reader knows) is near enough
 *  (vsph_params_nearest), then " (the S keys: a, b, ...)" listing the keys
 *  of @p key's section S, or of every section where S holds none.
 *  Empty where @p prm, @p key or @p buf is NULL. */
VSPH_API void vsph_params_hint(const struct vsph_params *prm, const char *key,
                               char *buf, size_t len);

/** @brief 1 if @p key was given (by a file, a setting or an option), 0 if
 *  it is absent or holds a default a getter filled in. @p prm may be NULL
 *  (0). */
VSPH_API int vsph_params_given(const struct vsph_params *prm, const char *key);

/** @brief Number of entries (given or used). */
VSPH_API size_t vsph_params_count(const struct vsph_params *prm);

/** @brief Entry @p i in insertion order: key, value, and whether it was
 *  read (used). */
VSPH_API void vsph_params_entry(const struct vsph_params *prm, size_t i,
                                const char **key, const char **value,
                                int *used);

/* ------------------------------------------------------- parameter tables */

/** Longest word a NAME parameter holds, terminator included. */
#define VSPH_PARAMS_NAME_MAX 32

/** Kinds of parameter value. */
enum vsph_params_kind {
  VSPH_PARAMS_REAL = 0, /*!< a finite decimal number in [lo, hi] (double) */
  VSPH_PARAMS_INT,      /*!< a whole number in [lo, hi] (stored as size_t) */
  VSPH_PARAMS_NAME      /*!< a word (char[VSPH_PARAMS_NAME_MAX]) */
};

/** One parameter of a module's section: the one place that holds its
 *  default, bounds and meaning, and where the module's props_init stores
 *  it. `vsph scenes`, `--help` and used_parameters.yml all read it. */
struct vsph_params_spec {
  const char *key;            /*!< name under the section */
  enum vsph_params_kind kind; /*!< value kind */
  double def;                 /*!< default (REAL, INT) */
  const char *word;           /*!< default (NAME) */
  double lo, hi;              /*!< closed bounds (REAL, INT) */
  size_t offset;              /*!< offsetof the field in the props struct */
  const char *help;           /*!< meaning and unit */
};

/** Table entries whose key is the name of the props field they fill, so a
 *  parameter has one name from the file to the struct. */
#define VSPH_PARAMS_REAL_SPEC(type, field, def, lo, hi, help)                 \
  {                                                                           \
#field, VSPH_PARAMS_REAL, (def), NULL, (lo), (hi), offsetof(type, field), \
        (help)                                                                \
  }
#define VSPH_PARAMS_INT_SPEC(type, field, def, lo, hi, help)                 \
  {                                                                          \
#field, VSPH_PARAMS_INT, (def), NULL, (lo), (hi), offsetof(type, field), \
        (help)                                                               \
  }
#define VSPH_PARAMS_NAME_SPEC(type, field, word, help)                      \
  {                                                                         \
#field, VSPH_PARAMS_NAME, 0.0, (word), 0.0, 0.0, offsetof(type, field), \
        (help)                                                              \
  }

/** @brief Fill the props struct at @p props from "SECTION:key" entries of
 *  @p prm (or the defaults where a key is absent; @p prm may be NULL for
 *  all defaults). Numbers are parsed strictly (decimal, no spaces, finite)
 *  and checked against their bounds before any conversion; whole numbers
 *  must be integral. Every value is recorded as used. @p size is the
 *  struct's size in bytes (sizeof *props): a table whose field would lie
 *  beyond it is refused before anything is written.
 *  @return VSPH_OK or VSPH_EINVAL (malformed or out of bounds: the message
 *  names the key, the value and the bounds; a field beyond @p size),
 *  VSPH_ENOMEM. */
VSPH_API int vsph_params_load(struct vsph_params *prm, const char *section,
                              const struct vsph_params_spec *spec, size_t n,
                              void *props, size_t size);

/** @brief The spec called @p key in a table, or NULL. */
VSPH_API const struct vsph_params_spec *vsph_params_spec_find(
    const struct vsph_params_spec *spec, size_t n, const char *key);

/** @brief A spec's default as text ("1.3333333333333333", "40", "mgf"). */
VSPH_API void vsph_params_spec_default(const struct vsph_params_spec *s,
                                       char *buf, size_t len);

/** @brief Strict number: decimal notation only (digits, one point, an
 *  exponent), no leading or trailing space, no hex, inf or nan.
 *  @return VSPH_OK or VSPH_EINVAL (not reported: the caller words it). */
VSPH_API int vsph_params_parse_number(const char *s, double *out);

#endif /* VSPH_COMMON_PARAMS_H */
