/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
#ifndef VSPH_ANALYSIS_DISSIPATION_H
#define VSPH_ANALYSIS_DISSIPATION_H

#include <stddef.h>

#include "../common/api.h"
#include "fields.h"

struct vsph_kernel_type;
struct vsph_params;
struct vsph_params_spec;

/** @file dissipation.h
 *  @brief The dissipation integrals of THEORY.md section 4 (Colagrossi et
 *  al. 2011, Sec. V and Appendix C): P = sum_i V_i u_i.(div V)_i of each
 *  formulation for an analytic field sampled on a disc or square of
 *  particles, against P_exact = -int V:D dV and P_grad = -mu int |grad u|^2,
 *  with the error split into the formulation's consistency error, the
 *  lattice error of h/dx (measured on the particles whose support is full)
 *  and the surface deficit. No I/O. */

/** Particle-set shape: both have extent 1 m (square side, disc diameter). */
enum vsph_dissipation_shape {
  VSPH_DISSIPATION_DISC = 0, /*!< radius 0.5, concentric rings */
  VSPH_DISSIPATION_SQUARE,   /*!< side 1, square lattice */
  VSPH_DISSIPATION_SHAPE_COUNT
};

/** One dissipation evaluation. */
struct vsph_dissipation_props {
  int form;                              /*!< viscous formulation */
  const struct vsph_kernel_type *kernel; /*!< smoothing kernel */
  struct vsph_fields_props field;        /*!< 2-D analytic field */
  enum vsph_dissipation_shape shape;     /*!< disc or square */
  size_t nacross;                        /*!< particles across the shape */
  double hdx;                            /*!< h / dx */
  double mu;                             /*!< dynamic viscosity (Pa s) */
  double perturb;                        /*!< lattice perturbation / dx */
  unsigned long seed;                    /*!< perturbation seed */
  double epsrel;                         /*!< accuracy of the exact integrals */
  double max_memory; /*!< refuse a set estimated to need more (GiB) */
  double max_pairs;  /*!< refuse a set estimated to need more neighbour
                          interactions (each pass counted) */
};

/** What one evaluation measured (powers in W per unit depth). */
struct vsph_dissipation_result {
  size_t n_particles;       /*!< particles in the set */
  size_t n_interior;        /*!< particles at least kappa h from the edge */
  double h, dx;             /*!< smoothing length and spacing (m) */
  double P;                 /*!< sum_i V_i u_i.(div V)_i */
  double P_pair;            /*!< sum_i V_i p_i (pairwise form; = P exactly) */
  double P_exact;           /*!< -int V:D dV (Stokes lambda = -2 mu/d) */
  double P_grad;            /*!< -mu int |grad u|^2 dV */
  double P_limit;           /*!< the form's continuum limit of P (its
                                 descriptor's limit): P_exact (stress),
                                 P_grad (gradient) or mu int u.lap u dV
                                 (a per-particle Laplacian) */
  double rel_error;         /*!< (P - P_exact)/|P_exact|, or P/|P_grad| */
  double consistency_error; /*!< (P_limit - P_exact)/norm: MEAF's W:W term,
                                 a Laplacian's lost surface term */
  double lattice_error;     /*!< interior sum vs its continuous limit */
  double surface_error;     /*!< the rest: (P - P_limit)/norm - lattice */
  double momentum;          /*!< |sum V_i (div V)_i| / sum V_i |(div V)_i| */
  double angular;           /*!< |sum V_i x_i x (div V)_i| / sum |..| */
  size_t n_fallback;        /*!< PVWF particles whose L fell back to I */
};

/** @brief Name of a shape ("disc", "square"). */
VSPH_API const char *vsph_dissipation_shape_name(int shape);

/** @brief Shape called @p name, or -1. */
VSPH_API int vsph_dissipation_shape_find(const char *name);

/** @brief The "Dissipation" parameter table (@p n receives its length). */
VSPH_API const struct vsph_params_spec *vsph_dissipation_params(size_t *n);

/** @brief Props from the "Dissipation" section of @p prm (NULL: the
 *  defaults: MGF, strain, square, 3h Gaussian, 40 across, h/dx = 4/3,
 *  mu = 0.0137, no perturbation, seed 2385, epsrel 1e-10), checked and
 *  resolved. @return VSPH_OK or VSPH_EINVAL. */
VSPH_API int vsph_dissipation_props_init(struct vsph_dissipation_props *dp,
                                         struct vsph_params *prm);

/** @brief Exact -int V:D dV and -mu int |grad u|^2 dV over the shape, by
 *  nested GSL quadrature. @return VSPH_OK, VSPH_ELIB, VSPH_ENOMEM. */
VSPH_API int vsph_dissipation_exact(const struct vsph_dissipation_props *dp,
                                    double *P_exact, double *P_grad);

/** @brief Build the set, evaluate the formulation, fill @p res.
 *  @note Allocates and frees its own particle set, cell list and workspace
 *  (a driver, not a hot function).
 *  @return VSPH_OK, VSPH_EINVAL, VSPH_ENOMEM, VSPH_ELIB. */
VSPH_API int vsph_dissipation_compute(const struct vsph_dissipation_props *dp,
                                      struct vsph_dissipation_result *res);

struct vsph_viscous_props;
struct vsph_particles;

/** The dissipation of a particle set (W, per unit depth in 2-D). */
struct vsph_dissipation_power {
  double P;          /*!< sum_i V_i u_i.(div V)_i */
  double P_pair;     /*!< sum_i V_i p_i, the formulation's pairwise density
                          (THEORY.md section 4; equal to P to rounding) */
  size_t n_fallback; /*!< PVWF: particles whose L fell back to I */
};

/** @brief The dissipation of the formulation @p vp for a particle set of
 *  the caller's (pos, vel, m and rho of its p->n particles): every
 *  particle gathers from all the others within kappa h, the set taken as
 *  it is (no walls, no ghosts, a free surface wherever it ends). For
 *  regression tests of another code's dissipation. The set is read only:
 *  the sums run over a copy, sorted by cell.
 *  @return VSPH_OK; VSPH_EINVAL (bad props, dimension, a non-positive
 *  mass or density, a non-finite position or velocity, particles too far
 *  apart for a grid, a result that is not finite: two particles at one
 *  place), @p out untouched; VSPH_ENOMEM. */
VSPH_API int vsph_dissipation_particles(const struct vsph_viscous_props *vp,
                                        const struct vsph_particles *p,
                                        struct vsph_dissipation_power *out);

#endif /* VSPH_ANALYSIS_DISSIPATION_H */
