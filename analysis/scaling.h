/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
#ifndef VSPH_ANALYSIS_SCALING_H
#define VSPH_ANALYSIS_SCALING_H

#include <stddef.h>

#include "../common/api.h"
#include "../solver/viscous.h"
#include "fields.h"

struct vsph_kernel_type;
struct vsph_params;
struct vsph_params_spec;

/** @file scaling.h
 *  @brief Truncation-error scaling at the free surface (THEORY.md section
 *  2, Appendix B of Colagrossi et al. 2011): with h/dx fixed and h halved,
 *  h F and h N at a surface particle stay constant and the viscous
 *  operators applied to a linear field grow like 1/h unless the leading
 *  term vanishes. Also the interior convergence of MGF and MEAF on a
 *  quadratic field as h/dx grows. No I/O. */

/** Most levels a sweep can hold. */
#define VSPH_SCALING_MAXLEVELS 16

/** Surface sweep settings. */
struct vsph_scaling_props {
  const struct vsph_kernel_type *kernel; /*!< smoothing kernel */
  struct vsph_fields_props field;        /*!< linear field (strain/rotation) */
  int lattice;                           /*!< vsph_lattice_kind */
  double perturb;                        /*!< lattice perturbation / dx */
  unsigned long seed;                    /*!< perturbation seed */
  size_t levels;                         /*!< number of h values */
  double h0;                             /*!< largest h (m) */
  double hdx;                            /*!< h / dx, fixed */
  double mu;                             /*!< dynamic viscosity (Pa s) */
  double round_tol; /*!< |op| below round_tol mu U / h_min: rounding level */
  double max_pairs; /*!< refuse a sweep estimated to need more neighbour
                         interactions (every form, every pass, every level) */
};

/** Surface sweep results; index l is level l (h = h0 / 2^l). */
struct vsph_scaling_result {
  size_t levels;                     /*!< levels run */
  double h[VSPH_SCALING_MAXLEVELS];  /*!< smoothing length */
  double hF[VSPH_SCALING_MAXLEVELS]; /*!< h F_ddd (normal) */
  double hN[VSPH_SCALING_MAXLEVELS]; /*!< h N_d (normal) */
  /** n.(div V)_i per formulation */
  double normal[VSPH_VISCOUS_FORM_COUNT][VSPH_SCALING_MAXLEVELS];
  /** |(I - nn)(div V)_i| */
  double tangential[VSPH_VISCOUS_FORM_COUNT][VSPH_SCALING_MAXLEVELS];
  /** |(div V)_i| */
  double magnitude[VSPH_VISCOUS_FORM_COUNT][VSPH_SCALING_MAXLEVELS];
  /** log-log slope of the magnitude against h */
  double slope[VSPH_VISCOUS_FORM_COUNT];
  /** 1 if every value is at rounding level (slope NaN) */
  int rounding[VSPH_VISCOUS_FORM_COUNT];
  /** the largest |(div V)_i| over the levels, per formulation */
  double max_magnitude[VSPH_VISCOUS_FORM_COUNT];
  /** the rounding level: round_tol mu U / h at the finest h (U: the
   *  field's |A| or |Omega|); rounding[] is max_magnitude <= it */
  double round_level;
};

/** Interior sweep results over h/dx. */
struct vsph_scaling_interior {
  size_t n;                            /*!< h/dx values */
  double hdx[VSPH_SCALING_MAXLEVELS];  /*!< h / dx */
  double mgf[VSPH_SCALING_MAXLEVELS];  /*!< |MGF - mu(lap u + 2 grad div u)|
                                            / |target| */
  double meaf[VSPH_SCALING_MAXLEVELS]; /*!< |MEAF - mu lap u| / |target| */
};

/** @brief The "Scaling" parameter table (@p n receives its length):
 *  kernel, dim, field, lattice, perturb, seed, levels, hdx, mu, h0. */
VSPH_API const struct vsph_params_spec *vsph_scaling_params(size_t *n);

/** @brief Props from the "Scaling" section of @p prm (NULL: the defaults:
 *  3h Gaussian, 2-D strain, square lattice, 5 levels from h0 = 0.1, h/dx =
 *  4/3, mu = 0.0137, round_tol = 1e-9), checked and resolved.
 *  @return VSPH_OK or VSPH_EINVAL (the message names the parameter). */
VSPH_API int vsph_scaling_props_init(struct vsph_scaling_props *sp,
                                     struct vsph_params *prm);

/** @brief Least-squares slope of log y against log x over the points with
 *  x, y > 0 and finite (GSL gsl_fit_linear); NaN if fewer than two. */
VSPH_API double vsph_scaling_slope(const double *x, const double *y, size_t n);

/** @brief The h/dx values of the interior sweep (1, 4/3, 2, 3, 4, 6) into
 *  @p hdx; returns their number. */
VSPH_API size_t vsph_scaling_hdx_ladder(const double **hdx);

/** @brief Run the surface sweep: at each level a half-space patch of radius
 *  2 kappa h + 2 dx around the surface particle (exactly what the operators
 *  see: PVWF's second pass reaches 2 kappa h).
 *  @return VSPH_OK, VSPH_EINVAL (bad props, or the estimate of its work
 *  above max_pairs: refused before anything is laid), VSPH_ENOMEM,
 *  VSPH_ELIB. */
VSPH_API int vsph_scaling_surface(const struct vsph_scaling_props *sp,
                                  struct vsph_scaling_result *res);

/** @brief Interior convergence of MGF and MEAF on the 2-D quadratic field
 *  of @p sp->field, at the centre of a full patch, for each h/dx in
 *  @p hdx (n values). */
VSPH_API int vsph_scaling_interior(const struct vsph_scaling_props *sp,
                                   const double *hdx, size_t n,
                                   struct vsph_scaling_interior *res);

/** @brief The viscous term along the vertical symmetry axis of a square
 *  (side 1 m, square lattice, @p nacross particles across, h = sp->hdx dx)
 *  carrying the field of @p sp (2-D strain: the stretching square's start,
 *  paper Fig. 7): for the column of particles nearest x = 0 (x = dx/2),
 *  bottom to top, their y into @p y and the y component of (div V) of each
 *  formulation into @p f[form] (arrays of at least @p nacross).
 *  The exact value is 0 (a linear field); the surface rows show the 1/h
 *  truncation error.
 *  @return VSPH_OK, VSPH_EINVAL (not a 2-D field), VSPH_ENOMEM. */
VSPH_API int vsph_scaling_axis(const struct vsph_scaling_props *sp,
                               size_t nacross, double *y,
                               double *f[VSPH_VISCOUS_FORM_COUNT], size_t *n);

#endif /* VSPH_ANALYSIS_SCALING_H */
