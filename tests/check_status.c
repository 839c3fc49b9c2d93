/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
#include <fcntl.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "../common/scratch.h"
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

/* A scratch file: written and read back, nothing left in its folder (the
 * folder removable at once), closed on exec; none where the folder does
 * not exist (NULL, and no name handed back). */
START_TEST(test_scratch_file_unlinked_closed_on_exec) {
  char dir[] = "/tmp/vsph_scratchXXXXXX";
  ck_assert_ptr_nonnull(mkdtemp(dir));
  char *kept = (char *)1;
  FILE *f = vsph_scratch_open(dir, "s-", &kept);
  ck_assert_ptr_nonnull(f);
  ck_assert_ptr_null(kept); /* unlinked at once on this file system */
  ck_assert_int_eq(fcntl(fileno(f), F_GETFD) & FD_CLOEXEC, FD_CLOEXEC);
  static const char text[] = "scratch";
  char back[sizeof text];
  ck_assert_uint_eq(fwrite(text, 1, sizeof text, f), sizeof text);
  ck_assert_int_eq(fseek(f, 0, SEEK_SET), 0);
  ck_assert_uint_eq(fread(back, 1, sizeof back, f), sizeof back);
  ck_assert_str_eq(back, text);
  ck_assert_int_eq(rmdir(dir), 0); /* empty while the file is open */
  fclose(f);
  char missing[64];
  snprintf(missing, sizeof missing, "%s/none", dir);
  kept = (char *)1;
  ck_assert_ptr_null(vsph_scratch_open(missing, "s-", &kept));
  ck_assert_ptr_null(kept);
}
END_TEST

Suite *vsph_status_suite(void) {
  Suite *s = suite_create("status");
  TCase *tc = tcase_create("core");
  tcase_add_test(tc, test_names_complete);
  tcase_add_test(tc, test_fail_reports_and_returns);
  tcase_add_test(tc, test_scratch_file_unlinked_closed_on_exec);
  suite_add_tcase(s, tc);
  return s;
}
