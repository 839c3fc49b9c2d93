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
int vsph_report_claims_plan(struct vsph_report *R);

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
int vsph_report_stability_write(struct vsph_report *R);
int vsph_report_claims_write(struct vsph_report *R);

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
