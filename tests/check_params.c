/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "../common/consts.h"
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

/* vsph_params_nearest by hand: a swap of two neighbours is one step
 * ("vsic" -> "visc"), case is no step, and a word further than its slip
 * allowance (1 step up to 4 letters, 2 up to 8, 3 beyond) has no
 * nearest; vsph_params_hint names the nearest key the store holds and
 * lists its section's keys. */
START_TEST(test_nearest_and_hint) {
  const char *const cand[] = {"visc", "cfl", "t_end", "checkpoint_s"};
  ck_assert_uint_eq(vsph_params_nearest("vsic", cand, 4), 0);
  ck_assert_uint_eq(vsph_params_nearest("CFL", cand, 4), 1);
  ck_assert_uint_eq(vsph_params_nearest("cf", cand, 4), 1);       /* 1 step */
  ck_assert_uint_eq(vsph_params_nearest("xyl", cand, 4), 4);      /* 2 > 1 */
  ck_assert_uint_eq(vsph_params_nearest("tend", cand, 4), 2);     /* 1 step */
  ck_assert_uint_eq(vsph_params_nearest("t_ned_", cand, 4), 2);   /* 1 + 1 */
  ck_assert_uint_eq(vsph_params_nearest("t_nde___", cand, 4), 4); /* 1 + 3 */
  ck_assert_uint_eq(vsph_params_nearest("chekpoint_sx", cand, 4), 3); /* 2 */
  ck_assert_uint_eq(vsph_params_nearest(NULL, cand, 4), 4);
  struct vsph_params *prm = vsph_params_alloc();
  ck_assert_int_eq(vsph_params_set(prm, "Solver:visc", "mgf"), 0);
  ck_assert_int_eq(vsph_params_set(prm, "Solver:cfl", "1"), 0);
  ck_assert_int_eq(vsph_params_set(prm, "Scene:Re", "100"), 0);
  char buf[256];
  vsph_params_hint(prm, "Solver:vsic", buf, sizeof buf);
  ck_assert_str_eq(buf,
                   "; did you mean Solver:visc? (the Solver keys: visc, "
                   "cfl)");
  vsph_params_hint(prm, "Scen:Re", buf, sizeof buf);
  ck_assert_str_eq(buf,
                   "; did you mean Scene:Re? (the sections: Solver, Scene)");
  vsph_params_hint(prm, "Scene:zzzzzz", buf, sizeof buf);
  ck_assert_str_eq(buf, " (the Scene keys: Re)");
  vsph_params_hint(prm, "Solver:vsic", buf, 20); /* cut, marked */
  ck_assert_uint_eq(strlen(buf), 19);
  ck_assert_str_eq(buf + 15, "...)");
  vsph_params_free(prm);
  /* common/consts.h: what a table prints never reads "-0.0" */
  char t[32];
  snprintf(t, sizeof t, "%+.1f %.3e", vsph_consts_shown(-0.04, 0.05),
           vsph_consts_shown(-0.0, 0.0));
  ck_assert_str_eq(t, "+0.0 0.000e+00");
  snprintf(t, sizeof t, "%+.1f %.3e", vsph_consts_shown(-0.06, 0.05),
           vsph_consts_shown(-1e-300, 0.0));
  ck_assert_str_eq(t, "-0.1 -1.000e-300");
}
END_TEST

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

START_TEST(test_bad_yaml_files_refused) {
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
  tcase_add_test(tc, test_nearest_and_hint);
  tcase_add_loop_test(tc, test_bad_yaml_files_refused, 0,
                      (int)(sizeof bad_files / sizeof bad_files[0]));
  tcase_add_test(tc, test_bad_files_keys_values_refused);
  suite_add_tcase(s, tc);
  return s;
}
