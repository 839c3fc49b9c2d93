/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
#ifndef VSPH_ANALYSIS_CONTACT_H
#define VSPH_ANALYSIS_CONTACT_H

#include <signal.h>
#include <stddef.h>

#include "../common/api.h"

struct vsph_kernel_type;
struct vsph_params;

/** @file contact.h
 *  @brief The numerical viscosity of contact SPH (Parshikov, Medin,
 *  Rublev & Dyachkov; docs/theory.md section 12): the exact
 * shear layer (Stokes' first problem, their eq. 10) and its control surface,
 *  the lattice-sum prediction of the acoustic solver's viscosity, and the
 *  paper's measurement: run the shear scene, fit the viscosity whose exact
 *  solution matches the SPH profile. No I/O beyond the run's progress.
 *  A NULL argument is refused: VSPH_EINVAL (reported) where a status is
 *  returned, else NaN; an output the caller does not want (rms,
 *  rms_exact, U, drift, ustar) may be NULL. */

/** @brief u_y(x, t) of the shear layer u_y(x, 0) = U0 sign(x) on the
 *  period (-W, W) (slip walls at +-W/2 are planes of symmetry):
 *  U0 [sum_n erf((x - 2nW)/d) - erf((x - 2nW - W)/d) - 1], d = sqrt(4 nu
 *  t), the images summed while they matter. Stokes' first problem, Parshikov et
 * al. eq. (10), while d << W. NaN for a NaN @p nu (a fit not available). */
VSPH_API double vsph_contact_shear_u(double x, double t, double nu, double U0,
                                     double W);

/** @brief The displacement of the same flow's material line (Parshikov et al.'s
 *  "control surface"), int_0^t u_y dt, in closed form: per erf image,
 *  t sign(xi) [1 - (1 + 2 xi^2) erfc|xi| + 2|xi| e^{-xi^2}/sqrt(pi)],
 *  xi = x/d. */
VSPH_API double vsph_contact_shear_dy(double x, double t, double nu, double U0,
                                      double W);

/** @brief The effective viscosity that the correcting tensor leaves
 *  (Parshikov et al.'s model, docs/theory.md section 12): the scheme's
 *  own dynamic numerical viscosity C rho c D0 plus the lattice factor
 *  f_lat times what the contact stress carries, the physical eta less
 *  the removed fraction zeta of the fitted numerical one,
 *  eta_num = fit rho c D0 (Pa s). */
VSPH_API double vsph_contact_eta_model(double C, double rho, double c,
                                       double D0, double flat, double eta,
                                       double zeta, double fit);

/** @brief The contact velocity that best fits a two-material profile:
 *  the @p n samples (x[i], u[i]) taken at time tt[i]; those at time @p t
 *  (to 1e-6 relative) with |x| < W/2 (the paper's box: beyond it the
 *  mirror image's interface) fit u = U* (1 - e) + u_side e, e =
 *  erf(|x|/sqrt(4 nu_side t)), u_side = -U0 (x < 0) or U0, nu_side = nuL or
 *  nuR; linear in U*, so least squares in closed form. @return U* over U0, NaN
 *  for no sample. @p rms_exact receives the RMS misfit (over U0) of the
 *  exact profile (vsph_contact_bimaterial_u with etaL, rhoL, etaR, rhoR)
 *  at those samples. */
VSPH_API double vsph_contact_bimaterial_fit(const double *tt, const double *x,
                                            const double *u, size_t n, double t,
                                            double U0, double nuL, double nuR,
                                            double W, double etaL, double rhoL,
                                            double etaR, double rhoR,
                                            double *rms_exact);

/** @brief The drag of a square array of cylinders (period S, fluid
 *  density @p rho) driven by eq. (39)'s force at the target superficial
 *  velocity @p U_drive, from the run's momentum series px (n rows): the
 *  reached velocity *U = px[n-1]/(rho S^2), its relative change over the
 *  last tenth of the rows *drift = (px[n-1] - px[n-1-(n-1)/10])/px[n-1],
 *  and the drag ratio (F/(eta U))_SPH over eq. (39)'s, U_drive / *U (the
 *  force is eq. (39)'s at U_drive). NaN for n = 0. */
VSPH_API double vsph_contact_drag_ratio(const double *px, size_t n, double rho,
                                        double S, double U_drive, double *U,
                                        double *drift);

/** @brief Two semi-infinite materials (left x < 0, right x > 0) sliding at
 *  uL and uR with viscosities etaL, etaR and densities rhoL, rhoR: the
 *  contact velocity (Parshikov et al. eq. 27, the effusivity-weighted mean
 *  sqrt(eta rho)) and u(x, t) = U* + (u_side - U*) erf(|x|/sqrt(4 nu_side
 *  t)). @p ustar receives U* when not NULL. */
VSPH_API double vsph_contact_bimaterial_u(double x, double t, double uL,
                                          double etaL, double rhoL, double uR,
                                          double etaR, double rhoR,
                                          double *ustar);

/** @brief The acoustic solver's numerical viscosity predicted by a
 *  lattice sum (docs/theory.md section 12): for identical particles in
 *  shear, nu_num = (c/2) sum_j V_j x_j^2 (y_j/r_j)^2 |W'(r_j)| over the
 *  simple cubic lattice of spacing D0 (3-D; the square one in 2-D), with
 *  h = 2 alpha D0. @return nu_num/(c D0) = eta_num/(Z D0); NaN (reported)
 *  unless @p dim is 2 or 3 and 0 < kappa 2 alpha <= 64. */
VSPH_API double vsph_contact_lattice_coef(const struct vsph_kernel_type *k,
                                          int dim, double alpha);

/** @brief The shear viscosity of contact SPH's viscous traction
 *  (vsph_pair_contact_visc) on the same static lattice, over eta:
 *  sum_j V_j |W'(r_j)|/r_j x_j^2 (1 + y_j^2/(3 r_j^2)) (docs/theory.md
 *  section 12; its continuum limit is 1 + 1/(3(d + 2)), 16/15 in 3-D);
 *  NaN for the arguments vsph_contact_lattice_coef refuses. */
VSPH_API double vsph_contact_lattice_visc_factor(
    const struct vsph_kernel_type *k, int dim, double alpha);

/** @brief The viscosity nu in [lo, hi] whose shear-layer solution (@p dy
 *  0: u_y, vsph_contact_shear_u; 1: the control surface,
 *  vsph_contact_shear_dy) best fits the @p n values @p v at @p x in the
 *  least-squares sense: a log-spaced scan, then Brent's minimiser (GSL).
 *  @p rms receives the fit's RMS residual over U0 (u) or U0 t (dy).
 *  @return nu, or NaN on failure (reported). */
VSPH_API double vsph_contact_fit_nu(size_t n, const double *x, const double *v,
                                    int dy, double t, double U0, double W,
                                    double lo, double hi, double *rms);

/** The shear test's outcome. */
struct vsph_contact_shear {
  /* in */
  size_t nprof; /*!< profile times t_end (k + 1)/nprof, k < nprof (<= 8) */
  /** called about every 10 s of wall time with the run's time, its end
   *  time and the wall time so far (s); NULL: none (the analysis itself
   *  prints nothing) */
  void (*progress)(void *ctx, double t, double t_end, double wall);
  void *progress_ctx; /*!< passed to progress */
  /** a stop request (SIGINT, SIGTERM, a report's budget), or NULL: seen
   *  between two steps, it ends the test at a checkpoint (interrupted) */
  const volatile sig_atomic_t *stop;
  /** where the whole state goes (the run's and the measurement's so far,
   *  @p len bytes): every Solver:checkpoint_s of wall time and at a stop;
   *  NULL: nowhere. Returns VSPH_OK or a failure that ends the test. */
  int (*save)(void *ctx, const unsigned char *state, size_t len);
  void *save_ctx; /*!< passed to save */
  /** a state save() was given, to go on from bitwise as if never stopped
   *  (NULL: from the start); one of other settings is refused */
  const unsigned char *resume;
  size_t resume_len; /*!< its bytes */
  /* out */
  int interrupted; /*!< 1: a stop ended it at a checkpoint (save()d) */
  size_t n;        /*!< particles */
  size_t nbins;    /*!< slabs of width D0 along x (2 res) */
  double D0, W, U0, t_end, rho0, c0; /*!< the run's, material x > 0 */
  double t[8];                       /*!< the profile times reached */
  double *x;                         /*!< slab centres (nbins) */
  double *u[8];               /*!< mean u_y per slab at each profile time */
  double *dy[8];              /*!< mean displacement along y per slab */
  double nu_u[8];             /*!< nu fitted to u_y at each time */
  double nu_dy[8];            /*!< nu fitted to the control surface */
  double rms_u[8], rms_dy[8]; /*!< their RMS residuals */
  /** why a fit is not available (its nu, its RMS are NaN), or NULL: a
   *  profile narrower than one slab (sqrt(4 nu t) < D0, too early to
   *  carry information), or a fit at the end of its search range */
  const char *na_u[8], *na_dy[8];
  size_t nt;        /*!< profile times reached */
  int stable;       /*!< 0: stopped as unstable */
  double t_stop;    /*!< time reached */
  char reason[160]; /*!< why it stopped early */
  double wall_s;    /*!< run time (s) */
  size_t steps;     /*!< steps taken */
};

/** @brief The measurement's own defaults into the parameters as given
 *  (before any is read): the shear scene's Solver defaults
 *  (vsph_scene_solver_defaults: contact SPH, Wendland C2, alpha 0.5, D0 =
 *  10 nm) and, where Scene:viscous is not given, the inviscid run
 *  (Scene:viscous = 0) of Parshikov et al.'s Table 1, which measures the
 * numerical viscosity alone. @return VSPH_OK, VSPH_ENOMEM. */
VSPH_API int vsph_contact_defaults(struct vsph_params *prm);

/** @brief Run the shear scene with the "Solver" and "Scene" sections of
 *  @p prm (any scheme) and measure its viscosity: at each profile time
 *  the slab means of u_y and of each particle's unwrapped displacement,
 *  and the fitted nu of both. A fit that carries no information is NaN
 *  with its reason (na_u, na_dy). Free with vsph_contact_shear_free.
 *  @return VSPH_OK (an unstable run is a result), VSPH_EINVAL (bad
 *  parameters, or a run too short for its profiles: fewer steps than
 *  profiles, each needing a step of its own; the message names them, and
 *  nothing was run), VSPH_ENOMEM. */
VSPH_API int vsph_contact_shear_measure(struct vsph_params *prm,
                                        struct vsph_contact_shear *cs);

/** @brief Free the profiles of @p cs. */
VSPH_API void vsph_contact_shear_free(struct vsph_contact_shear *cs);

/** @brief How self-similar the shear test @p cs's profiles are (Parshikov
 *  et al.: the profiles coincide in x sqrt(t0/t)): over the profile times
 *  whose fit of nu held (finite and positive; the others left out, with
 *  their times), the spread of the fitted nu, 100 (max - min)/min %, into
 *  @p spread, and its ratio max/min's place in logarithm from 1 (the
 *  paper's law) to the ratio of the last of those times to the first (a
 *  layer that does not spread as sqrt(t): held in place, or spreading at a
 *  steady speed) into @p lean (vsph_series_log_between). Both NaN with
 *  fewer than two such times, or a NULL @p cs. */
VSPH_API void vsph_contact_self_similar(const struct vsph_contact_shear *cs,
                                        double *spread, double *lean);

#endif /* VSPH_ANALYSIS_CONTACT_H */
