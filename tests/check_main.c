/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
/* The single Check runner. No OpenMP region may run before
 * srunner_run_all: forked tests would deadlock in their first one. */
#include <gsl/gsl_errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../common/params.h"
#include "../common/status.h"
#include "../solver/run.h"
#include "../solver/scene.h"
#include "check_suites.h"

static int last_status;
static void silent(int status, const char *file, int line, const char *msg) {
  (void)file;
  (void)line;
  (void)msg;
  last_status = status;
}
struct vsph_run *vsph_test_run(const struct vsph_scene_type *type,
                               const char *const *set, struct vsph_scene *sc) {
  struct vsph_params *prm = vsph_params_alloc();
  for (size_t k = 0; set[k]; k++) {
    char key[128];
    const char *eq = strchr(set[k], '=');
    ck_assert_ptr_nonnull(eq);
    ck_assert_uint_lt((size_t)(eq - set[k]), sizeof key);
    memcpy(key, set[k], (size_t)(eq - set[k]));
    key[eq - set[k]] = '\0';
    ck_assert_int_eq(vsph_params_set(prm, key, eq + 1), 0);
  }
  struct vsph_run_props rp;
  struct vsph_scene scene;
  ck_assert_int_eq(vsph_run_props_init(&rp, prm), 0);
  ck_assert_int_eq(vsph_scene_init(&scene, type, prm), 0);
  vsph_params_free(prm);
  struct vsph_run *run = NULL;
  ck_assert_int_eq(vsph_run_alloc(&rp, &scene, &run), 0);
  if (sc) *sc = scene;
  return run;
}

void vsph_test_silence(void) {
  last_status = 0;
  vsph_status_set_handler(silent);
}
int vsph_test_last_status(void) { return last_status; }

/* The suites in the order they run, and the lane of each when make check
 * runs two runners at once (scripts/check-lanes: VSPH_CHECK_LANE=1 and
 * 2 on two cores; unset: every suite here). Lane 1 holds the four
 * slowest (the library's installs and compiles, the contact and channel
 * runs, the baseline), lane 2 the other 32: 81 s and 75 s of 156 s,
 * measured one suite at a time on the project's 2-core machine. */
static const struct {
  Suite *(*make)(void);
  int lane;
} SUITES[] = {
    {vsph_status_suite, 2},     {vsph_params_suite, 2},
    {vsph_kernel_suite, 2},     {vsph_moments_suite, 2},
    {vsph_cells_suite, 2},      {vsph_viscous_suite, 2},
    {vsph_pair_suite, 2},       {vsph_equations_suite, 2},
    {vsph_scaling_suite, 2},    {vsph_dissipation_suite, 2},
    {vsph_laplacian_suite, 2},  {vsph_poisson_suite, 2},
    {vsph_references_suite, 2}, {vsph_solver_suite, 2},
    {vsph_baseline_suite, 1},   {vsph_cli_suite, 2},
    {vsph_hardening_suite, 2},  {vsph_channel_suite, 1},
    {vsph_walls_suite, 2},      {vsph_integrate_suite, 2},
    {vsph_cavity_suite, 2},     {vsph_contact_suite, 1},
    {vsph_jobs_suite, 2},       {vsph_rundir_suite, 2},
    {vsph_folder_suite, 2},     {vsph_archive_suite, 2},
    {vsph_report_suite, 2},     {vsph_vtk_suite, 2},
    {vsph_plot_suite, 2},       {vsph_series_suite, 2},
    {vsph_grade_suite, 2},      {vsph_claim_suite, 2},
    {vsph_measures_suite, 2},   {vsph_api_suite, 2},
    {vsph_fvref_suite, 2},      {vsph_library_suite, 1},
};

int main(void) {
  gsl_set_error_handler_off();
  const char *env = getenv("VSPH_CHECK_LANE");
  /* 0: every suite */
  const int lane = !env                ? 0
                   : !strcmp(env, "1") ? 1
                   : !strcmp(env, "2") ? 2
                                       : -1;
  SRunner *sr = NULL;
  /* every suite in one of the two lanes: a third would run in neither */
  for (size_t k = 0; k < sizeof SUITES / sizeof SUITES[0]; k++)
    if (SUITES[k].lane != 1 && SUITES[k].lane != 2) {
      fprintf(stderr, "check_vsph: suite %zu has lane %d, not 1 or 2\n", k,
              SUITES[k].lane);
      return EXIT_FAILURE;
    }
  if (lane < 0) {
    fprintf(stderr, "check_vsph: VSPH_CHECK_LANE is 1 or 2, not '%s'\n", env);
    return EXIT_FAILURE;
  }
  for (size_t k = 0; k < sizeof SUITES / sizeof SUITES[0]; k++) {
    if (lane && SUITES[k].lane != lane) continue; /* the lane's own */
    if (!sr)
      sr = srunner_create(SUITES[k].make());
    else
      srunner_add_suite(sr, SUITES[k].make());
  }
  if (!sr) {
    fprintf(stderr, "check_vsph: lane %d holds no suite\n", lane);
    return EXIT_FAILURE;
  }
  srunner_run_all(sr, CK_NORMAL);
  const int failed = srunner_ntests_failed(sr);
  srunner_free(sr);
  return failed ? EXIT_FAILURE : EXIT_SUCCESS;
}
