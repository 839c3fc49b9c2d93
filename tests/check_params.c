/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "../common/params.h"
#include "check_suites.h"

static char path[64];
static void write_file(const char *text) {
  snprintf(path, sizeof path, "/tmp/vsph_paramsXXXXXX");
  const int fd = mkstemp(path);
  ck_assert_int_ge(fd, 0);
  FILE *f = fdopen(fd, "w");
  fputs(text, f);
  fclose(f);
}

START_TEST(test_read_and_get) {
  write_file(
      "# a comment\nSolver:\n  cfl: 0.75   # inline\n  kernel: cubic\n"
      "Scene:\n  nu: 2.385e-4\n  box: [1, 2.5, -3]\n");
  struct vsph_params *p = vsph_params_alloc();
  ck_assert_int_eq(vsph_params_read(p, path), 0);
  remove(path);
  double v;
  ck_assert_int_eq(vsph_params_get_double(p, "Solver:cfl", &v), 0);
  ck_assert(v == 0.75);
  ck_assert_int_eq(vsph_params_get_double_or(p, "Scene:nu", 1.0, &v), 0);
  ck_assert(v == 2.385e-4);
  ck_assert_int_eq(vsph_params_get_double_or(p, "Scene:R", 1.2348, &v), 0);
  ck_assert(v == 1.2348); /* default, recorded as used */
  const char *s, *s2;
  ck_assert_int_eq(vsph_params_get_string_or(p, "Solver:kernel", "x", &s), 0);
  ck_assert_str_eq(s, "cubic");
  /* the key given but never read is reported */
  ck_assert_str_eq(vsph_params_unused(p), "Scene:box");
  ck_assert_int_eq(vsph_params_get_string_or(p, "Scene:box", "", &s2), 0);
  ck_assert_str_eq(s2, "1, 2.5, -3");
  ck_assert_ptr_null(vsph_params_unused(p));
  /* overrides win; many insertions keep earlier pointers valid */
  ck_assert_int_eq(vsph_params_set(p, "Solver:cfl", "0.5"), 0);
  for (int i = 0; i < 100; i++) {
    char k[32];
    snprintf(k, sizeof k, "Extra:k%d", i);
    ck_assert_int_eq(vsph_params_get_double_or(p, k, i, &v), 0);
  }
  ck_assert_str_eq(s, "cubic");
  ck_assert_int_eq(vsph_params_get_double(p, "Solver:cfl", &v), 0);
  ck_assert(v == 0.5);
  ck_assert_uint_eq(vsph_params_count(p), 105);
  vsph_params_free(p);
}
END_TEST

/* Everything outside the subset is refused. */
static const char *const bad_files[] = {
    "Solver:\n  cfl: [1, [2]]\n",
    "Solver:\n  deep:\n    cfl: 1\n",
    "a: &x 1\n",
    "Solver:\n  cfl: 1\n---\nScene:\n  nu: 1\n",
    "Solver:\n  cfl: 1\n  cfl: 2\n",
    "cfl: 1\n",
    "Solver: [\n",
    "Solver:\n  cfl: *x\n",
    /* a NUL inside a value (issue 23, defect 12): it was read as "linear" */
    "Solver:\n  walls: \"linear\\u0000junk\"\n",
};

START_TEST(test_bad_files) {
  vsph_test_silence();
  write_file(bad_files[_i]);
  struct vsph_params *p = vsph_params_alloc();
  ck_assert_int_eq(vsph_params_read(p, path), 1 /* VSPH_EINVAL */);
  remove(path);
  vsph_params_free(p);
}
END_TEST

START_TEST(test_bad_files_keys_values_refused) {
  vsph_test_silence();
  struct vsph_params *p = vsph_params_alloc();
  ck_assert_int_eq(vsph_params_read(p, "/nonexistent/x.yml"), 3 /* EIO */);
  ck_assert_int_eq(vsph_params_set(p, "cfl", "1"), 1);
  ck_assert_int_eq(vsph_params_set(p, "Solver:", "1"), 1);
  ck_assert_int_eq(vsph_params_set(p, "A:b:c", "1"), 1);
  double v;
  ck_assert_int_eq(vsph_params_get_double(p, "Solver:missing", &v), 1);
  ck_assert_int_eq(vsph_params_set(p, "Solver:cfl", "1.5x"), 0);
  ck_assert_int_eq(vsph_params_get_double_or(p, "Solver:cfl", 1, &v), 1);
  vsph_params_free(p);
}
END_TEST

Suite *vsph_params_suite(void) {
  Suite *s = suite_create("params");
  TCase *tc = tcase_create("yaml");
  tcase_add_test(tc, test_read_and_get);
  tcase_add_loop_test(tc, test_bad_files, 0,
                      (int)(sizeof bad_files / sizeof bad_files[0]));
  tcase_add_test(tc, test_bad_files_keys_values_refused);
  suite_add_tcase(s, tc);
  return s;
}
