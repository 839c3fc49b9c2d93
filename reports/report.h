/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
#ifndef VSPH_REPORTS_REPORT_H
#define VSPH_REPORTS_REPORT_H

#include <signal.h>
#include <stddef.h>
#include <stdio.h>

#include "../runs/archive.h"
#include "../runs/jobs.h"

/** @file report.h
 *  @brief The main job: the report. It runs the analysis (THEORY 2-4) and
 *  the scenes (THEORY 5-6) part by part and writes report.md, a
 *  self-contained report.html, the CSV behind every table and figure, the
 *  figures (PNG beside their gnuplot scripts), the solver runs,
 *  baseline.csv and run.json into one folder. Runs and cheap parts are
 *  cached by the version, the source hash and their settings. */

/** What to write. */
struct vsph_report_props {
  const char *dir;     /*!< output folder */
  int full;            /*!< 1: the paper's resolutions and end times */
  unsigned long parts; /*!< bit p: part p (vsph_report_part_*); 0: all */
  unsigned scenes;     /*!< bit s: scene s of vsph_report_scene_name in the
                            scene-wise parts (scenes, convergence, speed);
                            0: all. The claims always read every scene. */
  /** if not NULL, a run in progress stops after the step during which
   *  *stop became non-zero, and the report returns VSPH_EINTR (the run is
   *  redone next time: it is not cached) */
  const volatile sig_atomic_t *stop;
  /** if not NULL, set to 1 while runs go on (a stop must let them
   *  checkpoint) and to 0 around them, when a caller's handler may end
   *  the process at once (vsph_args_quick_stop: every part and file is
   *  written whole or not at all, and the seal comes last) */
  volatile sig_atomic_t *writing;
  int mode;              /*!< VSPH_REPORT_LOCAL, ... (below) */
  size_t jobs, threads;  /*!< POOL: processes at a time, threads each;
                              SLURM: threads (CPUs) per task */
  const char *exe;       /*!< POOL, SLURM: vsph itself (absolute path) */
  const char *partition; /*!< SLURM: or NULL */
  const char *time;      /*!< SLURM: time limit per task, or NULL */
  const char *only;      /*!< SLURM: the --only text, for the assembly */
  FILE *plan_out;        /*!< PLAN: where the plan goes */
  /** > 0 (LOCAL, POOL): run only the missing runs that fit this many
   *  seconds of wall time (vsph_jobs::budget_s), then stop without
   *  assembling; the caller's clock raises *stop when it is spent */
  double budget_s;
  /** LOCAL, POOL: if not NULL, the runs that stand in this run archive
   *  (vsph_archive_standing, judged by *judge's history, baseline and
   *  commit; its plan is the report's) are not run */
  const char *skip_archive;
  /** ASSEMBLE: if not NULL, each run the plan needs that is not cached
   *  in DIR and stands in this run archive (judged as skip_archive) is
   *  read from its entry there, and the archive's summary.md gets the
   *  report's claims and convergence tables */
  const char *from_archive;
  const struct vsph_archive_judge *judge;
  /** if not NULL: the run archive (reports/full) whose runs at the
   *  paper's resolutions the summary shows beside the quick figures, each
   *  judged by *judge (which must then be set) */
  const char *beside;
  /** if not NULL: the folder of committed finite-volume references
   *  (reference/data; reports/fvref.h) the square and the cavity are
   *  judged against; NULL: those rows say not tested */
  const char *fv;
};

/** How the report's missing runs are run. Every mode first lists every
 *  run the parts on will read (the plan); a run is one `vsph run` or
 *  `vsph contact` command whose folder ends with key.txt. */
enum vsph_report_mode {
  VSPH_REPORT_LOCAL = 0, /*!< here, a run per thread; then assemble */
  VSPH_REPORT_PLAN,      /*!< print the plan and stop (writes nothing) */
  VSPH_REPORT_POOL,      /*!< child processes, jobs at a time; assemble */
  VSPH_REPORT_SLURM,     /*!< submit them as a Slurm job array, with the
                              assembly as a job after it; stop */
  VSPH_REPORT_ASSEMBLE   /*!< run nothing: fail unless every run is cached */
};

/** @brief Number of parts. */
size_t vsph_report_part_count(void);

/** @brief Name of part @p p ("tensors", ...), or NULL. */
const char *vsph_report_part_name(size_t p);

/** @brief One line on what part @p p holds, or NULL. */
const char *vsph_report_part_what(size_t p);

/** @brief Part called @p name, or -1. */
int vsph_report_part_find(const char *name);

/** @brief Name of the report's scene @p s (0, 1, 2: vortex-patch,
 *  stretching-square, standing-wave), or NULL. */
const char *vsph_report_scene_name(size_t s);

/** @brief Write the report, printing one line per part to stderr.
 *  @return VSPH_OK or the first failure (reported). */
int vsph_report_write(const struct vsph_report_props *rp);

/** @brief The runs the report of fidelity @p full (0 quick, 1 FULL) reads,
 *  as planned for folder @p dir (each run's key, as its key.txt would
 *  hold it), into @p jobs; nothing is written or run. Free with
 *  vsph_jobs_plan_free. @return VSPH_OK or the plan's error. */
int vsph_report_plan_jobs(const char *dir, int full, struct vsph_jobs *jobs);

/** @brief @p jd: @p base (history, baseline, commit) with the plan of
 *  @p jobs (each run's folder name and key; they point into @p jobs,
 *  which must outlive @p jd). Free with vsph_report_plan_judge_free.
 *  @return VSPH_OK or VSPH_ENOMEM (reported). */
int vsph_report_plan_judge(const struct vsph_jobs *jobs,
                           const struct vsph_archive_judge *base,
                           struct vsph_archive_judge *jd);

/** @brief Free what vsph_report_plan_judge allocated. */
void vsph_report_plan_judge_free(struct vsph_archive_judge *jd);

struct vsph_report;
/** @brief The FULL plan and each of its runs' standing in the archive
 *  R->beside, into R (for the table after the claims, which reads them):
 *  the driver's, before the parts are written. Free with
 *  vsph_report_beside_free. @return VSPH_OK or the first failure
 *  (reported). */
int vsph_report_beside_prepare(struct vsph_report *R);

/** @brief Free what vsph_report_beside_prepare made (none: nothing). */
void vsph_report_beside_free(struct vsph_report *R);

#endif /* VSPH_REPORTS_REPORT_H */
