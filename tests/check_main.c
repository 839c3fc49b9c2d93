/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
/* The single Check runner. No OpenMP region may run before
 * srunner_run_all: forked tests would deadlock in their first one. */
#include <gsl/gsl_errno.h>
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

int main(void) {
  gsl_set_error_handler_off();
  SRunner *sr = srunner_create(vsph_status_suite());
  srunner_add_suite(sr, vsph_params_suite());
  srunner_add_suite(sr, vsph_kernel_suite());
  srunner_add_suite(sr, vsph_moments_suite());
  srunner_add_suite(sr, vsph_cells_suite());
  srunner_add_suite(sr, vsph_viscous_suite());
  srunner_add_suite(sr, vsph_pair_suite());
  srunner_add_suite(sr, vsph_equations_suite());
  srunner_add_suite(sr, vsph_scaling_suite());
  srunner_add_suite(sr, vsph_dissipation_suite());
  srunner_add_suite(sr, vsph_laplacian_suite());
  srunner_add_suite(sr, vsph_poisson_suite());
  srunner_add_suite(sr, vsph_references_suite());
  srunner_add_suite(sr, vsph_solver_suite());
  srunner_add_suite(sr, vsph_baseline_suite());
  srunner_add_suite(sr, vsph_cli_suite());
  srunner_add_suite(sr, vsph_hardening_suite());
  srunner_add_suite(sr, vsph_channel_suite());
  srunner_add_suite(sr, vsph_walls_suite());
  srunner_add_suite(sr, vsph_integrate_suite());
  srunner_add_suite(sr, vsph_cavity_suite());
  srunner_add_suite(sr, vsph_contact_suite());
  srunner_add_suite(sr, vsph_jobs_suite());
  srunner_add_suite(sr, vsph_rundir_suite());
  srunner_add_suite(sr, vsph_folder_suite());
  srunner_add_suite(sr, vsph_archive_suite());
  srunner_add_suite(sr, vsph_report_suite());
  srunner_add_suite(sr, vsph_vtk_suite());
  srunner_add_suite(sr, vsph_plot_suite());
  srunner_add_suite(sr, vsph_series_suite());
  srunner_add_suite(sr, vsph_grade_suite());
  srunner_add_suite(sr, vsph_claim_suite());
  srunner_add_suite(sr, vsph_api_suite());
  srunner_add_suite(sr, vsph_fvref_suite());
  srunner_add_suite(sr, vsph_library_suite());
  srunner_run_all(sr, CK_NORMAL);
  const int failed = srunner_ntests_failed(sr);
  srunner_free(sr);
  return failed ? EXIT_FAILURE : EXIT_SUCCESS;
}
