/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
/* The verdict engine (claim.h): a claim's block parsed, its tests run on
 * the part's measures, its verdict chosen by the first expression of tests
 * that holds, its templates filled. */
#include "claim.h"

#include <ctype.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../analysis/series.h"
#include "../common/status.h"
#include "grade.h"

/* Most tests, verdicts and word lines one claim may hold. */
#define MAXTESTS 24
#define MAXIFS 16
#define MAXWORDS 32
#define MAXLETS 24

void vsph_claim_clear(struct vsph_claim_vals *v) {
  v->n = 0;
  v->overflow = 0;
}

/* The slot of the value named by the @p n characters at @p name, or v->n
 * where none is: the one lookup of a name among the part's values. */
static size_t find(const struct vsph_claim_vals *v, const char *name,
                   size_t n) {
  size_t k = 0;
  while (k < v->n && (strlen(v->key[k]) != n || strncmp(v->key[k], name, n)))
    k++;
  return k;
}

/* The plain finite number as people write it at @p s (digits, a point,
 * an exponent: no nan, inf or hex) into *x: the characters it takes, or 0
 * where none is there. The one reading of numbers in a test's arguments
 * and a let's expression. */
static size_t plain_number(const char *s, double *x) {
  char *end;
  *x = strtod(s, &end);
  const size_t n = (size_t)(end - s);
  return n && strspn(s, "+-0123456789.eE") >= n && isfinite(*x) ? n : 0;
}

/* The slot of @p key (a new one at the end when absent), or
 * VSPH_CLAIM_MAXVALS when none is left (then v->overflow is set). */
static size_t slot(struct vsph_claim_vals *v, const char *key) {
  const size_t k = find(v, key, strlen(key));
  if (k == v->n) {
    if (v->n == VSPH_CLAIM_MAXVALS || strlen(key) >= sizeof v->key[0]) {
      v->overflow = 1;
      return VSPH_CLAIM_MAXVALS;
    }
    snprintf(v->key[v->n++], sizeof v->key[0], "%s", key);
  }
  return k;
}

void vsph_claim_num(struct vsph_claim_vals *v, const char *key, double x) {
  const size_t k = slot(v, key);
  if (k == VSPH_CLAIM_MAXVALS) return;
  v->num[k] = x;
  v->str[k][0] = '\0';
  v->is_str[k] = 0;
}

void vsph_claim_str(struct vsph_claim_vals *v, const char *key, const char *fmt,
                    ...) {
  const size_t k = slot(v, key);
  if (k == VSPH_CLAIM_MAXVALS) return;
  va_list ap;
  va_start(ap, fmt);
  const int m = vsnprintf(v->str[k], sizeof v->str[0], fmt, ap);
  va_end(ap);
  if (m < 0 || (size_t)m >= sizeof v->str[0]) v->overflow = 1;
  v->num[k] = (double)NAN;
  v->is_str[k] = 1;
}

/* ------------------------------------------------------------- parsing */

/* One test: its name, kind, arguments (as written) and origin. */
struct test {
  char name[32], kind[16], arg[3][32], origin[400];
  int nargs;
};

/* A claim's block, parsed: each field's text (continuations joined). */
struct block {
  char claim[256], where[128], paper[256], ours[1600], setup[1000];
  char checked[160]; /* the make-check test a claim without tests rests on */
  struct test test[MAXTESTS];
  int ntests;
  char cond[MAXIFS][256], verdict[MAXIFS][1000]; /* the last: else */
  int nifs, has_else;
  /* words the tests choose: "word NAME: EXPR => TEXT", the first line of
   * a name whose EXPR holds giving {{NAME}}, its last line "else" */
  char wname[MAXWORDS][32], wcond[MAXWORDS][256], wtext[MAXWORDS][400];
  int nwords;
  /* measures the block derives from the part's: "let NAME: EXPR", in turn */
  char lname[MAXLETS][32], lexpr[MAXLETS][256];
  int nlets;
};

static const struct {
  const char *kind;
  int nargs;
} KINDS[] = {{"below", 2},  {"above", 2}, {"atmost", 2}, {"atleast", 2},
             {"within", 3}, {"order", 2}, {"apart", 2},  {"larger", 3},
             {"flag", 1},   {"finite", 1}};
#define NKINDS (sizeof KINDS / sizeof KINDS[0])

/* A copy of @p s without blanks at either end into @p buf. */
static int trim_copy(char *buf, size_t len, const char *s, size_t n) {
  while (n && isspace((unsigned char)*s)) s++, n--;
  while (n && isspace((unsigned char)s[n - 1])) n--;
  if (n >= len) return -1;
  memcpy(buf, s, n);
  buf[n] = '\0';
  return 0;
}

static int parse_test(const char *name, const char *head, const char *val,
                      struct test *t) {
  /* head: "test NAME" */
  if (trim_copy(t->name, sizeof t->name, head + 4, strlen(head + 4)) ||
      !t->name[0])
    VSPH_FAIL(VSPH_EINVAL, "claim %s: a test without a name", name);
  for (const char *c = t->name; *c; c++)
    if (!isalnum((unsigned char)*c) && *c != '_')
      VSPH_FAIL(VSPH_EINVAL, "claim %s: test name '%s' is not a word", name,
                t->name);
  const char *dash = strstr(val, " -- ");
  if (!dash ||
      trim_copy(t->origin, sizeof t->origin, dash + 4, strlen(dash + 4)) ||
      !t->origin[0])
    VSPH_FAIL(VSPH_EINVAL,
              "claim %s: test %s gives no origin of its threshold "
              "(' -- ORIGIN')",
              name, t->name);
  char rule[200];
  if (trim_copy(rule, sizeof rule, val, (size_t)(dash - val)))
    VSPH_FAIL(VSPH_EINVAL, "claim %s: test %s too long", name, t->name);
  char *save = NULL, *tok = strtok_r(rule, " \t", &save);
  if (!tok || strlen(tok) >= sizeof t->kind)
    VSPH_FAIL(VSPH_EINVAL, "claim %s: test %s has no kind", name, t->name);
  snprintf(t->kind, sizeof t->kind, "%s", tok);
  size_t k = 0;
  while (k < NKINDS && strcmp(KINDS[k].kind, t->kind)) k++;
  if (k == NKINDS)
    VSPH_FAIL(VSPH_EINVAL, "claim %s: test %s: no kind '%s'", name, t->name,
              t->kind);
  t->nargs = 0;
  while ((tok = strtok_r(NULL, " \t", &save))) {
    if (t->nargs == 3 || strlen(tok) >= sizeof t->arg[0])
      VSPH_FAIL(VSPH_EINVAL,
                "claim %s: test %s: too many or too long "
                "arguments",
                name, t->name);
    snprintf(t->arg[t->nargs++], sizeof t->arg[0], "%s", tok);
  }
  if (t->nargs != KINDS[k].nargs)
    VSPH_FAIL(VSPH_EINVAL, "claim %s: test %s: %s takes %d arguments, not %d",
              name, t->name, t->kind, KINDS[k].nargs, t->nargs);
  return VSPH_OK;
}

static int arith_value(const char *name, const char *text,
                       const struct vsph_claim_vals *v, double *x);

/* "let NAME: EXPR [-- WHAT]" into the block: a name no measure or derived
 * measure of the block has yet, its expression well formed. */
static int parse_let(const char *name, struct block *b, const char *key,
                     const char *val) {
  if (b->nlets == MAXLETS)
    VSPH_FAIL(VSPH_EINVAL, "claim %s: more than %d let lines", name, MAXLETS);
  char *ln = b->lname[b->nlets];
  if (trim_copy(ln, sizeof b->lname[0], key + 4, strlen(key + 4)) || !*ln ||
      !(isalpha((unsigned char)*ln) || *ln == '_') ||
      strspn(ln,
             "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ"
             "0123456789_") != strlen(ln))
    VSPH_FAIL(VSPH_EINVAL, "claim %s: '%s' names no measure", name, key);
  for (int k = 0; k < b->nlets; k++)
    if (!strcmp(b->lname[k], ln))
      VSPH_FAIL(VSPH_EINVAL, "claim %s: let %s given twice", name, ln);
  const char *dash = strstr(val, " -- ");
  if (trim_copy(b->lexpr[b->nlets], sizeof b->lexpr[0], val,
                dash ? (size_t)(dash - val) : strlen(val)) ||
      !b->lexpr[b->nlets][0])
    VSPH_FAIL(VSPH_EINVAL, "claim %s: let %s: no expression, or one too long",
              name, ln);
  double x;
  const int st = arith_value(name, b->lexpr[b->nlets], NULL, &x);
  if (st) return st;
  b->nlets++;
  return VSPH_OK;
}

/* One field "key: value" into the block. */
static int field(const char *name, struct block *b, const char *key,
                 const char *val) {
  struct {
    const char *key;
    char *buf;
    size_t len;
  } plain[] = {{"claim", b->claim, sizeof b->claim},
               {"where", b->where, sizeof b->where},
               {"paper", b->paper, sizeof b->paper},
               {"ours", b->ours, sizeof b->ours},
               {"setup", b->setup, sizeof b->setup},
               {"checked", b->checked, sizeof b->checked}};
  for (size_t k = 0; k < sizeof plain / sizeof plain[0]; k++)
    if (!strcmp(key, plain[k].key)) {
      if (plain[k].buf[0])
        VSPH_FAIL(VSPH_EINVAL, "claim %s: field %s given twice", name, key);
      if (trim_copy(plain[k].buf, plain[k].len, val, strlen(val)))
        VSPH_FAIL(VSPH_EINVAL, "claim %s: field %s too long", name, key);
      return VSPH_OK;
    }
  if (!strncmp(key, "word ", 5)) {
    if (b->nwords == MAXWORDS)
      VSPH_FAIL(VSPH_EINVAL, "claim %s: more than %d word lines", name,
                MAXWORDS);
    const char *arrow = strstr(val, "=>");
    char *wn = b->wname[b->nwords];
    if (trim_copy(wn, sizeof b->wname[0], key + 5, strlen(key + 5)) || !*wn ||
        strspn(wn, "abcdefghijklmnopqrstuvwxyz0123456789_") != strlen(wn))
      VSPH_FAIL(VSPH_EINVAL, "claim %s: '%s' names no word", name, key);
    if (!arrow ||
        trim_copy(b->wcond[b->nwords], sizeof b->wcond[0], val,
                  (size_t)(arrow - val)) ||
        !b->wcond[b->nwords][0] ||
        trim_copy(b->wtext[b->nwords], sizeof b->wtext[0], arrow + 2,
                  strlen(arrow + 2)))
      VSPH_FAIL(VSPH_EINVAL,
                "claim %s: word %s: 'EXPR => TEXT' (or 'else => TEXT', its "
                "last line), within their lengths",
                name, wn);
    b->nwords++;
    return VSPH_OK;
  }
  if (!strncmp(key, "let ", 4)) return parse_let(name, b, key, val);
  if (!strncmp(key, "test ", 5)) {
    if (b->ntests == MAXTESTS)
      VSPH_FAIL(VSPH_EINVAL, "claim %s: more than %d tests", name, MAXTESTS);
    int st = parse_test(name, key, val, &b->test[b->ntests]);
    if (st) return st;
    for (int k = 0; k < b->ntests; k++)
      if (!strcmp(b->test[k].name, b->test[b->ntests].name))
        VSPH_FAIL(VSPH_EINVAL, "claim %s: test %s given twice", name,
                  b->test[k].name);
    b->ntests++;
    return VSPH_OK;
  }
  const int is_if = !strncmp(key, "if ", 3), is_else = !strcmp(key, "else");
  if (is_if || is_else) {
    if (b->has_else)
      VSPH_FAIL(VSPH_EINVAL, "claim %s: a verdict after 'else'", name);
    if (b->nifs == MAXIFS)
      VSPH_FAIL(VSPH_EINVAL, "claim %s: more than %d verdicts", name, MAXIFS);
    const char *e = is_if ? key + 3 : "";
    if (is_if && strspn(e, " \t") == strlen(e))
      VSPH_FAIL(VSPH_EINVAL, "claim %s: an 'if' without an expression", name);
    if (trim_copy(b->cond[b->nifs], sizeof b->cond[0], e, strlen(e)) ||
        trim_copy(b->verdict[b->nifs], sizeof b->verdict[0], val, strlen(val)))
      VSPH_FAIL(VSPH_EINVAL, "claim %s: a verdict too long", name);
    if (vsph_claim_class(b->verdict[b->nifs]) < 0)
      VSPH_FAIL(VSPH_EINVAL,
                "claim %s: verdict '%.40s' does not start with reproduced, "
                "reproduced on a substitute, partly, differs, not "
                "reproduced or not tested",
                name, b->verdict[b->nifs]);
    b->nifs++;
    b->has_else = is_else;
    return VSPH_OK;
  }
  VSPH_FAIL(VSPH_EINVAL, "claim %s: no field '%s'", name, key);
}

/* One logical line "key: value" into the block. */
static int line(const char *name, struct block *b, char *l) {
  char *colon = strchr(l, ':');
  if (!colon)
    VSPH_FAIL(VSPH_EINVAL, "claim %s: a line that is no field: '%.40s'", name,
              l);
  *colon = '\0';
  return field(name, b, l, colon + 1);
}

/* Block @p text into @p b: its physical lines joined into logical ones
 * (a line that starts with a blank continues the one before, after one
 * space), each a field. */
static int parse(const char *name, const char *text, struct block *b) {
  memset(b, 0, sizeof *b);
  const size_t len = strlen(text);
  char *buf = malloc(len + 2);
  if (!buf) VSPH_FAIL(VSPH_ENOMEM, "cannot parse claim %s", name);
  size_t m = 0;
  int open = 0; /* a logical line is being built */
  for (const char *s = text; *s;) {
    const char *eol = strchr(s, '\n');
    const size_t n = eol ? (size_t)(eol - s) : strlen(s);
    const size_t lead = strspn(s, " \t");
    if (lead >= n) { /* blank: ends the line before */
      open = 0;
    } else if (lead > 0) { /* continues it */
      if (!open) {
        free(buf);
        VSPH_FAIL(VSPH_EINVAL, "claim %s: a continued line with no field",
                  name);
      }
      buf[m++] = ' ';
      memcpy(buf + m, s + lead, n - lead);
      m += n - lead;
    } else {
      if (open) buf[m++] = '\n';
      memcpy(buf + m, s, n);
      m += n;
      open = 1;
    }
    s += n + (eol != NULL);
  }
  buf[m] = '\0';
  int st = VSPH_OK;
  char *save = NULL;
  for (char *l = strtok_r(buf, "\n", &save); l && !st;
       l = strtok_r(NULL, "\n", &save))
    st = line(name, b, l);
  free(buf);
  if (st) return st;
  const char *need[] = {b->claim, b->where, b->paper, b->ours, b->setup};
  const char *called[] = {"claim", "where", "paper", "ours", "setup"};
  for (int k = 0; k < 5; k++)
    if (!need[k][0])
      VSPH_FAIL(VSPH_EINVAL, "claim %s: no field %s", name, called[k]);
  if (!b->has_else)
    VSPH_FAIL(VSPH_EINVAL, "claim %s: no 'else' verdict (the last)", name);
  /* a claim without tests is not graded here: it says so ("not tested"),
   * or names the test of make check that holds it */
  if (!b->ntests && (b->nifs != 1 || (vsph_claim_class(b->verdict[0]) !=
                                          VSPH_CLAIM_NOT_TESTED &&
                                      !b->checked[0])))
    VSPH_FAIL(VSPH_EINVAL,
              "claim %s: no test, yet a verdict other than 'not tested' "
              "and no 'checked:' test of make check named",
              name);
  /* each word's lines: an expression each, 'else' the last and only there */
  for (int k = 0; k < b->nwords; k++) {
    int last = 1;
    for (int q = k + 1; q < b->nwords; q++)
      last &= strcmp(b->wname[q], b->wname[k]) != 0;
    const int is_else = !strcmp(b->wcond[k], "else");
    if (is_else != last)
      VSPH_FAIL(VSPH_EINVAL,
                "claim %s: word %s: 'else' is its last line, and only it", name,
                b->wname[k]);
  }
  if (b->ntests && b->checked[0])
    VSPH_FAIL(VSPH_EINVAL,
              "claim %s: 'checked:' is for a claim without "
              "tests",
              name);
  return VSPH_OK;
}

/* ---------------------------------------------------------------- tests */

int vsph_claim_class(const char *verdict) {
  if (!strncmp(verdict, "not tested", 10)) return VSPH_CLAIM_NOT_TESTED;
  if (!strncmp(verdict, "partly", 6)) return VSPH_CLAIM_PARTLY;
  if (!strncmp(verdict, "reproduced on a substitute", 26))
    return VSPH_CLAIM_SUBSTITUTE;
  if (!strncmp(verdict, "reproduced", 10)) return VSPH_CLAIM_REPRODUCED;
  if (!strncmp(verdict, "differs", 7) ||
      !strncmp(verdict, "not reproduced", 14))
    return VSPH_CLAIM_DIFFERS;
  return -1;
}

/* Argument @p a: a number as written, or the measure of that name (with
 * @p v NULL, for the lint, 0). */
static int arg(const char *name, const char *a, const struct vsph_claim_vals *v,
               double *x) {
  char *end;
  (void)strtod(a, &end);
  if (end != a && !*end) { /* a number as people write it: no nan, inf, hex */
    if (plain_number(a, x) != strlen(a))
      VSPH_FAIL(VSPH_EINVAL, "claim %s: '%s' is no plain finite number", name,
                a);
    return VSPH_OK;
  }
  if (!isalpha((unsigned char)a[0]) && a[0] != '_')
    VSPH_FAIL(VSPH_EINVAL,
              "claim %s: argument '%s' is neither a number nor "
              "a name",
              name, a);
  if (!v) { /* the lint: a name stands for a value it cannot know */
    *x = 0.0;
    return VSPH_OK;
  }
  const size_t k = find(v, a, strlen(a));
  if (k == v->n)
    VSPH_FAIL(VSPH_EINVAL, "claim %s: no measure '%s' (the part sets none)",
              name, a);
  if (v->is_str[k])
    VSPH_FAIL(VSPH_EINVAL, "claim %s: '%s' is a word, not a measure", name, a);
  *x = v->num[k];
  return VSPH_OK;
}

int vsph_claim_test(const char *kind, const double *x) {
  if (!strcmp(kind, "below")) return x[0] < x[1];
  if (!strcmp(kind, "above")) return x[0] > x[1];
  if (!strcmp(kind, "atmost")) return x[0] <= x[1];
  if (!strcmp(kind, "atleast")) return x[0] >= x[1];
  if (!strcmp(kind, "within")) return vsph_grade_within(x[0], x[1], x[2]);
  if (!strcmp(kind, "order")) {
    const double n = x[1];
    if (!(n == floor(n)) || fabs(n) > 64) return -1;
    return vsph_grade_order_is(x[0], (int)n) == 1;
  }
  if (!strcmp(kind, "apart")) return vsph_grade_apart(x[0], x[1]);
  if (!strcmp(kind, "larger")) return vsph_grade_larger(x[0], x[1], x[2]);
  if (!strcmp(kind, "flag")) return x[0] == 1.0;
  if (!strcmp(kind, "finite")) return isfinite(x[0]) != 0;
  return -1;
}

/* ----------------------------------------------------------- expression */

struct expr {
  const char *s, *name;
  const struct block *b;
  const int *holds; /* each test's result: 1, 0 or UNKNOWN */
  int err;
};

/* A test fed a NaN: neither holds nor fails (Kleene's third value). */
#define UNKNOWN 2

static int not3(int a) { return a == UNKNOWN ? UNKNOWN : !a; }
static int and3(int a, int b) {
  return !a || !b ? 0 : a == UNKNOWN || b == UNKNOWN ? UNKNOWN : 1;
}
static int or3(int a, int b) {
  return a == 1 || b == 1 ? 1 : a == UNKNOWN || b == UNKNOWN ? UNKNOWN : 0;
}

static void skip(struct expr *e) {
  while (*e->s == ' ' || *e->s == '\t') e->s++;
}

static int expr_or(struct expr *e);

static int expr_atom(struct expr *e) {
  skip(e);
  if (*e->s == '!') {
    e->s++;
    return not3(expr_atom(e));
  }
  if (*e->s == '(') {
    e->s++;
    const int r = expr_or(e);
    skip(e);
    if (*e->s != ')')
      e->err = 1;
    else
      e->s++;
    return r;
  }
  const size_t n = strspn(e->s,
                          "abcdefghijklmnopqrstuvwxyz"
                          "ABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_");
  for (int k = 0; n && k < e->b->ntests; k++)
    if (strlen(e->b->test[k].name) == n &&
        !strncmp(e->b->test[k].name, e->s, n)) {
      e->s += n;
      return e->holds[k];
    }
  e->err = 1;
  e->s += n ? n : strlen(e->s); /* no such test: stop here */
  return 0;
}

static int expr_and(struct expr *e) {
  int r = expr_atom(e);
  for (skip(e); *e->s == '&'; skip(e)) {
    e->s++;
    r = and3(expr_atom(e), r); /* both sides parsed, whatever the first says */
  }
  return r;
}

static int expr_or(struct expr *e) {
  int r = expr_and(e);
  for (skip(e); *e->s == '|'; skip(e)) {
    e->s++;
    r = or3(expr_and(e), r);
  }
  return r;
}

/* Expression @p cond on the tests' results: 1, 0, UNKNOWN, or -1 if
 * malformed. */
static int eval(const char *cond, const struct block *b, const int *holds) {
  struct expr e = {cond, NULL, b, holds, 0};
  const int r = expr_or(&e);
  skip(&e);
  return e.err || *e.s ? -1 : r;
}

/* ----------------------------------------------------------- arithmetic */

/* A derived measure's expression ("let NAME: EXPR"): plain finite numbers,
 * the part's measures and the block's earlier lets, + - * /, a unary -,
 * parentheses, abs(x), max and min (two to four arguments),
 * logplace(x, a, b) (vsph_series_log_between) and round(x). A NaN in gives
 * a NaN out,
 * max and min included (a figure not measured is never passed over, as
 * C's fmax would). With no values (the lint) a name reads 0. */
struct arith {
  const char *s, *name; /* where it reads; the claim, for messages */
  const char *text;     /* the whole expression, for messages */
  const struct vsph_claim_vals *v;
  int err; /* 1: reported */
};

static double ar_sum(struct arith *a);

static double ar_fail(struct arith *a, const char *what, size_t n,
                      const char *at) {
  if (!a->err)
    vsph_status_report(VSPH_EINVAL, __FILE__, __LINE__,
                       "claim %s: let '%s': %s '%.*s'", a->name, a->text, what,
                       (int)n, at);
  a->err = 1;
  return (double)NAN;
}

static void ar_skip(struct arith *a) {
  while (*a->s == ' ' || *a->s == '\t') a->s++;
}

/* A number as people write it (no nan, inf or hex). */
static double ar_number(struct arith *a) {
  double x;
  const size_t n = plain_number(a->s, &x);
  if (!n) return ar_fail(a, "no plain finite number at", 1, a->s);
  a->s += n;
  return x;
}

/* The value of measure @p n chars at @p at. */
static double ar_measure(struct arith *a, const char *at, size_t n) {
  if (!a->v) return 0.0;
  const size_t k = find(a->v, at, n);
  if (k == a->v->n)
    return ar_fail(a, "no measure (the part sets none, nor a let before)", n,
                   at);
  if (a->v->is_str[k]) return ar_fail(a, "a word, not a measure:", n, at);
  return a->v->num[k];
}

/* A function's call after its name: abs(x); max(a, b, ...) and min(a, b,
 * ...), two to four arguments; logplace(x, a, b), where x lies between a
 * (0) and b (1) in logarithm (vsph_series_log_between); round(x), the
 * nearest integer, halves away from zero. */
static double ar_call(struct arith *a, const char *at, size_t n) {
  static const struct {
    const char *name;
    int lo, hi; /* how many arguments */
  } FN[] = {{"abs", 1, 1},
            {"max", 2, 4},
            {"min", 2, 4},
            {"logplace", 3, 3},
            {"round", 1, 1}};
  size_t f = 0;
  while (f < sizeof FN / sizeof FN[0] &&
         (strlen(FN[f].name) != n || strncmp(FN[f].name, at, n)))
    f++;
  if (f == sizeof FN / sizeof FN[0]) return ar_fail(a, "no function", n, at);
  double x[4];
  int m = 0;
  do {
    a->s++; /* '(' or ',' */
    if (m == FN[f].hi) return ar_fail(a, "too many arguments for", n, at);
    x[m++] = ar_sum(a);
    ar_skip(a);
  } while (*a->s == ',');
  if (*a->s != ')') return ar_fail(a, "no ')' closing", n, at);
  if (m < FN[f].lo) return ar_fail(a, "too few arguments for", n, at);
  a->s++;
  if (f == 0) return fabs(x[0]);
  if (f == 3) return vsph_series_log_between(x[0], x[1], x[2]);
  if (f == 4) return round(x[0]);
  double r = x[0];
  for (int k = 0; k < m; k++) {
    if (isnan(x[k])) return (double)NAN; /* never passed over */
    if (f == 1 ? x[k] > r : x[k] < r) r = x[k];
  }
  return r;
}

static double ar_atom(struct arith *a) {
  ar_skip(a);
  const char *at = a->s;
  if (*at == '-' || *at == '+') {
    a->s++;
    const double x = ar_atom(a);
    return *at == '-' ? -x : x;
  }
  if (*at == '(') {
    a->s++;
    const double x = ar_sum(a);
    ar_skip(a);
    if (*a->s != ')') return ar_fail(a, "no ')' at", 1, a->s);
    a->s++;
    return x;
  }
  if (isdigit((unsigned char)*at) || *at == '.') return ar_number(a);
  const size_t n = strspn(at,
                          "abcdefghijklmnopqrstuvwxyz"
                          "ABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_");
  if (!n || isdigit((unsigned char)*at))
    return ar_fail(a, "no number, measure or '(' at", *at ? 1 : 0, at);
  a->s += n;
  ar_skip(a);
  if (*a->s == '(') return ar_call(a, at, n);
  return ar_measure(a, at, n);
}

static double ar_product(struct arith *a) {
  double x = ar_atom(a);
  for (ar_skip(a); *a->s == '*' || *a->s == '/'; ar_skip(a)) {
    const char op = *a->s++;
    const double y = ar_atom(a);
    /* a ratio over zero is no figure: not measured */
    x = op == '*' ? x * y : y == 0.0 ? (double)NAN : x / y;
  }
  return x;
}

static double ar_sum(struct arith *a) {
  double x = ar_product(a);
  for (ar_skip(a); *a->s == '+' || *a->s == '-'; ar_skip(a)) {
    const char op = *a->s++;
    const double y = ar_product(a);
    x = op == '+' ? x + y : x - y;
  }
  return x;
}

/* Expression @p text on the measures @p v (NULL: its form only) into *x. */
static int arith_value(const char *name, const char *text,
                       const struct vsph_claim_vals *v, double *x) {
  struct arith a = {text, name, text, v, 0};
  *x = ar_sum(&a);
  ar_skip(&a);
  if (!a.err && *a.s)
    ar_fail(&a, "more after the expression:", strlen(a.s), a.s);
  return a.err ? VSPH_EINVAL : VSPH_OK;
}

/* The part's measures @p v and the block's lets, each in turn from those
 * before it, into a copy *@p out (freed by the caller; NULL with @p v
 * NULL, the lint). A let may not take the name of a measure the part set. */
static int derive(const char *name, const struct block *b,
                  const struct vsph_claim_vals *v,
                  struct vsph_claim_vals **out) {
  *out = NULL;
  if (!v) return VSPH_OK;
  struct vsph_claim_vals *w = malloc(sizeof *w);
  if (!w) VSPH_FAIL(VSPH_ENOMEM, "cannot grade claim %s", name);
  memcpy(w, v, sizeof *w);
  for (int k = 0; k < b->nlets; k++) {
    for (size_t q = 0; q < v->n; q++)
      if (!strcmp(v->key[q], b->lname[k])) {
        free(w);
        VSPH_FAIL(VSPH_EINVAL,
                  "claim %s: let %s: the part sets a measure of that name",
                  name, b->lname[k]);
      }
    double x;
    const int st = arith_value(name, b->lexpr[k], w, &x);
    if (st) {
      free(w);
      return st;
    }
    vsph_claim_num(w, b->lname[k], x);
  }
  *out = w;
  return VSPH_OK;
}

/* ------------------------------------------------------------ templates */

/* A conditional placeholder's body "?EXPR|HOLDS|FAILS[|UNKNOWN]" (its
 * texts literal) into @p piece: the text its expression of the tests
 * @p holds chooses (UNKNOWN: the third text, or else the second). */
static int choose(const char *name, char *ph, const struct block *b,
                  const int *holds, char *piece, size_t len) {
  char *part[4] = {ph + 1, NULL, NULL, NULL};
  int n = 1;
  for (char *c = ph + 1; *c && n < 4; c++)
    if (*c == '|') *c = '\0', part[n++] = c + 1;
  if (n < 3 || strchr(part[n - 1], '|'))
    VSPH_FAIL(VSPH_EINVAL,
              "claim %s: {{?%s...}}: a condition takes two or three texts "
              "(?EXPR|holds|fails[|unknown])",
              name, part[0]);
  const int r = eval(part[0], b, holds);
  if (r < 0)
    VSPH_FAIL(VSPH_EINVAL,
              "claim %s: {{?%s|...}}: not an expression of its tests", name,
              part[0]);
  const char *text = r == 1                   ? part[1]
                     : r == UNKNOWN && n == 4 ? part[3]
                                              : part[2];
  snprintf(piece, len, "%s", text);
  return VSPH_OK;
}

/* Word @p w of block @p b, as its lines choose on the tests @p holds, into
 * *text: 1, 0 when the block has no such word, -1 with a report when a
 * line's expression is malformed. */
static int word_text(const char *name, const struct block *b, const int *holds,
                     const char *w, const char **text) {
  int found = 0;
  for (int k = 0; k < b->nwords; k++) {
    if (strcmp(b->wname[k], w)) continue;
    found = 1;
    const int is_else = !strcmp(b->wcond[k], "else");
    /* a line speaks where it holds and every one before it fails, so the
     * first not failing decides, an unknown one saying so */
    const int r = is_else ? 1 : eval(b->wcond[k], b, holds);
    if (r == UNKNOWN) {
      *text = "(not measured)";
      return 1;
    }
    if (r < 0) {
      vsph_status_report(VSPH_EINVAL, __FILE__, __LINE__,
                         "claim %s: word %s: '%s' is not an expression of "
                         "its tests",
                         name, w, b->wcond[k]);
      return -1;
    }
    if (r == 1) {
      *text = b->wtext[k];
      return 1;
    }
  }
  return found ? -1 : 0; /* (an else line ends every word: unreachable) */
}

/* Template @p t filled from @p v into @p out (@p len bytes), its
 * conditions read on the tests' results @p holds of block @p b; with @p v
 * NULL only its placeholders' form is checked. */
/* @p n bytes of @p text after the *m of @p out (@p len bytes in all), or
 * a refusal when they do not fit. */
static int put(const char *name, char *out, size_t len, size_t *m,
               const char *text, size_t n) {
  if (*m + n >= len)
    VSPH_FAIL(VSPH_EINVAL, "claim %s: a text longer than its field (%zu)", name,
              len - 1);
  memcpy(out + *m, text, n);
  *m += n;
  return VSPH_OK;
}

static int fill(const char *name, const char *t, const struct block *b,
                const int *holds, const struct vsph_claim_vals *v, char *out,
                size_t len, int words) {
  size_t m = 0;
  for (const char *s = t; *s;) {
    const char *open = strstr(s, "{{");
    int st = put(name, out, len, &m, s, open ? (size_t)(open - s) : strlen(s));
    if (st) return st;
    if (!open) break;
    const char *close = strstr(open + 2, "}}");
    char ph[512];
    if (!close || (size_t)(close - open - 2) >= sizeof ph)
      VSPH_FAIL(VSPH_EINVAL, "claim %s: a placeholder without '}}'", name);
    memcpy(ph, open + 2, (size_t)(close - open - 2));
    ph[close - open - 2] = '\0';
    s = close + 2;
    char piece[700];
    if (ph[0] == '?') { /* a text the tests choose */
      if ((st = choose(name, ph, b, holds, piece, sizeof piece)) ||
          (st = put(name, out, len, &m, piece, strlen(piece))))
        return st;
      continue;
    }
    /* name[*100][:FMT] */
    char *fmt = strchr(ph, ':');
    if (fmt) *fmt++ = '\0';
    char *scale = strstr(ph, "*100");
    const double mult = scale ? 100.0 : 1.0;
    if (scale) {
      if (scale[4])
        VSPH_FAIL(VSPH_EINVAL,
                  "claim %s: {{%s}}: only *100 "
                  "scales",
                  name, ph);
      *scale = '\0';
    }
    if (fmt) { /* flags, a width of at most two digits, a precision '.' and
                * at most two, then one of e f g E G */
      const char *c = fmt + strspn(fmt, "-+ 0#");
      size_t d = strspn(c, "0123456789");
      int ok = d <= 2;
      c += d;
      if (*c == '.') {
        d = strspn(++c, "0123456789");
        ok &= d <= 2;
        c += d;
      }
      if (!ok || !*c || !strchr("efgEG", *c) || c[1])
        VSPH_FAIL(VSPH_EINVAL,
                  "claim %s: {{%s:%s}}: not a format of a "
                  "number (%%[flags][width][.prec]e|f|g)",
                  name, ph, fmt);
    }
    const char *wt = NULL;
    const int wr = words ? word_text(name, b, holds, ph, &wt) : 0;
    if (wr < 0) return VSPH_EINVAL;
    if (wr == 1) {
      if (fmt || scale)
        VSPH_FAIL(VSPH_EINVAL, "claim %s: {{%s}} is a word: no format", name,
                  ph);
      /* a word's text may hold measures and words of the part, not words
       * of the block (no word is made of words) */
      if ((st = fill(name, wt, b, holds, v, piece, sizeof piece, 0))) return st;
    } else if (!v) {
      piece[0] = '\0';
    } else {
      const size_t k = find(v, ph, strlen(ph));
      if (k == v->n)
        VSPH_FAIL(VSPH_EINVAL, "claim %s: {{%s}} has no value", name, ph);
      if (v->is_str[k]) {
        if (fmt || scale)
          VSPH_FAIL(VSPH_EINVAL, "claim %s: {{%s}} is a word: no format", name,
                    ph);
        snprintf(piece, sizeof piece, "%s", v->str[k]);
      } else {
        char f[16];
        snprintf(f, sizeof f, "%%%s", fmt ? fmt : "g");
        /* f is checked above: one conversion of a double */
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wformat-nonliteral"
        snprintf(piece, sizeof piece, f, mult * v->num[k]);
#pragma GCC diagnostic pop
      }
    }
    if ((st = put(name, out, len, &m, piece, strlen(piece)))) return st;
  }
  out[m] = '\0';
  return VSPH_OK;
}

/* --------------------------------------------------------------- grading */

/* Block @p b graded (or, with @p v NULL, only checked) into @p row. */
/* Test @p k of block @p b on the measures @p v into *holds: 1, 0, or
 * UNKNOWN where a measure is not measured (NaN; `finite` reads it). A
 * measure the part did not set, or an order that is no integer, refused. */
static int test_holds(const char *name, const struct block *b, int k,
                      const struct vsph_claim_vals *v, int *holds) {
  double x[3] = {0};
  int nan = 0; /* a measure not measured: the test is unknown */
  for (int a = 0; a < b->test[k].nargs; a++) {
    const int st = arg(name, b->test[k].arg[a], v, &x[a]);
    if (st) return st;
    nan |= isnan(x[a]);
  }
  *holds = vsph_claim_test(b->test[k].kind, x);
  if (*holds < 0 && !nan)
    VSPH_FAIL(VSPH_EINVAL, "claim %s: test %s: %s of %s is no integer order",
              name, b->test[k].name, b->test[k].kind, b->test[k].arg[1]);
  if (nan && strcmp(b->test[k].kind, "finite")) *holds = UNKNOWN;
  return VSPH_OK;
}

/* Whether test @p t is named in an 'if' of block @p b (a word, not a
 * part of a longer name). */
static int read_by_ifs(const struct block *b, const char *t) {
  const size_t n = strlen(t);
  static const char WORD[] =
      "abcdefghijklmnopqrstuvwxyz"
      "ABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_";
  for (int k = 0; k < b->nifs; k++)
    for (const char *c = strstr(b->cond[k], t); c; c = strstr(c + 1, t))
      if ((c == b->cond[k] || !strchr(WORD, c[-1])) &&
          (!c[n] || !strchr(WORD, c[n])))
        return 1;
  return 0;
}

/* The verdict of block @p b where no verdict holds for certain (a test an
 * 'if' reads was fed a figure not measured): not tested, naming the tests
 * left unknown. */
static int undecided(const char *name, const struct block *b, const int *holds,
                     struct vsph_claim_row *row) {
  size_t m = (size_t)snprintf(row->verdict, sizeof row->verdict,
                              "not tested: a figure its verdict needs was "
                              "not measured (unknown:");
  for (int k = 0, n = 0; k < b->ntests && m < sizeof row->verdict; k++)
    if (holds[k] == UNKNOWN && read_by_ifs(b, b->test[k].name))
      m += (size_t)snprintf(row->verdict + m, sizeof row->verdict - m, "%s %s",
                            n++ ? "," : "", b->test[k].name);
  if (m + 2 > sizeof row->verdict)
    VSPH_FAIL(VSPH_EINVAL, "claim %s: a verdict longer than its field", name);
  memcpy(row->verdict + m, ")", 2);
  return VSPH_OK;
}

static int grade(const char *name, const struct block *b,
                 const struct vsph_claim_vals *v, struct vsph_claim_row *row) {
  if (v && v->overflow)
    VSPH_FAIL(VSPH_EINVAL,
              "claim %s: the part set too many or too long "
              "values",
              name);
  int holds[MAXTESTS];
  for (int k = 0; k < b->ntests; k++) {
    const int st = test_holds(name, b, k, v, &holds[k]);
    if (st) return st;
  }
  for (int k = 0; k < b->nwords; k++) { /* every word line well formed */
    if (strcmp(b->wcond[k], "else") && eval(b->wcond[k], b, holds) < 0)
      VSPH_FAIL(VSPH_EINVAL,
                "claim %s: word %s: '%s' is not an expression of its tests",
                name, b->wname[k], b->wcond[k]);
    char scratch[700]; /* the lint: each line's placeholders */
    if (!v) {
      const int st =
          fill(name, b->wtext[k], b, holds, v, scratch, sizeof scratch, 0);
      if (st) return st;
    }
  }
  /* every one checked; a verdict holds where its expression holds for
   * certain and every one before it fails for certain (the else: where
   * they all fail), so the first not failing decides: where it is unknown,
   * no verdict is taken but a 'not tested' one that holds for certain */
  int pick = -1, open = 0;
  for (int k = 0; k < b->nifs; k++) {
    const int is_else = !b->cond[k][0];
    const int r = is_else ? 1 : eval(b->cond[k], b, holds);
    if (r < 0)
      VSPH_FAIL(VSPH_EINVAL,
                "claim %s: 'if %s': not an expression of its "
                "tests (names, &, |, !, parentheses)",
                name, b->cond[k]);
    /* a 'not tested' verdict claims nothing: it may speak past an unknown */
    if (r == 1 && pick < 0 &&
        (!open || vsph_claim_class(b->verdict[k]) == VSPH_CLAIM_NOT_TESTED))
      pick = k;
    open |= r == UNKNOWN; /* every later verdict undecided */
  }
  const char *where = b->where;
  char claim[sizeof row->claim];
  /* the core paper's claims carry no mark in the table (its head says so) */
  if (!strncmp(where, "Colagrossi", 10))
    snprintf(claim, sizeof claim, "%s", b->claim);
  else if (snprintf(claim, sizeof claim, "%s (%s)", b->claim, where) >=
           (int)sizeof claim)
    VSPH_FAIL(VSPH_EINVAL, "claim %s: a claim longer than its field", name);
  int st = fill(name, claim, b, holds, v, row->claim, sizeof row->claim, 1);
  if (!st)
    st = fill(name, b->paper, b, holds, v, row->paper, sizeof row->paper, 1);
  if (!st)
    st = fill(name, b->ours, b, holds, v, row->ours, sizeof row->ours, 1);
  if (!st)
    st = fill(name, b->setup, b, holds, v, row->setup, sizeof row->setup, 1);
  for (int k = 0; k < b->nifs && !st; k++)
    if (!v || k == pick) /* the lint checks every verdict's placeholders */
      st = fill(name, b->verdict[k], b, holds, v, row->verdict,
                sizeof row->verdict, 1);
  if (!st && v && pick < 0) /* no verdict decided: say which tests */
    return undecided(name, b, holds, row);
  /* a word filled into the verdict must not change its class */
  if (!st && v &&
      vsph_claim_class(row->verdict) != vsph_claim_class(b->verdict[pick]))
    VSPH_FAIL(VSPH_EINVAL,
              "claim %s: the verdict's words change its class ('%.40s')", name,
              row->verdict);
  return st;
}

int vsph_claim_grade_text(const char *name, const char *text,
                          const struct vsph_claim_vals *v,
                          struct vsph_claim_row *row) {
  struct block *b = malloc(sizeof *b);
  if (!b) VSPH_FAIL(VSPH_ENOMEM, "cannot grade claim %s", name);
  struct vsph_claim_vals *w = NULL;
  int st = parse(name, text, b);
  if (!st) st = derive(name, b, v, &w);
  if (!st) st = grade(name, b, w, row);
  free(w);
  free(b);
  return st;
}

int vsph_claim_test_text(const char *name, const char *text, const char *test,
                         const struct vsph_claim_vals *v, int *holds) {
  if (!name || !text || !test || !v || !holds)
    VSPH_FAIL(VSPH_EINVAL, "vsph_claim_test_text: a NULL argument");
  struct block *b = malloc(sizeof *b);
  if (!b) VSPH_FAIL(VSPH_ENOMEM, "cannot read claim %s", name);
  int st = parse(name, text, b), k = 0;
  while (!st && k < b->ntests && strcmp(b->test[k].name, test)) k++;
  if (!st && k == b->ntests) {
    free(b);
    VSPH_FAIL(VSPH_EINVAL, "claim %s: no test %s", name, test);
  }
  struct vsph_claim_vals *w = NULL;
  if (!st) st = derive(name, b, v, &w);
  if (!st) st = test_holds(name, b, k, w, holds);
  if (!st && *holds == UNKNOWN) *holds = -1; /* not measured */
  free(w);
  free(b);
  return st;
}

int vsph_claim_lint(const char *name, const char *text) {
  struct vsph_claim_row *row = malloc(sizeof *row);
  if (!row) VSPH_FAIL(VSPH_ENOMEM, "cannot check claim %s", name);
  const int st = vsph_claim_grade_text(name, text, NULL, row);
  free(row);
  return st;
}
