/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
#ifndef VSPH_TESTS_CHECK_SUITES_H
#define VSPH_TESTS_CHECK_SUITES_H
/* One suite per module, all run by tests/check_main.c (STYLE B10). */
#include <check.h>

Suite *vsph_status_suite(void);
Suite *vsph_params_suite(void);
Suite *vsph_kernel_suite(void);
Suite *vsph_moments_suite(void);
Suite *vsph_cells_suite(void);
Suite *vsph_viscous_suite(void);
Suite *vsph_pair_suite(void);
Suite *vsph_equations_suite(void);
Suite *vsph_scaling_suite(void);
Suite *vsph_dissipation_suite(void);
Suite *vsph_laplacian_suite(void);
Suite *vsph_poisson_suite(void);
Suite *vsph_references_suite(void);
Suite *vsph_solver_suite(void);
Suite *vsph_baseline_suite(void);
Suite *vsph_cli_suite(void);
Suite *vsph_hardening_suite(void);
Suite *vsph_channel_suite(void);
Suite *vsph_walls_suite(void);
Suite *vsph_integrate_suite(void);
Suite *vsph_cavity_suite(void);
Suite *vsph_contact_suite(void);
Suite *vsph_jobs_suite(void);
Suite *vsph_report_suite(void);
Suite *vsph_vtk_suite(void);
Suite *vsph_plot_suite(void);
Suite *vsph_rundir_suite(void);
Suite *vsph_folder_suite(void);
Suite *vsph_archive_suite(void);
Suite *vsph_library_suite(void);
Suite *vsph_series_suite(void);
Suite *vsph_grade_suite(void);
Suite *vsph_claim_suite(void);
Suite *vsph_measures_suite(void);
Suite *vsph_api_suite(void);
Suite *vsph_fvref_suite(void);

/* What a run of the built binary ($VSPH_BIN) gave (tests/check_cli.c). */
struct vsph_test_outcome {
  int status;        /* exit status, -1 if it did not exit */
  char out[1 << 16]; /* stdout */
  char err[4096];    /* stderr */
  int err_lines;     /* lines on stderr */
};
/* Run `$VSPH_BIN ARGS` through the shell (static result, overwritten). */
struct vsph_test_outcome *vsph_test_cli(const char *args);
/* Run a shell script (it may use $VSPH_BIN) and capture its output. */
struct vsph_test_outcome *vsph_test_shell(const char *script);
/* A scratch folder: DIR ends in XXXXXX (mkdtemp); removed with all it
 * holds by vsph_test_rm_tree. */
void vsph_test_scratch(char *dir);
void vsph_test_rm_tree(const char *dir);
/* The first n - 1 bytes of a file ("" if it cannot be read). */
void vsph_test_slurp(const char *path, char *buf, size_t n);

/* Array NAME of the snapshot at PATH, decoded by the test's own reader
 * (tests/check_vtk.c) as doubles (malloc'd; NULL if the file has none):
 * its components into ncomp, its values into count. */
double *vsph_test_vtp_values(const char *path, const char *name, int *ncomp,
                             size_t *count);

struct vsph_run;
struct vsph_scene;
struct vsph_scene_type;
/* A run of scene TYPE with the settings SET ("Section:key=value" strings,
 * NULL-terminated), every step asserted to succeed; the scene into *sc
 * when sc is not NULL. */
struct vsph_run *vsph_test_run(const struct vsph_scene_type *type,
                               const char *const *set, struct vsph_scene *sc);

/* Silent error handler for tests: records the last status. */
void vsph_test_silence(void);
int vsph_test_last_status(void);

#endif
