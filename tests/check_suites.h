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
Suite *vsph_scaling_suite(void);
Suite *vsph_dissipation_suite(void);
Suite *vsph_poisson_suite(void);
Suite *vsph_references_suite(void);
Suite *vsph_solver_suite(void);
Suite *vsph_baseline_suite(void);
Suite *vsph_cli_suite(void);

/* Silent error handler for tests: records the last status. */
void vsph_test_silence(void);
int vsph_test_last_status(void);

#endif
