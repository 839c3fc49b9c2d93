/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
#ifndef VSPH_REPORTS_REPORT_RUNS_H
#define VSPH_REPORTS_REPORT_RUNS_H

/* The runs the report reads (report_runs.c): the scenes' ladders, the
 * stretching square's reference, the vortex patch's disc layouts, the
 * baseline's figures, and the line styles every figure shares. Within
 * reports/ and the tests only. */

#include <signal.h>
#include <stddef.h>

#include "../analysis/series.h"
#include "../io/plot.h"
#include "../runs/jobs.h"
#include "../solver/viscous.h"

/** The report's scenes: the three of the paper, in its order. */
#define VSPH_REPORT_NSCENES 3

/** Runs of one resolution ladder per scene. */
#define VSPH_REPORT_LADDER 3

/** A scene's ladder: resolutions and end time. */
struct vsph_report_ladderdef {
  const char *scene;              /* scene name */
  size_t res[VSPH_REPORT_LADDER]; /* particles across, coarse first */
  double t_end;                   /* end time (s) */
};

/* Figures of one scene's ladder, per formulation and resolution, computed
 * once per report invocation (convergence, speed and claims read them). */
struct vsph_report_ladder {
  double dx[VSPH_VISCOUS_FORM_COUNT][VSPH_REPORT_LADDER];
  double err[VSPH_VISCOUS_FORM_COUNT][VSPH_REPORT_LADDER];
  double wall[VSPH_VISCOUS_FORM_COUNT][VSPH_REPORT_LADDER];
  double pairs[VSPH_VISCOUS_FORM_COUNT][VSPH_REPORT_LADDER];
  double cpu[VSPH_VISCOUS_FORM_COUNT][VSPH_REPORT_LADDER];
  double load[VSPH_VISCOUS_FORM_COUNT][VSPH_REPORT_LADDER];
  int ok[VSPH_VISCOUS_FORM_COUNT][VSPH_REPORT_LADDER];
  double t_unstable[VSPH_VISCOUS_FORM_COUNT][VSPH_REPORT_LADDER];
  /* energy lost by the last row over the reference's loss (1 exact; NaN
   * without a reference for t > 0: the square) */
  double loss[VSPH_VISCOUS_FORM_COUNT][VSPH_REPORT_LADDER];
  /* the ladder's self-convergence: successive rungs against each other */
  struct vsph_series_selfconv self[VSPH_VISCOUS_FORM_COUNT];
};

/* The stretching square's reference for t > 0, free of MGF's lattice
 * bias at h/dx = 4/3 (-6 %, section 4), extrapolated in both h and h/dx:
 * MGF at h/dx = 2 and 3, each extrapolated in h by first-order Richardson
 * 2 E(L/dx) - E(L/dx / 2) over two resolutions (which removes the surface
 * deficit, first order in h/L), then to h/dx -> infinity with the error
 * taken proportional to the measured lattice error eps(h/dx) of section 4
 * (-1.2 % and -0.2 %); on 101 equally spaced times, with its rate dE/dt
 * by differences. */
struct vsph_report_richardson {
  double t[101], E[101], dE[101];
  size_t res[4];     /* L/dx: h/dx = 2 (two), then h/dx = 3 (two) */
  double eps[2];     /* lattice errors at h/dx = 2 and 3 */
  double correction; /* largest h/dx step, max |E - E(h/dx = 3)| / E(0) */
  double diss0;      /* its initial dissipation error, extrapolated alike */
};

/* The vortex patch's ladder on both disc layouts (0 rings, 1 Cartesian):
 * per formulation and resolution the decay error, the initial dissipation
 * error, the stability verdict and stop time (convergence and claims). */
struct vsph_report_layouts {
  double dx[VSPH_REPORT_LADDER]; /* 1 / (R/dx) */
  double err[2][VSPH_VISCOUS_FORM_COUNT][VSPH_REPORT_LADDER];
  double d0[2][VSPH_VISCOUS_FORM_COUNT][VSPH_REPORT_LADDER];
  double tu[2][VSPH_VISCOUS_FORM_COUNT][VSPH_REPORT_LADDER];
  int ok[2][VSPH_VISCOUS_FORM_COUNT][VSPH_REPORT_LADDER];
  double loss[2][VSPH_VISCOUS_FORM_COUNT][VSPH_REPORT_LADDER]; /* as above */
  struct vsph_series_selfconv self[2][VSPH_VISCOUS_FORM_COUNT];
};

/* What reads runs: the report's fidelity and scenes, its runs (planned,
 * or made as read in the tests), what made them, and the figures of the
 * ladders computed once per report invocation. The parts reach it as
 * R->runs (report_doc.h); nothing here writes the report. */
struct vsph_report_runs {
  int full;        /* 1: the paper's resolutions and end times */
  unsigned scenes; /* scene-wise parts: bit s on (0: all) */
  const volatile sig_atomic_t *stop; /* stop request, or NULL */
  struct vsph_jobs jobs; /* the runs: planned, or made as read (tests) */
  size_t made;           /* runs the plan missed at the start */
  double runs_wall;      /* their wall time (s) */
  const char *made_by;   /* who made them (run.json) */
  size_t from_archive;   /* runs read from a run archive's entries */
  size_t unjudged;       /* runs missing here that it holds unjudged */
  const char *archive;   /* that archive, or NULL */
  struct vsph_report_ladder ladder[VSPH_REPORT_NSCENES]; /* memo */
  int have_ladder[VSPH_REPORT_NSCENES];
  struct vsph_report_richardson rr; /* memo: the square's reference */
  int have_rr;
  struct vsph_report_layouts layouts; /* memo: the vortex disc layouts */
  int have_layouts;
};

/* 1 if the scene-wise parts include scene @p sc. */
static inline int vsph_report_scene_on(const struct vsph_report_runs *R,
                                       int sc) {
  return !R->scenes || (R->scenes >> sc & 1u);
}

/* Basa et al.'s kernel settings (cubic spline, dx/h = 0.637), as a
 * runspec's extra settings: the channel part and the channel baseline. */
#define VSPH_REPORT_BASA "Solver:kernel=cubic", "Solver:hdx=1.5699"
/* Adami et al.'s kernel for the cavity: the quintic spline with h = dx */
#define VSPH_REPORT_ADAMI "Solver:kernel=quintic", "Solver:hdx=1"

/* The FULL ladder of scene @p sc (the paper's resolutions), whatever the
 * report's fidelity. */
const struct vsph_report_ladderdef *vsph_report_runs_full_ladder(int sc);

/* The ladder of scene @p sc (0..VSPH_REPORT_NSCENES-1) at the report's
 * fidelity, or the quick one when @p quick. */
const struct vsph_report_ladderdef *vsph_report_runs_ladder(
    const struct vsph_report_runs *R, int sc, int quick);

/* A run through runs/jobs (vsph_jobs_store_get). */
int vsph_report_runs_get(struct vsph_report_runs *R,
                         const struct vsph_jobs_spec *rs,
                         struct vsph_jobs_run *out);

/* The extra settings of the vortex patch's Cartesian-disc ladder (its
 * runs carry the tag "cartesian"). */
extern const char *const vsph_report_runs_cartesian[2];

/* The layouts' figures (memoised in R; the runs through the cache). */
int vsph_report_runs_layouts(struct vsph_report_runs *R,
                             struct vsph_report_layouts *out);

/* Plan scene @p sc's ladder (the runs the scene-wise parts read): with
 * the stretching square's reference runs (sc = 1) or the vortex patch's
 * Cartesian ladder (sc = 0). */
int vsph_report_runs_plan_scene(struct vsph_report_runs *R, int sc);

/* The same for the scenes on (vsph_report_scene_on), or all when @p all. */
int vsph_report_runs_plan_ladders(struct vsph_report_runs *R, int all);

/* Plan the runs of baseline.csv. */
int vsph_report_runs_plan_baseline(struct vsph_report_runs *R);

/* Free a run's loaded data. */
void vsph_report_runs_free(struct vsph_jobs_run *r);

/* The square's reference (memoised in R; its runs through the cache). */
int vsph_report_runs_richardson(struct vsph_report_runs *R,
                                struct vsph_report_richardson *rr);

/* The four runs behind it (tags "hdx2", "hdx3"). */
extern const char *const vsph_report_runs_hdx[2][2];
void vsph_report_runs_reference_specs(const struct vsph_report_runs *R,
                                      struct vsph_jobs_spec rs[4]);

/* The threshold of the onset (the reference's own uncertainty, its
 * lattice error and the Richardson remainder, is below 1 %). */
#define VSPH_REPORT_ONSET 0.1

/* PVWF's onset of instability, the paper's way (the time its dissipation
 * departs from the reference, not the time it is stopped): the first of
 * the reference's times at which |dE_k/dt - dE_ref/dt| exceeds
 * @p threshold |dE_ref/dt| (or the run has stopped); NaN if never. */
double vsph_report_runs_onset(const struct vsph_jobs_run *r,
                              const struct vsph_report_richardson *rr,
                              double threshold);

/* Reference E_k at row @p row: the run's own, or the Richardson curve. */
double vsph_report_runs_eref(const struct vsph_jobs_run *r, size_t row,
                             const struct vsph_report_richardson *rr);

/* Decay error max_t |E_k/E_k(0) - E_ref/E_ref(0)|. */
double vsph_report_runs_error(const struct vsph_jobs_run *r,
                              const struct vsph_report_richardson *rr);

/* The energy budget at row @p row (the paper's measure of damping, free of
 * the kinetic/potential exchange's phase): the mechanical energy the run
 * has lost, (E_k + E_p + E_c)(0) - (E_k + E_p + E_c)(t), over E_k(0),
 * against the reference's lost share 1 - E_m(t)/E_m(0) (standing wave:
 * Lighthill's envelope). Above 1: too much damping. NaN at t = 0 or
 * without a reference. */
double vsph_report_runs_loss_ratio(const struct vsph_jobs_run *r, size_t row);

/* The same with only the viscous part of the loss, -int_0^t P_visc dt
 * (trapezoidal rule over the rows), so the two split the loss into the
 * viscous formulation's share and the rest (acoustic exchange, walls). */
double vsph_report_runs_visc_loss_ratio(const struct vsph_jobs_run *r,
                                        size_t row);

/* Initial dissipation error (P_visc(0) - dEk_ref(0)) / |dEk_ref(0)|. */
double vsph_report_runs_diss0(const struct vsph_jobs_run *r);

/* gnuplot's point type for formulation f: the same in every figure. */
int vsph_report_runs_point(int f);

/* gnuplot's colour for formulation (or series) f, "lc K": linetype K of
 * the shared palette (io/plot.h), the same in every figure (MGF blue,
 * MEAF red, PVWF green), distinct for VSPH_PLOT_NSTYLES series. */
const char *vsph_report_runs_colour(int f);

/* The line style of formulation f in every figure: "linespoints pt P lw 2
 * COLOUR" with @p more appended (e.g. " dt 2"; "" for none). */
void vsph_report_runs_style(char *buf, size_t len, int f, const char *more);

/* Formulation @p f's runs stopped as unstable drawn hollow in figure
 * @p pl: over each such point of its curve (@p using picks them: the
 * others 1/0) a white disc, then the open marker of its filled one in its
 * colour (gnuplot's pt 7 -> 6, 5 -> 4, ...; a form whose marker is open
 * already gets a black ring round it instead). Out of the key, titled
 * @p hover in the SVG (vsph_plot_add_unkeyed: the curve's name and what
 * stopped); the first call of a figure (*@p said 0) adds one key entry
 * saying what hollow means. */
int vsph_report_runs_hollow(struct vsph_plot *pl, const char *file,
                            const char *using, int f, const char *hover,
                            int *said);

/* A fitted order (vsph_series_slope_where) as the tables print it: bold,
 * through how many stable rungs (@p ns), or a dash where fewer than two
 * were stable: never through a stopped run's point. */
void vsph_report_runs_fitted(char *buf, size_t len, double order, size_t ns);

/* Formulation @p f's successive differences of file @p file (x in column
 * 1, the difference in column @p y, rung k against rung k - 1 on row k,
 * none on the first row) drawn hollow where either run of the pair
 * stopped: its row's or the row before's stable (column @p stable, 0 or
 * 1) is 0. As vsph_report_runs_hollow, which draws them. */
int vsph_report_runs_hollow_pairs(struct vsph_plot *pl, const char *file,
                                  int stable, int y, int f, const char *hover,
                                  int *said);

/* The self-convergence of a ladder's runs (coarse first, E_k, spacings
 * @p dx): vsph_series_selfconv on their energy series. */
int vsph_report_runs_selfconv(const struct vsph_jobs_run run[],
                              const double dx[],
                              struct vsph_series_selfconv *out);

/* The figures of scene @p sc's ladder (memoised in R). */
int vsph_report_runs_ladder_figures(struct vsph_report_runs *R, int sc,
                                    struct vsph_report_ladder *out);

/* Baseline figures of the quick ladder's coarsest runs (tests reuse it):
 * for each scene and formulation, the final decay error E_k/E_k(0) -
 * E_ref/E_ref(0) (vortex, wave) or the final E_k/E_k(0) (square, no
 * reference for t > 0), the initial dissipation error and the stability
 * verdict. */
struct vsph_report_baseline {
  char scene[32], visc[16];
  size_t res;
  double t_end;
  double ek_final; /* see above; channels: (E_k - E_k,ref)/E_k,ref at t_end */
  double diss0;    /* (P_visc(0) - dEk_ref(0)) / |dEk_ref(0)|; channels: the
                      RMS velocity error (u - U)/U0 at t_end (u_err) */
  int ok;          /* stability verdict */
};
size_t vsph_report_runs_baseline_count(void);
int vsph_report_runs_baseline(struct vsph_report_runs *R, size_t i,
                              struct vsph_report_baseline *b);

#endif /* VSPH_REPORTS_REPORT_RUNS_H */
