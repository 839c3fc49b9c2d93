/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
#ifndef VSPH_REPORTS_REPORT_CHANNEL_H
#define VSPH_REPORTS_REPORT_CHANNEL_H

/* Section 11, internal flows, in three files, each with its table of run
 * specs, its tables and its claims: report_channel.c, Basa et al.'s
 * Poiseuille (their forms, Cleary's xi, the corrections, the wall
 * treatments, the state equations, the robustness map), Couette, and the
 * part's entries (report_parts.h), which call the other two in the
 * section's order; report_channel_p003.c, Vukčević et al.'s own set-up and
 * its time step against the sound speed; report_channel_cavity.c, the
 * lid-driven cavity. What they share. Within reports/ only. */

#include <stdio.h>

#include "report_doc.h"

struct vsph_plot;

/* Column @p col of run @p r at time t (NaN past its end). */
double vsph_report_channel_at(const struct vsph_jobs_run *r, const char *col,
                              double t);
/* The last row's value of column @p col. */
double vsph_report_channel_last(const struct vsph_jobs_run *r, const char *col);
/* The final value of a finished run; NaN ("-") for one stopped early. */
double vsph_report_channel_final(const struct vsph_jobs_run *r,
                                 const char *col);
/* A table cell: @p v times @p scale, "-" where not finite. */
void vsph_report_channel_cell(FILE *md, double v, double scale);
/* Why run @p r stopped, in a few words: "pairing" and, where the stop
 * names it, the closest pair's place; else the solver's reason. */
const char *vsph_report_channel_stop_words(const struct vsph_jobs_run *r,
                                           char *buf, size_t len);
/* "stopped at t = T s (why)" or "ran to its end" for run @p r. */
const char *vsph_report_channel_stop_phrase(const struct vsph_jobs_run *r,
                                            char *buf, size_t len);
/* "stopped at t = T s (why)" or "yes", as a cell. */
void vsph_report_channel_stop_cell(FILE *md, const struct vsph_jobs_run *r);
/* Run @p r's column @p col of its energy.csv against t times @p tscale
 * as a line of plot @p pl; VSPH_EIO when the table has no such column. */
int vsph_report_channel_plot_add(const struct vsph_report *R,
                                 struct vsph_plot *pl,
                                 const struct vsph_jobs_run *r, const char *col,
                                 double tscale, const char *label,
                                 const char *style);

/* Vukčević et al.'s own set-up and its time step against the sound speed
 * (report_channel_p003.c): its runs planned; loaded into *p (freed by
 * vsph_report_channel_p003_free, even after a failure); their tables with
 * their readings; their claims. */
struct vsph_report_channel_p003;
int vsph_report_channel_p003_plan(struct vsph_report *R);
int vsph_report_channel_p003_load(struct vsph_report *R,
                                  struct vsph_report_channel_p003 **p);
void vsph_report_channel_p003_free(struct vsph_report_channel_p003 *p);
int vsph_report_channel_p003_write(struct vsph_report *R,
                                   const struct vsph_report_channel_p003 *p);
int vsph_report_channel_p003_claims(struct vsph_report *R,
                                    const struct vsph_report_channel_p003 *p,
                                    struct vsph_claim_vals *v);

/* The lid-driven cavity (report_channel_cavity.c): the same, its figure
 * and its comparison with the finite volume apart; its claims in the
 * section's order: Zheng et al.'s forms (visc), Basa et al.'s (claims),
 * and VISC-02's (visc02, among the claims measured only at FULL). */
struct vsph_report_channel_cavity;
int vsph_report_channel_cavity_plan(struct vsph_report *R);
int vsph_report_channel_cavity_load(struct vsph_report *R,
                                    struct vsph_report_channel_cavity **c);
void vsph_report_channel_cavity_free(struct vsph_report_channel_cavity *c);
int vsph_report_channel_cavity_write(
    struct vsph_report *R, const struct vsph_report_channel_cavity *c);
int vsph_report_channel_cavity_figure(
    struct vsph_report *R, const struct vsph_report_channel_cavity *c);
int vsph_report_channel_cavity_fv(struct vsph_report *R,
                                  const struct vsph_report_channel_cavity *c);
int vsph_report_channel_cavity_visc(struct vsph_report *R,
                                    const struct vsph_report_channel_cavity *c,
                                    struct vsph_claim_vals *v);
int vsph_report_channel_cavity_claims(
    struct vsph_report *R, const struct vsph_report_channel_cavity *c,
    struct vsph_claim_vals *v);
int vsph_report_channel_cavity_visc02(
    struct vsph_report *R, const struct vsph_report_channel_cavity *c,
    struct vsph_claim_vals *v);

#endif /* VSPH_REPORTS_REPORT_CHANNEL_H */
