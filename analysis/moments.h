/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
#ifndef VSPH_ANALYSIS_MOMENTS_H
#define VSPH_ANALYSIS_MOMENTS_H

#include <gsl/gsl_integration.h>
#include <stddef.h>

#include "../common/api.h"

struct vsph_kernel_type;
struct vsph_particles;
struct vsph_params;
struct vsph_params_spec;

/** @file moments.h
 *  @brief Kernel moment tensors F, G, N, M of THEORY.md section 2
 *  (Colagrossi et al. 2011, Sec. IV) at depth delta below a planar free
 *  surface with outward normal n = +e_d: by GSL adaptive quadrature, by
 *  particle sums, and their theoretical full/half-support values. Units
 *  h = 1 unless stated. No I/O. */

/** The four tensors; entries beyond dim are zero. Index d-1 is normal. */
struct vsph_moments {
  int dim;              /*!< 1, 2 or 3 */
  double F[3][3][3];    /*!< F_ijk = -K int x_i x_j x_k / s^3 W' dV */
  double G[3][3][3][3]; /*!< G_ijkl = -K/2 int x_i x_j x_k x_l / s^3 W' */
  double N[3];          /*!< N_j = -2 int x_j / s W' dV */
  double M[3][3];       /*!< M_jk = - int x_j x_k / s W' dV */
};

/** @brief F, G, N, M at depth @p depth (units of h, >= 0) by nested GSL
 *  qag quadrature in spherical coordinates: radial integrals
 *  R_p(a) = -int_0^a w'(s) s^p ds inside, angle outside, the outer interval
 *  split where the support meets the surface. The azimuthal integral of
 *  monomials in 3-D is done in closed form.
 *  @param k the kernel; @param dim the dimension (1-3).
 *  @param depth the depth (units of h, >= 0).
 *  @param epsrel relative accuracy of the outer integrals (>= 1e-13).
 *  @param outer,inner caller-owned GSL workspaces (distinct).
 *  @param out receives the tensors.
 *  @return VSPH_OK, VSPH_EINVAL, VSPH_ELIB (GSL failed to converge). */
VSPH_API int vsph_moments_quadrature(const struct vsph_kernel_type *k, int dim,
                                     double depth, double epsrel,
                                     gsl_integration_workspace *outer,
                                     gsl_integration_workspace *inner,
                                     struct vsph_moments *out);

/** @brief The surface constants of THEORY.md section 2 from the closed
 *  formula: I = int_0^kappa q^{d-2} w(q) dq, C_F = K (d-1) beta_d I,
 *  C_N = 2 (d-1) gamma_d I; in 1-D C_F = K w(0)/2, C_N = 2 w(0).
 *  @return VSPH_OK, VSPH_EINVAL, VSPH_ELIB. */
VSPH_API int vsph_moments_constants(const struct vsph_kernel_type *k, int dim,
                                    double epsrel,
                                    gsl_integration_workspace *ws, double *C_F,
                                    double *C_N);

/** @brief Theoretical values: full support (half = 0) G = S, M = delta,
 *  F = N = 0; half support (half = 1) G = S/2, M = delta/2,
 *  F = -C_F (d_ij n_k + d_ik n_j + d_jk n_i - n_i n_j n_k), N = -C_N n. */
VSPH_API void vsph_moments_theory(int dim, int half, double C_F, double C_N,
                                  struct vsph_moments *out);

/** @brief The tensors as particle sums sum_j V_j (...) about particle
 *  @p centre of @p p, for smoothing length @p h (values then scale as
 *  F, N ~ 1/h, G, M ~ 1). O(N).
 *  @return VSPH_OK or VSPH_EINVAL. */
VSPH_API int vsph_moments_sum(const struct vsph_kernel_type *k,
                              const struct vsph_particles *p, size_t centre,
                              double h, struct vsph_moments *out);

/** @brief Largest absolute entry difference of F, G, N, M (gap[0..3]). */
VSPH_API void vsph_moments_gap(const struct vsph_moments *a,
                               const struct vsph_moments *b, double gap[4]);

/* ------------------------------------------------ one evaluation (driver) */

/** One evaluation of the tensors at a depth ("Tensors" section). */
struct vsph_moments_props {
  const struct vsph_kernel_type *kernel; /*!< smoothing kernel */
  int dim;                               /*!< 1, 2 or 3 */
  double depth;       /*!< depth below the surface (units of h) */
  int particles;      /*!< 1: also particle sums over a lattice */
  int lattice_kind;   /*!< vsph_lattice_kind (square or hex) */
  double perturb;     /*!< perturbation amplitude (dx), 0 for none; its
                           name is vsph_lattice_label(lattice_kind,
                           perturb) */
  unsigned long seed; /*!< seed of the perturbation */
  double hdx;         /*!< h/dx of the lattice */
  double epsrel;      /*!< relative accuracy of the quadrature */
};

/** What one evaluation gives. */
struct vsph_moments_result {
  struct vsph_moments quad;   /*!< by quadrature */
  struct vsph_moments sum;    /*!< by particle sums (particles = 1) */
  struct vsph_moments theory; /*!< theoretical values (have_theory = 1) */
  int have_theory;            /*!< 1 at half (depth 0) or full support */
  double C_F, C_N;            /*!< surface constants */
  size_t n_particles;         /*!< particles summed over */
  double gap[4];              /*!< largest |sum - quad| of F, G, N, M */
};

/** @brief The "Tensors" parameter table (@p n receives its length). */
VSPH_API const struct vsph_params_spec *vsph_moments_params(size_t *n);

/** @brief Props from the "Tensors" section of @p prm (NULL: defaults: 3h
 *  Gaussian, 2-D, depth 0, quadrature, square lattice at h/dx 4/3), checked
 *  and resolved. @return VSPH_OK or VSPH_EINVAL. */
VSPH_API int vsph_moments_props_init(struct vsph_moments_props *mp,
                                     struct vsph_params *prm);

/** @brief Evaluate: quadrature, constants, theory where it exists and the
 *  particle sums if asked.
 *  @note Allocates its own workspaces and particle set (a driver).
 *  @return VSPH_OK, VSPH_EINVAL, VSPH_ENOMEM, VSPH_ELIB. */
VSPH_API int vsph_moments_compute(const struct vsph_moments_props *mp,
                                  struct vsph_moments_result *res);

#endif /* VSPH_ANALYSIS_MOMENTS_H */
