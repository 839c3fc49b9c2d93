/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
#ifndef VSPH_REPORTS_CLAIM_H
#define VSPH_REPORTS_CLAIM_H

#include <stddef.h>

/** @file claim.h
 *  @brief The verdict engine: a claim of a paper kept as data, graded on
 *  the figures a part measured. Each claim is a block of
 *  reports/claims/PART.md (compiled in, as the prose is), one field per
 *  line ("key: value"; a line that starts with a blank continues the one
 *  before):
 *
 *  - `claim:` the paper's statement; `where:` where it stands (paper,
 *    section, figure or table); `paper:` the paper's figure;
 *  - `ours:` what we measured, `setup:` how our set-up differs from the
 *    paper's ("none" where nothing does), each a template whose
 *    placeholders {{name}} take a measure or a word the part set
 *    ({{name:FMT}} prints a measure with printf's %FMT, {{name*100:FMT}}
 *    a hundred times it; {{?EXPR|HOLDS|FAILS}} or {{?EXPR|HOLDS|FAILS|
 *    UNKNOWN}} the literal text that an expression of the block's tests
 *    chooses, so that words which repeat a test are the test's own);
 *  - `test NAME: KIND ARG... -- ORIGIN` (one or more): a rule on the
 *    measures and its threshold, with the threshold's origin. Kinds:
 *    below a b (a < b), above a b (a > b), atmost a b (a <= b), atleast a
 *    b (a >= b), within a s w (|a - s| <= w), order p n (p rounds to the
 *    integer n, vsph_grade_order_is), apart bad good (bad at least
 *    VSPH_GRADE_APART times good), larger a b noise (a > b + noise), flag
 *    a (a is 1: a fact the part states, such as a run that ended), finite
 *    a (a was measured: not NaN, not infinite). An argument is a
 *    measure's name or a plain finite number (no nan, inf or hex). A test
 *    fed a NaN (a figure not measured) is unknown, neither holding nor
 *    failing, but finite, which fails; `within` is inclusive at its edge
 *    as the doubles compute |a - s| (a decimal edge such as 0.2 may sit
 *    a rounding away);
 *  - `let NAME: EXPR [-- WHAT]` (any number, in turn): a measure the
 *    block derives from the part's and from the lets before it, so that
 *    arithmetic on figures (a ratio, a difference, an absolute value)
 *    stands in the data beside the rule that reads it: plain finite
 *    numbers, measures, + - * /, a unary -, parentheses, abs(x), max(a,
 *    b, ...) and min(a, b, ...) of two to four, logplace(x, a, b) (where
 *    x lies between a and b in logarithm: vsph_series_log_between),
 *    round(x) (the nearest integer, halves away from zero), a unary + or
 *    -; a NaN in gives a NaN out, max and min included (a figure not
 *    measured is never passed over), and so does a ratio over zero. WHAT
 *    starts at the first " -- " (an expression holds none). A let may not
 *    take the name of a measure the part set (found when grading: the
 *    lint knows no part's names); tests and templates read it as a
 *    measure;
 *  - `if EXPR: VERDICT` (one or more, the first that holds is taken) and
 *    `else: VERDICT`: EXPR combines the tests' names with & (and), | (or),
 *    ! (not) and parentheses, in Kleene's three values (!unknown is
 *    unknown; a & b fails where either fails; a | b holds where either
 *    holds), and a verdict is taken only where its EXPR holds for certain
 *    and every 'if' before it fails for certain (the else: where all of
 *    them fail), so an 'if' left unknown leaves every later verdict
 *    undecided, but for a "not tested" one whose EXPR holds for certain
 *    (it claims nothing); where none is taken the verdict is "not tested:
 *    a figure its verdict needs was not measured (unknown: TESTS)", the
 *    tests the 'if's read that were left unknown;
 *    a VERDICT starts with its class's words
 *    (reproduced, reproduced on a substitute, partly, differs, not
 *    tested) and may hold placeholders;
 *  - `word NAME: EXPR => TEXT` (one or more lines per NAME, the last
 *    `word NAME: else => TEXT`): the literal TEXT of the first line whose
 *    EXPR of the tests holds for certain, which {{NAME}} then inserts in
 *    any template: words that repeat a test are the test's own (the else
 *    line speaks only where every line before it fails for certain; where
 *    the first not failing is unknown the word is "(not measured)");
 *  - a claim without tests holds one verdict, `else:`, which says "not
 *    tested", or rests on a test of make check that `checked:` names
 *    ("tests/FILE.c test_NAME").
 *
 *  The class of a claim's verdict thus follows from its tests; no C
 *  writes one. tests/check_claim.c holds every kind at, just below and
 *  just above its threshold, and every block of reports/claims/ to this
 *  grammar. Within reports/ and the tests only. */

/** Most values a claim may read. */
#define VSPH_CLAIM_MAXVALS 64

/** The measures a claim reads and the words its templates take. */
struct vsph_claim_vals {
  size_t n;                                 /*!< values set */
  char key[VSPH_CLAIM_MAXVALS][32];         /*!< their names */
  double num[VSPH_CLAIM_MAXVALS];           /*!< a measure (NaN for a word) */
  char str[VSPH_CLAIM_MAXVALS][640];        /*!< a word (empty for a measure) */
  unsigned char is_str[VSPH_CLAIM_MAXVALS]; /*!< 1: a word */
  int overflow; /*!< 1: a value did not fit (grading then fails) */
};

/** A graded claim: the claims table's fields. */
struct vsph_claim_row {
  char claim[256], paper[256], ours[1600], setup[1000], verdict[1000];
};

/** The five verdict classes, in the claims table's tally order (the rule:
 *  docs/theory.md section 13). */
enum {
  VSPH_CLAIM_REPRODUCED = 0,
  VSPH_CLAIM_SUBSTITUTE, /*!< reproduced on a substitute set-up */
  VSPH_CLAIM_PARTLY,
  VSPH_CLAIM_DIFFERS,
  VSPH_CLAIM_NOT_TESTED,
  VSPH_CLAIM_NCLASSES
};

/** @brief A verdict's class, from its first words: "reproduced on a
 *  substitute...", "reproduced...", "partly...", "differs..." or "not
 *  reproduced...", "not tested..."; -1 for any other start. */
int vsph_claim_class(const char *verdict);

/** @brief Test kind @p kind ("below", ..., "flag": the file's comment) on
 *  its arguments @p x: 1 holds, 0 not (a NaN never holds), -1 no such kind
 *  or (order) an order that is no integer. */
int vsph_claim_test(const char *kind, const double *x);

/** @brief No values. */
void vsph_claim_clear(struct vsph_claim_vals *v);

/** @brief Measure @p key is @p x (a later set replaces it). */
void vsph_claim_num(struct vsph_claim_vals *v, const char *key, double x);

/** @brief Word @p key is the printf-formatted text. */
void vsph_claim_str(struct vsph_claim_vals *v, const char *key, const char *fmt,
                    ...) __attribute__((format(printf, 3, 4)));

/** @brief Grade claim @p text (a block in the grammar above, named
 *  @p name in messages) on @p v into @p row. @return VSPH_OK, or
 *  VSPH_EINVAL (reported, naming the claim and the fault): a field
 *  missing or repeated, a test of no known kind or with the wrong number
 *  of arguments, a measure the part did not set, an expression naming no
 *  test, a verdict that does not start with a class, a let malformed or
 *  naming a measure not set, a text too long for its field. */
int vsph_claim_grade_text(const char *name, const char *text,
                          const struct vsph_claim_vals *v,
                          struct vsph_claim_row *row);

/** @brief Test @p test of claim block @p text (named @p name in
 *  messages) on the measures @p v, as grading reads it, into @p holds: 1
 *  holds, 0 fails, -1 unknown (a measure not measured). For words a part
 *  must choose from one of the block's rules (the first of several cases
 *  that meets it), so that the rule's threshold stays in the block.
 *  The block's lets are derived first, so @p v holds every measure they
 *  read. @return VSPH_OK, or VSPH_EINVAL (the block malformed, no test
 *  @p test, a measure the part did not set). */
int vsph_claim_test_text(const char *name, const char *text, const char *test,
                         const struct vsph_claim_vals *v, int *holds);

/** @brief Check block @p text's grammar without values (every field, test
 *  and expression well formed; measures not looked up). @return as
 *  vsph_claim_grade_text. */
int vsph_claim_lint(const char *name, const char *text);

#endif /* VSPH_REPORTS_CLAIM_H */
