/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
/* Regression baseline: the quick report's key figures for each scene and
 * formulation (its coarsest runs), committed in reports/baseline.csv, are
 * recomputed and compared. A change to the numerics shows up here.
 * The channel rows (every formulation, Poiseuille and Couette, Basa et
 * al.'s kernel) hold E_k against the series and the RMS velocity error at
 * t_end in place of the free-surface rows' E_k and initial dissipation.
 * Tolerances: the verdict (stable or not) must match; the figures agree
 * to 1e-6 relative (plus 1e-9 absolute: VSPH_ARCHIVE_BASELINE_REL and
 * _ABS, by which the run archive judges too): the code is deterministic, so
 * only compiler or libm rounding (about 1e-12, grown over a few thousand
 * steps) may differ. Update the baseline with `make baseline` after an
 * intended change, and say why in the commit. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "../analysis/series.h"
#include "../reports/report_claims.h"
#include "../reports/report_parts.h"
#include "../runs/archive.h"
#include "check_suites.h"

START_TEST(test_baseline_rows_hold) {
  FILE *f = fopen("reports/baseline.csv", "r");
  ck_assert_msg(f != NULL, "reports/baseline.csv is missing");
  char line[512];
  ck_assert_ptr_nonnull(fgets(line, sizeof line, f)); /* header */
  char dir[] = "/tmp/vsph_baselineXXXXXX";
  ck_assert_ptr_nonnull(mkdtemp(dir));
  struct vsph_report R;
  memset(&R, 0, sizeof R);
  R.dir = R.runs.jobs.dir = dir;
  size_t i = 0;
  while (fgets(line, sizeof line, f)) {
    char scene[32], visc[16];
    size_t res;
    double t_end, ek, d0;
    int ok;
    ck_assert_int_eq(sscanf(line, "%31[^,],%15[^,],%zu,%lf,%lf,%lf,%d", scene,
                            visc, &res, &t_end, &ek, &d0, &ok),
                     7);
    struct vsph_report_baseline b;
    ck_assert_int_eq(vsph_report_runs_baseline(&R.runs, i, &b), 0);
    ck_assert_str_eq(b.scene, scene);
    ck_assert_str_eq(b.visc, visc);
    ck_assert_uint_eq(b.res, res);
    ck_assert_msg(b.ok == ok, "%s %s: stability verdict changed", scene, visc);
    ck_assert_msg(
        fabs(b.ek_final - ek) <=
            VSPH_ARCHIVE_BASELINE_REL * fabs(ek) + VSPH_ARCHIVE_BASELINE_ABS,
        "%s %s: final E_k figure %.10e, baseline %.10e", scene, visc,
        b.ek_final, ek);
    ck_assert_msg(fabs(b.diss0 - d0) <= VSPH_ARCHIVE_BASELINE_REL * fabs(d0) +
                                            VSPH_ARCHIVE_BASELINE_ABS,
                  "%s %s: initial dissipation error %.10e, baseline %.10e",
                  scene, visc, b.diss0, d0);
    i++;
  }
  fclose(f);
  ck_assert_uint_eq(i, vsph_report_runs_baseline_count());
  char cmd[128];
  snprintf(cmd, sizeof cmd, "rm -rf %s", dir);
  ck_assert_int_eq(system(cmd), 0);
}
END_TEST

/* The energy budget of report_runs.c on synthetic rows: a run that loses
 * its energy exactly like the reference (E = E_k(0) e^{-g t} while
 * E_m = E_m(0) e^{-g t}, whatever the offsets E_p, E_c and the E_k(0)
 * against E_m(0) normalisation) scores 1 to rounding; one that loses twice
 * as much scores 2; the kinetic/potential split does not enter. */
START_TEST(test_loss_ratio) {
  enum { N = 5 };
  double t[N], Ek[N], Ep[N], Ec[N], Emr[N];
  const double g = 0.37, E0 = 0.25;
  for (int k = 0; k < N; k++) {
    t[k] = 0.5 * k;
    const double E = E0 * exp(-g * t[k]);
    const double share = 0.5 * (1 + cos(3.1 * t[k])); /* kinetic share */
    Ek[k] = share * E;
    Ep[k] = -4.9 + (1 - share) * E; /* hydrostatic offset */
    Ec[k] = 0.016;
    Emr[k] = 1.07 * E0 * exp(-g * t[k]); /* another E(0) */
  }
  Ek[0] = E0, Ep[0] = -4.9; /* all kinetic at t = 0 */
  struct vsph_jobs_run r = {
      .nrow = N, .t = t, .Ek = Ek, .Ep = Ep, .Ec = Ec, .Emr = Emr};
  for (size_t k = 1; k < N; k++)
    ck_assert_double_eq_tol(vsph_report_runs_loss_ratio(&r, k), 1.0, 1e-12);
  ck_assert(isnan(vsph_report_runs_loss_ratio(&r, 0)));
  for (int k = 1; k < N; k++) Ec[k] -= E0 * (1 - exp(-g * t[k]));
  for (size_t k = 1; k < N; k++)
    ck_assert_double_eq_tol(vsph_report_runs_loss_ratio(&r, k), 2.0, 1e-12);
}
END_TEST

/* The square's reference extrapolation recovers E* exactly from data of
 * the model it assumes, E(h, r) = E* + a h + b eps(r) (first order in h,
 * error proportional to the lattice error at h/dx = r), for any a and b;
 * and it is the identity when the data carry no error. Rounding only. */
START_TEST(test_extrapolate) {
  const double eps[2] = {-0.0115, -0.00195}, Es = 0.0833;
  const double h[2][2] = {{0.0667, 0.0333}, {0.075, 0.0375}};
  for (int t = 0; t < 3; t++) {
    const double a = 0.3 * (t + 1), b = -2.1 + t;
    double e[2][2];
    for (int r = 0; r < 2; r++)
      for (int m = 0; m < 2; m++)
        e[r][m] = Es + a * (m ? h[r][0] / 2 : h[r][0]) + b * eps[r];
    ck_assert_double_eq_tol(vsph_series_extrapolate(e, eps), Es, 1e-13);
  }
  double flat[2][2] = {{Es, Es}, {Es, Es}};
  ck_assert_double_eq_tol(vsph_series_extrapolate(flat, eps), Es, 1e-15);
}
END_TEST

Suite *vsph_baseline_suite(void) {
  Suite *s = suite_create("baseline");
  TCase *tc = tcase_create("quick report");
  tcase_set_timeout(tc, 180);
  tcase_add_test(tc, test_baseline_rows_hold);
  tcase_add_test(tc, test_loss_ratio);
  tcase_add_test(tc, test_extrapolate);
  suite_add_tcase(s, tc);
  return s;
}
