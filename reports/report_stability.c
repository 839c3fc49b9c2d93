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
#include "report_internal.h"

#define NFORM VSPH_VISCOUS_PAPER_COUNT /* the free-surface study's three */

/* One cell of a stability table: "stable" or "unstable t = x (kind)". */
static void verdict(char *buf, size_t n, const struct vsph_report_run *r) {
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

static int sweep(struct vsph_report *R, const struct sweep *sw) {
  FILE *m = NULL;
  if (sw->map &&
      !(m = vsph_csv_open(R->dir, sw->map, "value,form,stable,t_unstable")))
    return VSPH_EIO;
  int st = VSPH_OK;
  for (size_t v = 0; v < sw->nv && !st; v++) {
    char set[128], tag[48];
    snprintf(set, sizeof set, "%s=%.10g", sw->key, sw->vals[v]);
    snprintf(tag, sizeof tag, "%s%zu", sw->tag, v);
    const char *extra[2] = {set, NULL};
    fprintf(R->md, "| %s | %s = %.4g |", sw->scene, sw->label, sw->vals[v]);
    for (int f = 0; f < NFORM && !st; f++) {
      struct vsph_report_runspec rs = {
          sw->scene, vsph_viscous_name(f), sw->res, sw->t_end, extra, tag};
      struct vsph_report_run r;
      if ((st = vsph_report_runs_get(R, &rs, &r))) break;
      char cell[160];
      verdict(cell, sizeof cell, &r);
      fprintf(R->md, " %s |", cell);
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

static int stability_map(struct vsph_report *R, const char *map,
                         const char *name, const char *title,
                         const char *xlabel) {
  struct vsph_plot pl;
  vsph_plot_init(&pl, R->dir, name, title, xlabel, "formulation");
  /* one row per formulation, labelled from the formulation table */
  size_t len = (size_t)snprintf(pl.extra, sizeof pl.extra, "set ytics (");
  for (int f = 0; f < NFORM && len < sizeof pl.extra; f++)
    len += (size_t)snprintf(pl.extra + len, sizeof pl.extra - len, "%s'%s' %d",
                            f ? ", " : "", vsph_viscous_label(f), f + 1);
  if (len < sizeof pl.extra)
    snprintf(pl.extra + len, sizeof pl.extra - len,
             ")\nset yrange [0.5:%g]\nset offsets graph 0.05, graph 0.05, "
             "0, 0\n",
             NFORM + 0.5);
  int st = vsph_plot_add(&pl, map, "1:($3==1 ? $2 : 1/0)", "stable",
                         "points pt 7 ps 2.5 lc rgb '#2a9d2a'");
  if (!st)
    st = vsph_plot_add(&pl, map, "1:($3==0 ? $2 : 1/0)", "unstable",
                       "points pt 2 ps 2.5 lw 3 lc rgb '#d62728'");
  if (st) return st;
  fprintf(R->md, "\n");
  vsph_text_set(&R->tv, "title", "%s", title);
  return vsph_report_figure_say(R, &pl, "stability.map_caption");
}

/* PVWF's pairing: the stretching square across its ladder. */
static int square_ladder(struct vsph_report *R) {
  const struct vsph_report_ladderdef *L = vsph_report_runs_ladder(R, 1, 0);
  struct vsph_report_richardson rr;
  int st = vsph_report_runs_richardson(R, &rr);
  for (int k = 0; k < VSPH_REPORT_LADDER && !st; k++) {
    fprintf(R->md, "| %s | L/dx = %zu |", L->scene, L->res[k]);
    for (int f = 0; f < NFORM && !st; f++) {
      struct vsph_report_runspec rs = {
          L->scene, vsph_viscous_name(f), L->res[k], L->t_end, NULL, NULL};
      struct vsph_report_run r;
      if ((st = vsph_report_runs_get(R, &rs, &r))) break;
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

/* Every run of the sweeps, made two at a time before the tables read
 * them (vsph_report_runs_prefetch). */
static int prefetch(struct vsph_report *R, const struct sweep *sws, size_t n) {
  size_t total = 0;
  for (size_t k = 0; k < n; k++) total += sws[k].nv * NFORM;
  struct vsph_report_runspec *specs = calloc(total, sizeof *specs);
  char(*sets)[128] = calloc(total, sizeof *sets);
  char(*tags)[48] = calloc(total, sizeof *tags);
  const char *(*extras)[2] = calloc(total, sizeof *extras);
  int st = VSPH_OK;
  if (!specs || !sets || !tags || !extras) {
    st = VSPH_ENOMEM;
    vsph_status_report(st, __FILE__, __LINE__, "cannot list the sweeps");
  }
  size_t m = 0;
  for (size_t k = 0; k < n && !st; k++)
    for (size_t v = 0; v < sws[k].nv; v++)
      for (int f = 0; f < NFORM; f++, m++) {
        snprintf(sets[m], sizeof sets[m], "%s=%.10g", sws[k].key,
                 sws[k].vals[v]);
        snprintf(tags[m], sizeof tags[m], "%s%zu", sws[k].tag, v);
        extras[m][0] = sets[m];
        extras[m][1] = NULL;
        const struct vsph_report_runspec rs = {
            sws[k].scene, vsph_viscous_name(f),
            sws[k].res,   sws[k].t_end,
            extras[m],    tags[m]};
        specs[m] = rs;
      }
  if (!st) st = vsph_report_runs_prefetch(R, specs, m);
  free(specs);
  free(sets);
  free(tags);
  free(extras);
  return st;
}

int vsph_report_stability_write(struct vsph_report *R) {
  const size_t res = R->full ? 40 : 20;
  const char *vortex = vsph_report_runs_ladder(R, 0, 0)->scene;
  const char *wave = vsph_report_runs_ladder(R, 2, 0)->scene;
  const double tv = vsph_report_runs_ladder(R, 0, 0)->t_end;
  const double tw = vsph_report_runs_ladder(R, 2, 0)->t_end;
  /* c0 = k U_max with the vortex patch's U_max */
  struct vsph_scene scene;
  int st = vsph_scene_init(&scene, &vsph_vortex_patch_type, NULL);
  if (st) return st;
  static const double ks[4] = {10, 6, 4, 3};
  double c0s[4] = {0};
  for (int k = 0; k < 4; k++) c0s[k] = ks[k] * scene.U_max;
  static const double nus[3] = {1e-3, 1e-4, 1e-5}, pert[1] = {0.2};
  static const double cfl[6] = {1.0, 1.5, 2.0, 2.5, 3.0, 3.5};
  /* the sweeps: nu, a perturbed lattice per scene, c0, CFL (two scenes) */
  struct sweep sws[7] = {
      {vortex, res, tv, "nu (m^2/s)", "Scene:nu", nus, 3, "nu", NULL},
      {NULL},
      {NULL},
      {NULL},
      {vortex, res, tv, "c0 (m/s)", "Scene:c0", c0s, 4, "c0",
       "stability_c0.csv"},
      {vortex, res, tv / 2, "CFL", "Solver:cfl", cfl, 6, "cfl",
       "stability_cfl_vortex.csv"},
      {wave, res, tw / 3, "CFL", "Solver:cfl", cfl, 6, "cfl",
       "stability_cfl_wave.csv"}};
  for (int sc = 0; sc < VSPH_REPORT_NSCENES; sc++) {
    const struct vsph_report_ladderdef *L = vsph_report_runs_ladder(R, sc, 0);
    const struct sweep p = {L->scene,
                            res,
                            L->t_end,
                            "initial shift / dx",
                            "Solver:perturb",
                            pert,
                            1,
                            "perturb",
                            NULL};
    sws[1 + sc] = p;
  }
  vsph_text_set(&R->tv, "res", "%zu", res);
  vsph_text_set(&R->tv, "onset", "%g", 100 * VSPH_REPORT_ONSET);
  st = vsph_report_say(R, "stability.intro");
  if (!st) st = prefetch(R, sws, sizeof sws / sizeof sws[0]);
  if (!st) st = square_ladder(R);
  if (!st) st = vsph_report_say(R, "stability.hard");
  for (int k = 0; k < 4 && !st; k++) st = sweep(R, &sws[k]); /* nu, shift */
  if (!st) st = sweep(R, &sws[4]);                           /* c0 */
  if (!st) {
    vsph_text_set(&R->tv, "U_max", "%.4f", scene.U_max);
    vsph_text_set(&R->tv, "c0", "%.4f", scene.c0);
    st = vsph_report_say(R, "stability.c0_note");
  }
  if (!st)
    st = stability_map(R, "stability_c0.csv", "fig_stability_c0",
                       "Vortex patch: stability against the sound speed",
                       "sound speed c0 (m/s)");
  if (!st) st = vsph_report_say(R, "stability.cfl");
  if (!st) st = sweep(R, &sws[5]);
  if (!st) st = sweep(R, &sws[6]);
  if (!st)
    st = stability_map(R, "stability_cfl_vortex.csv", "fig_stability_cfl",
                       "Vortex patch: stability against the CFL number",
                       "Courant number CFL (RK4)");
  if (!st)
    st = stability_map(R, "stability_cfl_wave.csv", "fig_stability_cfl_wave",
                       "Standing wave: stability against the CFL number",
                       "Courant number CFL (RK4)");
  return st;
}
