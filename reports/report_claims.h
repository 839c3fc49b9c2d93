/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
#ifndef VSPH_REPORTS_REPORT_CLAIMS_H
#define VSPH_REPORTS_REPORT_CLAIMS_H

/* The core paper's claims (report_claims.c), graded first by the driver's
 * claims part (report.c), and the FULL runs beside the quick ones. Within
 * reports/ and the tests only. */

#include "report_doc.h"

/* The runs the core paper's claims read: every scene's ladder, whatever
 * the filter, the wave's time-step study and rounding run, the Cartesian
 * disc's, the finite-volume comparison's and the square with delta-SPH. */
int vsph_report_claims_plan(struct vsph_report *R);

/* The core paper's claims into R's table (each sets the part that shows
 * it). */
int vsph_report_claims_grade(struct vsph_report *R);

/* The table of the paper's resolutions after the claims: beside the quick
 * ladder's finest run of each scene and formulation, the FULL plan's run
 * from the run archive R->beside where it holds it, judged as
 * R->beside_jd and R->beside_stands say (vsph_report_beside_prepare). */
int vsph_report_claims_archived(struct vsph_report *R);

/* The same for given quick runs @p run with their E_k errors @p err (the
 * square's against its Richardson reference). */
int vsph_report_claims_beside(
    struct vsph_report *R,
    const struct vsph_jobs_run run[][VSPH_VISCOUS_PAPER_COUNT],
    const double err[][VSPH_VISCOUS_PAPER_COUNT]);
#endif /* VSPH_REPORTS_REPORT_CLAIMS_H */
