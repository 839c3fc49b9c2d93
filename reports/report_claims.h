/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
#ifndef VSPH_REPORTS_REPORT_CLAIMS_H
#define VSPH_REPORTS_REPORT_CLAIMS_H

/* The claims table (report_claims.c): its verdict classes, the tally and
 * the table, and the FULL runs beside the quick ones. Within reports/ and
 * the tests only. */

#include "report_doc.h"

/* The five verdict classes of the claims table, in the tally's order
 * (the rule: docs/theory.md section 12). */
enum {
  VSPH_REPORT_REPRODUCED = 0,
  VSPH_REPORT_SUBSTITUTE, /* reproduced on a substitute set-up */
  VSPH_REPORT_PARTLY,
  VSPH_REPORT_DIFFERS,
  VSPH_REPORT_NOT_TESTED,
  VSPH_REPORT_NVERDICTS
};

/* A verdict's class, from its first words: "reproduced on a
 * substitute...", "reproduced...", "partly...", "differs..." or "not
 * reproduced...", "not tested..."; -1 for any other start
 * (vsph_report_claim refuses such a verdict). */
int vsph_report_claims_class(const char *verdict);

/* Beside the quick ladder's finest run of each scene and formulation
 * (@p run, with its E_k error @p err: the square's against its Richardson
 * reference), the FULL plan's run (the paper's resolution) from the run
 * archive R->beside where it holds it, with whether it stands (judged by
 * R->judge): a table after the claims. */
int vsph_report_claims_beside(
    struct vsph_report *R,
    const struct vsph_jobs_run run[][VSPH_VISCOUS_PAPER_COUNT],
    const double err[][VSPH_VISCOUS_PAPER_COUNT]);

/* The tally of R->claims by class, then the claims table (each verdict
 * marked with its class's word, symbol and colour class), into R->md. */
int vsph_report_claims_table(struct vsph_report *R);
#endif /* VSPH_REPORTS_REPORT_CLAIMS_H */
