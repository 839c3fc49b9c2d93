/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
#include "../common/status.h"
#include "check_suites.h"

START_TEST(test_names_complete) {
  for (int s = 0; s < VSPH_STATUS_COUNT; s++)
    ck_assert_ptr_nonnull(vsph_status_str(s));
  ck_assert_str_eq(vsph_status_str(VSPH_EINVAL), "invalid argument");
  ck_assert_str_eq(vsph_status_str(-1), "unknown status");
}
END_TEST

static int fail_helper(void) { VSPH_FAIL(VSPH_ENOCONV, "value %d", 7); }

START_TEST(test_fail_reports_and_returns) {
  vsph_test_silence();
  ck_assert_int_eq(fail_helper(), VSPH_ENOCONV);
  ck_assert_int_eq(vsph_test_last_status(), VSPH_ENOCONV);
}
END_TEST

Suite *vsph_status_suite(void) {
  Suite *s = suite_create("status");
  TCase *tc = tcase_create("core");
  tcase_add_test(tc, test_names_complete);
  tcase_add_test(tc, test_fail_reports_and_returns);
  suite_add_tcase(s, tc);
  return s;
}
