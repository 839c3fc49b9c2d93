/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
#include <gsl/gsl_integration.h>
#include <math.h>

#include "../analysis/moments.h"
#include "../analysis/scaling.h"
#include "../kernels/kernel.h"
#include "../solver/lattice.h"
#include "../solver/particles.h"
#include "../solver/viscous.h"
#include "check_suites.h"

static void setup(struct vsph_scaling_props *sp, int kind, int dim) {
  ck_assert_int_eq(vsph_scaling_props_init(sp, NULL), 0);
  sp->kernel = &vsph_gaussian_type;
  sp->levels = 4;
  ck_assert_int_eq(vsph_fields_props_init(&sp->field, kind, dim), 0);
}

/* Strain (n.D.n != 0): every operator grows like 1/h at the surface, slope
 * -1; h F and h N stay constant (THEORY 2, "Truncation-error scaling"). The
 * patch is self-similar, so the slope is -1 to rounding: tol 1e-9. */
START_TEST(test_strain_slopes) {
  struct vsph_scaling_props sp;
  setup(&sp, VSPH_FIELDS_STRAIN, 2 + _i);
  struct vsph_scaling_result r;
  ck_assert_int_eq(vsph_scaling_surface(&sp, &r), 0);
  for (int f = 0; f < 3; f++) {
    ck_assert(!r.rounding[f]);
    ck_assert_double_eq_tol(r.slope[f], -1.0, 1e-9);
  }
  for (size_t l = 1; l < r.levels; l++) {
    ck_assert_double_eq_tol(r.hF[l], r.hF[0], 1e-12 * fabs(r.hF[0]));
    ck_assert_double_eq_tol(r.hN[l], r.hN[0], 1e-12 * fabs(r.hN[0]));
  }
}
END_TEST

/* Same on a randomly perturbed lattice: each level has its own random set,
 * so the slope is only close to -1. With 10 % perturbations and 6 levels
 * the fitted slopes come out within 0.05 of -1 (measured); tol 0.1. */
START_TEST(test_strain_slopes_perturbed) {
  struct vsph_scaling_props sp;
  setup(&sp, VSPH_FIELDS_STRAIN, 2);
  sp.perturb = 0.1;
  sp.levels = 6;
  struct vsph_scaling_result r;
  ck_assert_int_eq(vsph_scaling_surface(&sp, &r), 0);
  for (int f = 0; f < 3; f++) ck_assert_double_eq_tol(r.slope[f], -1.0, 0.1);
}
END_TEST

/* Rigid rotation (n.D.n = 0): MGF and PVWF stay at rounding level, MEAF
 * grows with slope -1 (its N.grad u term, grad u tangential). */
START_TEST(test_rotation_slopes) {
  struct vsph_scaling_props sp;
  setup(&sp, VSPH_FIELDS_ROTATION, 2 + _i);
  struct vsph_scaling_result r;
  ck_assert_int_eq(vsph_scaling_surface(&sp, &r), 0);
  ck_assert(r.rounding[VSPH_VISCOUS_MGF]);
  ck_assert(r.rounding[VSPH_VISCOUS_PVWF]);
  ck_assert(!r.rounding[VSPH_VISCOUS_MEAF]);
  ck_assert_double_eq_tol(r.slope[VSPH_VISCOUS_MEAF], -1.0, 1e-9);
  /* MEAF on a rotation is tangential: normal part at rounding level */
  for (size_t l = 0; l < r.levels; l++)
    ck_assert_double_le(fabs(r.normal[VSPH_VISCOUS_MEAF][l]),
                        1e-9 * r.magnitude[VSPH_VISCOUS_MEAF][l]);
  /* the rounding level and each form's largest value, as the report's
   * claims read them: round_tol mu |Omega| / h at the finest h, worked
   * out here from the props (the same operations, so the same double),
   * and the largest magnitude over the levels, which sets the flag */
  ck_assert_double_eq(
      r.round_level,
      sp.round_tol * sp.mu * fabs(sp.field.Omega) / r.h[r.levels - 1]);
  for (int f = 0; f < VSPH_VISCOUS_FORM_COUNT; f++) {
    double mx = 0.0;
    for (size_t l = 0; l < r.levels; l++) mx = fmax(mx, r.magnitude[f][l]);
    ck_assert_double_eq(r.max_magnitude[f], mx);
    ck_assert_int_eq(r.rounding[f], mx <= r.round_level);
  }
}
END_TEST

/* For a linear field the MGF operator is exactly mu F:D with the discrete
 * F of the same particle set (Taylor expansion exact): an independent
 * path through moments.c. Normal component: mu (F_d00 D_00 + F_ddd D_dd).
 * h F -> -2 C_F and h N -> -C_N as h/dx grows: within 1 % at h/dx = 6
 * (measured 0.5 %; 1.1 % at h/dx = 4, 10 % at 4/3 for N). */
START_TEST(test_mgf_equals_FD) {
  struct vsph_scaling_props sp;
  setup(&sp, VSPH_FIELDS_STRAIN, 2);
  sp.hdx = 6.0;
  sp.levels = 2;
  struct vsph_scaling_result r;
  ck_assert_int_eq(vsph_scaling_surface(&sp, &r), 0);
  const double h = r.h[0], dx = h / sp.hdx;
  struct vsph_lattice_props lp = {.dim = 2, .dx = dx};
  struct vsph_particles *p = NULL;
  size_t c;
  ck_assert_int_eq(vsph_lattice_halfspace(&lp, 2 * 3 * h + 2 * dx, 0.0, &p, &c),
                   0);
  struct vsph_moments m;
  ck_assert_int_eq(vsph_moments_sum(sp.kernel, p, c, h, &m), 0);
  vsph_particles_free(p);
  const double A = sp.field.A;
  const double want = sp.mu * (m.F[1][0][0] * A - m.F[1][1][1] * A);
  ck_assert_double_eq_tol(r.normal[VSPH_VISCOUS_MGF][0], want,
                          1e-12 * fabs(want));
  gsl_integration_workspace *ws = gsl_integration_workspace_alloc(100);
  double C_F, C_N;
  ck_assert_int_eq(vsph_moments_constants(sp.kernel, 2, 1e-10, ws, &C_F, &C_N),
                   0);
  gsl_integration_workspace_free(ws);
  ck_assert_double_eq_tol(r.hF[0], -2.0 * C_F, 0.01 * 2.0 * C_F);
  ck_assert_double_eq_tol(r.hN[0], -C_N, 0.01 * C_N);
}
END_TEST

/* Interior: MGF -> mu(lap u + 2 grad div u), MEAF -> mu lap u on a
 * quadratic field as h/dx grows. Measured: MGF 14 % at h/dx = 1 down to
 * 5.5e-4 at 4 (lattice error of G); MEAF below 4e-3 throughout (its
 * lattice error of M is small, floored by the 3h truncation). */
START_TEST(test_interior_convergence) {
  struct vsph_scaling_props sp;
  setup(&sp, VSPH_FIELDS_QUADRATIC, 2);
  const double hdx[4] = {1.0, 4.0 / 3.0, 2.0, 4.0};
  struct vsph_scaling_interior r;
  ck_assert_int_eq(vsph_scaling_interior(&sp, hdx, 4, &r), 0);
  for (size_t l = 1; l < 4; l++) ck_assert_double_lt(r.mgf[l], r.mgf[l - 1]);
  ck_assert_double_lt(r.mgf[3], 1e-3);
  ck_assert_double_gt(r.mgf[0], 0.05); /* the effect is real at h/dx = 1 */
  for (size_t l = 0; l < 4; l++) ck_assert_double_lt(r.meaf[l], 4e-3);
}
END_TEST

/* The square's axis (paper Fig. 7): at fixed h/dx the lattice sums are
 * self-similar, so the top row's term is exactly proportional to 1/h
 * (ratio 2 when L/dx doubles, to rounding: the far edges lie beyond the
 * support); the bottom row mirrors the top (u_y = -A y is odd in y); rows
 * further than 2 kappa h from both edges see a symmetric lattice, where a
 * linear field's term is zero (odd moments vanish) to rounding. Model A
 * uncorrected (Basa's eq. 27) is the exception: it is not zero-order
 * consistent, so its term holds u_i sum V d2W ~ u_i/h^2 besides the 1/h
 * part, and the top row's ratio lies between 2 and 4 (measured 3.82); its
 * interior rows carry u_i times the lattice's uniform-field error. */
START_TEST(test_square_axis) {
  struct vsph_scaling_props sp;
  ck_assert_int_eq(vsph_scaling_props_init(&sp, NULL), 0);
  ck_assert_int_eq(vsph_fields_props_init(&sp.field, VSPH_FIELDS_STRAIN, 2), 0);
  /* at h/dx = 4/3 the 3h Gaussian's support edge 4 dx passes through
   * lattice nodes, which rounding puts inside at one resolution and
   * outside at another (0.1 % at L/dx = 20): 1.3 keeps every node off
   * the edge */
  sp.hdx = 1.3;
  double y[2][40], v[2][VSPH_VISCOUS_FORM_COUNT][40];
  size_t n[2];
  for (int r = 0; r < 2; r++) {
    double *f[VSPH_VISCOUS_FORM_COUNT];
    for (int k = 0; k < VSPH_VISCOUS_FORM_COUNT; k++) f[k] = v[r][k];
    ck_assert_int_eq(vsph_scaling_axis(&sp, 20 * (r + 1), y[r], f, &n[r]), 0);
  }
  ck_assert_uint_eq(n[1], 40);
  for (int form = 0; form < VSPH_VISCOUS_FORM_COUNT; form++) {
    const double top1 = v[0][form][19], top2 = v[1][form][39];
    /* Schwaiger's VISC-03 corrects for the truncated support: its surface
     * term is sixty times smaller than MEAF's, but still 1/h */
    ck_assert_double_gt(fabs(top1), form == VSPH_VISCOUS_VISC03 ? 1e-3 : 0.1);
    if (form == VSPH_VISCOUS_TAKEDA) {
      ck_assert_double_gt(top2 / top1, 3.0);
      ck_assert_double_lt(top2 / top1, 4.0);
      continue;
    }
    ck_assert_double_eq_tol(top2 / top1, 2.0, 1e-9);
    ck_assert_double_eq_tol(v[1][form][0], -top2, 1e-9 * fabs(top2));
    const double reach = 2 * 3.0 * sp.hdx / 40.0 + 1.0 / 40.0;
    for (size_t k = 0; k < 40; k++)
      if (fabs(y[1][k]) < 0.5 - reach)
        ck_assert_double_le(fabs(v[1][form][k]), 1e-10 * fabs(top2));
  }
}
END_TEST

Suite *vsph_scaling_suite(void) {
  Suite *s = suite_create("scaling");
  TCase *tc = tcase_create("surface");
  tcase_set_timeout(tc, 60);
  tcase_add_loop_test(tc, test_strain_slopes, 0, 2);
  tcase_add_test(tc, test_strain_slopes_perturbed);
  tcase_add_loop_test(tc, test_rotation_slopes, 0, 2);
  tcase_add_test(tc, test_mgf_equals_FD);
  tcase_add_test(tc, test_interior_convergence);
  tcase_add_test(tc, test_square_axis);
  suite_add_tcase(s, tc);
  return s;
}
