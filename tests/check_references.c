/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
#include <complex.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>
#include <gsl/gsl_odeiv2.h>
#include <gsl/gsl_sf_bessel.h>
#include <math.h>
#include <stdlib.h>

#include "../analysis/references.h"
#include "../common/consts.h"
#include "../common/params.h"
#include "../common/status.h"
#include "../kernels/kernel.h"
#include "../solver/particles.h"
#include "../solver/scene.h"
#include "check_suites.h"

/* THEORY 6.1 defaults: R = 1, l^2 = 0.1, the weight a, omega0 = 1,
 * nu = 1e-3. */
static struct vsph_references_vortex *paper(size_t nterms) {
  struct vsph_references_vortex *v = vsph_references_vortex_alloc(
      1.0, 0.1, VSPH_VORTEX_PATCH_A, 1.0, 1e-3, nterms);
  ck_assert_ptr_nonnull(v);
  return v;
}

/* c_0 = 4 int omega r^3 dr / R^4 in closed form, for omega = omega0 [1 -
 * a + a g(r)], g = l^2 [1/(l^2 + r^2) + r^2/(l^2 + R^2)^2]:
 * int g r^3 dr = (l^2/2)(R^2 - l^2 ln((l^2 + R^2)/l^2)) +
 * l^2 R^6 / (6 (l^2 + R^2)^2), so c_0 = 1 - a + a (4/R^4) that.
 * The reconstruction of (6.39) must meet every fact the paper states, each
 * within 0.5 % (the tolerance; the paper's own figures are given to
 * 3 and 4 digits): omega(0) = omega0 = 1 rad/s, d omega/dr = 0 at R = 1,
 * Re = R u_theta(R, 0)/nu = 256, omega_inf = 0.2848 omega0; and the weight
 * is the minimax one, both figures off by the same 0.27 % in opposite
 * directions (to the 5 digits the weight is given: 1e-4). a = 1 is the
 * earlier profile: omega_inf 0.2071, Re 173.55 (THEORY's first reading). */
START_TEST(test_final_rotation) {
  const double l2 = 0.1, R = 1.0, L = l2 + R * R;
  const double gbar =
      4.0 *
      (0.5 * l2 * (R * R - l2 * log(L / l2)) + l2 * pow(R, 6) / (6.0 * L * L)) /
      pow(R, 4);
  const double as[2] = {VSPH_VORTEX_PATCH_A, 1.0};
  for (int m = 0; m < 2; m++) {
    struct vsph_references_vortex *v =
        vsph_references_vortex_alloc(R, l2, as[m], 1.0, 1e-3, 10);
    ck_assert_ptr_nonnull(v);
    const double want = 1.0 - as[m] + as[m] * gbar;
    ck_assert_double_eq_tol(v->c0, want, 1e-12); /* quadrature at 1e-12 */
    const double Re = R * R * vsph_references_vortex_initial(v, R) / 1e-3;
    ck_assert_double_eq(vsph_references_vortex_initial(v, 0.0), 1.0);
    /* d omega/dr at R by a centred difference (error O(e^2) ~ 1e-12) */
    const double e = 1e-6;
    const double dw = (vsph_references_vortex_initial(v, R + e) -
                       vsph_references_vortex_initial(v, R - e)) /
                      (2 * e);
    ck_assert_double_lt(fabs(dw), 1e-9);
    if (m == 0) {
      const double eRe = Re / 256.0 - 1.0, ew = v->c0 / 0.2848 - 1.0;
      ck_assert_double_lt(fabs(eRe), 0.005);
      ck_assert_double_lt(fabs(ew), 0.005);
      ck_assert_double_lt(fabs(eRe + ew), 1e-4);
    } else {
      ck_assert_double_eq_tol(v->c0, 0.2071, 5e-5);
      ck_assert_double_eq_tol(Re, 173.55, 0.01);
    }
    vsph_references_vortex_free(v);
  }
}
END_TEST

/* The series reproduces the initial profile; its error falls as terms are
 * added (coefficients decay algebraically, c_n ~ n^-2.5). Measured max
 * error: 6.2e-7 with 50 terms, 2.0e-8 with 200, 3.7e-9 with 400. */
START_TEST(test_series_initial) {
  double err[2];
  const size_t terms[2] = {50, 200};
  for (int m = 0; m < 2; m++) {
    struct vsph_references_vortex *v = paper(terms[m]);
    err[m] = 0.0;
    for (double r = 0.0; r <= 1.0; r += 0.0137) {
      double w;
      vsph_references_vortex_eval(v, r, 0.0, &w, NULL);
      err[m] = fmax(err[m], fabs(w - vsph_references_vortex_initial(v, r)));
    }
    vsph_references_vortex_free(v);
  }
  ck_assert_double_lt(err[1], 1e-7);
  ck_assert_double_lt(err[1], 0.1 * err[0]);
}
END_TEST

/* Angular momentum 2 pi rho int omega r^3 dr is conserved (zero stress at
 * R): every phi_n is orthogonal to the constant. */
static double am_integrand(double r, void *p) {
  double w;
  vsph_references_vortex_eval(p, r, 7.31, &w, NULL);
  return w * r * r * r;
}
START_TEST(test_angular_momentum) {
  struct vsph_references_vortex *v = paper(60);
  gsl_integration_workspace *ws = gsl_integration_workspace_alloc(200);
  gsl_function f = {am_integrand, v};
  double res, err;
  ck_assert_int_eq(gsl_integration_qag(&f, 0, 1, 0, 1e-12, 200,
                                       GSL_INTEG_GAUSS61, ws, &res, &err),
                   0);
  /* the truncated series keeps it to the quadrature accuracy */
  ck_assert_double_eq_tol(res, v->c0 / 4.0, 1e-11);
  gsl_integration_workspace_free(ws);
  vsph_references_vortex_free(v);
}
END_TEST

/* Method of lines, independent of the series: second-order differences of
 * omega'' + 3 omega'/r on r_i = i dr (omega_{-1} = omega_1 at the axis,
 * where the operator is 4 omega''; omega_{M+1} = omega_{M-1} at R),
 * integrated with GSL's rk8pd at 1e-10. */
struct mol {
  size_t M;
  double dr, nu;
};
static int mol_rhs(double t, const double *w, double *f, void *p) {
  (void)t;
  const struct mol *m = p;
  const double idr2 = 1.0 / (m->dr * m->dr);
  f[0] = m->nu * 8.0 * (w[1] - w[0]) * idr2;
  for (size_t i = 1; i < m->M; i++) {
    const double r = (double)i * m->dr;
    f[i] = m->nu * ((w[i + 1] - 2 * w[i] + w[i - 1]) * idr2 +
                    3.0 / r * (w[i + 1] - w[i - 1]) / (2 * m->dr));
  }
  f[m->M] = m->nu * 2.0 * (w[m->M - 1] - w[m->M]) * idr2;
  return GSL_SUCCESS;
}

static double mol_error(const struct vsph_references_vortex *v, size_t M,
                        double tend) {
  struct mol m = {M, 1.0 / (double)M, v->nu};
  double *w = malloc((M + 1) * sizeof *w);
  for (size_t i = 0; i <= M; i++)
    w[i] = vsph_references_vortex_initial(v, (double)i * m.dr);
  gsl_odeiv2_system sys = {mol_rhs, NULL, M + 1, &m};
  gsl_odeiv2_driver *d = gsl_odeiv2_driver_alloc_y_new(
      &sys, gsl_odeiv2_step_rk8pd, 1e-3, 1e-10, 1e-10);
  double t = 0.0;
  ck_assert_int_eq(gsl_odeiv2_driver_apply(d, &t, tend, w), GSL_SUCCESS);
  gsl_odeiv2_driver_free(d);
  double err = 0.0;
  for (size_t i = 0; i <= M; i++) {
    double ws;
    vsph_references_vortex_eval(v, (double)i * m.dr, tend, &ws, NULL);
    err = fmax(err, fabs(ws - w[i]));
  }
  free(w);
  return err;
}

/* The MOL solution converges to the series at second order: measured max
 * errors at t = 10 s are 4.80e-4, 1.20e-4, 3.00e-5, 7.49e-6 for M = 50,
 * 100, 200, 400, a ratio of 4.00 per halving of dr; tol 3.8-4.2. The
 * series (200 terms, error 2e-8) is far more accurate than either. */
START_TEST(test_series_vs_mol) {
  struct vsph_references_vortex *v = paper(200);
  const double e1 = mol_error(v, 50, 10.0), e2 = mol_error(v, 100, 10.0);
  ck_assert_double_gt(e1 / e2, 3.8);
  ck_assert_double_lt(e1 / e2, 4.2);
  ck_assert_double_lt(e2, 2e-4);
  vsph_references_vortex_free(v);
}
END_TEST

/* dE_k/dt (Eq. 6.41) against a centred difference of E_k in time:
 * error ~ dt^2 E''' / 6, below 1e-8 relative for dt = 1e-2. */
START_TEST(test_energy_rate) {
  struct vsph_references_vortex *v = paper(100);
  const double t = 3.7, dt = 1e-2;
  double Ea, Eb, E, dE, dummy;
  ck_assert_int_eq(vsph_references_vortex_energy(v, t - dt, 1.0, &Ea, &dummy),
                   0);
  ck_assert_int_eq(vsph_references_vortex_energy(v, t + dt, 1.0, &Eb, &dummy),
                   0);
  ck_assert_int_eq(vsph_references_vortex_energy(v, t, 1.0, &E, &dE), 0);
  ck_assert_double_lt(dE, 0.0);
  ck_assert_double_eq_tol((Eb - Ea) / (2 * dt), dE, 1e-6 * fabs(dE));
  /* the orthogonality shortcut agrees with the quadrature of the series
   * (both from the same 100 terms; quadrature at 1e-12) */
  double Es, dEs;
  vsph_references_vortex_energy_series(v, t, 1.0, &Es, &dEs);
  ck_assert_double_eq_tol(Es, E, 1e-10 * E);
  ck_assert_double_eq_tol(dEs, dE, 1e-9 * fabs(dE));
  vsph_references_vortex_free(v);
}
END_TEST

/* Lighthill at t = 0 against the kinetic energy of the potential-flow
 * initial velocity, integrated over the tank by nested GSL quadrature:
 * (1/2) rho int |grad phi0|^2 = rho g A^2 L / 4. */
struct wave {
  struct vsph_scene_wave sw; /* A, g, k, L = H, omega */
  double x;
  gsl_integration_workspace *wi;
};
static double wave_inner(double y, void *p) {
  const struct wave *w = p;
  double u[2];
  vsph_standing_wave_velocity(&w->sw, w->x, y, u);
  return 0.5 * (u[0] * u[0] + u[1] * u[1]);
}
static double wave_outer(double x, void *p) {
  struct wave *w = p;
  w->x = x;
  gsl_function f = {wave_inner, w};
  double res, err;
  gsl_integration_qag(&f, -w->sw.L, 0.0, 0, 1e-12, 200, GSL_INTEG_GAUSS61,
                      w->wi, &res, &err);
  return res;
}
START_TEST(test_lighthill_initial) {
  const double lambda = 2.0, L = lambda / 2, H = L, g = 9.81;
  const double k = 2 * VSPH_PI / lambda, A = 0.05 * lambda / 2;
  const double om = sqrt(g * k * tanh(k * H));
  struct wave w = {.sw = {.A = A, .g = g, .k = k, .L = H, .omega = om},
                   .x = 0.0,
                   .wi = gsl_integration_workspace_alloc(200)};
  gsl_integration_workspace *wo = gsl_integration_workspace_alloc(200);
  gsl_function f = {wave_outer, &w};
  double Ek, err;
  ck_assert_int_eq(gsl_integration_qag(&f, 0.0, L, 0, 1e-11, 200,
                                       GSL_INTEG_GAUSS61, wo, &Ek, &err),
                   0);
  const struct vsph_scene_wave sw = {
      .g = g, .A = A, .L = L, .nu = 1e-3, .k = k, .omega = om};
  const double want = vsph_references_lighthill(&sw, 1.0, 0.0);
  ck_assert_double_eq_tol(Ek, want, 1e-9 * want);
  ck_assert_double_eq_tol(want, g * A * A * L / 4.0, 1e-15);
  gsl_integration_workspace_free(wo);
  gsl_integration_workspace_free(w.wi);
}
END_TEST

/* The closed-form normalisation 2 R^2 J_1(kR)^2/k^2 against quadrature. */
static double phi2_r3(double r, void *p) {
  const double x = *(const double *)p * r;
  const double f = 2.0 * gsl_sf_bessel_J1(x) / x;
  return f * f * r * r * r;
}
START_TEST(test_norm_closed_form) {
  struct vsph_references_vortex *v = paper(30);
  gsl_integration_workspace *ws = gsl_integration_workspace_alloc(200);
  for (size_t n = 0; n < 30; n += 7) {
    gsl_function f = {phi2_r3, &v->k[n]};
    double res, err;
    gsl_integration_qag(&f, 1e-9, 1.0, 0, 1e-12, 200, GSL_INTEG_GAUSS61, ws,
                        &res, &err);
    ck_assert_double_eq_tol(v->norm[n], res, 1e-10 * res);
  }
  gsl_integration_workspace_free(ws);
  vsph_references_vortex_free(v);
}
END_TEST

/* The standing wave's exact initial viscous power -2 mu int D:D, from the
 * scene's reference, against a quadrature of 2 mu D:D with D from centred
 * differences of the initial velocity (step 1e-5: error ~1e-10). */
static double dd_inner(double y, void *p) {
  const struct wave *w = p;
  const double e = 1e-5;
  double a[2], b[2], c[2], d[2];
  vsph_standing_wave_velocity(&w->sw, w->x + e, y, a);
  vsph_standing_wave_velocity(&w->sw, w->x - e, y, b);
  vsph_standing_wave_velocity(&w->sw, w->x, y + e, c);
  vsph_standing_wave_velocity(&w->sw, w->x, y - e, d);
  const double ux = (a[0] - b[0]) / (2 * e), vy = (c[1] - d[1]) / (2 * e);
  const double uy = (c[0] - d[0]) / (2 * e), vx = (a[1] - b[1]) / (2 * e);
  const double dxy = 0.5 * (uy + vx);
  return ux * ux + vy * vy + 2 * dxy * dxy;
}
static double dd_outer(double x, void *p) {
  struct wave *w = p;
  w->x = x;
  gsl_function f = {dd_inner, w};
  double res, err;
  gsl_integration_qag(&f, -w->sw.L, 0.0, 0, 1e-10, 200, GSL_INTEG_GAUSS61,
                      w->wi, &res, &err);
  return res;
}
START_TEST(test_wave_initial_power) {
  struct vsph_params *prm = vsph_params_alloc();
  struct vsph_scene sc;
  ck_assert_int_eq(vsph_scene_init(&sc, &vsph_standing_wave_type, prm), 0);
  vsph_params_free(prm);
  struct vsph_references_scene *ref = vsph_references_scene_alloc(&sc);
  double Ek, dEk;
  ck_assert_int_eq(vsph_references_scene_eval(ref, 0.0, &Ek, &dEk), 0);
  vsph_references_scene_free(ref);
  struct wave w = {
      .sw = sc.u.wave, .x = 0.0, .wi = gsl_integration_workspace_alloc(200)};
  gsl_integration_workspace *wo = gsl_integration_workspace_alloc(200);
  gsl_function f = {dd_outer, &w};
  double DD, err;
  gsl_integration_qag(&f, 0.0, sc.ref_length, 0, 1e-9, 200, GSL_INTEG_GAUSS61,
                      wo, &DD, &err);
  gsl_integration_workspace_free(wo);
  gsl_integration_workspace_free(w.wi);
  const double want = -2.0 * sc.mu * DD;
  ck_assert_double_eq_tol(dEk, want, 1e-7 * fabs(want));
  /* and it is -8 nu k^2 E_k(0): twice the envelope's slope */
  const struct vsph_scene_wave *sw = &sc.u.wave;
  ck_assert_double_eq_tol(dEk, -8.0 * sw->nu * sw->k * sw->k * Ek,
                          1e-12 * fabs(dEk));
}
END_TEST

/* The wave's mechanical reference is Lighthill's envelope: at t = 0 all
 * of the wave's energy is kinetic (flat surface), so E_m(0) = E_k,ref(0);
 * E_m >= E_k,ref always, with equality at the kinetic peaks
 * (cos 2 omega t = 1); dE_m/dt = -4 nu k^2 E_m (its definition, checked
 * against a centred difference of E_m, truncation O(dt^2) ~ 1e-10). */
START_TEST(test_wave_mech) {
  struct vsph_params *prm = vsph_params_alloc();
  struct vsph_scene sc;
  ck_assert_int_eq(vsph_scene_init(&sc, &vsph_standing_wave_type, prm), 0);
  vsph_params_free(prm);
  struct vsph_references_scene *ref = vsph_references_scene_alloc(&sc);
  const struct vsph_scene_wave *w = &sc.u.wave;
  double Ek, dEk, Em, dEm;
  ck_assert_int_eq(vsph_references_scene_eval(ref, 0.0, &Ek, &dEk), 0);
  ck_assert_int_eq(vsph_references_scene_mech(ref, 0.0, &Em, &dEm), 0);
  ck_assert_double_eq_tol(Em, Ek, 1e-14 * Ek);
  for (int k = 1; k <= 40; k++) {
    const double t = 0.137 * k;
    vsph_references_scene_eval(ref, t, &Ek, &dEk);
    vsph_references_scene_mech(ref, t, &Em, &dEm);
    ck_assert_double_le(Ek, Em * (1 + 1e-14));
    double a, b, da, db;
    const double h = 1e-4;
    vsph_references_scene_mech(ref, t + h, &a, &da);
    vsph_references_scene_mech(ref, t - h, &b, &db);
    ck_assert_double_eq_tol(dEm, (a - b) / (2 * h), 1e-8 * fabs(dEm));
  }
  const double tp = VSPH_PI / w->omega; /* a kinetic peak */
  vsph_references_scene_eval(ref, tp, &Ek, &dEk);
  vsph_references_scene_mech(ref, tp, &Em, &dEm);
  ck_assert_double_eq_tol(Ek, Em, 1e-12 * Em);
  vsph_references_scene_free(ref);
}
END_TEST

START_TEST(test_vortex_bad_args_refused) {
  vsph_test_silence();
  ck_assert_ptr_null(vsph_references_vortex_alloc(-1.0, 0.1, 1, 1, 1e-3, 5));
  ck_assert_ptr_null(vsph_references_vortex_alloc(1.0, 0.1, 1, 1, 1e-3, 0));
  ck_assert_ptr_null(vsph_references_vortex_alloc(1.0, 0.1, NAN, 1, 1e-3, 5));
}
END_TEST

/* Zheng et al.'s u_min metric on a table made by hand: two times of
 * 3 + 3 rows (u(y) first); Ghia et al.'s smallest u at Re 1000 is
 * -0.38289 (their Table I, y = 0.1719), so u rows {0.1, -0.30, 0.2} give
 * |-0.30 + 0.38289| = 0.08289 and {-0.5, 0, 1} give 0.11711; the v rows
 * (-0.9) are not read. A torn block or an Re without a table: 0 times. */
/* A cavity at rest (its start) is as far from Ghia et al. as
 * vsph_references_ghia_rest says: vsph_references_cavity_error on a
 * 40 x 40 lattice of particles at rest in the Re = 1000 cavity (the
 * Shepard average of zero velocities is zero: each point's error is
 * their value) against the RMS of their table; the two sum in a different
 * order, so to a few roundings (1e-14). No table at Re 50: NaN. */
START_TEST(test_ghia_rest_is_a_cavity_at_rest) {
  struct vsph_params *prm = vsph_params_alloc();
  ck_assert_int_eq(vsph_params_set(prm, "Scene:Re", "1000"), 0);
  struct vsph_scene sc;
  ck_assert_int_eq(vsph_scene_init(&sc, &vsph_cavity_type, prm), 0);
  vsph_params_free(prm);
  const size_t N = 40;
  const double L = sc.u.cavity.L, dx = L / (double)N;
  struct vsph_particles *p = vsph_particles_alloc(N * N, 2);
  ck_assert_ptr_nonnull(p);
  for (size_t a = 0; a < N; a++)
    for (size_t b = 0; b < N; b++) {
      const size_t i = a * N + b;
      p->pos[0][i] = (a + 0.5) * dx;
      p->pos[1][i] = (b + 0.5) * dx;
      p->vel[0][i] = p->vel[1][i] = 0.0;
      p->id[i] = i;
    }
  p->n = N * N;
  struct vsph_references_profile_err e;
  vsph_references_cavity_error(&sc, p, p->n, vsph_kernel_find("quintic"), dx,
                               &e);
  vsph_particles_free(p);
  const double rest = vsph_references_ghia_rest(1000.0);
  /* the RMS of their 30 interior Re 1000 values, summed by hand from the
   * tables (Python, 9 digits): 0.341198916 */
  ck_assert_double_eq_tol(rest, 0.341198916, 1e-9);
  ck_assert_double_eq_tol(e.rms, rest, 1e-14);
  ck_assert(isnan(vsph_references_ghia_rest(50.0)));
}
END_TEST

/* A centreline table holding Ghia et al.'s own Re 400 values at two
 * times, for a lid at U = 2 m/s (in units of U): its distance from their Re 400
 * is 0, from their Re 1000 0.105013915 and from their Re 100 0.111641232, the
 * RMS of the tables' difference, by hand (Python over the printed tables, 9
 * digits); a torn block, another point count or an Re without a table gives 0
 * times. */
START_TEST(test_cavity_rms_between_ghia_tables) {
  struct vsph_references_ghia g;
  ck_assert(vsph_references_ghia(400.0, &g));
  double t[68], vel[68], to[2], e[2];
  for (size_t b = 0; b < 2; b++)
    for (size_t q = 0; q < 17; q++) {
      t[34 * b + q] = t[34 * b + 17 + q] = (double)b;
      vel[34 * b + q] = 2.0 * g.u[q]; /* a lid at U = 2 m/s */
      vel[34 * b + 17 + q] = 2.0 * g.v[q];
    }
  ck_assert_uint_eq(
      vsph_references_cavity_rms(t, vel, 68, 17, 400.0, 2.0, to, e, 2), 2);
  ck_assert_double_eq(e[0], 0.0);
  ck_assert_double_eq(to[1], 1.0);
  ck_assert_uint_eq(
      vsph_references_cavity_rms(t, vel, 68, 17, 1000.0, 2.0, to, e, 2), 2);
  ck_assert_double_eq_tol(e[0], 0.105013915, 1e-9);
  ck_assert_double_eq_tol(e[1], 0.105013915, 1e-9);
  ck_assert_uint_eq(
      vsph_references_cavity_rms(t, vel, 68, 17, 100.0, 2.0, to, e, 1), 1);
  ck_assert_double_eq_tol(e[0], 0.111641232, 1e-9);
  ck_assert_uint_eq(
      vsph_references_cavity_rms(t, vel, 68, 17, 400.0, 0.0, to, e, 2), 0);
  t[40] = 7.0; /* a torn second block */
  ck_assert_uint_eq(
      vsph_references_cavity_rms(t, vel, 68, 17, 400.0, 2.0, to, e, 2), 0);
  ck_assert_uint_eq(
      vsph_references_cavity_rms(t, vel, 64, 16, 400.0, 2.0, to, e, 2), 0);
  ck_assert_uint_eq(
      vsph_references_cavity_rms(t, vel, 68, 17, 50.0, 2.0, to, e, 2), 0);
}
END_TEST

START_TEST(test_cavity_umin) {
  const double t[12] = {1, 1, 1, 1, 1, 1, 2, 2, 2, 2, 2, 2};
  const double v[12] = {0.1,  -0.30, 0.2, -0.9, -0.9, -0.9,
                        -0.5, 0.0,   1.0, -0.9, -0.9, -0.9};
  double to[4], e[4];
  ck_assert_uint_eq(vsph_references_cavity_umin(t, v, 12, 3, 1000.0, to, e, 4),
                    2);
  ck_assert_double_eq(to[0], 1.0);
  ck_assert_double_eq(to[1], 2.0);
  ck_assert_double_eq_tol(e[0], 0.08289, 1e-15);
  ck_assert_double_eq_tol(e[1], 0.11711, 1e-15);
  ck_assert_uint_eq(vsph_references_cavity_umin(t, v, 12, 3, 1000.0, to, e, 1),
                    1);
  ck_assert_uint_eq(vsph_references_cavity_umin(t, v, 10, 3, 1000.0, to, e, 4),
                    0);
  ck_assert_uint_eq(vsph_references_cavity_umin(t, v, 12, 3, 50.0, to, e, 4),
                    0);
  const double torn[6] = {1, 1, 1, 1, 1, 2};
  ck_assert_uint_eq(
      vsph_references_cavity_umin(torn, v, 6, 3, 1000.0, to, e, 4), 0);
}
END_TEST

/* The profile's zigzag against hand-worked errors on 9 bins (7 interior):
 * an alternating error A (-1)^k over a slip and a tilt (both invisible to
 * the measure) gives A in every bin; a parabola q k^2 gives -q/2 in every
 * bin; a single bump B at bin 4 gives B/2 there and -B/4 beside it
 * (sqrt((1/4 + 2/16)/7) B in RMS); a NaN bin drops the triples that
 * hold it (two here: bin 0 is no centre). Exact but for rounding. */
START_TEST(test_profile_zigzag) {
  enum { NB = 9 };
  double y[NB], u[NB], U[NB];
  const double A = 0.03, q = 2e-3, B = 0.4, s = 2.0;
  struct vsph_references_zigzag z;
  for (int k = 0; k < NB; k++) {
    y[k] = 0.1 * k;
    U[k] = 1.0 - 0.05 * (k - 4) * (k - 4); /* the series: any shape */
    u[k] = U[k] + A * (k % 2 ? -1 : 1) + 0.3 + 0.01 * k;
  }
  vsph_references_profile_zigzag(y, u, U, NB, s, &z);
  ck_assert_uint_eq(z.n, NB - 2);
  ck_assert_double_eq_tol(z.rms, A / s, 1e-15);
  ck_assert_double_eq_tol(z.max, A / s, 1e-15);
  for (int k = 0; k < NB; k++) u[k] = U[k] + q * k * k;
  vsph_references_profile_zigzag(y, u, U, NB, 1.0, &z);
  ck_assert_double_eq_tol(z.rms, q / 2, 1e-15);
  for (int k = 0; k < NB; k++) u[k] = U[k] + (k == 4 ? B : 0.0);
  vsph_references_profile_zigzag(y, u, U, NB, 1.0, &z);
  ck_assert_double_eq_tol(z.max, B / 2, 1e-15);
  ck_assert_double_eq_tol(z.y_max, 0.4, 1e-15);
  ck_assert_double_eq_tol(z.rms, sqrt((0.25 + 2.0 / 16.0) / 7.0) * B, 1e-15);
  u[1] = (double)NAN;
  vsph_references_profile_zigzag(y, u, U, NB, 1.0, &z);
  ck_assert_uint_eq(z.n, NB - 2 - 2); /* bins 1 and 2 (bin 0 is no centre) */
  ck_assert_double_eq_tol(z.max, B / 2, 1e-15);
}
END_TEST

/* Lamb's viscous decay of a gravity wave: the root satisfies the relation
 * (s + 2 nu k^2)^2 + gk tanh kH = 4 nu^2 k^3 sqrt(k^2 + s/nu), checked here
 * by its own complex arithmetic (residual below 1e-12 of omega0^2); for a
 * small nu k^2/omega0 = e its rate follows the expansion gamma/(2 nu k^2)
 * = 1 - sqrt(e/2) + O(e), here at e = 1e-6 (tolerance 1e-5, a few times
 * the O(e) term); without viscosity gamma = 0 and omega = omega0; a
 * negative nu is refused. At the standing wave's Re = 140, eps = 0.05 (nu
 * = 3.9728e-3, k = pi, H = 1) the same expansion to its sqrt term gives
 * 0.9405, the root 0.9403: within the O(e) = 7e-3 of the expansion. */
START_TEST(test_wave_decay) {
  const double g = 9.81, k = VSPH_PI, H = 1.0;
  const double w0 = sqrt(g * k * tanh(k * H));
  double gamma, omega;
  const double nus[2] = {1e-6 * w0 / (k * k), 3.972760876943673e-3};
  for (int m = 0; m < 2; m++) {
    const double nu = nus[m];
    ck_assert_int_eq(vsph_references_wave_decay(g, k, H, nu, &gamma, &omega),
                     VSPH_OK);
    const double complex s = CMPLX(-gamma, omega);
    const double complex a = s + 2.0 * nu * k * k;
    const double complex res =
        a * a + w0 * w0 - 4.0 * nu * nu * k * k * k * csqrt(k * k + s / nu);
    ck_assert_double_lt(cabs(res), 1e-12 * w0 * w0);
    const double e = nu * k * k / w0;
    const double want = 1.0 - sqrt(e / 2.0);
    ck_assert_double_eq_tol(gamma / (2.0 * nu * k * k), want,
                            m == 0 ? 1e-5 : e);
  }
  ck_assert_int_eq(vsph_references_wave_decay(g, k, H, 0.0, &gamma, &omega),
                   VSPH_OK);
  ck_assert_double_eq(gamma, 0.0);
  ck_assert_double_eq_tol(omega, w0, 1e-15 * w0);
  vsph_test_silence();
  ck_assert_int_eq(vsph_references_wave_decay(g, k, H, -1.0, &gamma, &omega),
                   VSPH_EINVAL);
}
END_TEST

Suite *vsph_references_suite(void) {
  Suite *s = suite_create("references");
  TCase *tc = tcase_create("vortex");
  tcase_set_timeout(tc, 60);
  tcase_add_test(tc, test_final_rotation);
  tcase_add_test(tc, test_series_initial);
  tcase_add_test(tc, test_angular_momentum);
  tcase_add_test(tc, test_series_vs_mol);
  tcase_add_test(tc, test_energy_rate);
  tcase_add_test(tc, test_cavity_umin);
  tcase_add_test(tc, test_ghia_rest_is_a_cavity_at_rest);
  tcase_add_test(tc, test_cavity_rms_between_ghia_tables);
  tcase_add_test(tc, test_lighthill_initial);
  tcase_add_test(tc, test_wave_mech);
  tcase_add_test(tc, test_norm_closed_form);
  tcase_add_test(tc, test_wave_initial_power);
  tcase_add_test(tc, test_vortex_bad_args_refused);
  tcase_add_test(tc, test_profile_zigzag);
  tcase_add_test(tc, test_wave_decay);
  suite_add_tcase(s, tc);
  return s;
}
