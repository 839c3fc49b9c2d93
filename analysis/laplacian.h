/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
#ifndef VSPH_ANALYSIS_LAPLACIAN_H
#define VSPH_ANALYSIS_LAPLACIAN_H

#include <stddef.h>

#include "../common/api.h"

struct vsph_kernel_type;
struct vsph_params;
struct vsph_params_spec;

/** @file laplacian.h
 *  @brief The Laplacian patch test of Zheng, Ma & Shao (2018), Sec. 4
 *  (docs/theory.md section 7): the four Laplacian forms VISC-01..04 of
 *  solver/pair.h applied to an analytic field sampled on a uniform or
 *  randomly perturbed lattice over the unit square (or cube), padded with
 *  ghost particles carrying the analytic field so that every evaluated
 *  particle has full support, against the exact Laplacian. No I/O. A
 *  NULL argument is refused: VSPH_EINVAL (reported) where a status is
 *  returned, else -1 or "unknown". */

/** Test fields, each with its exact Laplacian. */
enum vsph_laplacian_field {
  VSPH_LAPLACIAN_QUARTIC = 0, /*!< sum_a x_a^4 (the paper's), 12 sum x_a^2 */
  VSPH_LAPLACIAN_QUADRATIC,   /*!< 0.7 x^2 - 1.3 x y + 0.45 y^2 (+ 0.9 z^2) */
  VSPH_LAPLACIAN_LINEAR,      /*!< 1.2348 x - 0.8731 y (+ 0.5 z), Laplacian 0 */
  VSPH_LAPLACIAN_FIELD_COUNT
};

/** One patch test. */
struct vsph_laplacian_props {
  int form;                              /*!< vsph_pair_lap_form */
  const struct vsph_kernel_type *kernel; /*!< smoothing kernel */
  int dim;                               /*!< 2 or 3 */
  int field;                             /*!< vsph_laplacian_field */
  size_t n;                              /*!< particles across the unit side */
  double hdx;                            /*!< h / dx */
  double perturb;     /*!< each coordinate shifted by U(-a, a) dx */
  unsigned long seed; /*!< seed of that shift (mt19937) */
  double eta;         /*!< regulariser eta / h of the hybrid forms */
  double line_x;      /*!< the line x = line_x of the line errors */
  double max_memory;  /*!< refuse a set estimated to need more (GiB) */
  double max_pairs;   /*!< refuse a set estimated to need more neighbour
                           interactions (n^d pi (kappa hdx)^d in 2-D) */
};

/** What one test measured. */
struct vsph_laplacian_result {
  size_t n_eval;      /*!< particles evaluated (n^d) */
  size_t n_total;     /*!< with the ghost padding */
  double dx, h;       /*!< spacing and smoothing length (m) */
  double err_literal; /*!< eq. (21): mean |num - exact| / |num| */
  double err_exact;   /*!< mean |num - exact| / |exact| */
  double err_paper;   /*!< err_exact dx^2: the scale of the paper's tables */
  double abs_max;     /*!< max |num - exact| */
  double ref_max;     /*!< max |exact| (0 for the linear field) */
  /** the paper's Fig. 2 sampling: the particles within (1/2 + perturb) dx
   *  of the line x = line_x (the nearest one or two lattice columns) */
  size_t n_line;           /*!< how many */
  double err_line_literal; /*!< eq. (21) over them, times dx^2 */
  double err_line_paper;   /*!< the same with the exact denominator */
};

/** @brief Name of form @p form ("visc01" ...), or "unknown". */
VSPH_API const char *vsph_laplacian_form_name(int form);

/** @brief Form called @p name, or -1. */
VSPH_API int vsph_laplacian_form_find(const char *name);

/** @brief Name of field @p field ("quartic" ...), or "unknown". */
VSPH_API const char *vsph_laplacian_field_name(int field);

/** @brief The "Laplacian" parameter table (@p n, when not NULL, receives
 *  its length). */
VSPH_API const struct vsph_params_spec *vsph_laplacian_params(size_t *n);

/** @brief Props from the "Laplacian" section of @p prm (NULL: defaults:
 *  visc01, cubic spline, 2-D, quartic, n = 20, h/dx = 1, no perturbation,
 *  eta = 0, as the paper's patch test).
 *  @return VSPH_OK, VSPH_EINVAL (one message naming the problem). */
VSPH_API int vsph_laplacian_props_init(struct vsph_laplacian_props *lp,
                                       struct vsph_params *prm);

/** @brief Run the patch test. @return VSPH_OK, VSPH_EINVAL (props out of
 *  their ranges, or the estimate of its work above max_pairs or of its
 *  memory above max_memory, refused before anything is allocated),
 *  VSPH_ENOMEM. */
VSPH_API int vsph_laplacian_patch(const struct vsph_laplacian_props *lp,
                                  struct vsph_laplacian_result *res);

#endif /* VSPH_ANALYSIS_LAPLACIAN_H */
