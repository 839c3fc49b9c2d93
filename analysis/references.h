/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
#ifndef VSPH_ANALYSIS_REFERENCES_H
#define VSPH_ANALYSIS_REFERENCES_H

#include <stddef.h>

#include "../common/api.h"

/** @file references.h
 *  @brief Exact reference solutions of the free-surface scenes (THEORY.md
 *  section 6). Vortex patch: the Bessel-series solution of Eq. (6.38) of
 *  Colagrossi et al. (2011), d omega/dt = nu (omega'' + 3 omega'/r),
 *  omega'(R) = 0, from the [reconstructed] initial profile
 *  omega(r,0) = omega0 [1 - a + a l^2 (1/(l^2 + r^2) + r^2/(l^2 + R^2)^2)]
 *  (vsph_vortex_patch_omega). No I/O. */

/** Vortex-patch series: omega = c_0 + sum_n c_n phi_n(r) exp(-nu k_n^2 t),
 *  phi_n = 2 J_1(k_n r)/(k_n r), J_2(k_n R) = 0. */
struct vsph_references_vortex {
  double R;      /*!< patch radius (m) */
  double l2;     /*!< profile parameter l^2 (m^2) */
  double a;      /*!< the profile's weight over a rigid rotation */
  double omega0; /*!< angular velocity at the centre (rad/s) */
  double nu;     /*!< kinematic viscosity (m^2/s) */
  size_t nterms; /*!< series terms beyond c_0 */
  double c0;     /*!< final rigid rotation omega_inf (rad/s) */
  double *k;     /*!< k_n (1/m), n = 1..nterms at k[n-1] */
  double *c;     /*!< c_n (rad/s) */
  double *norm;  /*!< int_0^R phi_n^2 r^3 dr (m^4) */
  void *ws;      /*!< private quadrature workspace */
};

/** @brief Build the series: zeros of J_2 (gsl_sf_bessel_zero_Jnu) and the
 *  coefficients c_n = int omega(r,0) phi_n r^3 dr / int phi_n^2 r^3 dr by
 *  GSL quadrature. NULL (after reporting) on bad values or failure. */
VSPH_API struct vsph_references_vortex *vsph_references_vortex_alloc(
    double R, double l2, double a, double omega0, double nu, size_t nterms);

/** @brief Free; NULL is a no-op. */
VSPH_API void vsph_references_vortex_free(struct vsph_references_vortex *v);

/** @brief The initial profile omega(r, 0), closed form. */
VSPH_API double vsph_references_vortex_initial(
    const struct vsph_references_vortex *v, double r);

/** @brief omega(r, t) and d omega/dr (r, t) from the series. */
VSPH_API void vsph_references_vortex_eval(
    const struct vsph_references_vortex *v, double r, double t, double *omega,
    double *domega_dr);

/** @brief Kinetic energy E_k = pi rho int omega^2 r^3 dr and its rate
 *  dE_k/dt = -mu int (r domega/dr)^2 dV (Eq. 6.41), per unit depth, by
 *  GSL quadrature of the series. @return VSPH_OK or VSPH_ELIB.
 *  @note Uses the object's workspace: not for concurrent calls. */
VSPH_API int vsph_references_vortex_energy(struct vsph_references_vortex *v,
                                           double t, double rho, double *Ek,
                                           double *dEk_dt);

/** @brief The same E_k and dE_k/dt from the series coefficients alone:
 *  by orthogonality (weight r^3) E_k = pi rho [c_0^2 R^4/4 + sum c_n^2
 *  N_n e^{-2 nu k_n^2 t}], N_n = int phi_n^2 r^3 dr, and dE_k/dt =
 *  -2 pi rho nu sum k_n^2 c_n^2 N_n e^{-2 nu k_n^2 t}. Fast; checked
 *  against the quadrature version in the tests. */
VSPH_API void vsph_references_vortex_energy_series(
    const struct vsph_references_vortex *v, double t, double rho, double *Ek,
    double *dEk_dt);

struct vsph_scene;
struct vsph_scene_wave;
struct vsph_scene_channel;
struct vsph_scene_cavity;
struct vsph_particles;
struct vsph_kernel_type;

/** @brief Poiseuille start-up from rest (Basa et al. 2009, eq. 36 with its
 *  sign corrected; docs/theory.md, section 9): the velocity U(y, t) at
 *  height @p y above the lower wall of a channel of width @p W, kinematic
 *  viscosity @p nu, steady centreline speed @p U0, d = W/2, yc = y - d:
 *  U/U0 = 1 - (yc/d)^2 - (32/pi^3) sum_n (-1)^n/(2n+1)^3
 *  cos((2n+1) pi yc/(2d)) exp(-(2n+1)^2 pi^2 nu t/(4 d^2)), and dU/dt
 *  into @p dudt (may be NULL). Terms are summed until they fall below
 *  1e-17 U0. Below nu t/W^2 = 0.05, where that series needs ever more
 *  terms (a million at t = 1e-300), the same solution by the method of
 *  images: U = g t - sum_n (-1)^n [V(y + n W) + V((n + 1) W - y)], V(s) =
 *  4 g t i^2erfc(s/(2 sqrt(nu t))), g = 2 nu U0/d^2, a few terms at any t;
 *  the two agree to rounding where they meet. At t = 0 the exact values
 *  U = 0, dU/dt = 2 nu U0/d^2. */
VSPH_API double vsph_references_poiseuille(double y, double t, double W,
                                           double nu, double U0, double *dudt);

/** @brief Couette start-up (Morris et al. 1997, eq. 23 of Zheng et al.):
 *  the wall y = W moves at @p v0 from t = 0:
 *  U = v0 y/W + sum_{n>=1} (2 v0/(n pi)) (-1)^n sin(n pi y/W)
 *  exp(-n^2 pi^2 nu t/W^2), and dU/dt into @p dudt (may be NULL); below
 *  nu t/W^2 = 0.05 by images, U = v0 sum_n [erfc(((2n+1) W - y)/s) -
 *  erfc(((2n+1) W + y)/s)], s = 2 sqrt(nu t). At t = 0: U = 0 below the
 *  wall (dU/dt is singular there: NaN). */
VSPH_API double vsph_references_couette(double y, double t, double W, double nu,
                                        double v0, double *dudt);

/** @brief The channel's reference velocity U(y, t) (Poiseuille or
 *  Couette by @p ch), and dU/dt into @p dudt (may be NULL). */
VSPH_API double vsph_references_channel(const struct vsph_scene_channel *ch,
                                        double y, double t, double *dudt);

/** Velocity-profile errors of a channel run against its series. */
struct vsph_references_profile_err {
  double rms;     /*!< sqrt(mean (u_i - U(y_i))^2) / U (U0 or v0) */
  double rms_rel; /*!< Basa et al.'s eq. (38): sqrt(mean ((u_i - U)/U)^2),
                       ill-conditioned near the walls and at start-up; NaN
                       where U(y_i) = 0 (t = 0) */
  double v_rms;   /*!< sqrt(mean v_i^2) / U: transverse agitation */
};

/** @brief The errors of the fluid particles (ids < @p n_fluid) of @p p at
 *  time @p t against the channel's series; NaN for every field when the
 *  scene @p sc is not a channel. */
VSPH_API void vsph_references_profile_error(
    const struct vsph_scene *sc, const struct vsph_particles *p, size_t n_fluid,
    double t, struct vsph_references_profile_err *e);

/** @brief The velocity profile binned into @p nb rows across the channel:
 *  per bin the mean y, mean u_x, the series at that mean y and the count
 *  (bins with no particle: y the bin centre, u NaN).
 *  @return VSPH_OK, or VSPH_EINVAL when @p sc is not a channel. */
VSPH_API int vsph_references_profile_bins(const struct vsph_scene *sc,
                                          const struct vsph_particles *p,
                                          size_t n_fluid, double t, size_t nb,
                                          double *y, double *u, double *U,
                                          size_t *count);

/** The row-to-row oscillation of a binned profile, apart from its smooth
 *  error: per interior bin k, the second difference of the error
 *  e = u - U, z_k = (2 e_k - e_{k-1} - e_{k+1}) / 4, which is A for an
 *  alternating error A (-1)^k, vanishes for an error linear in k (a slip,
 *  a tilt) and is -q/2 for a parabola q k^2 (the smooth error's share,
 *  O(dx^2) on a resolved profile). */
struct vsph_references_zigzag {
  double rms;   /*!< sqrt(mean z_k^2) over @p scale */
  double max;   /*!< max |z_k| over @p scale */
  double y_max; /*!< the y of that bin */
  size_t n;     /*!< the bins counted (0: none; rms, max NaN) */
};

/** @brief The zigzag of the profile @p y, @p u, @p U (@p nb bins, as
 *  vsph_references_profile_bins writes them; a triple with a NaN u or U is left
 *  out), over @p scale (the peak speed). */
VSPH_API void vsph_references_profile_zigzag(const double *y, const double *u,
                                             const double *U, size_t nb,
                                             double scale,
                                             struct vsph_references_zigzag *z);

/** Ghia, Ghia & Shin (1982), Tables I and II: the steady lid-driven
 *  cavity's u on the vertical centreline x = L/2 at heights y, and v on the
 *  horizontal centreline y = L/2 at abscissae x, over L and U, 17 points
 *  each, the walls included (published data, carried over as printed). */
struct vsph_references_ghia {
  const double *y, *u; /*!< Table I: y/L, u/U */
  const double *x, *v; /*!< Table II: x/L, v/U */
  size_t n;            /*!< points per line (17) */
};

/** @brief Ghia et al.'s profiles at Reynolds number @p Re into @p g.
 *  @return 1 for Re = 100, 400 or 1000 (to 1e-9), else 0 (g untouched). */
VSPH_API int vsph_references_ghia(double Re, struct vsph_references_ghia *g);

/** @brief The distance of a fluid at rest from Ghia et al.'s profiles at
 *  @p Re, as vsph_references_cavity_error measures a cavity's (the RMS of
 *  their 15 + 15 interior centreline values, in units of U): the start of
 *  every cavity run, the figure a claim weighs "approaches Ghia" against.
 *  NaN where they have no table for @p Re. */
VSPH_API double vsph_references_ghia_rest(double Re);

/** @brief The fluid's velocity at @p x by the Shepard average with kernel
 *  @p k of smoothing length @p h: u = sum_i W_i u_i / sum_i W_i over the
 *  fluid particles (id < n_fluid), NaN where none is within reach. */
VSPH_API void vsph_references_shepard(const struct vsph_particles *p,
                                      size_t n_fluid,
                                      const struct vsph_kernel_type *k,
                                      double h, const double x[3], double u[3]);

/** @brief Point @p q of Ghia et al.'s centreline @p line of the cavity
 *  @p cv (0: u on x = L/2 at their y_q; 1: v on y = L/2 at their x_q):
 *  the SPH velocity there (vsph_references_shepard) into @p sph and
 *  their value into @p ref (m/s). @return the point's position along the
 *  line (m). */
VSPH_API double vsph_references_cavity_point(
    const struct vsph_scene_cavity *cv, const struct vsph_references_ghia *g,
    int line, size_t q, const struct vsph_particles *p, size_t n_fluid,
    const struct vsph_kernel_type *k, double h, double *sph, double *ref);

/** @brief The cavity's distance from Ghia et al. at its Re: the velocity
 *  (Shepard average, vsph_references_shepard) at their interior points of
 *  both centrelines (15 + 15, the walls' own values left out), against
 *  their values, in units of U: e->rms the RMS, e->rms_rel the largest,
 *  e->v_rms NaN. All NaN when the scene is not the cavity or Ghia et al.
 *  have no table for its Re. */
VSPH_API void vsph_references_cavity_error(
    const struct vsph_scene *sc, const struct vsph_particles *p, size_t n_fluid,
    const struct vsph_kernel_type *k, double h,
    struct vsph_references_profile_err *e);

/** @brief Zheng et al.'s cavity metric (their Fig. 10), |u_min - u_min,Ghia|
 *  over U: the smallest u on the vertical centreline against Ghia et al.'s
 *  (the smallest of their Table I at @p Re), per output time, from a
 *  centreline table as runs/ writes it (centreline.csv: per time, the
 *  @p npts points of u(y) first, then as many of v(x); columns t and vel,
 *  @p n rows). The times into @p t_out and the errors into @p err (at most
 *  @p cap). @return the number of times, 0 when Ghia et al. have no table
 *  for @p Re or a time's block is not whole. */
VSPH_API size_t vsph_references_cavity_umin(const double *t, const double *vel,
                                            size_t n, size_t npts, double Re,
                                            double *t_out, double *err,
                                            size_t cap);

/** @brief The RMS distance of a cavity's centrelines from Ghia et al.'s
 *  at @p Re (their interior points, 15 + 15, as
 *  vsph_references_cavity_error takes them), per output time, from a
 *  centreline table as vsph_references_cavity_umin reads it (@p npts = 17
 *  points of u(y), then of v(x), at their positions, which their tables
 *  share at every Re): a run's distance from another Re's flow than its
 *  own. In units of the lid speed @p U (the table's velocities over it).
 *  The times into @p t_out and the
 *  distances into @p err (at most @p cap). @return the number of times, 0
 *  when Ghia et al. have no table for @p Re, @p npts is not theirs, @p U
 *  is not positive and finite or a time's block is not whole. */
VSPH_API size_t vsph_references_cavity_rms(const double *t, const double *vel,
                                           size_t n, size_t npts, double Re,
                                           double U, double *t_out, double *err,
                                           size_t cap);

/** @brief The exact decay of a small standing (or progressive) gravity
 *  wave of wavenumber @p k on water of depth @p H, kinematic viscosity
 *  @p nu, gravity @p g, by linear viscous theory (Lamb 1932, art. 349):
 *  the root s = -gamma + i omega of (s + 2 nu k^2)^2 + omega0^2 =
 *  4 nu^2 k^3 sqrt(k^2 + s/nu), omega0^2 = g k tanh(kH) (the deep-water
 *  relation with the finite depth's inviscid frequency: a free-slip bottom
 *  at kH = pi changes it by about e^{-2 kH}), found by Newton's method from
 *  Lighthill's s = -2 nu k^2 + i omega0. Its energy decays as e^{-2 gamma
 *  t}; Lighthill's leading order is gamma = 2 nu k^2, and the next term,
 *  -(2 nu k^2)(nu k^2/omega0)^{1/2}/sqrt 2, is 6 % of it at the standing
 *  wave's Re = 140 and eps = 0.05 (docs/theory.md section 6).
 *  @return VSPH_OK, VSPH_EINVAL (a value not positive, nu < 0),
 *  VSPH_ENOCONV (Newton's method did not converge to 1e-14). */
VSPH_API int vsph_references_wave_decay(double g, double k, double H, double nu,
                                        double *gamma, double *omega);

/** @brief Lighthill's standing-wave kinetic energy (THEORY 6.3) for the
 *  wave @p w (g, A, L, nu, k, omega) at density @p rho and time @p t:
 *  E_k = (rho g A^2 L / 8) exp(-4 nu k^2 t) [1 + cos(2 omega t)]. */
VSPH_API double vsph_references_lighthill(const struct vsph_scene_wave *w,
                                          double rho, double t);

/** A scene's reference curve: E_k(t) and dE_k/dt(t), NaN where the scene
 *  has none (channels: (rho/2) length int U^2 dy by 64-point
 *  Gauss-Legendre quadrature of the series) (stretching square: only t = 0,
 * exact dE_k/dt = -4 mu A0^2 L^2 and E_k = rho A0^2 L^4/12). Standing wave:
 * Lighthill's E_k(t) and its derivative, except at t = 0 where dE_k/dt is the
 * exact viscous power of the initial potential flow, -2 rho nu k^2 g A^2 L. */
struct vsph_references_scene {
  const struct vsph_scene *scene;        /*!< borrowed */
  struct vsph_references_vortex *vortex; /*!< vortex patch only */
  void *gl; /*!< channels: their gsl_integration_glfixed_table */
};

/** @brief Reference of @p sc (kept by reference until _free).
 *  NULL (after reporting) on failure. */
VSPH_API struct vsph_references_scene *vsph_references_scene_alloc(
    const struct vsph_scene *sc);

/** @brief Free; NULL is a no-op. */
VSPH_API void vsph_references_scene_free(struct vsph_references_scene *r);

/** @brief E_k and dE_k/dt of the reference at time t (NaN where none).
 *  @return VSPH_OK or VSPH_ELIB. */
VSPH_API int vsph_references_scene_eval(struct vsph_references_scene *r,
                                        double t, double *Ek, double *dEk_dt);

/** @brief The reference's mechanical (wave) energy E_m(t) and its rate
 *  dE_m/dt, which the viscous power must match (NaN where none). Standing
 *  wave: Lighthill's phase-free envelope E_m = (rho g A^2 L / 4)
 *  exp(-4 nu k^2 t), dE_m/dt = -4 nu k^2 E_m, the energy the wave has left
 *  whatever its phase; vortex patch: its E_k (its body-force potential
 *  energy stays constant while the disc stays round); stretching square:
 *  t = 0 only (E_k and the exact viscous power); channels: their E_k.
 *  @return VSPH_OK or VSPH_ELIB. */
VSPH_API int vsph_references_scene_mech(struct vsph_references_scene *r,
                                        double t, double *Em, double *dEm_dt);

#endif /* VSPH_ANALYSIS_REFERENCES_H */
