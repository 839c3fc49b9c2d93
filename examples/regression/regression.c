/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
/* A regression test of another code, written against libvsph alone: the
 * installed headers and library, found by pkg-config (see Makefile here
 * and docs/library.md). It checks three things a code of
 * one's own would check against vsph:
 *
 *   1. a kernel moment tensor: M = -int x (x) x W'(s)/s dV of the 2-D
 *      Gaussian is the identity on the full support and half of it on
 *      the half support (THEORY.md section 2), by vsph's quadrature;
 *   2. an exact reference: the start-up Poiseuille flow at nu t/W^2 = 10
 *      is the steady parabola U0 (1 - (yc/d)^2) to rounding, and at
 *      t = 0 it is at rest and accelerates at 2 nu U0/d^2;
 *   3. the dissipation of a particle set of one's own: MGF's pairs see
 *      (u_j - u_i).(r_j - r_i) = 0 under a rigid rotation, so its
 *      dissipation vanishes to rounding, while a shear dissipates.
 *
 * Each line: what, the value, the value it must have. Exit 0 when every
 * one agrees within its stated tolerance, 1 otherwise. */
#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <vsph/vsph.h>

static int failures = 0;

static void expect(const char *what, double got, double want, double tol) {
  const int ok = fabs(got - want) <= tol;
  printf("%-40s %.17g %.17g %s\n", what, got, want, ok ? "ok" : "FAIL");
  failures += !ok;
}

/* The 2-D Gaussian's M at depth 0 (half support) and 3 (full support). */
static int tensors(void) {
  const struct vsph_kernel_type *k = vsph_kernel_find("gaussian");
  gsl_integration_workspace *a = gsl_integration_workspace_alloc(1000);
  gsl_integration_workspace *b = gsl_integration_workspace_alloc(1000);
  struct vsph_moments half, full;
  int st = !k || !a || !b;
  if (!st) st = vsph_moments_quadrature(k, 2, 0.0, 1e-10, a, b, &half);
  if (!st) st = vsph_moments_quadrature(k, 2, 3.0, 1e-10, a, b, &full);
  gsl_integration_workspace_free(a);
  gsl_integration_workspace_free(b);
  if (st) return st;
  /* tolerance: the quadrature's relative 1e-10, tenfold */
  expect("M_xx, full support", full.M[0][0], 1.0, 1e-9);
  expect("M_yy, full support", full.M[1][1], 1.0, 1e-9);
  expect("M_xx, half support", half.M[0][0], 0.5, 1e-9);
  expect("M_yy, half support", half.M[1][1], 0.5, 1e-9);
  return 0;
}

/* The start-up Poiseuille flow, W = 1, nu = 0.1, U0 = 1. */
static void poiseuille(void) {
  const double W = 1.0, nu = 0.1, U0 = 1.0, d = 0.5, y = 0.3, yc = y - d;
  double dudt;
  /* the series' terms fall below 1e-17 U0: rounding, 1e-14 */
  expect("Poiseuille U, nu t/W^2 = 10",
         vsph_references_poiseuille(y, 10.0 * W * W / nu, W, nu, U0, NULL),
         U0 * (1.0 - yc * yc / (d * d)), 1e-14);
  expect("Poiseuille U, t = 0",
         vsph_references_poiseuille(y, 0.0, W, nu, U0, &dudt), 0.0, 0.0);
  expect("Poiseuille dU/dt, t = 0", dudt, 2.0 * nu * U0 / (d * d), 1e-14);
}

/* A 20 x 20 square lattice, dx = 0.05, rho = 1000, moving as u. */
static struct vsph_particles *lattice(double omega, double shear) {
  struct vsph_particles *p = vsph_particles_alloc(400, 2);
  if (!p) return NULL;
  const double dx = 0.05;
  p->n = 400;
  for (size_t i = 0; i < p->n; i++) {
    const double x = (double)(i % 20) * dx, y = (double)(i / 20) * dx;
    p->pos[0][i] = x;
    p->pos[1][i] = y;
    p->vel[0][i] = -omega * y + shear * y;
    p->vel[1][i] = omega * x;
    p->rho[i] = 1000.0;
    p->m[i] = 1000.0 * dx * dx;
    p->id[i] = i;
  }
  return p;
}

static int dissipation(void) {
  const struct vsph_kernel_type *k = vsph_kernel_find("gaussian");
  struct vsph_viscous_props vp;
  int st = vsph_viscous_props_init(&vp, vsph_viscous_find("mgf"), k, 2,
                                   4.0 / 3.0 * 0.05, 1e-3);
  if (st) return st;
  struct vsph_dissipation_power rot, shear;
  struct vsph_particles *p = lattice(2.0, 0.0), *q = lattice(0.0, 2.0);
  st = !p || !q;
  if (!st) st = vsph_dissipation_particles(&vp, p, &rot);
  if (!st) st = vsph_dissipation_particles(&vp, q, &shear);
  vsph_particles_free(p);
  vsph_particles_free(q);
  if (st) return st;
  /* rotation: each pair's du.x is rounding, ~1e-16 of |u| s; the sum of
   * 400 particles' ~45 pairs against the shear's |P|: 1e-12 of it */
  expect("MGF dissipation, rotation / shear's", rot.P / fabs(shear.P), 0.0,
         1e-12);
  expect("MGF dissipation, shear < 0", shear.P < 0.0, 1.0, 0.0);
  expect("MGF pairwise = particle form, shear", shear.P_pair / shear.P, 1.0,
         1e-12);
  return 0;
}

int main(void) {
  /* vsph's GSL calls return their status, as every vsph function does:
   * GSL's default handler would abort the program instead */
  gsl_set_error_handler_off();
  printf("# libvsph %s, source %s\n", VSPH_VERSION, vsph_source_hash_id);
  if (tensors() || dissipation()) {
    fprintf(stderr, "regression: a vsph call failed\n");
    return 1;
  }
  poiseuille();
  printf("# %d failed\n", failures);
  return failures ? 1 : 0;
}
