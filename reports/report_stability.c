/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
/* Section 8 of the report: stability on hard cases: PVWF's pairing on the
 * stretching square, high Reynolds number, a perturbed start, low sound
 * speed and large time steps. A run stopped as unstable is a result. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../common/status.h"
#include "../io/csv.h"
#include "../io/files.h"
#include "../io/plot.h"
#include "../solver/scene.h"
#include "report_parts.h"

#define NFORM VSPH_VISCOUS_PAPER_COUNT /* the free-surface study's three */

/* One cell of a stability table: "stable" or "unstable t = x (kind)". */
static void verdict(char *buf, size_t n, const struct vsph_jobs_run *r) {
  if (r->ok) {
    snprintf(buf, n, "stable");
    return;
  }
  char why[48];
  snprintf(why, sizeof why, "%.47s", r->reason);
  char *colon = strchr(why, ':'); /* keep the kind of failure */
  if (colon) *colon = '\0';
  const char *p = strstr(why, " of particle");
  if (p) why[p - why] = '\0';
  snprintf(buf, n, "**unstable** t = %.3g (%s)", r->t_unstable, why);
}

/* A sweep: one scene at one resolution and end time, a setting `key` over
 * `vals`, each formulation; a table row per value and, if map != NULL, the
 * stable/unstable map data. */
struct sweep {
  const char *scene;
  size_t res;
  double t_end;
  const char *label, *key; /* table label, "Section:key" */
  const double *vals;
  size_t nv;
  const char *tag; /* run folder suffix */
  const char *map; /* map CSV, or NULL */
};

#define MAXV 8 /* most values of a sweep */

/* A sweep's verdicts, for its map: ok[v][f], 1 if stable. */
struct verdicts {
  size_t nv;
  double vals[MAXV];
  int ok[MAXV][NFORM];
};

/* The run of sweep @p sw at value @p v and formulation @p f: its setting
 * and tag in @p set and @p tag. */
static struct vsph_jobs_spec sweep_spec(const struct sweep *sw, size_t v, int f,
                                        char set[128], char tag[48],
                                        const char *extra[2]) {
  snprintf(set, 128, "%s=%.10g", sw->key, sw->vals[v]);
  snprintf(tag, 48, "%s%zu", sw->tag, v);
  extra[0] = set;
  extra[1] = NULL;
  return (struct vsph_jobs_spec){
      sw->scene, vsph_viscous_name(f), sw->res, sw->t_end, extra, tag};
}

static int sweep(struct vsph_report *R, const struct sweep *sw,
                 struct verdicts *vd) {
  if (sw->nv > MAXV)
    VSPH_FAIL(VSPH_EINVAL, "sweep of %s: more than %d values", sw->key, MAXV);
  if (vd) {
    vd->nv = sw->nv;
    for (size_t v = 0; v < sw->nv; v++) vd->vals[v] = sw->vals[v];
  }
  FILE *m = NULL;
  if (sw->map &&
      !(m = vsph_csv_open(R->dir, sw->map, "value,form,stable,t_unstable")))
    return VSPH_EIO;
  int st = VSPH_OK;
  for (size_t v = 0; v < sw->nv && !st; v++) {
    fprintf(R->md, "| %s | %s = %.4g |", sw->scene, sw->label, sw->vals[v]);
    for (int f = 0; f < NFORM && !st; f++) {
      char set[128], tag[48];
      const char *extra[2];
      const struct vsph_jobs_spec rs = sweep_spec(sw, v, f, set, tag, extra);
      struct vsph_jobs_run r;
      if ((st = vsph_report_runs_get(&R->runs, &rs, &r))) break;
      char cell[160];
      verdict(cell, sizeof cell, &r);
      fprintf(R->md, " %s |", cell);
      if (vd) vd->ok[v][f] = r.ok;
      if (m)
        fprintf(m, "%.6g,%d,%d,%.6g\n", sw->vals[v], f + 1, r.ok,
                r.ok ? (double)NAN : r.t_unstable);
      vsph_report_runs_free(&r);
    }
    fprintf(R->md, "\n");
  }
  if (m) {
    if (st)
      vsph_files_discard(m, R->dir, sw->map);
    else
      st = vsph_csv_close(m, R->dir, sw->map);
  }
  return st;
}

/* The map's own two colours, apart from every formulation's (blue, red,
 * green): light grey for stable, near-black for unstable; the boundary is
 * an orange bar (no formulation is orange among the three rows). */
#define STABLE_RGB "#c8c8c8"
#define UNSTABLE_RGB "#262626"
#define BOUNDARY_RGB "#ff7f0e"

static int stability_map(struct vsph_report *R, const char *map,
                         const struct verdicts *vd, const char *name,
                         const char *title, const char *xlabel) {
  struct vsph_plot pl;
  vsph_plot_init(&pl, R->dir, name, title, xlabel, "formulation");
  /* one row per formulation, labelled from the formulation table */
  size_t len = (size_t)snprintf(pl.extra, sizeof pl.extra, "set ytics (");
  for (int f = 0; f < NFORM && len < sizeof pl.extra; f++)
    len += (size_t)snprintf(pl.extra + len, sizeof pl.extra - len, "%s'%s' %d",
                            f ? ", " : "", vsph_viscous_label(f), f + 1);
  if (len < sizeof pl.extra)
    len += (size_t)snprintf(pl.extra + len, sizeof pl.extra - len,
                            ")\nset yrange [0.4:%g]\nset offsets graph 0.08, "
                            "graph 0.08, 0, 0\nset grid noytics\n",
                            NFORM + 0.6);
  /* the boundary of each row: a bar between neighbouring values (in
   * sorted order) of which one is stable and the other not; a row
   * without one says so at its right end */
  size_t idx[MAXV];
  for (size_t v = 0; v < vd->nv; v++) idx[v] = v;
  for (size_t a = 1; a < vd->nv; a++) /* insertion sort by value */
    for (size_t b = a; b > 0 && vd->vals[idx[b]] < vd->vals[idx[b - 1]]; b--) {
      const size_t t = idx[b];
      idx[b] = idx[b - 1], idx[b - 1] = t;
    }
  int bars = 0;
  for (int f = 0; f < NFORM && len < sizeof pl.extra; f++) {
    int found = 0, all = 1;
    for (size_t k = 0; k + 1 < vd->nv; k++) {
      const size_t a = idx[k], b = idx[k + 1];
      if (vd->ok[a][f] == vd->ok[b][f]) continue;
      const double x = 0.5 * (vd->vals[a] + vd->vals[b]);
      len += (size_t)snprintf(pl.extra + len, sizeof pl.extra - len,
                              "set arrow from %.6g,%g to %.6g,%g nohead "
                              "lw 4 lc rgb '" BOUNDARY_RGB "' front\n",
                              x, f + 0.6, x, f + 1.4);
      found = bars = 1;
    }
    for (size_t v = 0; v < vd->nv; v++) all &= vd->ok[v][f] == vd->ok[0][f];
    if (!found && all && vd->nv && len < sizeof pl.extra)
      len += (size_t)snprintf(
          pl.extra + len, sizeof pl.extra - len,
          "set label '%s at every value: boundary beyond the sweep' at "
          "graph 0.5, first %g center front font ',9'\n",
          vd->ok[0][f] ? "stable" : "unstable", f + 1.33);
  }
  if (len >= sizeof pl.extra)
    VSPH_FAIL(VSPH_EINVAL, "map %s: its gnuplot commands are too long", name);
  int st = vsph_plot_add(&pl, map, "1:($3==1 ? $2 : 1/0)", "stable",
                         "points pt 5 ps 3 lc rgb '" STABLE_RGB "'");
  if (!st)
    st = vsph_plot_add(&pl, map, "1:($3==0 ? $2 : 1/0)", "unstable (stopped)",
                       "points pt 5 ps 3 lc rgb '" UNSTABLE_RGB "'");
  if (!st && bars)
    st = vsph_plot_add(&pl, map, "1:(1/0)",
                       "stability boundary (between the values either side)",
                       "lines lw 4 lc rgb '" BOUNDARY_RGB "'");
  if (st) return st;
  fprintf(R->md, "\n");
  return vsph_report_doc_figure_say(R, &pl, "stability.map_caption");
}

/* PVWF's pairing: the stretching square across its ladder. */
static int square_ladder(struct vsph_report *R) {
  const struct vsph_report_ladderdef *L =
      vsph_report_runs_ladder(&R->runs, 1, 0);
  struct vsph_report_richardson rr;
  int st = vsph_report_runs_richardson(&R->runs, &rr);
  for (int k = 0; k < VSPH_REPORT_LADDER && !st; k++) {
    fprintf(R->md, "| %s | L/dx = %zu |", L->scene, L->res[k]);
    for (int f = 0; f < NFORM && !st; f++) {
      struct vsph_jobs_spec rs = {
          L->scene, vsph_viscous_name(f), L->res[k], L->t_end, NULL, NULL};
      struct vsph_jobs_run r;
      if ((st = vsph_report_runs_get(&R->runs, &rs, &r))) break;
      char cell[160];
      verdict(cell, sizeof cell, &r);
      const double on = vsph_report_runs_onset(&r, &rr, VSPH_REPORT_ONSET);
      if (isfinite(on))
        fprintf(R->md, " %s; departs from the reference at t A0 = %.2f |", cell,
                on);
      else
        fprintf(R->md, " %s; within %g %% of the reference throughout |", cell,
                100 * VSPH_REPORT_ONSET);
      vsph_report_runs_free(&r);
    }
    fprintf(R->md, "\n");
  }
  return st;
}

/* The sweeps: nu, a perturbed lattice per scene, c0 = k U_max with the
 * vortex patch's U_max (values in @p c0s), CFL (two scenes). */
#define NSWEEP 7
static int sweeps(const struct vsph_report *R, struct sweep sws[NSWEEP],
                  double c0s[4], struct vsph_scene *scene) {
  const size_t res = R->runs.full ? 40 : 20;
  const char *vortex = vsph_report_runs_ladder(&R->runs, 0, 0)->scene;
  const char *wave = vsph_report_runs_ladder(&R->runs, 2, 0)->scene;
  const double tv = vsph_report_runs_ladder(&R->runs, 0, 0)->t_end;
  const double tw = vsph_report_runs_ladder(&R->runs, 2, 0)->t_end;
  const int st = vsph_scene_init(scene, &vsph_vortex_patch_type, NULL);
  if (st) return st;
  static const double ks[4] = {10, 6, 4, 3};
  for (int k = 0; k < 4; k++) c0s[k] = ks[k] * scene->U_max;
  static const double nus[3] = {1e-3, 1e-4, 1e-5}, pert[1] = {0.2};
  static const double cfl[6] = {1.0, 1.5, 2.0, 2.5, 3.0, 3.5};
  sws[0] = (struct sweep){vortex, res, tv,   "nu (m^2/s)", "Scene:nu",
                          nus,    3,   "nu", NULL};
  for (int sc = 0; sc < VSPH_REPORT_NSCENES; sc++) {
    const struct vsph_report_ladderdef *L =
        vsph_report_runs_ladder(&R->runs, sc, 0);
    sws[1 + sc] = (struct sweep){L->scene,
                                 res,
                                 L->t_end,
                                 "initial shift / dx",
                                 "Solver:perturb",
                                 pert,
                                 1,
                                 "perturb",
                                 NULL};
  }
  sws[4] = (struct sweep){vortex, res, tv,   "c0 (m/s)",        "Scene:c0",
                          c0s,    4,   "c0", "stability_c0.csv"};
  sws[5] = (struct sweep){vortex, res,          tv / 2,
                          "CFL",  "Solver:cfl", cfl,
                          6,      "cfl",        "stability_cfl_vortex.csv"};
  sws[6] = (struct sweep){wave,  res,          tw / 3,
                          "CFL", "Solver:cfl", cfl,
                          6,     "cfl",        "stability_cfl_wave.csv"};
  return VSPH_OK;
}

int vsph_report_stability_plan(struct vsph_report *R) {
  struct sweep sws[NSWEEP];
  double c0s[4];
  struct vsph_scene scene;
  int st = sweeps(R, sws, c0s, &scene);
  for (size_t k = 0; k < NSWEEP && !st; k++)
    for (size_t v = 0; v < sws[k].nv && !st; v++)
      for (int f = 0; f < NFORM && !st; f++) {
        char set[128], tag[48];
        const char *extra[2];
        const struct vsph_jobs_spec rs =
            sweep_spec(&sws[k], v, f, set, tag, extra);
        st = vsph_jobs_plan_run(&R->runs.jobs, &rs);
      }
  /* PVWF's pairing: the stretching square's ladder and reference */
  if (!st) st = vsph_report_runs_plan_scene(&R->runs, 1);
  return st;
}

int vsph_report_stability_write(struct vsph_report *R) {
  const size_t res = R->runs.full ? 40 : 20;
  struct sweep sws[NSWEEP];
  double c0s[4];
  struct vsph_scene scene;
  int st = sweeps(R, sws, c0s, &scene);
  if (st) return st;
  vsph_text_set(&R->tv, "res", "%zu", res);
  vsph_text_set(&R->tv, "onset", "%g", 100 * VSPH_REPORT_ONSET);
  st = vsph_report_doc_say(R, "stability.intro");
  if (!st) st = square_ladder(R);
  if (!st) st = vsph_report_doc_say(R, "stability.hard");
  struct verdicts vc0, vcfl, vwave;
  for (int k = 0; k < 4 && !st; k++)
    st = sweep(R, &sws[k], NULL);        /* nu, shift */
  if (!st) st = sweep(R, &sws[4], &vc0); /* c0 */
  if (!st) {
    vsph_text_set(&R->tv, "U_max", "%.4f", scene.U_max);
    vsph_text_set(&R->tv, "c0", "%.4f", scene.c0);
    st = vsph_report_doc_say(R, "stability.c0_note");
  }
  if (!st)
    st = stability_map(R, "stability_c0.csv", &vc0, "fig_stability_c0",
                       "Vortex patch: stability against the sound speed",
                       "sound speed c_0 (m/s)");
  if (!st) st = vsph_report_doc_say(R, "stability.cfl");
  if (!st) st = sweep(R, &sws[5], &vcfl);
  if (!st) st = sweep(R, &sws[6], &vwave);
  if (!st)
    st =
        stability_map(R, "stability_cfl_vortex.csv", &vcfl, "fig_stability_cfl",
                      "Vortex patch: stability against the CFL number",
                      "Courant number CFL (RK4)");
  if (!st)
    st = stability_map(R, "stability_cfl_wave.csv", &vwave,
                       "fig_stability_cfl_wave",
                       "Standing wave: stability against the CFL number",
                       "Courant number CFL (RK4)");
  return st;
}
