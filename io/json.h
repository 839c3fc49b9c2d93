/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
#ifndef VSPH_IO_JSON_H
#define VSPH_IO_JSON_H

#include <cjson/cJSON.h>
#include <stddef.h>

#include "../common/api.h"

struct vsph_moments;
struct vsph_moments_props;
struct vsph_moments_result;
struct vsph_scaling_props;
struct vsph_scaling_result;
struct vsph_dissipation_props;
struct vsph_dissipation_result;
struct vsph_laplacian_props;
struct vsph_laplacian_result;

/** @file json.h
 *  @brief JSON through cJSON: arrays of numbers (NaN and infinities become
 *  null), the moment tensors as nested arrays, and whole objects printed to
 *  stdout or written atomically to a file. Not part of <vsph/vsph.h>
 *  (it brings cJSON's types): include <vsph/io/json.h>. A NULL argument
 *  is refused: VSPH_EINVAL where a status is returned, else NULL (both
 *  reported), the default, or nothing. */

/** @brief Array of @p n doubles (non-finite values become null). */
VSPH_API cJSON *vsph_json_array(const double *v, size_t n);

/** @brief Add a number to @p obj, or null when it is not finite. */
VSPH_API void vsph_json_number(cJSON *obj, const char *key, double v);

/** @brief The machine's state beside a timing: "load_average_start" and
 *  "load_average_end" (1, 5, 15 min; null where unknown) from @p start
 *  and @p end, and "omp_wait_policy". */
VSPH_API void vsph_json_load(cJSON *obj, const double start[3],
                             const double end[3]);

/** @brief The tensors as nested arrays: F d x d x d, G d^4, N d, M d x d,
 *  added to @p obj under the keys "F", "G", "N", "M". */
VSPH_API void vsph_json_moments(cJSON *obj, const struct vsph_moments *m);

/** @brief Print @p obj to stdout with a newline, and free it.
 *  @return VSPH_OK, VSPH_EINVAL, VSPH_ENOMEM or VSPH_EIO (stdout could not be
 *  written). */
VSPH_API int vsph_json_print(cJSON *obj);

/** @brief @p obj as the text vsph_json_write writes (pretty-printed, one
 *  newline at the end); frees @p obj. Caller frees; NULL after reporting. */
VSPH_API char *vsph_json_text(cJSON *obj);

/** @brief Write @p obj to DIR/NAME atomically, and free it.
 *  @return VSPH_OK, VSPH_EINVAL, VSPH_ENOMEM or VSPH_EIO. */
VSPH_API int vsph_json_write(cJSON *obj, const char *dir, const char *name);

/** @brief Parse the JSON file @p path; NULL if it cannot be read or
 *  parsed (not reported). */
VSPH_API cJSON *vsph_json_read(const char *path);

/** @brief The number under @p key, or @p def when absent or not a
 *  number. */
VSPH_API double vsph_json_get_number(const cJSON *obj, const char *key,
                                     double def);

/** @brief `vsph tensors --json`: kernel, dim, depth, method, F, G, N, M,
 *  C_F, C_N, kappa; with particle sums also lattice, hdx, (perturb, seed),
 *  n_particles, quadrature (F, G, N, M) and gap (F, G, N, M). */
VSPH_API cJSON *vsph_json_tensors(const struct vsph_moments_props *mp,
                                  const struct vsph_moments_result *r);

/** @brief `vsph scaling --json` (surface sweep): kernel, dim, field,
 *  lattice, hdx, mu, h, hF, hN, hF_theory, hN_theory and, per formulation
 *  F: F (normal components), F_tangential, F_magnitude, slope_F,
 *  rounding_F. */
VSPH_API cJSON *vsph_json_scaling(const struct vsph_scaling_props *sp,
                                  const struct vsph_scaling_result *r,
                                  double hF_th, double hN_th);

/** @brief `vsph dissipation --json`: the props and every field of the
 *  result (non-finite values as null). */
VSPH_API cJSON *vsph_json_dissipation(const struct vsph_dissipation_props *dp,
                                      const struct vsph_dissipation_result *r);

/** @brief `vsph laplacian --json`: the props and every field of the
 *  result. */
VSPH_API cJSON *vsph_json_laplacian(const struct vsph_laplacian_props *lp,
                                    const struct vsph_laplacian_result *r);

#endif /* VSPH_IO_JSON_H */
