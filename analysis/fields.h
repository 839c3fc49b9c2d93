/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
#ifndef VSPH_ANALYSIS_FIELDS_H
#define VSPH_ANALYSIS_FIELDS_H

#include "../common/api.h"

/** @file fields.h
 *  @brief Analytic velocity fields sampled on particle sets by the
 *  dissipation and scaling analyses (THEORY.md sections 2 and 4), with their
 *  exact gradients. The plane of rotation and strain is (x_1, x_d), so in
 *  2-D the fields are the paper's: rotation (-Omega y, Omega x), strain
 *  (A x, -A y). No I/O. */

/** Field kinds. */
enum vsph_fields_kind {
  VSPH_FIELDS_ROTATION = 0, /*!< rigid rotation, D = 0 */
  VSPH_FIELDS_STRAIN,       /*!< pure strain, n.D.n != 0 at the top face */
  VSPH_FIELDS_MIXED,        /*!< rotation + strain + Taylor-Green cell (2-D) */
  VSPH_FIELDS_QUADRATIC,    /*!< quadratic with divergence (2-D) */
  VSPH_FIELDS_KIND_COUNT
};

/** Field parameters. */
struct vsph_fields_props {
  enum vsph_fields_kind kind; /*!< which field */
  int dim;                    /*!< 1, 2 or 3 */
  double A;                   /*!< strain rate (1/s) */
  double Omega;               /*!< rotation rate (1/s) */
  double U;                   /*!< Taylor-Green amplitude (m/s), mixed */
  double k;                   /*!< Taylor-Green wavenumber (1/m), mixed */
  double theta;               /*!< strain: its axes turned by theta (rad)
                                   in the plane, u = A (x cos 2t + y sin 2t,
                                   x sin 2t - y cos 2t); 0: the paper's */
  double c[6];                /*!< quadratic: u = (c0 x^2 + c1 xy + c2 y^2,
                                   c3 x^2 + c4 xy + c5 y^2) (1/(m s)) */
};

/** @brief Name of a field kind. */
VSPH_API const char *vsph_fields_name(int kind);

/** @brief Kind called @p name, or -1. */
VSPH_API int vsph_fields_find(const char *name);

/** @brief Defaults: A = 1.2348, Omega = 0.8731, U = 0.4, k = pi,
 *  c = (0.7, -1.3, 0.45, -0.35, 0.9, 1.1) (GSL-style high-entropy values).
 *  @return VSPH_OK or VSPH_EINVAL (kind not defined in this dimension). */
VSPH_API int vsph_fields_props_init(struct vsph_fields_props *fp, int kind,
                                    int dim);

/** @brief Velocity u(x) and gradient grad[a*dim+b] = du_a/dx_b at x. */
VSPH_API void vsph_fields_eval(const struct vsph_fields_props *fp,
                               const double x[3], double u[3], double grad[9]);

/** @brief Laplacian and grad(div u) at x (exact). */
VSPH_API void vsph_fields_second(const struct vsph_fields_props *fp,
                                 const double x[3], double lap[3],
                                 double graddiv[3]);

#endif /* VSPH_ANALYSIS_FIELDS_H */
