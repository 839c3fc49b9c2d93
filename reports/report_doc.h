/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
#ifndef VSPH_REPORTS_REPORT_DOC_H
#define VSPH_REPORTS_REPORT_DOC_H

/* The report being written (report.c): what a part writes with (its
 * Markdown, the claims table, prose blocks and figures). Within reports/
 * and the tests only. */

#include <gsl/gsl_integration.h>
#include <stddef.h>
#include <stdio.h>

#include "../runs/archive.h"
#include "../runs/folder.h"
#include "claim.h"
#include "fvref.h"
#include "report_runs.h"
#include "text.h"

struct vsph_plot;

/* One row of the claims table. */
struct vsph_report_claim {
  char claim[256], paper[256], ours[1600], verdict[1000];
  char setup[1000]; /* how our set-up, quantity and method differ from the
                      paper's, and the [reconstructed] choices the verdict
                      rests on ("none" where nothing differs) */
  char see[32];  /* the part that shows it ("scenes"): the link in the table */
  char name[64]; /* its block in reports/claims ("paper.wave_damping") */
};

/* The report being written: its folder and Markdown, the claims table,
 * the prose blocks' values, and the runs it reads (R->runs). */
struct vsph_report {
  const char *dir;                    /* output folder */
  FILE *md;                           /* the current part's Markdown */
  gsl_integration_workspace *wo, *wi; /* quadrature workspaces */
  struct vsph_report_claim *claims;   /* the claims table (growing) */
  const char *claim_see;              /* part of the claims added next */
  const char *claim_name; /* the block of the claim added next, or NULL */
  size_t nclaims, cap_claims;
  struct vsph_text_vars tv; /* scratch values for the prose blocks */
  double load[2][3];        /* load averages before and after (run.json) */
  const char *beside;       /* a run archive whose FULL runs the summary shows
                               beside the quick ones, or NULL */
  const struct vsph_archive_judge *judge; /* what judges its entries */
  struct vsph_fvref *fv;        /* the committed finite-volume references (never
                                   NULL; fv->sq.ok, fv->cav[w].ok: read) */
  struct vsph_folder folder;    /* the claim on dir while it is written */
  struct vsph_report_runs runs; /* what reads the runs */
  /* the FULL plan (its runs' names in beside_jd) and each run's standing
   * in the archive R->beside, for the table after the claims: made by the
   * driver (vsph_report_beside_prepare) before the parts are written */
  struct vsph_jobs beside_jobs;
  struct vsph_archive_judge beside_jd;
  int *beside_stands;
  /* the assembly's expected seconds, for the time left: each part's, and
   * what follows them (report.md, report.html, the seal) */
  double asm_part[48], asm_rest;
};

/* The five verdict classes of the claims table, in the tally's order
 * (the engine's, claim.h; the rule: docs/theory.md section 13). */
enum {
  VSPH_REPORT_REPRODUCED = VSPH_CLAIM_REPRODUCED,
  VSPH_REPORT_SUBSTITUTE = VSPH_CLAIM_SUBSTITUTE,
  VSPH_REPORT_PARTLY = VSPH_CLAIM_PARTLY,
  VSPH_REPORT_DIFFERS = VSPH_CLAIM_DIFFERS,
  VSPH_REPORT_NOT_TESTED = VSPH_CLAIM_NOT_TESTED,
  VSPH_REPORT_NVERDICTS = VSPH_CLAIM_NCLASSES
};

/* A verdict's class, from its first words: "reproduced on a
 * substitute...", "reproduced...", "partly...", "differs..." or "not
 * reproduced...", "not tested..."; -1 for any other start
 * (vsph_report_doc_claim refuses such a verdict). */
int vsph_report_doc_class(const char *verdict);

/* The tally of R->claims by class, then the claims table (each verdict
 * marked with its class's word, symbol and colour class), into R->md. */
int vsph_report_doc_claims_table(struct vsph_report *R);

/* Add a row to the claims table (copied): the claim, the paper's figure,
 * ours, the set-up differences (never empty: "none" where nothing
 * differs) and the verdict, which starts with its class's word. The parts
 * add none themselves: they grade a claim's block (vsph_report_doc_grade),
 * which adds its row here. */
int vsph_report_doc_claim(struct vsph_report *R, const char *claim,
                          const char *paper, const char *ours,
                          const char *setup, const char *verdict);

/* Grade claim block "claims/PART.NAME" (@p name, claim.h) on the measures
 * and words @p v into a row of the claims table. */
int vsph_report_doc_grade(struct vsph_report *R, const char *name,
                          const struct vsph_claim_vals *v);

/* Write prose block NAME with the values in R->tv, then clear them. */
int vsph_report_doc_say(struct vsph_report *R, const char *name);

/* Render figure @p pl and put it in the Markdown with its caption. */
int vsph_report_doc_figure(struct vsph_report *R, const struct vsph_plot *pl,
                           const char *caption);

/* The same with the caption from prose block NAME and the values in R->tv
 * (then cleared). */
int vsph_report_doc_figure_say(struct vsph_report *R,
                               const struct vsph_plot *pl, const char *name);

#endif /* VSPH_REPORTS_REPORT_DOC_H */
