/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
#ifndef VSPH_REPORTS_REPORT_PARTS_H
#define VSPH_REPORTS_REPORT_PARTS_H

/* The report's parts (report_NAME.c, one file each), as report.c calls
 * them. Within reports/ and the tests only. */

#include "report_doc.h"

/* Each part that reads runs declares them first (its plan): the report
 * runs what is missing before any part is written, and a part that reads
 * a run its plan does not list fails (vsph_jobs_ready). */
int vsph_report_scenes_plan(struct vsph_report *R);
int vsph_report_stability_plan(struct vsph_report *R);
int vsph_report_channel_plan(struct vsph_report *R);
int vsph_report_contact_plan(struct vsph_report *R);

int vsph_report_tensors_write(struct vsph_report *R);
int vsph_report_profiles_write(struct vsph_report *R);
int vsph_report_scaling_write(struct vsph_report *R);
int vsph_report_dissipation_write(struct vsph_report *R);
int vsph_report_scenes_write(struct vsph_report *R);
int vsph_report_convergence_write(struct vsph_report *R);
int vsph_report_speed_write(struct vsph_report *R);
/* The speed part's runs: the ladders, and the ladder's two coarsest
 * resolutions again at CFL 0.5, 1.5 and 2. */
int vsph_report_speed_plan(struct vsph_report *R);
/* The study's run of scene @p sc, formulation @p f, rung @p k (0, 1) at
 * CFL index @p c (0.5, 1, 1.5, 2; the scene's own CFL: the ladder's run). */
struct vsph_jobs_spec vsph_report_speed_spec(const struct vsph_report *R,
                                             int sc, int f, int k, int c);
/* Those of scene @p sc alone (the claims read them too). */
int vsph_report_speed_plan_steps(struct vsph_report *R, int sc);
/* The Courant numbers of the step study: 0.5, 1, 1.5, 2. */
#define VSPH_REPORT_SPEED_NCFL 4
/* Of scene @p sc, formulation @p f, rung @p k (0 or 1: the study's two
 * coarsest): at each CFL of the study, whether the run stopped as
 * unstable and when (NaN: it ran to its end). */
int vsph_report_speed_stops(struct vsph_report *R, int sc, int f, int k,
                            int stopped[VSPH_REPORT_SPEED_NCFL],
                            double t_stop[VSPH_REPORT_SPEED_NCFL]);
int vsph_report_stability_write(struct vsph_report *R);
/* The scheme's own choices, isolated: the standing wave's variants, the
 * two-pass forms' null mode, the symmetry planes (report_choices.c). */
int vsph_report_choices_plan(struct vsph_report *R);
int vsph_report_choices_write(struct vsph_report *R);
/* The standing wave's run of formulation @p f at the defaults with the
 * lattice shifted by 1e-9 dx (another rounding of the same run) into
 * @p rs, and the ladder's rung it runs at (the speed study's) into
 * @p rung_k; and its plan, for every formulation (the claims read it). */
int vsph_report_choices_rounding(const struct vsph_report *R, int f,
                                 struct vsph_jobs_spec *rs, int *rung_k);
int vsph_report_choices_plan_rounding(struct vsph_report *R);
/* Form @p form's dissipation of the particle-scale checkerboard over
 * MEAF's, on a square of @p n across at h/dx 4/3 (the null mode). */
int vsph_report_choices_null(size_t n, int form, double *ratio);
/* The largest of the @p n > 0 values @p Ek over the first, and its time
 * t[k] into @p tpeak (the first of equal peaks): above 1 only where a run
 * gains kinetic energy, as a tank that stirs itself at rest. */
double vsph_report_choices_peak(const double *t, const double *Ek, size_t n,
                                double *tpeak);

int vsph_report_patch_write(struct vsph_report *R);

/* The claims of Zheng, Ma & Shao (2018) for section 9 (report_patch.c). */
int vsph_report_patch_claims(struct vsph_report *R);

/* Section 11: internal flows and the other formulations
 * (report_channel.c), and their claims. */
int vsph_report_channel_write(struct vsph_report *R);
int vsph_report_channel_claims(struct vsph_report *R);

/* Section 12: contact SPH and its numerical viscosity
 * (report_contact.c), and its claims. */
int vsph_report_contact_write(struct vsph_report *R);
int vsph_report_contact_claims(struct vsph_report *R);

#endif /* VSPH_REPORTS_REPORT_PARTS_H */
