/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
#ifndef VSPH_RUNS_JOBS_INTERNAL_H
#define VSPH_RUNS_JOBS_INTERNAL_H

/* What the pieces of the jobs module share (runs/jobs.c the plan,
 * jobs_local.c the missing runs in this process, jobs_pool.c as child
 * processes, jobs_slurm.c on Slurm, jobs_store.c reading the runs back).
 * Within runs/ only. */

#include "jobs.h"

/* The solver's estimate of @p j (particles, steps, memory). */
int vsph_jobs_estimate(struct vsph_jobs_job *j);

/* Pair interactions over the run: particles x neighbours x steps. */
double vsph_jobs_cost_of(const struct vsph_jobs_job *j);

/* Run @p j here: its folder ends with key.txt, or it failed. */
int vsph_jobs_execute(const struct vsph_jobs *J, const struct vsph_jobs_job *j);

/* The planned job of folder @p dir in plan @p P, or NULL. */
const struct vsph_jobs_job *vsph_jobs_find(const struct vsph_jobs *P,
                                           const char *dir);

/* The folder a planned job's files are read from, and the key its seal
 * must hold for. */
const char *vsph_jobs_where_of(const struct vsph_jobs_job *p, const char **key);

/* The cost a finished run actually had: its particles x neighbours x the
 * steps it took (run.json, or the shear test's summary.csv), which a run
 * stopped early (a stability map's) or whose time step changed makes
 * differ from the plan's estimate; the estimate where neither is read. */
double vsph_jobs_local_cost_taken(const struct vsph_jobs_job *j);

/* ", N more stand in a run archive" when the plan has such runs, for the
 * progress's first line. */
void vsph_jobs_local_archived_note(const struct vsph_jobs *J, char *buf,
                                   size_t len);

/* The missing runs, costliest first; with a budget, those that fit it on
 * @p lanes lanes. */
size_t vsph_jobs_local_missing(struct vsph_jobs *J, struct vsph_jobs_job ***out,
                               size_t lanes);

/* The runs' states for the estimate of the time left, in @p order's
 * order (the order they start), or NULL. */
struct vsph_jobs_eta *vsph_jobs_local_eta_start(struct vsph_jobs_job **order,
                                                size_t m);

/* ", about N s left" from the runs' states at @p now (running runs'
 * times so far from their start times @p t1) and the work after them
 * (@p after seconds, a report's assembly), or "" while no run has
 * finished: a rate is measured, never assumed. */
void vsph_jobs_local_eta_text(struct vsph_jobs_eta *e, const double *t1,
                              size_t m, size_t width, double now, double after,
                              char *buf, size_t len);

#endif /* VSPH_RUNS_JOBS_INTERNAL_H */
