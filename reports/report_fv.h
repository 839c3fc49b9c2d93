/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
#ifndef VSPH_REPORTS_REPORT_FV_H
#define VSPH_REPORTS_REPORT_FV_H

/* The finite-volume references in the report (report_fv.c): the
 * stretching square's OpenFOAM ladder in the scenes part, its error
 * column in the convergence part, the runs that isolate what sets MGF's
 * level against it, and the cavity's E_k history in the channel part.
 * Within reports/ and the tests only. */

#include "report_parts.h"

/* The resolution of the runs that isolate MGF's level (the quick ladder's
 * finest and the FULL ladder's coarsest), and their number (the first is
 * the ladder's own run). */
#define VSPH_REPORT_FV_WHY_RES 80
#define VSPH_REPORT_FV_NWHY 7
extern const char *const vsph_report_fv_why_what[VSPH_REPORT_FV_NWHY];

/* Run @p w of those (0: MGF as the ladder runs it). */
struct vsph_jobs_spec vsph_report_fv_why_spec(const struct vsph_report *R,
                                              int w);

/* Plan them (with the square on). */
int vsph_report_fv_plan(struct vsph_report *R);

/* Run @p r's decay error against the finest finite-volume grid:
 * max_t |E/E0 - E_FV/E_FV(0)| (NaN without the references). */
double vsph_report_fv_error(const struct vsph_report *R,
                            const struct vsph_jobs_run *r);

/* The extrapolated MGF's (section 5's stand-in, @p rr) decay error
 * against the finest judged grid (NaN without the references). */
double vsph_report_fv_standin_gap(const struct vsph_report *R,
                                  const struct vsph_report_richardson *rr);

/* The first time run @p r's dE_k/dt departs from the finest grid's by
 * more than @p threshold of it (vsph_series_onset; NaN without the
 * references or without a departure). */
double vsph_report_fv_onset(const struct vsph_report *R,
                            const struct vsph_jobs_run *r, double threshold);

/* Run @p r against the finest grid by five definitions, into @p m:
 * [0] the decay error above; [1] E/E0 - E_FV/E_FV(0) at t A0 = 1 (NaN
 * past a stop); [2] its RMS over t A0 in [0, 1]; [3] the dissipated
 * share's relative error at t A0 = 1; [4] max_t |E/E_FV - 1| (each
 * normalised by its own E(0)). NaN without the references. */
void vsph_report_fv_measures(const struct vsph_report *R,
                             const struct vsph_jobs_run *r, double m[5]);

/* The square's finite-volume subsection (scenes part). */
int vsph_report_fv_square(struct vsph_report *R);

/* The square's error against the finite volume, per run (convergence). */
int vsph_report_fv_convergence(struct vsph_report *R,
                               const struct vsph_report_ladder *lr);

/* The cavity's finite-volume subsection, with the SPH runs @p runs
 * (labels @p labels) at Re 1000 in its E_k figure (channel part). */
int vsph_report_fv_cavity(struct vsph_report *R,
                          const struct vsph_jobs_run *const *runs,
                          const char *const *labels, size_t nrun);

#endif /* VSPH_REPORTS_REPORT_FV_H */
