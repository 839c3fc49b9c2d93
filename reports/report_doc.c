/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
/* What the report's parts write with (report_doc.h): a claim's row and the
 * claims table, prose blocks, figures. It sits below every part and the
 * driver (report.c), and calls neither. */
#include "report_doc.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../common/status.h"
#include "../io/plot.h"

int vsph_report_doc_claim(struct vsph_report *R, const char *claim,
                          const char *paper, const char *ours,
                          const char *setup, const char *verdict) {
  /* every verdict says its class first, so the tally cannot misread one */
  if (vsph_report_doc_class(verdict) < 0)
    VSPH_FAIL(VSPH_EINVAL,
              "claim '%.60s': its verdict '%.40s' does not start with "
              "reproduced, reproduced on a substitute, partly, differs, not "
              "reproduced or not tested",
              claim, verdict);
  if (!setup || !*setup)
    VSPH_FAIL(VSPH_EINVAL, "claim '%.60s' says nothing of its set-up", claim);
  /* a field cut short would change what the row says: a bug, not a row */
  const struct vsph_report_claim *sz = NULL;
  const char *const field[5] = {claim, paper, ours, verdict, setup};
  const size_t room[5] = {sizeof sz->claim, sizeof sz->paper, sizeof sz->ours,
                          sizeof sz->verdict, sizeof sz->setup};
  for (int k = 0; k < 5; k++)
    if (strlen(field[k]) >= room[k])
      VSPH_FAIL(VSPH_EINVAL,
                "claim '%.60s': a field of %zu characters, more than the "
                "table's %zu",
                claim, strlen(field[k]), room[k] - 1);
  if (R->nclaims == R->cap_claims) {
    const size_t cap = R->cap_claims ? 2 * R->cap_claims : 32;
    struct vsph_report_claim *c = realloc(R->claims, cap * sizeof *c);
    if (!c) VSPH_FAIL(VSPH_ENOMEM, "cannot grow the claims table");
    R->claims = c;
    R->cap_claims = cap;
  }
  struct vsph_report_claim *c = &R->claims[R->nclaims++];
  snprintf(c->claim, sizeof c->claim, "%s", claim);
  snprintf(c->paper, sizeof c->paper, "%s", paper);
  snprintf(c->ours, sizeof c->ours, "%s", ours);
  snprintf(c->verdict, sizeof c->verdict, "%s", verdict);
  snprintf(c->setup, sizeof c->setup, "%s", setup);
  snprintf(c->see, sizeof c->see, "%s", R->claim_see ? R->claim_see : "");
  snprintf(c->name, sizeof c->name, "%s", R->claim_name ? R->claim_name : "");
  R->claim_name = NULL;
  return VSPH_OK;
}

int vsph_report_doc_say(struct vsph_report *R, const char *name) {
  const int st = vsph_text_write(R->md, name, &R->tv);
  vsph_text_clear(&R->tv);
  return st;
}

int vsph_report_doc_figure(struct vsph_report *R, const struct vsph_plot *pl,
                           const char *caption) {
  const int st = vsph_plot_write(pl);
  if (st) return st;
  char alt[256];
  vsph_plot_plain(alt, sizeof alt, pl->title);
  fprintf(R->md, "![%s](%s.svg)\n\n*Figure: %s*\n\n", alt, pl->name, caption);
  return VSPH_OK;
}

int vsph_report_doc_figure_say(struct vsph_report *R,
                               const struct vsph_plot *pl, const char *name) {
  char caption[1024], title[256];
  vsph_plot_plain(title, sizeof title, pl->title); /* {{title}}, as text */
  vsph_text_set(&R->tv, "title", "%s", title);
  const int st = vsph_text_format(caption, sizeof caption, name, &R->tv);
  vsph_text_clear(&R->tv);
  return st ? st : vsph_report_doc_figure(R, pl, caption);
}

/* The verdict classes: the word each verdict is marked with, the symbol
 * beside it (for Markdown readers without the HTML's colours) and the CSS
 * class of report.html's style. */
static const struct {
  const char *word, *symbol, *css;
} VERDICT[VSPH_REPORT_NVERDICTS] = {
    [VSPH_REPORT_REPRODUCED] = {"reproduced", "\u2714", "v-rep"},
    [VSPH_REPORT_SUBSTITUTE] = {"reproduced on a substitute", "\u2713",
                                "v-sub"},
    [VSPH_REPORT_PARTLY] = {"partly", "\u25d0", "v-part"},
    [VSPH_REPORT_DIFFERS] = {"differs", "\u2718", "v-diff"},
    [VSPH_REPORT_NOT_TESTED] = {"not tested", "\u2013", "v-none"}};

int vsph_report_doc_class(const char *verdict) {
  return vsph_claim_class(verdict);
}

int vsph_report_doc_grade(struct vsph_report *R, const char *name,
                          const struct vsph_claim_vals *v) {
  struct vsph_claim_row *row = malloc(sizeof *row);
  if (!row) VSPH_FAIL(VSPH_ENOMEM, "cannot grade claim %s", name);
  const char *text = vsph_text_get(name); /* reports/claims/, compiled in */
  int st = text ? vsph_claim_grade_text(name, text, v, row) : VSPH_EINVAL;
  if (!text)
    vsph_status_report(st, __FILE__, __LINE__, "no claim %s in reports/claims",
                       name);
  if (!st) {
    R->claim_name = !strncmp(name, "claims/", 7) ? name + 7 : name;
    st = vsph_report_doc_claim(R, row->claim, row->paper, row->ours, row->setup,
                               row->verdict);
  }
  free(row);
  return st;
}

/* Verdict @p text into @p m as a table cell: its class marked (symbol
 * and word), then the rest of its words, '|' escaped. */
static void verdict_cell(FILE *m, const char *text) {
  const int v = vsph_report_doc_class(text);
  fprintf(m, "<span class=\"v %s\">%s %s</span> ", VERDICT[v].css,
          VERDICT[v].symbol, VERDICT[v].word);
  const size_t w = strlen(VERDICT[v].word);
  if (!strncmp(text, VERDICT[v].word, w)) {
    text += w;
    text += strspn(text, ":, ");
  }
  for (const char *s = text; *s; s++) {
    if (*s == '|') fputc('\\', m);
    fputc(*s, m);
  }
}

/* The report's first screen, between marks the assembly moves to the
 * top (report.c): the tally, then the claims the text block
 * claims.findings names (one block name a line), each with its verdict
 * and a link to its section. */
static void findings(struct vsph_report *R, const size_t *tally) {
  fprintf(R->md,
          "<!-- findings -->\n**The verdicts on %zu claims of the five "
          "papers:**",
          R->nclaims);
  for (int v = 0; v < VSPH_REPORT_NVERDICTS; v++)
    fprintf(R->md, "%s <span class=\"v %s\">%s %zu %s</span>", v ? "," : "",
            VERDICT[v].css, VERDICT[v].symbol, tally[v], VERDICT[v].word);
  fprintf(R->md, " ([the summary](#sec-claims) gives each).\n\n");
  const char *list = vsph_text_get("claims.findings");
  int k = 0;
  for (const char *l = list; l && *l;) {
    const size_t n = strcspn(l, "\n");
    for (size_t c = 0; n && c < R->nclaims; c++)
      if (strlen(R->claims[c].name) == n && !strncmp(R->claims[c].name, l, n)) {
        if (!k++) fprintf(R->md, "**Three findings:**\n\n");
        fprintf(R->md, "%d. %s: ", k, R->claims[c].claim);
        verdict_cell(R->md, R->claims[c].verdict);
        fprintf(R->md, " ([%s](#sec-%s))\n", R->claims[c].see,
                R->claims[c].see);
      }
    l += n + (l[n] == '\n');
  }
  fprintf(R->md, "\n<!-- /findings -->\n");
}

int vsph_report_doc_claims_table(struct vsph_report *R) {
  size_t tally[VSPH_REPORT_NVERDICTS] = {0};
  for (size_t k = 0; k < R->nclaims; k++)
    tally[vsph_report_doc_class(R->claims[k].verdict)]++;
  findings(R, tally);
  fprintf(R->md, "**%zu claims:**", R->nclaims);
  for (int v = 0; v < VSPH_REPORT_NVERDICTS; v++)
    fprintf(R->md, "%s <span class=\"v %s\">%s %zu %s</span>", v ? "," : "",
            VERDICT[v].css, VERDICT[v].symbol, tally[v], VERDICT[v].word);
  fprintf(R->md, ".\n\n");
  fprintf(R->md,
          "<details open><summary>The %zu claims, a row each (click "
          "to fold)</summary>\n\n",
          R->nclaims);
  const int st = vsph_report_doc_say(R, "claims.table_head");
  if (st) return st;
  for (size_t k = 0; k < R->nclaims; k++) {
    const char *cell[5] = {R->claims[k].claim, R->claims[k].paper,
                           R->claims[k].ours, R->claims[k].setup,
                           R->claims[k].verdict};
    for (int c = 0; c < 5; c++) { /* a '|' inside a cell is escaped */
      fputs("| ", R->md);
      const char *text = cell[c];
      if (c == 4) /* the verdict: its class marked, then the rest of its
                   * words (the class's own word once, not twice) */
        verdict_cell(R->md, text);
      else
        for (const char *s = text; *s; s++) {
          if (*s == '|') fputc('\\', R->md);
          fputc(*s, R->md);
        }
      fputc(' ', R->md);
    }
    fprintf(R->md, "| [%s](#sec-%s) |\n", R->claims[k].see, R->claims[k].see);
  }
  fprintf(R->md, "\n</details>\n\n");
  return ferror(R->md) ? VSPH_EIO : VSPH_OK;
}
