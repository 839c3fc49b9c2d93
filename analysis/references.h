#ifndef VSPH_ANALYSIS_REFERENCES_H
#define VSPH_ANALYSIS_REFERENCES_H

#include <stddef.h>

/** @file references.h
 *  @brief Exact reference solutions of the free-surface scenes (THEORY.md
 *  section 6). Vortex patch: the Bessel-series solution of Eq. (6.38) of
 *  Colagrossi et al. (2011), d omega/dt = nu (omega'' + 3 omega'/r),
 *  omega'(R) = 0, from the [reconstructed] initial profile
 *  omega(r,0) = omega0 l^2 [1/(l^2 + r^2) + r^2/(l^2 + R^2)^2]. No I/O. */

/** Vortex-patch series: omega = c_0 + sum_n c_n phi_n(r) exp(-nu k_n^2 t),
 *  phi_n = 2 J_1(k_n r)/(k_n r), J_2(k_n R) = 0. */
struct vsph_references_vortex {
  double R;      /*!< patch radius (m) */
  double l2;     /*!< profile parameter l^2 (m^2) */
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
struct vsph_references_vortex *vsph_references_vortex_alloc(double R, double l2,
                                                            double omega0,
                                                            double nu,
                                                            size_t nterms);

/** @brief Free; NULL is a no-op. */
void vsph_references_vortex_free(struct vsph_references_vortex *v);

/** @brief The initial profile omega(r, 0), closed form. */
double vsph_references_vortex_initial(const struct vsph_references_vortex *v,
                                      double r);

/** @brief omega(r, t) and d omega/dr (r, t) from the series. */
void vsph_references_vortex_eval(const struct vsph_references_vortex *v,
                                 double r, double t, double *omega,
                                 double *domega_dr);

/** @brief Kinetic energy E_k = pi rho int omega^2 r^3 dr and its rate
 *  dE_k/dt = -mu int (r domega/dr)^2 dV (Eq. 6.41), per unit depth, by
 *  GSL quadrature of the series. @return VSPH_OK or VSPH_ELIB.
 *  @note Uses the object's workspace: not for concurrent calls. */
int vsph_references_vortex_energy(struct vsph_references_vortex *v, double t,
                                  double rho, double *Ek, double *dEk_dt);

/** @brief The same E_k and dE_k/dt from the series coefficients alone:
 *  by orthogonality (weight r^3) E_k = pi rho [c_0^2 R^4/4 + sum c_n^2
 *  N_n e^{-2 nu k_n^2 t}], N_n = int phi_n^2 r^3 dr, and dE_k/dt =
 *  -2 pi rho nu sum k_n^2 c_n^2 N_n e^{-2 nu k_n^2 t}. Fast; checked
 *  against the quadrature version in the tests. */
void vsph_references_vortex_energy_series(
    const struct vsph_references_vortex *v, double t, double rho, double *Ek,
    double *dEk_dt);

struct vsph_scene;
struct vsph_scene_wave;

/** @brief Lighthill's standing-wave kinetic energy (THEORY 6.3) for the
 *  wave @p w (g, A, L, nu, k, omega) at density @p rho and time @p t:
 *  E_k = (rho g A^2 L / 8) exp(-4 nu k^2 t) [1 + cos(2 omega t)]. */
double vsph_references_lighthill(const struct vsph_scene_wave *w, double rho,
                                 double t);

/** A scene's reference curve: E_k(t) and dE_k/dt(t), NaN where the scene
 *  has none (stretching square: only t = 0, exact dE_k/dt = -4 mu A0^2 L^2
 *  and E_k = rho A0^2 L^4/12). Standing wave: Lighthill's E_k(t) and its
 *  derivative, except at t = 0 where dE_k/dt is the exact viscous power of
 *  the initial potential flow, -2 rho nu k^2 g A^2 L. */
struct vsph_references_scene {
  const struct vsph_scene *scene;        /*!< borrowed */
  struct vsph_references_vortex *vortex; /*!< vortex patch only */
};

/** @brief Reference of @p sc (kept by reference until _free).
 *  NULL (after reporting) on failure. */
struct vsph_references_scene *vsph_references_scene_alloc(
    const struct vsph_scene *sc);

/** @brief Free; NULL is a no-op. */
void vsph_references_scene_free(struct vsph_references_scene *r);

/** @brief E_k and dE_k/dt of the reference at time t (NaN where none).
 *  @return VSPH_OK or VSPH_ELIB. */
int vsph_references_scene_eval(struct vsph_references_scene *r, double t,
                               double *Ek, double *dEk_dt);

/** @brief The reference's mechanical (wave) energy E_m(t) and its rate
 *  dE_m/dt, which the viscous power must match (NaN where none). Standing
 *  wave: Lighthill's phase-free envelope E_m = (rho g A^2 L / 4)
 *  exp(-4 nu k^2 t), dE_m/dt = -4 nu k^2 E_m, the energy the wave has left
 *  whatever its phase; vortex patch: its E_k (its body-force potential
 *  energy stays constant while the disc stays round); stretching square:
 *  t = 0 only (E_k and the exact viscous power).
 *  @return VSPH_OK or VSPH_ELIB. */
int vsph_references_scene_mech(struct vsph_references_scene *r, double t,
                               double *Em, double *dEm_dt);

#endif /* VSPH_ANALYSIS_REFERENCES_H */
