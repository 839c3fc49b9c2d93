/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
/* Section 7 of the report: wall time against the decay error, per scene
 * and formulation, over the resolution ladder. */
#include <math.h>
#include <stdio.h>

#include "../analysis/series.h"
#include "../common/consts.h"
#include "../common/status.h"
#include "../io/csv.h"
#include "../io/plot.h"
#include "../solver/scene.h"
#include "report_parts.h"

#define NFORM VSPH_VISCOUS_PAPER_COUNT /* the free-surface study's three */

static int scene(struct vsph_report *R, int sc) {
  struct vsph_report_ladder lr;
  int st = vsph_report_runs_ladder_figures(&R->runs, sc, &lr);
  if (st) return st;
  const char *scn = vsph_report_runs_ladder(&R->runs, sc, 0)->scene;
  char pname[64], title[160];
  snprintf(pname, sizeof pname, "fig_speed_%s", scn);
  snprintf(title, sizeof title, "%s: wall time against E_k error", scn);
  struct vsph_plot pl;
  vsph_plot_init(&pl, R->dir, pname, title,
                 "max_t |E_k/E_k(0) - E_{k,ref}/E_{k,ref}(0)|",
                 "wall time (s, 2 threads)");
  pl.logx = pl.logy = 1;
  int said = 0; /* the key's entry for hollow markers */
  for (int f = 0; f < NFORM && !st; f++) {
    char file[96];
    snprintf(file, sizeof file, "speed_%s_%s.csv", scn, vsph_viscous_name(f));
    FILE *c = vsph_csv_open(R->dir, file,
                            "error,wall_s,pairs,cpu_s,load_1min,stable");
    if (!c) return VSPH_EIO;
    int any = 0; /* a run stopped as unstable: its error and time are up to
                    its stop, not the whole run's; hollow */
    for (int k = 0; k < VSPH_REPORT_LADDER; k++) {
      fprintf(c, "%.6e,%.4f,%.6e,%.4f,%.2f,%d\n", lr.err[f][k], lr.wall[f][k],
              lr.pairs[f][k], lr.cpu[f][k], lr.load[f][k], lr.ok[f][k]);
      any |= !lr.ok[f][k];
    }
    if ((st = vsph_csv_close(c, R->dir, file))) break;
    char style[96];
    vsph_report_runs_style(style, sizeof style, f, "");
    st = vsph_plot_add(&pl, file, "1:2", vsph_viscous_label(f), style);
    char hover[96];
    snprintf(hover, sizeof hover,
             "%s: run stopped as unstable (up to the stop)",
             vsph_viscous_label(f));
    if (!st && any)
      st = vsph_report_runs_hollow(&pl, file, "1:($6==0 ? $2 : 1/0)", f, hover,
                                   &said);
  }
  if (st) return st;
  vsph_text_set(&R->tv, "title", "%s", title);
  return vsph_report_doc_figure_say(R, &pl, "speed.caption");
}

/* ------------------------------------------------ the time step, measured */

/* The Courant numbers of the study, on the ladder's two coarsest
 * resolutions; the scene's own (scene_cfl) is the ladder's own run. */
#define NCFL VSPH_REPORT_SPEED_NCFL
#define NRES 2
static const double CFLS[NCFL] = {0.5, 1.0, 1.5, 2.0};
static const char *const SET_CFL[NCFL][2] = {{"Solver:cfl=0.5", NULL},
                                             {"Solver:cfl=1", NULL},
                                             {"Solver:cfl=1.5", NULL},
                                             {"Solver:cfl=2", NULL}};
static const char *const TAG_CFL[NCFL] = {"step0.5", "step1", "step1.5",
                                          "step2"};

/* The default Courant number of the scene called @p name (its own, or
 * the solver's 1). */
static double scene_cfl(const char *name) {
  const struct vsph_scene_type *t = vsph_scene_find(name);
  return t && t->cfl > 0.0 ? t->cfl : 1.0;
}

/* The rule: a CFL is fine where every run of it is stable and its error
 * moves from CFL 0.5's by at most this fraction of CFL 0.5's error (the
 * resolution's own error, the time step's share all but gone). */
#define CFL_FRACTION 0.1

static struct vsph_jobs_spec cfl_spec(const struct vsph_report *R, int sc,
                                      int f, int k, int c) {
  const struct vsph_report_ladderdef *L =
      vsph_report_runs_ladder(&R->runs, sc, 0);
  const int own = CFLS[c] == scene_cfl(L->scene); /* the ladder's run */
  return (struct vsph_jobs_spec){
      L->scene, vsph_viscous_name(f),    L->res[k],
      L->t_end, own ? NULL : SET_CFL[c], own ? NULL : TAG_CFL[c]};
}

struct vsph_jobs_spec vsph_report_speed_spec(const struct vsph_report *R,
                                             int sc, int f, int k, int c) {
  return cfl_spec(R, sc, f, k, c);
}

int vsph_report_speed_plan_steps(struct vsph_report *R, int sc) {
  int st = VSPH_OK;
  for (int f = 0; f < NFORM && !st; f++)
    for (int k = 0; k < NRES && !st; k++)
      for (int c = 0; c < NCFL && !st; c++) {
        const struct vsph_jobs_spec rs = cfl_spec(R, sc, f, k, c);
        st = vsph_jobs_plan_run(&R->runs.jobs, &rs);
      }
  return st;
}

int vsph_report_speed_plan(struct vsph_report *R) {
  int st = vsph_report_runs_plan_ladders(&R->runs, 0);
  for (int sc = 0; sc < VSPH_REPORT_NSCENES && !st; sc++)
    if (vsph_report_scene_on(&R->runs, sc))
      st = vsph_report_speed_plan_steps(R, sc);
  return st;
}

int vsph_report_speed_stops(struct vsph_report *R, int sc, int f, int k,
                            int stopped[VSPH_REPORT_SPEED_NCFL],
                            double t_stop[VSPH_REPORT_SPEED_NCFL]) {
  if (k < 0 || k >= NRES)
    VSPH_FAIL(VSPH_EINVAL, "the time step was varied on rungs 1-%d only", NRES);
  for (int c = 0; c < NCFL; c++) {
    const struct vsph_jobs_spec rs = cfl_spec(R, sc, f, k, c);
    struct vsph_jobs_run r;
    const int st = vsph_report_runs_get(&R->runs, &rs, &r);
    if (st) return st;
    stopped[c] = !r.ok;
    t_stop[c] = r.ok ? (double)NAN : r.t_unstable;
    vsph_report_runs_free(&r);
  }
  return VSPH_OK;
}

/* One scene: error against cost at each CFL, a line per formulation and
 * resolution; the table of error changes; the CFL the rule picks. */
static int cfl_scene(struct vsph_report *R, int sc, double *pick) {
  const struct vsph_report_ladderdef *L =
      vsph_report_runs_ladder(&R->runs, sc, 0);
  struct vsph_report_richardson rr;
  int st = sc == 1 ? vsph_report_runs_richardson(&R->runs, &rr) : VSPH_OK;
  double err[NFORM][NRES][NCFL], wall[NFORM][NRES][NCFL];
  int ok[NFORM][NRES][NCFL], same = 1; /* every CFL the same steps */
  size_t steps[NCFL];
  for (int f = 0; f < NFORM && !st; f++)
    for (int k = 0; k < NRES && !st; k++)
      for (int c = 0; c < NCFL && !st; c++) {
        const struct vsph_jobs_spec rs = cfl_spec(R, sc, f, k, c);
        struct vsph_jobs_run r;
        if ((st = vsph_report_runs_get(&R->runs, &rs, &r))) break;
        err[f][k][c] = vsph_report_runs_error(&r, sc == 1 ? &rr : NULL);
        wall[f][k][c] = r.wall_s;
        ok[f][k][c] = r.ok;
        steps[c] = r.steps;
        same &= steps[c] == steps[0];
        vsph_report_runs_free(&r);
      }
  if (st) return st;
  /* the largest CFL fine for accuracy (vsph_series_cfl_pick); the runs
   * stable at CFL 0.5 but not at a larger CFL are said apart */
  const int best = vsph_series_cfl_pick(&err[0][0][0], &ok[0][0][0],
                                        NFORM * NRES, NCFL, CFL_FRACTION);
  *pick = CFLS[best];
  char unstable[512] = "";
  size_t ul = 0;
  for (int f = 0; f < NFORM; f++)
    for (int k = 0; k < NRES; k++)
      for (int c = 1; c < NCFL && ul < sizeof unstable - 64; c++)
        if (ok[f][k][0] && !ok[f][k][c]) {
          ul +=
              (size_t)snprintf(unstable + ul, sizeof unstable - ul,
                               "%s%s at %zu across from CFL %g", ul ? "; " : "",
                               vsph_viscous_label(f), L->res[k], CFLS[c]);
          break;
        }
  char pname[64], title[160];
  snprintf(pname, sizeof pname, "fig_cfl_%s", L->scene);
  snprintf(title, sizeof title,
           "%s: E_k error against wall time at CFL 0.5, 1, 1.5, 2", L->scene);
  struct vsph_plot pl;
  vsph_plot_init(&pl, R->dir, pname, title, "wall time of the run (s)",
                 "max_t |E_k/E_k(0) - E_{k,ref}/E_{k,ref}(0)|");
  pl.logx = pl.logy = 1;
  vsph_text_set(&R->tv, "scene", "%s", L->scene);
  if ((st = vsph_report_doc_say(R, "speed.cfl_head"))) return st;
  for (int f = 0; f < NFORM && !st; f++)
    for (int k = 0; k < NRES && !st; k++) {
      char file[128], label[96], style[128];
      snprintf(file, sizeof file, "cfl_%s_%s_%zu.csv", L->scene,
               vsph_viscous_name(f), L->res[k]);
      FILE *c = vsph_csv_open(R->dir, file, "cfl,wall_s,error,stable");
      if (!c) return VSPH_EIO;
      fprintf(R->md, "| %s | %zu | %.3e%s |", vsph_viscous_name(f), L->res[k],
              err[f][k][0], ok[f][k][0] ? "" : " (unstable)");
      for (int q = 0; q < NCFL; q++) {
        fprintf(c, "%g,%.4f,%.6e,%d\n", CFLS[q], wall[f][k][q], err[f][k][q],
                ok[f][k][q]);
        if (q == 0) continue;
        fprintf(R->md, " %+.1f %%%s |",
                vsph_consts_shown(
                    100.0 * (err[f][k][q] - err[f][k][0]) / err[f][k][0], 0.05),
                ok[f][k][q] ? "" : " (unstable)");
      }
      fprintf(R->md, "\n");
      if ((st = vsph_csv_close(c, R->dir, file))) break;
      snprintf(label, sizeof label, "%s, %zu across", vsph_viscous_label(f),
               L->res[k]);
      vsph_report_runs_style(style, sizeof style, f, k ? "" : " dt 2");
      st = vsph_plot_add(&pl, file, "2:3", label, style);
    }
  if (st) return st;
  fprintf(R->md, "\n");
  vsph_text_set(&R->tv, "title", "%s", title);
  vsph_text_set(&R->tv, "pick", "%g", *pick);
  vsph_text_set(&R->tv, "scene", "%s", L->scene);
  /* the scene's own default against the pick */
  const double own = scene_cfl(L->scene);
  vsph_text_set(&R->tv, "own", "Its default is CFL %g%s", own,
                same           ? "."
                : own <= *pick ? ", which the rule finds fine."
                               : ", **larger than the rule allows**.");
  vsph_text_set(&R->tv, "unstable", "%s",
                ul ? unstable : "none (every run stable at CFL 0.5 stays so)");
  /* a scene whose step another bound sets (the viscous one) */
  vsph_text_set(&R->tv, "same_steps", "%s",
                same ? " But every run here takes the same number of steps "
                       "at every CFL: its time step is set by another bound "
                       "(docs/theory.md section 5), not by the CFL, so the "
                       "pick says nothing for this scene."
                     : "");
  if ((st = vsph_report_doc_say(R, "speed.cfl_pick"))) return st;
  vsph_text_set(&R->tv, "title", "%s", title);
  vsph_text_set(&R->tv, "scene", "%s", L->scene);
  return vsph_report_doc_figure_say(R, &pl, "speed.cfl_caption");
}

int vsph_report_speed_write(struct vsph_report *R) {
  int st = vsph_report_doc_say(R, "speed.intro");
  for (int sc = 0; sc < VSPH_REPORT_NSCENES && !st; sc++)
    if (vsph_report_scene_on(&R->runs, sc)) st = scene(R, sc);
  vsph_text_set(&R->tv, "fraction", "%g", 100.0 * CFL_FRACTION);
  if (!st) st = vsph_report_doc_say(R, "speed.cfl_intro");
  double all = CFLS[NCFL - 1];
  for (int sc = 0; sc < VSPH_REPORT_NSCENES && !st; sc++)
    if (vsph_report_scene_on(&R->runs, sc)) {
      double pick;
      st = cfl_scene(R, sc, &pick);
      all = fmin(all, pick);
    }
  vsph_text_set(&R->tv, "pick", "%g", all);
  vsph_text_set(&R->tv, "cfl_where", "%s",
                R->runs.full
                    ? "These are the FULL report's ladders' two coarsest "
                      "rungs (the papers' resolutions); the finest rungs are "
                      "not swept"
                    : "These are the quick resolutions, where the time "
                      "step's share of the error is small beside the "
                      "resolution's; the FULL report's study, on the FULL "
                      "ladders' two coarsest rungs, is quoted in "
                      "docs/theory.md section 5");
  if (!st) st = vsph_report_doc_say(R, "speed.cfl_all");
  return st;
}
