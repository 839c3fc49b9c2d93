/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
#include <gsl/gsl_rng.h>
#include <math.h>
#include <omp.h>
#include <stdlib.h>
#include <string.h>

#include "../kernels/kernel.h"
#include "../solver/cells.h"
#include "../solver/lattice.h"
#include "../solver/particles.h"
#include "../solver/viscous.h"
#include "../solver/viscous_internal.h"
#include "check_suites.h"

/* A perturbed square patch (free surface all round) carrying a random
 * velocity field, in dim = 2 or 3. */
static struct vsph_particles *random_set(int dim, unsigned long seed) {
  struct vsph_lattice_props lp = {.dim = dim,
                                  .kind = VSPH_LATTICE_SQUARE,
                                  .dx = 0.05,
                                  .perturb = 0.25,
                                  .seed = seed};
  struct vsph_particles *p = NULL;
  size_t c;
  ck_assert_int_eq(
      vsph_lattice_halfspace(&lp, dim == 2 ? 0.6 : 0.3, 0.13, &p, &c), 0);
  gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937);
  gsl_rng_set(rng, seed);
  for (size_t i = 0; i < p->n; i++) {
    /* slightly non-uniform volumes too */
    p->vol[i] *= 0.9 + 0.2 * gsl_rng_uniform(rng);
    for (int k = 0; k < dim; k++) p->vel[k][i] = gsl_rng_uniform(rng) - 0.5;
  }
  gsl_rng_free(rng);
  return p;
}

struct run {
  double *f[3], *dens, *buf;
  size_t n_fallback;
};

static void run_form(int form, struct vsph_particles *p, int direct,
                     struct run *r) {
  const int dim = p->dim;
  struct vsph_viscous_props vp;
  ck_assert_int_eq(vsph_viscous_props_init(&vp, form, &vsph_gaussian_type, dim,
                                           1.3333 * 0.05, 0.0137),
                   0);
  struct vsph_cells *c = vsph_cells_alloc();
  if (direct)
    ck_assert_int_eq(vsph_cells_build_direct(c, p), 0);
  else
    ck_assert_int_eq(vsph_cells_build(c, p, 3.0 * vp.h), 0);
  struct vsph_viscous_ws *ws = vsph_viscous_ws_alloc(p->n, dim);
  r->buf = calloc(4 * p->n, sizeof(double));
  for (int k = 0; k < 3; k++) r->f[k] = k < dim ? r->buf + k * p->n : NULL;
  r->dens = r->buf + 3 * p->n;
  ck_assert_int_eq(vsph_viscous_compute(&vp, p, c, ws, r->f, r->dens), 0);
  r->n_fallback = ws->n_fallback;
  vsph_viscous_ws_free(ws);
  vsph_cells_free(c);
}

/* THEORY 3 derivation check: for any velocities, PVWF gives
 * sum V u.(div V) = -sum V T:D, and every formulation's pairwise density
 * sums to the same P; zero total force but for model A, which is not a sum
 * of pair forces (Basa et al.: B to E conserve linear momentum); angular
 * momentum for the central forms (MGF, C, D) and PVWF (its renormalised
 * A_i = T_i L_i), not for MEAF, Espanol-Revenga (a du: non-central), B
 * (T_i without L) or A; every form but PVWF and A dissipates (P < 0). */
START_TEST(test_identities) {
  const int dim = 2 + _i % 2, form = _i / 2;
  struct vsph_particles *p = random_set(dim, 2385 + (unsigned long)_i);
  struct run r;
  run_form(form, p, 0, &r);
  double P = 0, Pp = 0, Pabs = 0, F[3] = {0}, Fabs = 0, L = 0, Labs = 0;
  for (size_t i = 0; i < p->n; i++) {
    const double V = p->vol[i];
    double fu = 0.0, f2 = 0.0, x2 = 0.0;
    for (int k = 0; k < dim; k++) {
      fu += p->vel[k][i] * r.f[k][i];
      F[k] += V * r.f[k][i];
      f2 += r.f[k][i] * r.f[k][i];
      x2 += p->pos[k][i] * p->pos[k][i];
    }
    P += V * fu;
    Pabs += V * fabs(fu);
    Pp += V * r.dens[i];
    Fabs += V * sqrt(f2);
    /* z component of x x f (the (0,1) plane in 3-D) */
    L += V * (p->pos[0][i] * r.f[1][i] - p->pos[1][i] * r.f[0][i]);
    Labs += V * sqrt(x2 * f2);
  }
  /* tol 1e-12: sums of ~1e3-1e4 terms of mixed sign, each exact to ~1e-16
   * relative; a missing factor or pair would show at O(1). */
  ck_assert_double_le(fabs(P - Pp), 1e-12 * Pabs);
  /* per-particle normalisations: model A, VISC-03, VISC-04 */
  const int takeda = form == VSPH_VISCOUS_TAKEDA ||
                     form == VSPH_VISCOUS_TAKEDA0 ||
                     form == VSPH_VISCOUS_VISC03 || form == VSPH_VISCOUS_VISC04;
  const int central = form == VSPH_VISCOUS_MGF || form == VSPH_VISCOUS_VI ||
                      form == VSPH_VISCOUS_CLEARY || form == VSPH_VISCOUS_PVWF;
  double Fn = 0.0;
  for (int k = 0; k < dim; k++) Fn += F[k] * F[k];
  if (takeda) /* a random field: the total force is O(1) of Fabs */
    ck_assert_double_ge(sqrt(Fn), 1e-3 * Fabs);
  else
    ck_assert_double_le(sqrt(Fn), 1e-12 * Fabs);
  if (central) /* rounding */
    ck_assert_double_le(fabs(L), 1e-12 * Labs);
  else /* far above rounding (B: 1.7e-4 in 3-D, where B_i is near I) */
    ck_assert_double_ge(fabs(L), 1e-5 * Labs);
  if (form != VSPH_VISCOUS_PVWF && !takeda) ck_assert_double_lt(P, 0.0);
  ck_assert_uint_eq(r.n_fallback, 0);
  free(r.buf);
  vsph_particles_free(p);
}
END_TEST

/* Cell list against O(N^2): same values to 1e-12 relative (the sums run
 * over the same neighbours in a different order). */
START_TEST(test_cells_vs_direct) {
  const int dim = 2 + _i % 2, form = _i / 2;
  struct vsph_particles *p = random_set(dim, 99);
  struct run a, b;
  run_form(form, p, 1, &a);
  double *fa = malloc(dim * p->n * sizeof *fa);
  for (size_t i = 0; i < p->n; i++) /* direct keeps the input order */
    for (int k = 0; k < dim; k++) fa[k * p->n + p->id[i]] = a.f[k][i];
  run_form(form, p, 0, &b); /* reorders p */
  double scale = 0.0;
  for (size_t i = 0; i < p->n; i++)
    for (int k = 0; k < dim; k++) scale = fmax(scale, fabs(b.f[k][i]));
  for (size_t i = 0; i < p->n; i++)
    for (int k = 0; k < dim; k++)
      ck_assert_double_eq_tol(b.f[k][i], fa[k * p->n + p->id[i]],
                              1e-12 * scale);
  free(fa);
  free(a.buf);
  free(b.buf);
  vsph_particles_free(p);
}
END_TEST

/* 1 thread against 2 threads: bitwise identical (gather loops). */
START_TEST(test_threads_bitwise) {
  const int dim = 2 + _i % 2, form = _i / 2;
  struct vsph_particles *p = random_set(dim, 4242);
  struct run a, b;
  omp_set_num_threads(1);
  run_form(form, p, 0, &a);
  omp_set_num_threads(2);
  run_form(form, p, 0, &b);
  ck_assert_int_eq(memcmp(a.buf, b.buf, 4 * p->n * sizeof(double)), 0);
  free(a.buf);
  free(b.buf);
  vsph_particles_free(p);
}
END_TEST

/* PVWF's renormalised gradient is exact for a linear field at every
 * particle, surface included: -T:D = -(2 mu D:D + lambda tr(D)^2). */
START_TEST(test_pvwf_linear_exact) {
  struct vsph_particles *p = random_set(2, 5);
  const double G[4] = {0.37, -1.21, 0.83, 0.59}; /* du_a/dx_b */
  for (size_t i = 0; i < p->n; i++) {
    const double x = p->pos[0][i], y = p->pos[1][i];
    p->vel[0][i] = G[0] * x + G[1] * y;
    p->vel[1][i] = G[2] * x + G[3] * y;
  }
  struct run r;
  run_form(VSPH_VISCOUS_PVWF, p, 0, &r);
  const double mu = 0.0137, lambda = -mu, tr = G[0] + G[3];
  const double D01 = 0.5 * (G[1] + G[2]);
  const double want = -(2 * mu * (G[0] * G[0] + G[3] * G[3] + 2 * D01 * D01) +
                        lambda * tr * tr);
  /* tol: L B = I to rounding with condition numbers ~10 at the corners */
  for (size_t i = 0; i < p->n; i++)
    ck_assert_double_eq_tol(r.dens[i], want, 1e-12 * fabs(want));
  free(r.buf);
  vsph_particles_free(p);
}
END_TEST

/* An isolated particle has no support: L falls back to I and is counted. */
START_TEST(test_pvwf_fallback) {
  struct vsph_particles *p = vsph_particles_alloc(8, 2);
  p->n = 3;
  const double xs[3] = {0.0, 0.03, 5.0}; /* two neighbours, one alone */
  for (size_t i = 0; i < 3; i++) {
    p->pos[0][i] = xs[i];
    p->pos[1][i] = 0.0;
    p->vol[i] = p->m[i] = p->rho[i] = 1.0;
    p->id[i] = i;
  }
  struct run r;
  run_form(VSPH_VISCOUS_PVWF, p, 0, &r);
  /* all three fall back: the pair is collinear (rank-1 B), one is alone */
  ck_assert_uint_eq(r.n_fallback, 3);
  free(r.buf);
  vsph_particles_free(p);
}
END_TEST

/* The particle of @p p nearest the origin (2-D). */
static size_t nearest_origin(const struct vsph_particles *p) {
  size_t best = 0;
  for (size_t i = 1; i < p->n; i++)
    if (hypot(p->pos[0][i], p->pos[1][i]) <
        hypot(p->pos[0][best], p->pos[1][best]))
      best = i;
  return best;
}

/* Basa et al.'s models in the interior of a square lattice, cubic spline,
 * dx/h = 0.637, eta = 0.1 h for C and D, u = (y^2, 0): the operator's x
 * component over the exact value 2 mu (lap u = 2, div u = 0), against an
 * independent computation (the first digest's Part IV, its own scripts):
 * C 0.948, D with xi = 4.24 1.0045, D with xi = 4.96333 1.176, A
 * 1.777/2, A Shepard-corrected 1.922/2, B (two-pass, differenced) 1.9877/2.
 * Printed to three or four digits: tolerance 6e-4 (half a unit of the
 * last digit of 0.948 plus rounding). 17 x 17, so that a particle sits
 * at y = 0 as in the digest (model A is not Galilean invariant: at
 * y_i = dx/2 its uniform-field error moves A by -0.024); B reaches two
 * supports (6.3 dx): the centre has 8 dx all round. */
START_TEST(test_brookshaw_lattice) {
  static const int form[6] = {VSPH_VISCOUS_VI,      VSPH_VISCOUS_CLEARY,
                              VSPH_VISCOUS_CLEARY,  VSPH_VISCOUS_TAKEDA,
                              VSPH_VISCOUS_TAKEDA0, VSPH_VISCOUS_TWOPASS};
  static const double xi[6] = {0.0, 4.24, 4.96333, 0.0, 0.0, 0.0};
  static const double want[6] = {0.948,       1.0045,      1.176,
                                 1.777 / 2.0, 1.922 / 2.0, 1.9877 / 2.0};
  const int k = _i;
  struct vsph_lattice_props lp = {.dim = 2, .kind = VSPH_LATTICE_SQUARE};
  struct vsph_particles *p = NULL;
  const size_t n = 17;
  ck_assert_int_eq(vsph_lattice_square(&lp, 1.0, n, &p), 0);
  const double dx = 1.0 / n, mu = 0.37;
  for (size_t i = 0; i < p->n; i++) {
    p->vel[0][i] = p->pos[1][i] * p->pos[1][i];
    p->vel[1][i] = 0.0;
  }
  struct vsph_viscous_props vp;
  ck_assert_int_eq(vsph_viscous_props_init(&vp, form[k], &vsph_cubic_type, 2,
                                           dx / 0.637, mu),
                   0);
  if (xi[k] > 0.0) vp.xi = xi[k];
  struct vsph_cells *c = vsph_cells_alloc();
  ck_assert_int_eq(vsph_cells_build_direct(c, p), 0);
  struct vsph_viscous_ws *ws = vsph_viscous_ws_alloc(p->n, 2);
  double *buf = calloc(2 * p->n, sizeof *buf), *f[3] = {buf, buf + p->n, NULL};
  ck_assert_int_eq(vsph_viscous_compute(&vp, p, c, ws, f, NULL), 0);
  /* the particle nearest the centre: 2h = 3.1 dx of lattice all round */
  const size_t best = nearest_origin(p);
  ck_assert_double_eq_tol(f[0][best] / (2.0 * mu), want[k], 6e-4);
  ck_assert_double_le(fabs(f[1][best]), 1e-9 * fabs(f[0][best]));
  free(buf);
  vsph_viscous_ws_free(ws);
  vsph_cells_free(c);
  vsph_particles_free(p);
}
END_TEST

/* Model A's answer to a uniform velocity (U, 0), which should be zero, in
 * the interior of the same lattice (cubic, dx/h = 0.637): uncorrected,
 * (mu/3)(4 + 3) U sum_j V_j d_xx W = -0.193 mu U/dx^2 (the digest's Part
 * IV, its own scripts, three digits: tolerance 6e-4); Shepard-corrected
 * (eq. 23) exactly zero on any particle set, here also on the perturbed
 * patch with its free surface: |f| <= 1e-10 mu U/dx^2 (cancellation of
 * terms of size 1/dx^2 to rounding). */
START_TEST(test_takeda_uniform) {
  const double mu = 0.37, U = 1.7;
  for (int set = 0; set < 2; set++) {
    struct vsph_particles *p = NULL;
    double dx;
    if (set == 0) {
      struct vsph_lattice_props lp = {.dim = 2, .kind = VSPH_LATTICE_SQUARE};
      ck_assert_int_eq(vsph_lattice_square(&lp, 1.0, 16, &p), 0);
      dx = 1.0 / 16;
    } else {
      p = random_set(2, 77);
      dx = 0.05;
    }
    for (size_t i = 0; i < p->n; i++) {
      p->vel[0][i] = U;
      p->vel[1][i] = 0.0;
    }
    struct vsph_cells *c = vsph_cells_alloc();
    ck_assert_int_eq(vsph_cells_build_direct(c, p), 0);
    struct vsph_viscous_ws *ws = vsph_viscous_ws_alloc(p->n, 2);
    double *buf = calloc(2 * p->n, sizeof *buf);
    double *f[3] = {buf, buf + p->n, NULL};
    const double scale = mu * U / (dx * dx);
    for (int shep = 0; shep < 2; shep++) {
      struct vsph_viscous_props vp;
      ck_assert_int_eq(
          vsph_viscous_props_init(
              &vp, shep ? VSPH_VISCOUS_TAKEDA0 : VSPH_VISCOUS_TAKEDA,
              &vsph_cubic_type, 2, dx / 0.637, mu),
          0);
      ck_assert_int_eq(vsph_viscous_compute(&vp, p, c, ws, f, NULL), 0);
      const size_t best = nearest_origin(p);
      if (shep) {
        for (size_t i = 0; i < p->n; i++)
          for (int k = 0; k < 2; k++)
            ck_assert_double_le(fabs(f[k][i]), 1e-10 * scale);
      } else if (set == 0) {
        ck_assert_double_eq_tol(f[0][best] / scale, -0.193, 6e-4);
      }
    }
    free(buf);
    vsph_viscous_ws_free(ws);
    vsph_cells_free(c);
    vsph_particles_free(p);
  }
}
END_TEST

/* Model A against finite differences of the interpolant it differentiates
 * (the quintic spline: C4, so central differences converge): for a few
 * particles of the perturbed patch, with all positions fixed,
 * I_c(x) = sum_j V_j u^c_j W(x - r_j) (plain, eq. 27) or divided by
 * sum_j V_j W(x - r_j) (Shepard, eq. 23), its second derivatives at r_i by
 * central differences with step 1e-3 h, and mu lap u + (mu/3) grad div u
 * from them (eq. 6). This checks eq. 28's second derivative and the
 * quotient rule of eq. 23 without them. Tolerance 1e-5 of the largest
 * force: truncation (1e-3)^2 of the fourth derivative's scale, rounding
 * 1e-16/(1e-3)^2 = 1e-10. */
static double interp(const struct vsph_particles *p, int c, const double x[2],
                     double h, int shepard) {
  double num = 0.0, den = 0.0;
  for (size_t j = 0; j < p->n; j++) {
    const double q = hypot(x[0] - p->pos[0][j], x[1] - p->pos[1][j]) / h;
    if (q >= vsph_quintic_type.kappa) continue;
    const double W = vsph_kernel_w(&vsph_quintic_type, 2, q) / (h * h);
    num += p->vol[j] * p->vel[c][j] * W;
    den += p->vol[j] * W;
  }
  return shepard ? num / den : num;
}

START_TEST(test_takeda_fd) {
  const int shep = _i;
  struct vsph_particles *p = random_set(2, 4242);
  const double h = 1.2 * 0.05, mu = 0.0137, dlt = 1e-3 * h;
  struct vsph_viscous_props vp;
  ck_assert_int_eq(vsph_viscous_props_init(
                       &vp, shep ? VSPH_VISCOUS_TAKEDA0 : VSPH_VISCOUS_TAKEDA,
                       &vsph_quintic_type, 2, h, mu),
                   0);
  struct vsph_cells *c = vsph_cells_alloc();
  ck_assert_int_eq(vsph_cells_build_direct(c, p), 0);
  struct vsph_viscous_ws *ws = vsph_viscous_ws_alloc(p->n, 2);
  double *buf = calloc(2 * p->n, sizeof *buf);
  double *f[3] = {buf, buf + p->n, NULL};
  ck_assert_int_eq(vsph_viscous_compute(&vp, p, c, ws, f, NULL), 0);
  double scale = 0.0;
  for (size_t i = 0; i < p->n; i++)
    scale = fmax(scale, hypot(f[0][i], f[1][i]));
  for (size_t i = 0; i < p->n; i += p->n / 7) { /* interior and surface */
    double D[2][2][2];                          /* D[c][a][b] */
    for (int cc = 0; cc < 2; cc++)
      for (int a = 0; a < 2; a++)
        for (int b = 0; b < 2; b++) {
          double v = 0.0;
          for (int sa = -1; sa <= 1; sa += 2)
            for (int sb = -1; sb <= 1; sb += 2) {
              double x[2] = {p->pos[0][i], p->pos[1][i]};
              x[a] += sa * dlt;
              x[b] += sb * dlt;
              v += sa * sb * interp(p, cc, x, h, shep);
            }
          D[cc][a][b] = v / (4.0 * dlt * dlt);
        }
    for (int a = 0; a < 2; a++) {
      const double want =
          mu * (D[a][0][0] + D[a][1][1]) + mu / 3.0 * (D[0][a][0] + D[1][a][1]);
      ck_assert_msg(fabs(f[a][i] - want) <= 1e-5 * scale,
                    "particle %zu component %d: %.9e against %.9e", i, a,
                    f[a][i], want);
    }
  }
  free(buf);
  vsph_viscous_ws_free(ws);
  vsph_cells_free(c);
  vsph_particles_free(p);
}
END_TEST

/* The digest's lattice sums (notes, seed-000-003, part I.5): an interior
 * particle of the square lattice, cubic B-spline (support 2h), dx/h =
 * 0.637, V = dx^2, u = (y^2, 0), exact mu lap u = (2 mu, 0). Its values
 * (div V)_x/mu, computed there independently and printed to five
 * figures: model E as P000 prints it (MEAF, no eta) 1.9938; with
 * eta^2 = 0.01 h^2 (Morris et al. as they print it, MEAF-eta) 1.9705;
 * model B, two passes, differenced first derivatives 1.9877. Tolerance:
 * half a unit of the printed last digit. MEAF-eta and VISC-01 (the same
 * operator for uniform mu, written as a Laplacian) agree to rounding at
 * every particle of the patch, boundary ones too. */
START_TEST(test_digest_lattice) {
  const int N = 8; /* (2N + 1)^2 particles; the support is 3.14 dx */
  const size_t n = (size_t)(2 * N + 1) * (size_t)(2 * N + 1);
  const double dx = 0.05, h = dx / 0.637, mu = 1.3;
  struct vsph_particles *p = vsph_particles_alloc(n, 2);
  ck_assert_ptr_nonnull(p);
  p->n = n;
  size_t centre = 0;
  for (int a = -N; a <= N; a++)
    for (int b = -N; b <= N; b++) {
      const size_t i = (size_t)(a + N) * (size_t)(2 * N + 1) + (size_t)(b + N);
      p->pos[0][i] = a * dx;
      p->pos[1][i] = b * dx;
      p->vel[0][i] = (b * dx) * (b * dx);
      p->vel[1][i] = 0.0;
      p->m[i] = dx * dx;
      p->rho[i] = 1.0;
      p->id[i] = i;
      if (a == 0 && b == 0) centre = i;
    }
  vsph_particles_refresh_vol(p);
  struct vsph_cells *c = vsph_cells_alloc();
  ck_assert_int_eq(vsph_cells_build_direct(c, p), 0);
  struct vsph_viscous_ws *ws = vsph_viscous_ws_alloc(n, 2);
  double *f[3], *keep = malloc(2 * n * sizeof *keep);
  f[0] = malloc(n * sizeof(double));
  f[1] = malloc(n * sizeof(double));
  f[2] = NULL;
  static const struct {
    int form;
    double want;
  } rows[] = {{VSPH_VISCOUS_MEAF, 1.9938},
              {VSPH_VISCOUS_MEAFETA, 1.9705},
              {VSPH_VISCOUS_TWOPASS, 1.9877},
              {VSPH_VISCOUS_VISC01, 1.9705}};
  for (size_t r = 0; r < sizeof rows / sizeof rows[0]; r++) {
    struct vsph_viscous_props vp;
    ck_assert_int_eq(
        vsph_viscous_props_init(&vp, rows[r].form, &vsph_cubic_type, 2, h, mu),
        0);
    ck_assert_int_eq(vsph_viscous_compute(&vp, p, c, ws, f, NULL), 0);
    const double got = f[0][centre] / mu;
    ck_assert_msg(fabs(got - rows[r].want) <= 5e-5,
                  "%s: (div V)_x/mu = %.6f at the centre, the digest's %.4f",
                  vsph_viscous_label(rows[r].form), got, rows[r].want);
    ck_assert_double_le(fabs(f[1][centre]), 1e-9);
    if (rows[r].form == VSPH_VISCOUS_MEAFETA)
      for (size_t i = 0; i < n; i++) keep[i] = f[0][i], keep[n + i] = f[1][i];
    if (rows[r].form == VSPH_VISCOUS_VISC01) {
      double scale = 0.0, err = 0.0;
      for (size_t i = 0; i < n; i++)
        for (int k = 0; k < 2; k++) {
          scale = fmax(scale, fabs(keep[k * n + i]));
          err = fmax(err, fabs(keep[k * n + i] - f[k][i]));
        }
      /* ~40-term sums in another order: 1e-12 of the largest */
      ck_assert_msg(err <= 1e-12 * scale, "MEAF-eta - VISC-01: %.3e of %.3e",
                    err, scale);
    }
  }
  free(f[0]);
  free(f[1]);
  free(keep);
  vsph_viscous_ws_free(ws);
  vsph_cells_free(c);
  vsph_particles_free(p);
}
END_TEST

/* Every corrigible form's corrected pair term (its descriptor's pair_g)
 * with the uncorrected gradient g = grad_i W = -F x is its pair share:
 * the same force and dissipation density as its pair function, for three
 * pairs of "high-entropy" geometry in 2-D and 3-D (ER with zeta = 0.731
 * mu, so that its b term counts; VI and Cleary with their eta). Tolerance
 * 1e-14 of the force's size: the same products grouped otherwise (V_j F
 * as one factor or two), a few roundings of 1.1e-16 each. */
START_TEST(test_pair_g_uncorrected) {
  const int form = _i % VSPH_VISCOUS_FORM_COUNT;
  const int dim = 2 + _i / VSPH_VISCOUS_FORM_COUNT;
  const struct vsph_viscous_type *t = vsph_viscous_types[form];
  if (!t->pair_g) return;
  struct vsph_viscous_props vp;
  ck_assert_int_eq(vsph_viscous_props_init(&vp, form, &vsph_gaussian_type, dim,
                                           0.0713, 0.0137),
                   0);
  vp.zeta = 0.731 * vp.mu;
  struct vsph_viscous_loop lp;
  ck_assert_int_eq(vsph_viscous_loop_init(&lp, &vp, NULL), 0);
  static const double xs[3][3] = {{0.0312, -0.0457, 0.0219},
                                  {-0.0823, 0.0115, -0.0371},
                                  {0.0049, 0.0632, 0.0544}};
  static const double dus[3][3] = {
      {0.385, -1.207, 0.661}, {-0.913, 0.274, 1.538}, {2.385, 0.0137, -0.442}};
  const double vj = 0.00271, Ai[9] = {0};
  for (int q = 0; q < 3; q++) {
    struct vsph_pair pr = {.j = 0, .s2 = 0.0};
    struct vsph_pair_vec duv = {{0, 0, 0}};
    double du[3] = {0, 0, 0}, dux = 0.0, g[3] = {0, 0, 0}, f[3] = {0, 0, 0};
    for (int k = 0; k < dim; k++) {
      pr.x[k] = xs[q][k];
      pr.s2 += pr.x[k] * pr.x[k];
      du[k] = duv.v[k] = dus[q][k];
      dux += du[k] * pr.x[k];
    }
    pr.F = -41.3 / pr.s2;
    pr.VF = vj * pr.F;
    for (int k = 0; k < dim; k++) g[k] = -pr.F * pr.x[k];
    const struct vsph_pair_visc r = t->pair(&lp, dim, &pr, duv, dux, Ai);
    const double dens = t->pair_g(&lp, dim, &pr, vj, du, dux, g, f);
    double scale = 0.0;
    for (int k = 0; k < dim; k++) scale = fmax(scale, fabs(r.f[k]));
    ck_assert_double_gt(scale, 0.0);
    for (int k = 0; k < dim; k++)
      ck_assert_msg(fabs(f[k] - r.f[k]) <= 1e-14 * scale,
                    "%s, %d-D, pair %d: f[%d] %.17g, uncorrected %.17g",
                    t->name, dim, q, k, f[k], r.f[k]);
    ck_assert_msg(fabs(dens - r.dens) <= 1e-14 * fabs(r.dens),
                  "%s, %d-D, pair %d: density %.17g, uncorrected %.17g",
                  t->name, dim, q, dens, r.dens);
  }
}
END_TEST

START_TEST(test_bad_props_refused_names_listed) {
  vsph_test_silence();
  struct vsph_viscous_props vp;
  ck_assert_int_eq(vsph_viscous_props_init(&vp, VSPH_VISCOUS_FORM_COUNT,
                                           &vsph_cubic_type, 2, 1, 1),
                   1);
  ck_assert_int_eq(vsph_viscous_props_init(&vp, 0, &vsph_cubic_type, 2, 0, 1),
                   1);
  ck_assert_int_eq(vsph_viscous_props_init(&vp, 0, &vsph_cubic_type, 2, 1, -1),
                   1);
  ck_assert_int_eq(vsph_viscous_find("pvwf"), VSPH_VISCOUS_PVWF);
  char names[256] = ""; /* the help texts' list is the name table */
  for (int k = 0; k < VSPH_VISCOUS_FORM_COUNT; k++) {
    if (k) strcat(names, ", ");
    strcat(names, vsph_viscous_name(k));
  }
  ck_assert_str_eq(names, VSPH_VISCOUS_NAMES);
  /* the static help texts' lists are the descriptors' */
  char list[256];
  ck_assert_str_eq(vsph_viscous_list(0, list, sizeof list), VSPH_VISCOUS_NAMES);
  ck_assert_str_eq(
      vsph_viscous_list(VSPH_VISCOUS_CORRIGIBLE, list, sizeof list),
      VSPH_VISCOUS_CORRIGIBLE_NAMES);
  ck_assert_str_eq(vsph_viscous_list(VSPH_VISCOUS_FREE_SURFACE, list, 256),
                   "mgf, meaf, pvwf");
  ck_assert_str_eq(vsph_viscous_list(0, list, 9), "mgf, mea"); /* cut */
  for (int k = 0; k < VSPH_VISCOUS_FORM_COUNT; k++) {
    const struct vsph_viscous_type *t = vsph_viscous_type_get(k);
    ck_assert_ptr_nonnull(t);
    ck_assert_msg(t->name && t->label && t->cite && t->params, "form %d", k);
    /* the free-surface forms come first (VSPH_VISCOUS_PAPER_COUNT) */
    ck_assert_int_eq((t->flags & VSPH_VISCOUS_FREE_SURFACE) != 0,
                     k < VSPH_VISCOUS_PAPER_COUNT);
    /* a form with loops of its own: they inline its pair functions (the
     * pair and pair_g they were made with are the descriptor's), so the
     * specialised and the general loop run the one term */
    if (t->loops) {
      ck_assert(t->pair != NULL);
      ck_assert_msg(t->loops->pair == t->pair, "%s: loops of another term",
                    t->name);
      ck_assert_msg(t->loops->pair_g == t->pair_g,
                    "%s: loops of another corrected term", t->name);
    }
    ck_assert_int_eq(vsph_viscous_specialised(k), t->loops != NULL);
    /* the corrected pair term exactly where the corrections apply */
    ck_assert_int_eq(t->pair_g != NULL,
                     (t->flags & VSPH_VISCOUS_CORRIGIBLE) != 0);
    ck_assert(t->pair_g == NULL || t->pair != NULL);
    ck_assert_int_eq(t->pair == NULL,
                     t->pass == VSPH_VISCOUS_PASS_TAKEDA ||
                         t->pass == VSPH_VISCOUS_PASS_LAPLACIAN);
    ck_assert_int_eq(t->lap >= 0, t->pass == VSPH_VISCOUS_PASS_LAPLACIAN);
    /* its family's first pass exactly where it has one */
    ck_assert_int_eq(t->first != NULL, t->pass != VSPH_VISCOUS_PASS_NONE);
  }
  /* the families' loops: MGF's serve VI and Cleary (their constants in
   * the loop), PVWF's model B (its A_i in the workspace); MEAF-eta runs
   * the general loop; the four heads each their own */
  const struct vsph_viscous_type *const *const T = vsph_viscous_types;
  ck_assert_ptr_eq(T[VSPH_VISCOUS_VI]->loops, T[VSPH_VISCOUS_MGF]->loops);
  ck_assert_ptr_eq(T[VSPH_VISCOUS_CLEARY]->loops, T[VSPH_VISCOUS_MGF]->loops);
  ck_assert_ptr_eq(T[VSPH_VISCOUS_TWOPASS]->loops, T[VSPH_VISCOUS_PVWF]->loops);
  ck_assert_ptr_null(T[VSPH_VISCOUS_MEAFETA]->loops);
  const int heads[4] = {VSPH_VISCOUS_MGF, VSPH_VISCOUS_MEAF, VSPH_VISCOUS_PVWF,
                        VSPH_VISCOUS_ER};
  for (int a = 0; a < 4; a++) {
    ck_assert_ptr_nonnull(T[heads[a]]->loops);
    for (int b = 0; b < a; b++)
      ck_assert_ptr_ne(T[heads[a]]->loops, T[heads[b]]->loops);
  }
  /* README's table of formulations: one row per descriptor, its name,
   * label, first pass and the parameters it reads (tests run in the
   * repository's root) */
  static char readme[1 << 17];
  vsph_test_slurp("README.md", readme, sizeof readme);
  ck_assert_msg(strlen(readme) > 1000, "README.md not read");
  static const char *const pass_words[] = {
      [VSPH_VISCOUS_PASS_NONE] = "none",
      [VSPH_VISCOUS_PASS_STRESS] = "stress (two passes)",
      [VSPH_VISCOUS_PASS_TAKEDA] = "whole force (direct second derivatives)",
      [VSPH_VISCOUS_PASS_LAPLACIAN] = "whole force (Laplacian)"};
  for (int k = 0; k < VSPH_VISCOUS_FORM_COUNT; k++) {
    const struct vsph_viscous_type *t = vsph_viscous_types[k];
    char row[512], reads[128] = "";
    /* "xi, eta" -> "`xi`, `eta`" */
    for (const char *c = t->params; *c;) {
      size_t w = strcspn(c, ", ");
      if (w) {
        strcat(reads, *reads ? ", `" : "`");
        strncat(reads, c, w);
        strcat(reads, "`");
      }
      c += w;
      c += strspn(c, ", ");
    }
    const unsigned f = t->flags;
    char where[128];
    const int fs = (f & VSPH_VISCOUS_FREE_SURFACE) != 0,
              co = (f & VSPH_VISCOUS_CORRIGIBLE) != 0,
              tv = (f & VSPH_VISCOUS_TVF) != 0;
    snprintf(where, sizeof where, "%s%s%s%s%s", fs ? "free surface" : "",
             fs && (co || tv) ? "; " : "", co ? "corrections" : "",
             co && tv ? ", " : "", tv ? "transport velocity" : "");
    /* an empty cell is "| |" */
    snprintf(row, sizeof row, "| `%s` | %s | %s |%s%s%s|%s%s%s|", t->name,
             t->label, pass_words[t->pass], *where ? " " : " ", where,
             *where ? " " : "", *reads ? " " : " ", reads, *reads ? " " : "");
    ck_assert_msg(strstr(readme, row) != NULL, "README.md lacks the row\n%s",
                  row);
  }
  ck_assert_ptr_null(vsph_viscous_type_get(VSPH_VISCOUS_FORM_COUNT));
  ck_assert_ptr_null(vsph_viscous_type_get(-1));
  ck_assert_int_eq(vsph_viscous_find("sph"), -1);
  struct vsph_particles *p = random_set(2, 1);
  ck_assert_int_eq(vsph_viscous_props_init(&vp, VSPH_VISCOUS_PVWF,
                                           &vsph_cubic_type, 2, 0.1, 1),
                   0);
  struct vsph_cells *c = vsph_cells_alloc();
  vsph_cells_build_direct(c, p);
  double *f[3] = {p->acc[0], p->acc[1], NULL};
  ck_assert_int_eq(vsph_viscous_compute(&vp, p, c, NULL, f, NULL), 1);
  vsph_cells_free(c);
  vsph_particles_free(p);
}
END_TEST

Suite *vsph_viscous_suite(void) {
  Suite *s = suite_create("viscous");
  TCase *tc = tcase_create("operators");
  tcase_set_timeout(tc, 60);
  tcase_add_loop_test(tc, test_identities, 0, 2 * VSPH_VISCOUS_FORM_COUNT);
  tcase_add_loop_test(tc, test_cells_vs_direct, 0, 2 * VSPH_VISCOUS_FORM_COUNT);
  tcase_add_loop_test(tc, test_threads_bitwise, 0, 2 * VSPH_VISCOUS_FORM_COUNT);
  tcase_add_loop_test(tc, test_brookshaw_lattice, 0, 6);
  tcase_add_test(tc, test_takeda_uniform);
  tcase_add_loop_test(tc, test_takeda_fd, 0, 2);
  tcase_add_test(tc, test_pvwf_linear_exact);
  tcase_add_test(tc, test_pvwf_fallback);
  tcase_add_loop_test(tc, test_pair_g_uncorrected, 0,
                      2 * VSPH_VISCOUS_FORM_COUNT);
  tcase_add_test(tc, test_bad_props_refused_names_listed);
  tcase_add_test(tc, test_digest_lattice);
  suite_add_tcase(s, tc);
  return s;
}
