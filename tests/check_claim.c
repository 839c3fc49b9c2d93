/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
/* reports/claim.c, the verdict engine: every test kind at, just below and
 * just above its threshold on values worked by hand; the verdict chosen by
 * the first expression that holds; templates filled; each malformed block
 * refused with a status; and every claim block compiled in (from
 * reports/claims/) well formed. */
#include <check.h>
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../analysis/series.h"
#include "../common/status.h"
#include "../reports/claim.h"
#include "../reports/grade.h"
#include "../reports/text.h"
#include "check_suites.h"

/* Kind @p kind on the values @p a, @p b, @p c. */
static int t3(const char *kind, double a, double b, double c) {
  const double x[3] = {a, b, c};
  return vsph_claim_test(kind, x);
}

/* The four comparisons at their threshold (1), just below and just
 * above it (the next doubles), and with NaN on either side (never). */
START_TEST(test_kinds_compare) {
  const double th = 0.12, lo = nextafter(th, 0.0), hi = nextafter(th, 1.0);
  /* below: a < b, strict */
  ck_assert_int_eq(t3("below", lo, th, 0), 1);
  ck_assert_int_eq(t3("below", th, th, 0), 0);
  ck_assert_int_eq(t3("below", hi, th, 0), 0);
  /* atmost: a <= b */
  ck_assert_int_eq(t3("atmost", lo, th, 0), 1);
  ck_assert_int_eq(t3("atmost", th, th, 0), 1);
  ck_assert_int_eq(t3("atmost", hi, th, 0), 0);
  /* above: a > b, strict */
  ck_assert_int_eq(t3("above", lo, th, 0), 0);
  ck_assert_int_eq(t3("above", th, th, 0), 0);
  ck_assert_int_eq(t3("above", hi, th, 0), 1);
  /* atleast: a >= b */
  ck_assert_int_eq(t3("atleast", lo, th, 0), 0);
  ck_assert_int_eq(t3("atleast", th, th, 0), 1);
  ck_assert_int_eq(t3("atleast", hi, th, 0), 1);
  static const char *const k4[] = {"below", "atmost", "above", "atleast"};
  for (int k = 0; k < 4; k++) {
    ck_assert_int_eq(t3(k4[k], NAN, th, 0), 0);
    ck_assert_int_eq(t3(k4[k], th, NAN, 0), 0);
  }
}
END_TEST

/* within: |a - s| <= w, inclusive at both edges (2.5 from 2 by 0.5 is within;
 * the next double beyond is not); order: rounds to n (0.5 from 1 is not, the
 * next double inside is); apart: bad >= sqrt(10) good; larger: a > b + noise
 * (at b + noise it is not); flag: exactly 1; an unknown kind and a
 * fractional order: -1. */
START_TEST(test_kinds_rules) {
  ck_assert_int_eq(t3("within", 2.5, 2.0, 0.5), 1);
  ck_assert_int_eq(t3("within", nextafter(2.5, 3.0), 2.0, 0.5), 0);
  ck_assert_int_eq(t3("within", nextafter(2.5, 2.0), 2.0, 0.5), 1);
  ck_assert_int_eq(t3("within", 1.5, 2.0, 0.5), 1);
  ck_assert_int_eq(t3("within", nextafter(1.5, 1.0), 2.0, 0.5), 0);
  ck_assert_int_eq(t3("within", NAN, 2.0, 0.5), 0);
  ck_assert_int_eq(t3("order", 0.5, 1, 0), 0);
  ck_assert_int_eq(t3("order", nextafter(0.5, 1.0), 1, 0), 1);
  ck_assert_int_eq(t3("order", nextafter(1.5, 1.0), 1, 0), 1);
  ck_assert_int_eq(t3("order", 1.5, 1, 0), 0);
  ck_assert_int_eq(t3("order", NAN, 1, 0), 0);
  ck_assert_int_eq(t3("order", 1.0, 1.5, 0), -1);
  ck_assert_int_eq(t3("apart", VSPH_GRADE_APART, 1.0, 0), 1);
  ck_assert_int_eq(t3("apart", nextafter(VSPH_GRADE_APART, 0.0), 1.0, 0), 0);
  ck_assert_int_eq(t3("apart", nextafter(VSPH_GRADE_APART, 4.0), 1.0, 0), 1);
  ck_assert_int_eq(t3("apart", 0.0, 0.0, 0), 0); /* two zeros: not apart */
  ck_assert_int_eq(t3("apart", 1e-300, 0.0, 0), 1);
  ck_assert_int_eq(t3("apart", NAN, 1.0, 0), 0);
  ck_assert_int_eq(t3("larger", 1.5, 1.0, 0.5), 0);
  ck_assert_int_eq(t3("larger", nextafter(1.5, 2.0), 1.0, 0.5), 1);
  ck_assert_int_eq(t3("larger", nextafter(1.5, 1.0), 1.0, 0.5), 0);
  ck_assert_int_eq(t3("larger", NAN, 1.0, 0.5), 0);
  ck_assert_int_eq(t3("flag", 1.0, 0, 0), 1);
  ck_assert_int_eq(t3("flag", 0.0, 0, 0), 0);
  ck_assert_int_eq(t3("flag", nextafter(1.0, 2.0), 0, 0), 0);
  ck_assert_int_eq(t3("flag", nextafter(1.0, 0.0), 0, 0), 0);
  /* finite: measured, at the largest double and beyond it */
  ck_assert_int_eq(t3("finite", DBL_MAX, 0, 0), 1);
  ck_assert_int_eq(t3("finite", -DBL_MAX, 0, 0), 1);
  ck_assert_int_eq(t3("finite", INFINITY, 0, 0), 0);
  ck_assert_int_eq(t3("finite", NAN, 0, 0), 0);
  ck_assert_int_eq(t3("flag", NAN, 0, 0), 0);
  ck_assert_int_eq(t3("nearly", 1.0, 1.0, 0), -1);
}
END_TEST

/* A claim in the style of Basa et al.'s: Cleary's xi fails (eq. 38 at or
 * beyond 12 %) while the recalibrated one is good (below 5 %). */
static const char *const XI =
    "claim: Cleary's xi gives inaccurate velocities\n"
    "where: Basa §5\n"
    "paper: at or beyond 12 %\n"
    "ours: xi = 4.96333 {{bad*100:.1f}} %, xi = 4.24\n"
    "  {{good*100:.1f}} % ({{what}})\n"
    "setup: none\n"
    "test fails: atleast bad 0.12 -- the paper's failure level\n"
    "test good: below good 0.05 -- the paper's \"good\"\n"
    "if fails & good: reproduced: both\n"
    "if fails | good: partly: {{which}} holds\n"
    "else: differs: neither\n";

static int grade(const char *text, const struct vsph_claim_vals *v,
                 struct vsph_claim_row *row) {
  return vsph_claim_grade_text("test.claim", text, v, row);
}

/* The verdict is the first whose expression holds: both tests, one, none;
 * each at its threshold (12 % fails; 5 % is not good); the templates
 * filled with the measures (scaled, formatted) and words; the claim
 * marked with where it stands; the class follows. */
START_TEST(test_verdict_follows) {
  struct vsph_claim_vals v;
  struct vsph_claim_row row;
  const struct {
    double bad, good;
    const char *verdict;
  } cases[] = {{0.12, nextafter(0.05, 0.0), "reproduced: both"},
               {nextafter(0.12, 0.0), 0.01, "partly: the one holds"},
               {0.20, 0.05, "partly: the one holds"},
               {0.11, 0.05, "differs: neither"},
               /* "both" might hold: no verdict past it is certain */
               {NAN, 0.01,
                "not tested: a figure its verdict needs was not measured "
                "(unknown: fails)"}};
  for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
    vsph_claim_clear(&v);
    vsph_claim_num(&v, "bad", cases[k].bad);
    vsph_claim_num(&v, "good", cases[k].good);
    vsph_claim_str(&v, "what", "at t* = %.1f", 4.9);
    vsph_claim_str(&v, "which", "the one");
    ck_assert_int_eq(grade(XI, &v, &row), VSPH_OK);
    ck_assert_msg(!strcmp(row.verdict, cases[k].verdict), "case %zu: '%s'", k,
                  row.verdict);
  }
  vsph_claim_clear(&v);
  vsph_claim_num(&v, "bad", 0.1734);
  vsph_claim_num(&v, "good", 0.0123);
  vsph_claim_str(&v, "what", "at t* = 4.9");
  vsph_claim_str(&v, "which", "one");
  ck_assert_int_eq(grade(XI, &v, &row), VSPH_OK);
  ck_assert_str_eq(row.claim,
                   "Cleary's xi gives inaccurate velocities (Basa §5)");
  ck_assert_str_eq(row.ours,
                   "xi = 4.96333 17.3 %, xi = 4.24 1.2 % (at t* = 4.9)");
  ck_assert_str_eq(row.setup, "none");
  ck_assert_str_eq(row.verdict, "reproduced: both");
  ck_assert_int_eq(vsph_claim_class(row.verdict), VSPH_CLAIM_REPRODUCED);
  /* the core paper's claims carry no mark */
  const char *w = strstr(XI, "Basa §5");
  ck_assert_ptr_nonnull(w);
  char *core = malloc(strlen(XI) + 32);
  ck_assert_ptr_nonnull(core);
  sprintf(core, "%.*sColagrossi%s", (int)(w - XI), XI, w + strlen("Basa §5"));
  ck_assert_int_eq(grade(core, &v, &row), VSPH_OK);
  ck_assert_str_eq(row.claim, "Cleary's xi gives inaccurate velocities");
  free(core);
}
END_TEST

/* The classes from a verdict's first words. */
START_TEST(test_class_from_verdict_words) {
  ck_assert_int_eq(vsph_claim_class("reproduced (within 3 %)"),
                   VSPH_CLAIM_REPRODUCED);
  ck_assert_int_eq(vsph_claim_class("reproduced on a substitute: x"),
                   VSPH_CLAIM_SUBSTITUTE);
  ck_assert_int_eq(vsph_claim_class("partly"), VSPH_CLAIM_PARTLY);
  ck_assert_int_eq(vsph_claim_class("differs on a substitute"),
                   VSPH_CLAIM_DIFFERS);
  ck_assert_int_eq(vsph_claim_class("not reproduced"), VSPH_CLAIM_DIFFERS);
  ck_assert_int_eq(vsph_claim_class("not tested: no runs"),
                   VSPH_CLAIM_NOT_TESTED);
  ck_assert_int_eq(vsph_claim_class("agrees"), -1);
}
END_TEST

/* Text @p from replaced by @p to in XI (the first), graded with good
 * values: the status. */
static int variant(const char *from, const char *to, int set_values) {
  const char *at = strstr(XI, from);
  ck_assert_ptr_nonnull(at);
  const size_t n = strlen(XI) - strlen(from) + strlen(to) + 1;
  char *text = malloc(n);
  ck_assert_ptr_nonnull(text);
  snprintf(text, n, "%.*s%s%s", (int)(at - XI), XI, to, at + strlen(from));
  struct vsph_claim_vals v;
  vsph_claim_clear(&v);
  if (set_values) {
    vsph_claim_num(&v, "bad", 0.2);
    vsph_claim_num(&v, "good", 0.01);
    vsph_claim_str(&v, "what", "x");
    vsph_claim_str(&v, "which", "y");
  }
  struct vsph_claim_row row;
  const int st = grade(text, &v, &row);
  free(text);
  return st;
}

/* Each fault refused with a status (one line on stderr each): a field
 * missing, repeated or unknown; a test without an origin, of no known
 * kind, with an argument too few, naming a measure the part did not set or
 * a word; an expression naming no test or left open; a verdict without a
 * class, or none that holds; a placeholder without a value or a format
 * that is no number's; a continued line with no field. */
START_TEST(test_faults_refused) {
  ck_assert_int_eq(variant("", "", 1), VSPH_OK); /* the block itself */
  ck_assert_int_eq(variant("where: Basa §5\n", "", 1), VSPH_EINVAL);
  ck_assert_int_eq(variant("setup: none\n", "setup: none\nsetup: x\n", 1),
                   VSPH_EINVAL);
  ck_assert_int_eq(variant("setup: none\n", "set-up: none\n", 1), VSPH_EINVAL);
  ck_assert_int_eq(variant(" -- the paper's failure level", "", 1),
                   VSPH_EINVAL);
  ck_assert_int_eq(variant("atleast bad", "nearly bad", 1), VSPH_EINVAL);
  ck_assert_int_eq(variant("atleast bad 0.12", "atleast bad", 1), VSPH_EINVAL);
  ck_assert_int_eq(variant("atleast bad 0.12", "atleast worse 0.12", 1),
                   VSPH_EINVAL);
  ck_assert_int_eq(variant("atleast bad 0.12", "atleast what 0.12", 1),
                   VSPH_EINVAL);
  ck_assert_int_eq(variant("if fails & good", "if fails & god", 1),
                   VSPH_EINVAL);
  ck_assert_int_eq(variant("if fails & good", "if (fails & good", 1),
                   VSPH_EINVAL);
  ck_assert_int_eq(variant("reproduced: both", "agrees: both", 1), VSPH_EINVAL);
  ck_assert_int_eq(variant("else: differs: neither\n", "", 1), VSPH_EINVAL);
  ck_assert_int_eq(variant("", "", 0), VSPH_EINVAL); /* no values */
  ck_assert_int_eq(variant("{{what}}", "{{when}}", 1), VSPH_EINVAL);
  ck_assert_int_eq(variant("{{good*100:.1f}}", "{{good*100:.1d}}", 1),
                   VSPH_EINVAL);
  ck_assert_int_eq(variant("{{good*100:.1f}}", "{{good:s}}", 1), VSPH_EINVAL);
  ck_assert_int_eq(variant("claim:", "  claim:", 1), VSPH_EINVAL);
  ck_assert_int_eq(variant("{{what}}", "{{what:.1f}}", 1), VSPH_EINVAL);
  /* formats snprintf would misread or take long over */
  static const char *const badfmt[] = {"1.2.3f", "..f", "999f", ".999f",
                                       "f.",     "%f",  "ld",   "s"};
  for (size_t k = 0; k < sizeof badfmt / sizeof badfmt[0]; k++) {
    char to[64];
    snprintf(to, sizeof to, "{{good*100:%s}}", badfmt[k]);
    ck_assert_msg(variant("{{good*100:.1f}}", to, 1) == VSPH_EINVAL, "%s",
                  badfmt[k]);
  }
  ck_assert_int_eq(variant("{{good*100:.1f}}", "{{good*100:+08.2e}}", 1),
                   VSPH_OK);
  /* literals as people write them only: no nan, inf or hex */
  static const char *const badlit[] = {"nan", "inf", "0x1p-3", "1e999", "-"};
  for (size_t k = 0; k < sizeof badlit / sizeof badlit[0]; k++) {
    char to[64];
    snprintf(to, sizeof to, "atleast bad %s", badlit[k]);
    ck_assert_msg(variant("atleast bad 0.12", to, 1) == VSPH_EINVAL, "%s",
                  badlit[k]);
  }
  ck_assert_int_eq(variant("atleast bad 0.12", "atleast bad 1.2e-1", 1),
                   VSPH_OK);
  /* an 'if' without an expression; a verdict after 'else'; a test named
   * twice; 'checked:' beside tests; an order that is no integer */
  ck_assert_int_eq(variant("if fails & good:", "if :", 1), VSPH_EINVAL);
  ck_assert_int_eq(variant("else: differs: neither\n",
                           "else: differs: neither\nif good: partly\n", 1),
                   VSPH_EINVAL);
  ck_assert_int_eq(variant("test good:", "test fails:", 1), VSPH_EINVAL);
  ck_assert_int_eq(variant("setup: none\n",
                           "setup: none\nchecked: tests/check_claim.c x\n", 1),
                   VSPH_EINVAL);
  ck_assert_int_eq(variant("atleast bad 0.12", "order bad 1.5", 1),
                   VSPH_EINVAL);
}
END_TEST

/* Twenty-five tests (one more than a claim holds) are refused; a part that
 * sets more values than it may, or a word too long, fails its grading; a
 * word filled into a verdict may not change the verdict's class. */
START_TEST(test_limits_refused) {
  char text[4096];
  size_t m = (size_t)snprintf(text, sizeof text,
                              "claim: c\nwhere: w\npaper: p\nours: o\n"
                              "setup: none\n");
  for (int k = 0; k < 25; k++)
    m += (size_t)snprintf(text + m, sizeof text - m,
                          "test t%d: below x 1 -- a choice\n", k);
  snprintf(text + m, sizeof text - m, "else: differs\n");
  struct vsph_claim_vals v;
  vsph_claim_clear(&v);
  vsph_claim_num(&v, "x", 0.5);
  struct vsph_claim_row row;
  ck_assert_int_eq(grade(text, &v, &row), VSPH_EINVAL);
  /* too many values */
  static const char *const ONE =
      "claim: c\nwhere: w\npaper: p\nours: {{w}}\nsetup: none\n"
      "test t: below x 1 -- a choice\n"
      "if t: reproduced{{w}}\nelse: differs\n";
  vsph_claim_clear(&v);
  vsph_claim_num(&v, "x", 0.5);
  vsph_claim_str(&v, "w", "%s", "");
  ck_assert_int_eq(grade(ONE, &v, &row), VSPH_OK);
  ck_assert_str_eq(row.verdict, "reproduced");
  for (int k = 0; k < VSPH_CLAIM_MAXVALS; k++) {
    char key[16];
    snprintf(key, sizeof key, "v%d", k);
    vsph_claim_num(&v, key, 1.0);
  }
  ck_assert_int_eq(v.overflow, 1);
  ck_assert_int_eq(grade(ONE, &v, &row), VSPH_EINVAL);
  /* a word too long for a value */
  vsph_claim_clear(&v);
  vsph_claim_num(&v, "x", 0.5);
  char big[1000];
  memset(big, 'a', sizeof big - 1);
  big[sizeof big - 1] = '\0';
  vsph_claim_str(&v, "w", "%s", big);
  ck_assert_int_eq(grade(ONE, &v, &row), VSPH_EINVAL);
  /* a word that turns "reproduced" into "reproduced on a substitute" */
  vsph_claim_clear(&v);
  vsph_claim_num(&v, "x", 0.5);
  vsph_claim_str(&v, "w", "%s", " on a substitute");
  ck_assert_int_eq(grade(ONE, &v, &row), VSPH_EINVAL);
}
END_TEST

/* Words the tests choose: {{?EXPR|holds|fails|unknown}} takes the text
 * its expression picks, the third where it is unknown (the second where
 * no third is given); malformed conditions are refused. */
START_TEST(test_words_chosen) {
  static const char *const W =
      "claim: c\nwhere: w\npaper: p\n"
      "ours: x {{?big|grows|stays}}, {{?big & pos|both|not both|unsure}}\n"
      "setup: none\n"
      "test big: above x 1 -- a choice\n"
      "test pos: above y 0 -- a choice\n"
      "if pos: partly: {{?!big|small|large}}\nelse: differs\n";
  struct vsph_claim_vals v;
  struct vsph_claim_row row;
  const struct {
    double x, y;
    const char *ours, *verdict;
  } cases[] = {{2.0, 1.0, "x grows, both", "partly: large"},
               {nextafter(1.0, 0.0), 1.0, "x stays, not both", "partly: small"},
               {NAN, 1.0, "x stays, unsure", "partly: large"},
               {2.0, -1.0, "x grows, not both", "differs"}};
  for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
    vsph_claim_clear(&v);
    vsph_claim_num(&v, "x", cases[k].x);
    vsph_claim_num(&v, "y", cases[k].y);
    ck_assert_int_eq(grade(W, &v, &row), VSPH_OK);
    ck_assert_msg(!strcmp(row.ours, cases[k].ours), "case %zu: %s", k,
                  row.ours);
    ck_assert_msg(!strcmp(row.verdict, cases[k].verdict), "case %zu: %s", k,
                  row.verdict);
  }
  ck_assert_int_eq(vsph_claim_lint("w", W), VSPH_OK);
  static const char *const BAD[] = {"{{?big|grows}}", "{{?bog|a|b}}",
                                    "{{?big|a|b|c|d}}", "{{?(big|a|b}}"};
  for (size_t k = 0; k < 4; k++) {
    char text[512];
    snprintf(text, sizeof text,
             "claim: c\nwhere: w\npaper: p\nours: %s\nsetup: none\n"
             "test big: above x 1 -- a choice\nelse: differs\n",
             BAD[k]);
    ck_assert_msg(vsph_claim_lint("w", text) == VSPH_EINVAL, "%s", BAD[k]);
  }
}
END_TEST

/* Word lines: {{NAME}} is the text of NAME's first line whose expression
 * holds for certain, else its last ('else'), its own placeholders filled
 * (a measure, not another word); a word without its 'else' last, an
 * 'else' before the last line, a malformed expression, a format on a word,
 * a word text naming a measure badly are refused. */
START_TEST(test_word_lines) {
  static const char *const W =
      "claim: c\nwhere: w\npaper: p\nours: x {{conv}}\nsetup: none\n"
      "test a: above x 1 -- a choice\n"
      "test b: above y 1 -- a choice\n"
      "word conv: a & b => converges by both\n"
      "word conv: a | b => converges by one only\n"
      "word conv: !a & !b => does not converge ({{x:.1f}})\n"
      "word conv: else => not measured\n"
      "if a | b: partly: {{conv}}\nelse: differs\n";
  struct vsph_claim_vals v;
  struct vsph_claim_row row;
  const struct {
    double x, y;
    const char *ours;
  } cases[] = {
      {2, 2, "x converges by both"},
      {2, 0, "x converges by one only"},
      {0, 2, "x converges by one only"},
      {0, 0, "x does not converge (0.0)"},
      /* the first line not failing is unknown: the word is the engine's
         ("by both" might hold where b does) */
      {NAN, 0, "x (not measured)"},
      {NAN, 2, "x (not measured)"}};
  for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
    vsph_claim_clear(&v);
    vsph_claim_num(&v, "x", cases[k].x);
    vsph_claim_num(&v, "y", cases[k].y);
    ck_assert_int_eq(grade(W, &v, &row), VSPH_OK);
    ck_assert_msg(!strcmp(row.ours, cases[k].ours), "case %zu: %s", k,
                  row.ours);
  }
  static const char *const BAD[][2] = {
      {"word conv: else => not measured\n", ""},
      {"word conv: a & b =>", "word conv: else =>"},
      {"word conv: a | b =>", "word conv: (a =>"},
      {"ours: x {{conv}}", "ours: x {{conv:.1f}}"},
      {"word conv: a & b => converges by both", "word conv: a & b"},
      {"({{x:.1f}})", "({{x:.1d}})"}};
  for (size_t k = 0; k < sizeof BAD / sizeof BAD[0]; k++) {
    char text[2048];
    const char *at = strstr(W, BAD[k][0]);
    ck_assert_ptr_nonnull(at);
    snprintf(text, sizeof text, "%.*s%s%s", (int)(at - W), W, BAD[k][1],
             at + strlen(BAD[k][0]));
    ck_assert_msg(vsph_claim_lint("w", text) == VSPH_EINVAL, "case %zu", k);
  }
}
END_TEST

/* Kleene's three values: a test fed a NaN is unknown, so neither it nor
 * its negation holds for certain; & fails where either side fails, |
 * holds where either holds; finite fails on a NaN and is never unknown;
 * a verdict holds only where every one before it fails for certain (the
 * else where all do), but for a 'not tested' one. */
START_TEST(test_unknown_decides_nothing) {
  static const char *const K =
      "claim: c\nwhere: w\npaper: p\nours: o\nsetup: none\n"
      "test big: above x 1 -- a choice\n"
      "test pos: above y 0 -- a choice\n"
      "test meas: finite x -- measured\n"
      "if !big & pos: reproduced: small\n"
      "if big | pos: partly: one\n"
      "if !meas: not tested: x not measured\n"
      "else: differs\n";
  struct vsph_claim_vals v;
  struct vsph_claim_row row;
  const struct {
    double x, y;
    const char *verdict;
  } cases[] = {{0.5, 1.0, "reproduced: small"},
               /* !big unknown: "small" might hold, so "one" is not
                  certain; the not-tested line claims nothing and holds */
               {NAN, 1.0, "not tested: x not measured"},
               {NAN, -1.0, "not tested: x not measured"},
               {2.0, NAN, "partly: one"}, /* big holds: | holds */
               /* !big & unknown: unknown, and so is the else (the
                  negation of every if): no verdict holds, the tests
                  left unknown named */
               {0.5, NAN,
                "not tested: a figure its verdict needs was not measured "
                "(unknown: pos)"},
               {0.5, -1.0, "differs"}};
  for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
    vsph_claim_clear(&v);
    vsph_claim_num(&v, "x", cases[k].x);
    vsph_claim_num(&v, "y", cases[k].y);
    ck_assert_int_eq(grade(K, &v, &row), VSPH_OK);
    ck_assert_msg(!strcmp(row.verdict, cases[k].verdict), "case %zu: %s", k,
                  row.verdict);
  }
}
END_TEST
END_TEST

/* The test of make check that a claim's "checked:" names ("tests/FILE.c
 * test_NAME") is there: 1, or 0. */
static int checked_exists(const char *text) {
  const char *c = strstr(text, "checked: ");
  if (!c) return 1; /* none named */
  char file[128], test[96], want[128];
  if (sscanf(c + 9, "%127s %95s", file, test) != 2) return 0;
  snprintf(want, sizeof want, "START_TEST(%s)", test);
  FILE *f = fopen(file, "r"); /* the tests run in the source tree */
  if (!f) return 0;
  char line[512];
  int found = 0;
  while (!found && fgets(line, sizeof line, f)) found = !!strstr(line, want);
  fclose(f);
  return found;
}

/* Words the blocks choose that the parts' C once wrote (reports/claims/
 * channel.md): p003_dt's sentence on the first c where a smaller dt ends
 * better (it stops later, it ends better, none) and on the error's change
 * over dt; cavity_ek's count of runs at the paper's resolution (none, one,
 * several). Each case's text is the C's old sentence for those values. */
START_TEST(test_block_words_as_the_parts_wrote) {
  const char *dt = vsph_text_get("claims/channel.p003_dt");
  ck_assert_ptr_nonnull(dt);
  const struct {
    double c, stops, t, tmax, acc;
    const char *want;
  } sw[] = {
      {20.0, 1, 0.4123, 0.2, 0.0123,
       "the same sweep: where every dt runs, the error changes by at most "
       "1.2 % of itself over dt; at c = 20 m/s the smallest dt stops later, "
       "at t = 0.412 s against 0.2 s at most (of the run's 1 s)"},
      {7.5, 0, 1.0, 0.3, NAN,
       "the same sweep: no c runs at every dt; at c = 7.5 m/s the smallest dt "
       "ends better (the table)"},
      {NAN, 0, NAN, NAN, 6.8e-8,
       "the same sweep: where every dt runs, the error changes by at most "
       "6.8e-06 % of itself over dt; no c ends better at the smallest dt "
       "(each ends as at the largest, or stops no later)"}};
  struct vsph_claim_vals v;
  struct vsph_claim_row row;
  for (size_t k = 0; k < sizeof sw / sizeof sw[0]; k++) {
    vsph_claim_clear(&v);
    vsph_claim_str(&v, "dt_span", "x");
    vsph_claim_str(&v, "p003_diffs", "x");
    vsph_claim_str(&v, "dt_run", "x");
    vsph_claim_num(&v, "acc_change", sw[k].acc);
    vsph_claim_num(&v, "rise", 2.0); /* no fall: "falls" fails */
    vsph_claim_num(&v, "lag", 1.0);
    vsph_claim_num(&v, "turn", 0);
    vsph_claim_num(&v, "turn_stop", 0);
    vsph_claim_num(&v, "stab_c", sw[k].c);
    vsph_claim_num(&v, "stab_stops", sw[k].stops);
    vsph_claim_num(&v, "stab_t", sw[k].t);
    vsph_claim_num(&v, "stab_tmax", sw[k].tmax);
    vsph_claim_num(&v, "t_end", 1.0);
    ck_assert_int_eq(grade(dt, &v, &row), VSPH_OK);
    ck_assert_msg(!strcmp(row.ours, sw[k].want), "case %zu: %s", k, row.ours);
  }
  const char *ek = vsph_text_get("claims/channel.cavity_ek");
  ck_assert_ptr_nonnull(ek);
  static const char *const NUMS[] = {"fv_read", "fv_n",     "band",  "peak",
                                     "under",   "measured", "n",     "lo",
                                     "hi",      "e_seen",   "d_seen"};
  const double vals[] = {1, 64, 0.01, 0.9, 2, 2, 3, 0.8, 0.9, 1, 0};
  const struct {
    double n;
    const char *want;
  } ap[] = {{0, "; no measured run at the paper's 50 x 50"},
            {1, "; one measured run at the paper's 50 x 50"},
            {3, "; 3 measured runs at the paper's 50 x 50"}};
  for (size_t k = 0; k < sizeof ap / sizeof ap[0]; k++) {
    vsph_claim_clear(&v);
    for (size_t q = 0; q < sizeof NUMS / sizeof NUMS[0]; q++)
      vsph_claim_num(&v, NUMS[q], vals[q]);
    vsph_claim_num(&v, "n_paper", ap[k].n);
    vsph_claim_str(&v, "quick_runs", "x");
    vsph_claim_str(&v, "full_runs", "x");
    vsph_claim_str(&v, "hist", "30");
    ck_assert_int_eq(grade(ek, &v, &row), VSPH_OK);
    ck_assert_msg(strstr(row.verdict, ap[k].want), "case %zu: %s", k,
                  row.verdict);
  }
}
END_TEST

/* The four claims whose only other verdict was "partly" can say
 * "differs" (reports/claims/: eta_linear, self_similar, zeta_one,
 * cavity_re1000): each graded on figures just inside and just past the
 * line "as far as halfway to a contrary law" (docs/theory.md section 13;
 * the places in logarithm computed from the figures as the parts compute
 * them), on either side where the scale has two, inside it with the
 * paper's own rule failing (partly), and with a figure not measured (not
 * tested, never a class the figures did not earn). */
static double lb(double x, double a, double b) {
  return vsph_series_log_between(x, a, b);
}
START_TEST(test_partly_claims_can_differ) {
  struct vsph_claim_vals v;
  struct vsph_claim_row row;
  const char *lin = vsph_text_get("claims/contact.eta_linear");
  const double L[][4] = {/* q50, q_material, q20 (ours over lead's), class */
                         {1.01, 1.01, 1.01, VSPH_CLAIM_REPRODUCED},
                         {0.4, 1.01, 1.01, VSPH_CLAIM_PARTLY},  /* lean .40 */
                         {0.3, 1.01, 1.01, VSPH_CLAIM_DIFFERS}, /* .52 */
                         {3.5, 1.01, 1.01, VSPH_CLAIM_DIFFERS}, /* other side */
                         {1.01, 1.2, 1.01, VSPH_CLAIM_PARTLY},  /* Al: .44 */
                         {1.01, 1.25, 1.01, VSPH_CLAIM_DIFFERS}, /* Al: .54 */
                         {1.01, 1.01, 0.75, VSPH_CLAIM_PARTLY},  /* .42 */
                         {1.01, 1.01, 0.7, VSPH_CLAIM_DIFFERS},  /* .51 */
                         {1.01, NAN, 1.01, VSPH_CLAIM_NOT_TESTED},
                         {NAN, 1.01, 1.01, VSPH_CLAIM_NOT_TESTED},
                         {1.01, 1.01, NAN, VSPH_CLAIM_NOT_TESTED},
                         {1.01, 1.01, -0.2, VSPH_CLAIM_NOT_TESTED},
                         /* a certain departure is not hidden by a run
                            not measured */
                         {0.2, NAN, 1.01, VSPH_CLAIM_DIFFERS}};
  for (size_t k = 0; k < sizeof L / sizeof L[0]; k++) {
    vsph_claim_clear(&v);
    /* lead's eta_num/(Z D0) 1: the others are their ratios to it; water
     * and tungsten on lead's, aluminium's contrary Z_lead/Z_al =
     * 2.19e7/1.456e7 (the block's lets take the ratios and places) */
    vsph_claim_num(&v, "w", 1.0);
    vsph_claim_num(&v, "w50", L[k][0]);
    vsph_claim_num(&v, "w20", L[k][2]);
    vsph_claim_num(&v, "w_al", L[k][1]);
    vsph_claim_num(&v, "w_water", 1.0);
    vsph_claim_num(&v, "w_tu", 1.0);
    vsph_claim_num(&v, "zr_al", 2.193e7 / 1.456e7);
    vsph_claim_num(&v, "zr_water", 14.8);
    vsph_claim_num(&v, "zr_tu", 0.29);
    ck_assert_int_eq(grade(lin, &v, &row), VSPH_OK);
    ck_assert_msg(vsph_claim_class(row.verdict) == (int)L[k][3],
                  "eta_linear %zu: %s", k, row.verdict);
  }
  const char *ss = vsph_text_get("claims/contact.self_similar");
  const double S[][3] = {/* nu ratio hi/lo at zeta 0, at zeta 1, class */
                         {1.01, 1.02, VSPH_CLAIM_REPRODUCED},
                         {1.6, 1.02, VSPH_CLAIM_PARTLY},  /* lean .43 */
                         {1.8, 1.02, VSPH_CLAIM_DIFFERS}, /* .54 */
                         {1.01, 2.5, VSPH_CLAIM_DIFFERS}, /* .51 of 6.0 */
                         {NAN, 1.02, VSPH_CLAIM_NOT_TESTED},
                         {1.8, NAN, VSPH_CLAIM_DIFFERS}};
  for (size_t k = 0; k < sizeof S / sizeof S[0]; k++) {
    vsph_claim_clear(&v);
    vsph_claim_num(&v, "ss0", 100.0 * (S[k][0] - 1.0));
    vsph_claim_num(&v, "ss1", 100.0 * (S[k][1] - 1.0));
    vsph_claim_num(&v, "lean0", lb(S[k][0], 1.0, 3.0));
    vsph_claim_num(&v, "lean1", lb(S[k][1], 1.0, 14.0 / 2.334));
    ck_assert_int_eq(grade(ss, &v, &row), VSPH_OK);
    ck_assert_msg(vsph_claim_class(row.verdict) == (int)S[k][2],
                  "self_similar %zu: %s", k, row.verdict);
  }
  const char *z1 = vsph_text_get("claims/contact.zeta_one");
  const struct {
    double e1, e0;
    int cls;
    const char *says;
  } Z[] = {{2.4, 23.4, VSPH_CLAIM_REPRODUCED, ""},
           {3.18, 23.4, VSPH_CLAIM_PARTLY, "eta_num"},        /* lean .14 */
           {7.0, 23.4, VSPH_CLAIM_PARTLY, ""},                /* .48 */
           {8.0, 23.4, VSPH_CLAIM_DIFFERS, "uncorrected"},    /* .54 */
           {0.75, 23.4, VSPH_CLAIM_PARTLY, ""},               /* .48, below */
           {0.7, 23.4, VSPH_CLAIM_DIFFERS, "over-corrected"}, /* .51 */
           {-1.0, 23.4, VSPH_CLAIM_DIFFERS, "not positive"},
           {NAN, 23.4, VSPH_CLAIM_NOT_TESTED, ""},
           {12.0, NAN, VSPH_CLAIM_NOT_TESTED, "scale"},
           /* the uncorrected lattice's below the physical eta: no scale
              (lean 0.50 would read as a departure) */
           {3.5, 1.0, VSPH_CLAIM_NOT_TESTED, "no scale"},
           {1.5, 1.0, VSPH_CLAIM_NOT_TESTED, "no scale"}};
  for (size_t k = 0; k < sizeof Z / sizeof Z[0]; k++) {
    vsph_claim_clear(&v);
    vsph_claim_num(&v, "e1", Z[k].e1);
    vsph_claim_num(&v, "e0", Z[k].e0);
    vsph_claim_num(&v, "e05", 13.3); /* rel and lean: the block's lets */
    ck_assert_int_eq(grade(z1, &v, &row), VSPH_OK);
    ck_assert_msg(vsph_claim_class(row.verdict) == Z[k].cls &&
                      strstr(row.verdict, Z[k].says),
                  "zeta_one %zu: %s", k, row.verdict);
  }
  const char *cv = vsph_text_get("claims/channel.cavity_re1000");
  const struct {
    double e1, ok, d1000, d400, sw, t_run;
    int cls;
    const char *says;
  } C[] = {
      {0.04, 1, 0.04, 0.08, 0.01, 30, VSPH_CLAIM_PARTLY, "near Ghia"},
      {0.09, 1, 0.096, 0.081, 0.01, 30, VSPH_CLAIM_PARTLY,
       "nearer their Re 400"},
      {0.09, 1, 0.096, 0.081, 0.02, 30, VSPH_CLAIM_PARTLY, "about as near"},
      {0.09, 1, 0.07, 0.09, 0.01, 30, VSPH_CLAIM_PARTLY,
       "nearer their Re 1000"},
      {0.09, 1, 0.096, 0.081, 0.01, 80, VSPH_CLAIM_DIFFERS, "Re 400"},
      {0.09, 1, 0.096, 0.081, 0.02, 80, VSPH_CLAIM_PARTLY, "about as near"},
      {0.09, 1, 0.07, 0.09, 0.01, 80, VSPH_CLAIM_PARTLY,
       "nearer their Re 1000"},
      {0.16, 1, 0.16, 0.2, 0.01, 30, VSPH_CLAIM_PARTLY, ""},
      {0.18, 1, 0.18, 0.2, 0.01, 30, VSPH_CLAIM_DIFFERS, "half the fluid"},
      {NAN, 1, NAN, NAN, NAN, 30, VSPH_CLAIM_NOT_TESTED, ""},
      {0.04, 0, NAN, NAN, NAN, 12, VSPH_CLAIM_DIFFERS, "stopped"}};
  for (size_t k = 0; k < sizeof C / sizeof C[0]; k++) {
    vsph_claim_clear(&v);
    vsph_claim_str(&v, "cav_res", "x");
    vsph_claim_str(&v, "re1000_run", "x");
    vsph_claim_num(&v, "res", 30);
    vsph_claim_num(&v, "t1", C[k].t_run < 80 ? 30 : 80);
    vsph_claim_num(&v, "t0", 0.8 * (C[k].t_run < 80 ? 30 : 80)); /* CAV_TAIL */
    vsph_claim_num(&v, "e1", C[k].e1);
    vsph_claim_num(&v, "e1swing", 0.01);
    vsph_claim_num(&v, "m1", 0.2);
    vsph_claim_num(&v, "ek", 0.03);
    vsph_claim_num(&v, "ok", C[k].ok);
    vsph_claim_num(&v, "t_stop", 12.0);
    vsph_claim_num(&v, "rest", 0.341198916);
    vsph_claim_num(&v, "d1000", C[k].d1000);
    vsph_claim_num(&v, "d400", C[k].d400);
    vsph_claim_num(&v, "dswing", C[k].sw);
    vsph_claim_num(&v, "t_run", C[k].t_run);
    ck_assert_int_eq(grade(cv, &v, &row), VSPH_OK);
    ck_assert_msg(vsph_claim_class(row.verdict) == C[k].cls &&
                      strstr(row.verdict, C[k].says),
                  "cavity_re1000 %zu: %s", k, row.verdict);
  }
}
END_TEST

/* One test of a block read alone, as a part reads a rule to choose its
 * words (p003_dt's 'later'): at its threshold (strict: fails), just above
 * (holds), a NaN (unknown, -1); a measure not set and a test not there
 * refused; and p003_dt's own rule read from its block. */
START_TEST(test_one_test_read_alone) {
  static const char *const B =
      "claim: c\nwhere: w\npaper: p\nours: x\nsetup: none\n"
      "test later: above lag 1.5 -- a choice\nif later: partly\n"
      "else: differs\n";
  struct vsph_claim_vals v;
  int holds = 7;
  vsph_claim_clear(&v);
  vsph_claim_num(&v, "lag", 1.5);
  ck_assert_int_eq(vsph_claim_test_text("t", B, "later", &v, &holds), VSPH_OK);
  ck_assert_int_eq(holds, 0);
  vsph_claim_num(&v, "lag", nextafter(1.5, 2.0));
  ck_assert_int_eq(vsph_claim_test_text("t", B, "later", &v, &holds), VSPH_OK);
  ck_assert_int_eq(holds, 1);
  vsph_claim_num(&v, "lag", NAN);
  ck_assert_int_eq(vsph_claim_test_text("t", B, "later", &v, &holds), VSPH_OK);
  ck_assert_int_eq(holds, -1);
  vsph_test_silence();
  ck_assert_int_eq(vsph_claim_test_text("t", B, "sooner", &v, &holds),
                   VSPH_EINVAL);
  vsph_claim_clear(&v);
  ck_assert_int_eq(vsph_claim_test_text("t", B, "later", &v, &holds),
                   VSPH_EINVAL);
  const char *dt = vsph_text_get("claims/channel.p003_dt");
  vsph_claim_num(&v, "lag", 1.6);
  ck_assert_int_eq(vsph_claim_test_text("dt", dt, "later", &v, &holds),
                   VSPH_OK);
  ck_assert_int_eq(holds, 1); /* its rule: above lag 1.5 */
}
END_TEST

/* Derived measures ("let"): each operator on values worked by hand, the
 * order of operations, lets read by later lets, tests and templates; a
 * NaN carried through max and min (C's fmax would pass it over); and
 * every malformed let refused. */
static int let_grade(const char *lets, const char *rule, double a, double b,
                     struct vsph_claim_row *row) {
  char text[2048];
  snprintf(text, sizeof text,
           "claim: c\nwhere: w\npaper: p\nours: r = {{r:.4f}}\nsetup: none\n"
           "%stest t: %s -- worked by hand\nif t: reproduced\nelse: differs\n",
           lets, rule);
  struct vsph_claim_vals v;
  vsph_claim_clear(&v);
  vsph_claim_num(&v, "a", a);
  vsph_claim_num(&v, "b", b);
  vsph_claim_str(&v, "w", "a word");
  return vsph_claim_grade_text("let", text, &v, row);
}

START_TEST(test_lets_derive_measures) {
  struct vsph_claim_row row;
  /* a = 3, b = -4, each exact in doubles: the operators, max and min,
   * precedence and association to the left */
  const struct {
    const char *expr;
    double r;
  } cases[] = {{"abs(b) / 8 - 1", -0.5},
               {"max(a, b, 7, -9) + min(b, a, 2)", 3.0},
               /* vsph_series_log_between's own, tested in check_series */
               {"logplace(a + 1, 1, 16)", vsph_series_log_between(4, 1, 16)},
               {"logplace(b, 1, 16)", NAN},
               /* halves away from zero (rint would give 2, -2) */
               {"round(2.5) + round(a / 2) - round(-2.5)", 8.0},
               {"a - b * 2", 11.0},
               {"(a - b) * 2", 14.0},
               {"-a + -(b)", 1.0},
               {"max(a, b) - min(a, b)", 7.0},
               {"min(abs(b), 2.5e0) / 1e-1", 25.0},
               {"a / b / 2", -0.375},
               {"a - b - 1", 6.0},
               /* unary signs, numbers with a bare point */
               {"+a - +1 - -.5", 2.5},
               {"--a * 1.", 3.0},
               /* a ratio over zero is not measured */
               {"a / (b + 4)", NAN}};
  for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
    char lets[256], rule[128];
    snprintf(lets, sizeof lets, "let r: %s -- case %zu\n", cases[k].expr, k);
    /* at the value: within r v 0 holds; a rounding above the edge, not */
    snprintf(rule, sizeof rule, "within r %.17g 0", cases[k].r);
    if (isnan(cases[k].r)) { /* not measured: the test unknown */
      ck_assert_int_eq(let_grade(lets, "finite r", 3.0, -4.0, &row), VSPH_OK);
      ck_assert_msg(!strcmp(row.verdict, "differs"), "%s", cases[k].expr);
      continue;
    }
    ck_assert_int_eq(let_grade(lets, rule, 3.0, -4.0, &row), VSPH_OK);
    ck_assert_msg(!strcmp(row.verdict, "reproduced"), "%s: %s", cases[k].expr,
                  row.verdict);
    snprintf(rule, sizeof rule, "above r %.17g", cases[k].r);
    ck_assert_int_eq(let_grade(lets, rule, 3.0, -4.0, &row), VSPH_OK);
    ck_assert_msg(!strcmp(row.verdict, "differs"), "%s", cases[k].expr);
  }
  /* a later let reads an earlier one; a template shows it */
  ck_assert_int_eq(
      let_grade("let q: a * b\nlet r: q / 8\n", "below r -1.4", 3, -4, &row),
      VSPH_OK);
  ck_assert_str_eq(row.ours, "r = -1.5000");
  ck_assert_str_eq(row.verdict, "reproduced");
  /* a NaN in, a NaN out: max, min and abs too; finite fails on it for
   * certain (it is never unknown), so the else verdict */
  static const char *const nan_through[] = {"max(a, b)",       "min(b, a)",
                                            "abs(a)",          "a - a",
                                            "max(b, 1, 2, a)", "min(b, a, 1)"};
  for (size_t k = 0; k < 6; k++) {
    char lets[64];
    snprintf(lets, sizeof lets, "let r: %s\n", nan_through[k]);
    ck_assert_int_eq(let_grade(lets, "finite r", NAN, -4, &row), VSPH_OK);
    ck_assert_msg(!strcmp(row.verdict, "differs"), "%s", nan_through[k]);
    ck_assert_int_eq(let_grade(lets, "finite r", 3, -4, &row), VSPH_OK);
    ck_assert_msg(!strcmp(row.verdict, "reproduced"), "%s", nan_through[k]);
  }
  /* a test reading a let that is not measured is unknown: no verdict */
  ck_assert_int_eq(let_grade("let r: a / (b + 4)\n", "below r 5", 3, -4, &row),
                   VSPH_OK);
  ck_assert_str_eq(row.verdict,
                   "not tested: a figure its verdict needs was not measured "
                   "(unknown: t)");
  /* forms that grade */
  static const char *const ok[] = {"let r: max(a,b)\n", "let r: (a)\n",
                                   "let r: -1.5e-3 * a -- a note\n"};
  for (size_t k = 0; k < 3; k++)
    ck_assert_int_eq(let_grade(ok[k], "finite r", 3, -4, &row), VSPH_OK);
  /* the limits: an expression of 253 characters and a name of 31 grade,
   * one of 261 and a name of 32 do not (the block's fields: 256, 32) */
  char lets[400], name[40];
  int m = snprintf(lets, sizeof lets, "let r: a");
  for (int k = 0; k < 63; k++)
    m += snprintf(lets + m, sizeof lets - (size_t)m, " + 0");
  snprintf(lets + m, sizeof lets - (size_t)m, "\n");
  ck_assert_int_eq(let_grade(lets, "within r 3 0", 3, -4, &row), VSPH_OK);
  ck_assert_str_eq(row.verdict, "reproduced");
  memset(name, 'x', 31);
  name[31] = '\0';
  snprintf(lets, sizeof lets, "let %s: a\nlet r: %s\n", name, name);
  ck_assert_int_eq(let_grade(lets, "within r 3 0", 3, -4, &row), VSPH_OK);
  vsph_test_silence();
  /* each after a well-formed "let r: 1", so that the fault alone refuses:
   * the same block without it grades */
  static const char *const bad[] = {"let s: a +\n",
                                    "let s: (a\n",
                                    "let s: a b\n",
                                    "let s: nan\n",
                                    "let s: 0x10\n",
                                    "let s: 1e999\n",
                                    "let s: sqrt(a)\n",
                                    "let s: max(a)\n",
                                    "let s: abs(a, b)\n",
                                    "let s: c\n",
                                    "let s: max(a, b, a, b, a)\n",
                                    "let s: logplace(a, b)\n",
                                    "let s: min()\n",
                                    "let s: w\n",
                                    "let s:\n",
                                    "let 9s: a\n",
                                    "let s-t: a\n",
                                    "let s: a\nlet s: b\n",
                                    "let a: b\n",
                                    "let s: s + 1\n",
                                    "let s: a ) \n",
                                    "let : a\n",
                                    "let s: 1 -- x\nlet r: 2\n",
                                    "let s: max(a, b\n",
                                    "let s: abs(a b)\n",
                                    "let s: 1e\n",
                                    "let s: -(\n"};
  ck_assert_int_eq(let_grade("let r: 1\n", "finite r", 3, -4, &row), VSPH_OK);
  name[31] = 'x';
  name[32] = '\0';
  snprintf(lets, sizeof lets, "let %s: a\nlet r: 1\n", name);
  ck_assert_int_eq(let_grade(lets, "finite r", 3, -4, &row), VSPH_EINVAL);
  m = snprintf(lets, sizeof lets, "let r: a");
  for (int k = 0; k < 65; k++)
    m += snprintf(lets + m, sizeof lets - (size_t)m, " + 0");
  snprintf(lets + m, sizeof lets - (size_t)m, "\n");
  ck_assert_int_eq(let_grade(lets, "finite r", 3, -4, &row), VSPH_EINVAL);
  for (size_t k = 0; k < sizeof bad / sizeof bad[0]; k++) {
    char one[128];
    snprintf(one, sizeof one, "let r: 1\n%s", bad[k]);
    ck_assert_msg(let_grade(one, "finite r", 3, -4, &row) == VSPH_EINVAL, "%s",
                  bad[k]);
  }
  /* the lint refuses a malformed let without values */
  ck_assert_int_eq(vsph_claim_lint("let",
                                   "claim: c\nwhere: w\npaper: p\n"
                                   "ours: o\nsetup: none\nlet r: (a\n"
                                   "test t: finite r -- x\n"
                                   "if t: reproduced\nelse: differs\n"),
                   VSPH_EINVAL);
  /* one test read alone sees the lets */
  int holds = 7;
  struct vsph_claim_vals v;
  vsph_claim_clear(&v);
  vsph_claim_num(&v, "a", 3);
  vsph_claim_num(&v, "b", 2);
  ck_assert_int_eq(
      vsph_claim_test_text("t",
                           "claim: c\nwhere: w\npaper: p\nours: o\n"
                           "setup: none\nlet r: a / b\n"
                           "test t: within r 1.5 0 -- x\nif t: reproduced\n"
                           "else: differs\n",
                           "t", &v, &holds),
      VSPH_OK);
  ck_assert_int_eq(holds, 1);
}
END_TEST

/* Every claim block compiled in from reports/claims/ is well formed (each
 * field, test and expression; its placeholders' forms), a test of make
 * check it names is there, and there are some. */
START_TEST(test_blocks_well_formed) {
  size_t n = 0;
  for (size_t k = 0; k < vsph_text_nblocks; k++)
    if (!strncmp(vsph_text_blocks[k].name, "claims/", 7)) {
      ck_assert_msg(vsph_claim_lint(vsph_text_blocks[k].name,
                                    vsph_text_blocks[k].text) == VSPH_OK,
                    "%s", vsph_text_blocks[k].name);
      ck_assert_msg(checked_exists(vsph_text_blocks[k].text),
                    "%s: the test it names as checked is not there",
                    vsph_text_blocks[k].name);
      n++;
    }
  /* every part that grades claims has its file, each with blocks */
  static const char *const part[] = {"paper", "patch", "channel", "contact"};
  for (size_t p = 0; p < 4; p++) {
    char prefix[32];
    snprintf(prefix, sizeof prefix, "claims/%s.", part[p]);
    size_t m = 0;
    for (size_t k = 0; k < vsph_text_nblocks; k++)
      m += !strncmp(vsph_text_blocks[k].name, prefix, strlen(prefix));
    ck_assert_msg(m > 0, "no claims in reports/claims/%s.md", part[p]);
  }
  ck_assert_uint_ge(n, 4);
}
END_TEST

Suite *vsph_claim_suite(void) {
  Suite *s = suite_create("claim");
  TCase *tc = tcase_create("core");
  tcase_add_test(tc, test_kinds_compare);
  tcase_add_test(tc, test_kinds_rules);
  tcase_add_test(tc, test_verdict_follows);
  tcase_add_test(tc, test_class_from_verdict_words);
  tcase_add_test(tc, test_faults_refused);
  tcase_add_test(tc, test_limits_refused);
  tcase_add_test(tc, test_unknown_decides_nothing);
  tcase_add_test(tc, test_words_chosen);
  tcase_add_test(tc, test_word_lines);
  tcase_add_test(tc, test_blocks_well_formed);
  tcase_add_test(tc, test_block_words_as_the_parts_wrote);
  tcase_add_test(tc, test_partly_claims_can_differ);
  tcase_add_test(tc, test_one_test_read_alone);
  tcase_add_test(tc, test_lets_derive_measures);
  suite_add_tcase(s, tc);
  return s;
}
