/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
/* The report's solver runs: the resolution ladders, a cache keyed by the
 * version, the source hash and every setting (so an unchanged run is never
 * repeated), the error measures the parts share, the stretching square's
 * Richardson reference, and the regression baseline. */
#include "report_runs.h"

#include <math.h>
#include <omp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../analysis/dissipation.h"
#include "../analysis/series.h"
#include "../common/consts.h"
#include "../common/params.h"
#include "../common/status.h"
#include "../io/csv.h"
#include "../io/files.h"
#include "../io/json.h"
#include "../io/plot.h"
#include "../runs/rundir.h"
#include "../solver/scene.h"

/* Resolution ladders and end times: quick (default) and full (the paper's
 * resolutions: R/dx 100, L/dx 320, H/dx 240; t_end 100 s, 1 s, 8 s). */
static const struct vsph_report_ladderdef QUICK[VSPH_REPORT_NSCENES] = {
    {"vortex-patch", {10, 20, 40}, 20.0},
    {"stretching-square", {20, 40, 80}, 1.0},
    {"standing-wave", {10, 20, 40}, 3.0}};
static const struct vsph_report_ladderdef FULL[VSPH_REPORT_NSCENES] = {
    {"vortex-patch", {25, 50, 100}, 100.0},
    {"stretching-square", {80, 160, 320}, 1.0},
    {"standing-wave", {60, 120, 240}, 8.0}};

const struct vsph_report_ladderdef *vsph_report_runs_ladder(
    const struct vsph_report_runs *R, int sc, int quick) {
  return R->full && !quick ? &FULL[sc] : &QUICK[sc];
}

const struct vsph_report_ladderdef *vsph_report_runs_full_ladder(int sc) {
  return &FULL[sc];
}

void vsph_report_runs_free(struct vsph_jobs_run *r) {
  vsph_jobs_store_run_free(r);
}

const char *const vsph_report_runs_cartesian[2] = {"Scene:layout=cartesian",
                                                   NULL};

int vsph_report_runs_layouts(struct vsph_report_runs *R,
                             struct vsph_report_layouts *out) {
  if (R->have_layouts) {
    *out = R->layouts;
    return VSPH_OK;
  }
  const struct vsph_report_ladderdef *L = vsph_report_runs_ladder(R, 0, 0);
  int st = VSPH_OK;
  for (int l = 0; l < 2 && !st; l++)
    for (int f = 0; f < VSPH_VISCOUS_PAPER_COUNT && !st; f++) {
      struct vsph_jobs_run run[VSPH_REPORT_LADDER];
      memset(run, 0, sizeof run);
      for (int k = 0; k < VSPH_REPORT_LADDER && !st; k++) {
        const struct vsph_jobs_spec rs = {L->scene,
                                          vsph_viscous_name(f),
                                          L->res[k],
                                          L->t_end,
                                          l ? vsph_report_runs_cartesian : NULL,
                                          l ? "cartesian" : NULL};
        struct vsph_jobs_run *r = &run[k];
        if ((st = vsph_report_runs_get(R, &rs, r))) break;
        out->dx[k] = 1.0 / (double)L->res[k];
        out->err[l][f][k] = vsph_report_runs_error(r, NULL);
        out->d0[l][f][k] = vsph_report_runs_diss0(r);
        out->ok[l][f][k] = r->ok;
        out->tu[l][f][k] = r->t_unstable;
        out->loss[l][f][k] = vsph_report_runs_loss_ratio(r, r->nrow - 1);
      }
      if (!st) st = vsph_report_runs_selfconv(run, out->dx, &out->self[l][f]);
      for (int k = 0; k < VSPH_REPORT_LADDER; k++)
        vsph_report_runs_free(&run[k]);
    }
  if (st) return st;
  R->layouts = *out;
  R->have_layouts = 1;
  return VSPH_OK;
}

int vsph_report_runs_plan_scene(struct vsph_report_runs *R, int sc) {
  int st = VSPH_OK;
  /* the stretching square's reference runs */
  if (sc == 1) {
    struct vsph_jobs_spec ref[4];
    vsph_report_runs_reference_specs(R, ref);
    for (int k = 0; k < 4 && !st; k++)
      st = vsph_jobs_plan_run(&R->jobs, &ref[k]);
  }
  const struct vsph_report_ladderdef *L = vsph_report_runs_ladder(R, sc, 0);
  for (int f = 0; f < VSPH_VISCOUS_PAPER_COUNT && !st; f++)
    for (int k = 0; k < VSPH_REPORT_LADDER && !st; k++) {
      const struct vsph_jobs_spec rs = {
          L->scene, vsph_viscous_name(f), L->res[k], L->t_end, NULL, NULL};
      /* the finest rung's snapshots: the scene's pictures (the first
       * formulation's first, each one's last) and the vortex patch's
       * profiles (every snapshot's velocities) */
      const unsigned fr = VSPH_JOBS_FRAME_LAST |
                          (f == 0 ? VSPH_JOBS_FRAME_FIRST : 0u) |
                          (sc == 0 ? VSPH_JOBS_FRAME_ALL : 0u);
      st = k == VSPH_REPORT_LADDER - 1
               ? vsph_jobs_plan_frames(&R->jobs, &rs, fr)
               : vsph_jobs_plan_run(&R->jobs, &rs);
      /* the vortex patch's ladder again on a Cartesian disc (section 6) */
      const struct vsph_jobs_spec cs = {
          L->scene, vsph_viscous_name(f),       L->res[k],
          L->t_end, vsph_report_runs_cartesian, "cartesian"};
      if (!st && sc == 0) st = vsph_jobs_plan_run(&R->jobs, &cs);
    }
  return st;
}

int vsph_report_runs_plan_ladders(struct vsph_report_runs *R, int all) {
  int st = VSPH_OK;
  for (int sc = 0; sc < VSPH_REPORT_NSCENES && !st; sc++)
    if (all || vsph_report_scene_on(R, sc))
      st = vsph_report_runs_plan_scene(R, sc);
  return st;
}

int vsph_report_runs_get(struct vsph_report_runs *R,
                         const struct vsph_jobs_spec *rs,
                         struct vsph_jobs_run *out) {
  return vsph_jobs_store_get(&R->jobs, rs, out);
}

const char *const vsph_report_runs_hdx[2][2] = {{"Solver:hdx=2", NULL},
                                                {"Solver:hdx=3", NULL}};

void vsph_report_runs_reference_specs(const struct vsph_report_runs *R,
                                      struct vsph_jobs_spec rs[4]) {
  /* h/dx = 2 at L/dx 30, 60 and h/dx = 3 at 40, 80 (full: twice these):
   * h = 0.067, 0.033 and 0.075, 0.038 */
  static const size_t res[2][2] = {{30, 60}, {40, 80}};
  static const char *const tag[2] = {"hdx2", "hdx3"};
  const struct vsph_report_ladderdef *L = vsph_report_runs_ladder(R, 1, 0);
  for (int r = 0; r < 2; r++)
    for (int k = 0; k < 2; k++) {
      const struct vsph_jobs_spec s = {L->scene,
                                       "mgf",
                                       (R->full ? 2 : 1) * res[r][k],
                                       L->t_end,
                                       vsph_report_runs_hdx[r],
                                       tag[r]};
      rs[2 * r + k] = s;
    }
}

/* MGF's lattice error of the dissipation of pure strain on the square
 * lattice at h/dx (section 4; full support, independent of h). */
static int lattice_error(double hdx, double *eps) {
  struct vsph_dissipation_props dp;
  struct vsph_dissipation_result d;
  int st = vsph_dissipation_props_init(&dp, NULL);
  dp.form = VSPH_VISCOUS_MGF;
  dp.nacross = 160;
  dp.hdx = hdx;
  if (!st) st = vsph_dissipation_compute(&dp, &d);
  *eps = d.lattice_error;
  return st;
}

int vsph_report_runs_richardson(struct vsph_report_runs *R,
                                struct vsph_report_richardson *rr) {
  if (R->have_rr) {
    *rr = R->rr;
    return VSPH_OK;
  }
  struct vsph_jobs_spec rs[4];
  vsph_report_runs_reference_specs(R, rs);
  const double t_end = rs[0].t_end;
  struct vsph_jobs_run run[4];
  memset(run, 0, sizeof run);
  int st = VSPH_OK;
  for (int k = 0; k < 4 && !st; k++) {
    st = vsph_report_runs_get(R, &rs[k], &run[k]);
    if (!st && !run[k].ok)
      VSPH_FAIL(VSPH_EFAIL,
                "the stretching square's reference run %s went unstable",
                run[k].dir);
  }
  if (!st) st = lattice_error(2.0, &rr->eps[0]);
  if (!st) st = lattice_error(3.0, &rr->eps[1]);
  rr->correction = 0.0;
  for (int k = 0; !st && k <= 100; k++) {
    rr->t[k] = t_end * k / 100.0;
    double e[2][2];
    for (int r = 0; r < 2; r++)
      for (int m = 0; m < 2; m++) {
        const struct vsph_jobs_run *u = &run[2 * r + m];
        e[r][m] = vsph_series_interp(u->t, u->Ek, u->nrow, rr->t[k]);
      }
    rr->E[k] = vsph_series_extrapolate(e, rr->eps);
    rr->correction =
        fmax(rr->correction, fabs(rr->E[k] - (2.0 * e[1][1] - e[1][0])));
  }
  /* its rate: centred differences inside, one-sided at the ends, O(dt^2)
   * and O(dt) with dt = t_end/100 */
  for (int k = 0; !st && k <= 100; k++) {
    const int a = k ? k - 1 : 0, b = k < 100 ? k + 1 : 100;
    rr->dE[k] = (rr->E[b] - rr->E[a]) / (rr->t[b] - rr->t[a]);
  }
  if (!st) {
    rr->correction /= rr->E[0];
    for (int k = 0; k < 4; k++) rr->res[k] = rs[k].res;
    double d[2][2];
    for (int r = 0; r < 2; r++)
      for (int m = 0; m < 2; m++)
        d[r][m] = vsph_report_runs_diss0(&run[2 * r + m]);
    rr->diss0 = vsph_series_extrapolate(d, rr->eps);
  }
  for (int k = 0; k < 4; k++) vsph_report_runs_free(&run[k]);
  if (st) return st;
  R->rr = *rr;
  R->have_rr = 1;
  return VSPH_OK;
}

double vsph_report_runs_onset(const struct vsph_jobs_run *r,
                              const struct vsph_report_richardson *rr,
                              double threshold) {
  return vsph_series_onset(r->t, r->dEk, r->nrow, rr->t, rr->dE, 101,
                           threshold);
}

double vsph_report_runs_eref(const struct vsph_jobs_run *r, size_t row,
                             const struct vsph_report_richardson *rr) {
  if (rr) return vsph_series_interp(rr->t, rr->E, 101, r->t[row]);
  return r->Ekr[row];
}

/* Normalising by the initial values removes the O(Ma^2) offset of E_k(0)
 * that the weakly compressible start carries (m = rho V with
 * rho = rho0 + p/c0^2), which no resolution removes and which is not the
 * viscous formulation's doing. */
double vsph_report_runs_error(const struct vsph_jobs_run *r,
                              const struct vsph_report_richardson *rr) {
  return rr ? vsph_series_decay_error_table(r->t, r->Ek, r->nrow, rr->t, rr->E,
                                            101)
            : vsph_series_decay_error(r->Ek, r->Ekr, r->nrow);
}

/* Energy @p lost by row @p row over the reference's lost share. Both
 * losses are normalised by their own initial energy (the run's E_k(0),
 * the reference's E_m(0)), as the decay error is: the weakly compressible
 * start's O(Ma^2) offset of E_k(0) is not the formulation's doing. */
static double over_reference(const struct vsph_jobs_run *r, size_t row,
                             double lost) {
  return row > 0
             ? vsph_series_loss_ratio(lost, r->Ek[0], r->Emr[0], r->Emr[row])
             : (double)NAN;
}

double vsph_report_runs_loss_ratio(const struct vsph_jobs_run *r, size_t row) {
  return over_reference(r, row,
                        (r->Ek[0] + r->Ep[0] + r->Ec[0]) -
                            (r->Ek[row] + r->Ep[row] + r->Ec[row]));
}

double vsph_report_runs_visc_loss_ratio(const struct vsph_jobs_run *r,
                                        size_t row) {
  return over_reference(r, row, -vsph_series_integral(r->t, r->Pv, row));
}

double vsph_report_runs_diss0(const struct vsph_jobs_run *r) {
  return (r->Pv[0] - r->dEkr[0]) / fabs(r->dEkr[0]);
}

int vsph_report_runs_selfconv(const struct vsph_jobs_run run[],
                              const double dx[],
                              struct vsph_series_selfconv *out) {
  struct vsph_series_rung rung[VSPH_REPORT_LADDER];
  for (int k = 0; k < VSPH_REPORT_LADDER; k++)
    rung[k] =
        (struct vsph_series_rung){run[k].t, run[k].Ek, run[k].nrow, dx[k]};
  return vsph_series_selfconv(rung, VSPH_REPORT_LADDER, out);
}

int vsph_report_runs_ladder_figures(struct vsph_report_runs *R, int sc,
                                    struct vsph_report_ladder *out) {
  if (R->have_ladder[sc]) {
    *out = R->ladder[sc];
    return VSPH_OK;
  }
  struct vsph_report_ladder *lr = &R->ladder[sc];
  const struct vsph_report_ladderdef *L = vsph_report_runs_ladder(R, sc, 0);
  struct vsph_report_richardson rr;
  int st = sc == 1 ? vsph_report_runs_richardson(R, &rr) : VSPH_OK;
  for (int f = 0; f < VSPH_VISCOUS_PAPER_COUNT && !st; f++) {
    struct vsph_jobs_run run[VSPH_REPORT_LADDER];
    memset(run, 0, sizeof run);
    for (int k = 0; k < VSPH_REPORT_LADDER && !st; k++) {
      struct vsph_jobs_spec rs = {
          L->scene, vsph_viscous_name(f), L->res[k], L->t_end, NULL, NULL};
      struct vsph_jobs_run *r = &run[k];
      if ((st = vsph_report_runs_get(R, &rs, r))) break;
      lr->dx[f][k] = 1.0 / (double)L->res[k]; /* reference length 1 m */
      lr->err[f][k] = vsph_report_runs_error(r, sc == 1 ? &rr : NULL);
      lr->wall[f][k] = r->wall_s;
      lr->pairs[f][k] = r->pairs;
      lr->cpu[f][k] = r->cpu_s;
      lr->load[f][k] = r->load;
      lr->ok[f][k] = r->ok;
      lr->t_unstable[f][k] = r->t_unstable;
      lr->loss[f][k] = vsph_report_runs_loss_ratio(r, r->nrow - 1);
    }
    if (!st) st = vsph_report_runs_selfconv(run, lr->dx[f], &lr->self[f]);
    for (int k = 0; k < VSPH_REPORT_LADDER; k++) vsph_report_runs_free(&run[k]);
  }
  if (st) return st;
  R->have_ladder[sc] = 1;
  *out = *lr;
  return VSPH_OK;
}

const char *vsph_report_runs_colour(int f) {
  /* linetype k of every script is colour k - 1 of the shared palette
   * (io/plot.h): distinct for the first VSPH_PLOT_NSTYLES, then cycling */
  static const char *const lc[VSPH_PLOT_NSTYLES] = {
      "lc 1", "lc 2",  "lc 3",  "lc 4",  "lc 5",  "lc 6",  "lc 7", "lc 8",
      "lc 9", "lc 10", "lc 11", "lc 12", "lc 13", "lc 14", "lc 15"};
  return lc[(size_t)f % VSPH_PLOT_NSTYLES];
}

void vsph_report_runs_style(char *buf, size_t len, int f, const char *more) {
  snprintf(buf, len, "linespoints pt %d lw 2 %s%s", vsph_report_runs_point(f),
           vsph_report_runs_colour(f), more);
}

int vsph_report_runs_point(int f) { return vsph_plot_point((size_t)f); }

int vsph_report_runs_hollow(struct vsph_plot *pl, const char *file,
                            const char *using, int f, const char *hover,
                            int *said) {
  const int pt = vsph_report_runs_point(f);
  const int filled = pt >= 5 && pt <= 15 && pt % 2; /* 5, 7, ..., 15 */
  char style[96];
  int st = VSPH_OK;
  if (filled) {
    snprintf(style, sizeof style, "points pt %d ps 1.2 lc rgb 'white'", pt);
    st = vsph_plot_add_unkeyed(pl, file, using, hover, style);
    snprintf(style, sizeof style, "points pt %d lw 2 %s", pt - 1,
             vsph_report_runs_colour(f));
  } else
    snprintf(style, sizeof style, "points pt 6 ps 2.5 lw 2 lc rgb 'black'");
  if (!st) st = vsph_plot_add_unkeyed(pl, file, using, hover, style);
  if (!st && said && !*said) {
    *said = 1;
    st = vsph_plot_add(pl, file, "1:(1/0)",
                       "hollow: stopped as unstable (up to the stop)",
                       "points pt 6 lw 2 lc rgb 'black'");
  }
  return st;
}

void vsph_report_runs_fitted(char *buf, size_t len, double order, size_t ns) {
  if (ns >= 2)
    snprintf(buf, len, "**%.2f** (fitted through the %zu stable rungs)", order,
             ns);
  else
    snprintf(buf, len, "– (fewer than two stable rungs to fit)");
}

int vsph_report_runs_hollow_pairs(struct vsph_plot *pl, const char *file,
                                  int stable, int y, int f, const char *hover,
                                  int *said) {
  /* gnuplot evaluates the expression row by row in order: "was" holds
   * the row before's stable ($0 counts rows from 0: the first has none) */
  char using[128];
  snprintf(using, sizeof using,
           "1:(was = ($0 == 0 ? 1 : stable), stable = $%d, was == 0 || "
           "stable == 0 ? $%d : 1/0)",
           stable, y);
  return vsph_report_runs_hollow(pl, file, using, f, hover, said);
}

/* The channel rows of the baseline: every formulation on Basa et al.'s
 * Poiseuille (10 x 10, t* = 4.9) and Morris' Couette (16 rows to 0.25 s,
 * long enough a period for the two-pass forms), Basa's kernel. */
static const struct {
  const char *scene;
  size_t res;
  double t_end;
} CHANNEL_BASE[2] = {{"poiseuille", 10, 0.5}, {"couette", 16, 0.25}};

/* The cavity rows: each corrigible form of the descriptor table (the
 * pair forms the transport-velocity scheme first took), in its order,
 * Re = 100,
 * 16 x 16 to t = 1 s (quintic, h = dx); E_k at the end and the RMS
 * distance from Ghia et al. then (the flow is still developing). */
static size_t cavity_base_count(void) {
  size_t n = 0;
  for (int f = 0; f < VSPH_VISCOUS_FORM_COUNT; f++)
    n += (size_t)vsph_viscous_corrigible(f);
  return n;
}

/* The k-th of those forms' name. */
static const char *cavity_base_form(size_t k) {
  for (int f = 0; f < VSPH_VISCOUS_FORM_COUNT; f++)
    if (vsph_viscous_corrigible(f) && k-- == 0) return vsph_viscous_name(f);
  return "?";
}
#define NCAVITY_BASE cavity_base_count()

/* The contact-SPH rows: the shear scene at D0 = 40 nm to 1 ns (Wendland
 * C2, alpha = 0.5, 3 D0 deep): lead inviscid, lead with its viscosity and
 * the full correction, paraffin | glycerol at 10 m/s to 0.4 us with it;
 * E_k(t_end)/E_k(0) and P_visc(t_end)/P_visc(0), the acoustic solver's
 * dissipation and the stress's (the shear scene has no velocity error). */
#define CONTACT_BASE_COMMON "Solver:kernel=wendland2", "Solver:alpha=0.5"
static const char *const CONTACT_LEAD[] = {CONTACT_BASE_COMMON,
                                           "Scene:Ly=120e-9", "Scene:Lz=120e-9",
                                           "Scene:viscous=0", NULL};
static const char *const CONTACT_LEADZ[] = {
    CONTACT_BASE_COMMON, "Scene:Ly=120e-9", "Scene:Lz=120e-9",
    "Solver:zeta_num=1", NULL};
static const char *const CONTACT_BI[] = {
    CONTACT_BASE_COMMON,   "Scene:W=600e-6",    "Scene:Ly=30e-6",
    "Scene:Lz=30e-6",      "Scene:U0=10",       "Scene:material=glycerol",
    "Scene:left=paraffin", "Solver:zeta_num=1", NULL};
static const struct {
  size_t res;
  double t_end;
  const char *const *set;
  const char *tag;
} CONTACT_BASE[] = {{20, 1e-9, CONTACT_LEAD, "contact-lead"},
                    {20, 1e-9, CONTACT_LEADZ, "contact-leadz1"},
                    {60, 0.4e-6, CONTACT_BI, "contact-bimaterial"}};
#define NCONTACT_BASE (sizeof CONTACT_BASE / sizeof CONTACT_BASE[0])

/* The cylinders row: the report's Stokes flow past a periodic array of
 * held cylinders (glycerol, d/S = 0.5, uncorrected, its settings) at 20
 * particles across the cell to 10 us, some 400 steps. It starts at rest
 * (E_k(0) = 0), so its figures are E_k(t_end)/E_k(t_end/2), how the
 * driven flow grows, and P_visc(t_end) t_end / E_k(t_end), the viscous
 * work against it: both O(1), both set by the set-up and the contact
 * pair function. */
static const char *const CYL_BASE[] = {
    "Solver:kernel=wendland2", "Solver:alpha=0.5", "Solver:outputs=50", NULL};
#define NCYL_BASE 1

size_t vsph_report_runs_baseline_count(void) {
  return VSPH_REPORT_NSCENES * VSPH_VISCOUS_PAPER_COUNT +
         2 * VSPH_VISCOUS_FORM_COUNT + NCAVITY_BASE + NCONTACT_BASE + NCYL_BASE;
}

/* A baseline row from the run of @p rs: its final E_k (relative to the
 * reference when @p rel, else as it is), its final u_err and verdict. */
static int velocity_row(struct vsph_report_runs *R,
                        const struct vsph_jobs_spec *rs, int rel,
                        struct vsph_report_baseline *b) {
  struct vsph_jobs_run r;
  const int st = vsph_report_runs_get(R, rs, &r);
  if (st) return st;
  snprintf(b->scene, sizeof b->scene, "%s", rs->scene);
  snprintf(b->visc, sizeof b->visc, "%s", rs->visc);
  b->res = rs->res;
  b->t_end = rs->t_end;
  const size_t last = r.nrow - 1;
  const double *ue = vsph_csv_column(r.energy, "u_err");
  b->ek_final = rel ? (r.Ek[last] - r.Ekr[last]) / r.Ekr[last] : r.Ek[last];
  b->diss0 = ue ? ue[last] : (double)NAN;
  b->ok = r.ok;
  vsph_report_runs_free(&r);
  return VSPH_OK;
}

/* The settings of the channel and cavity rows */
static const char *const BASE_BASA[] = {VSPH_REPORT_BASA, NULL};
static const char *const BASE_TVF[] = {VSPH_REPORT_ADAMI, "Solver:tvf=1", NULL};

/* The run behind baseline row @p i, and its kind: 0 free surface, 1
 * channel, 2 cavity, 3 contact, 4 cylinders. */
static int baseline_spec(const struct vsph_report_runs *R, size_t i,
                         struct vsph_jobs_spec *rs) {
  const size_t nfree = VSPH_REPORT_NSCENES * VSPH_VISCOUS_PAPER_COUNT;
  const size_t nchan = 2 * VSPH_VISCOUS_FORM_COUNT;
  if (i >= nfree + nchan + NCAVITY_BASE + NCONTACT_BASE) {
    *rs = (struct vsph_jobs_spec){"cylinders", "contact", 20,
                                  1e-5,        CYL_BASE,  "base"};
    return 4;
  }
  if (i >= nfree + nchan + NCAVITY_BASE) {
    const size_t j = i - nfree - nchan - NCAVITY_BASE;
    *rs = (struct vsph_jobs_spec){"shear",
                                  "contact",
                                  CONTACT_BASE[j].res,
                                  CONTACT_BASE[j].t_end,
                                  CONTACT_BASE[j].set,
                                  CONTACT_BASE[j].tag};
    return 3;
  }
  if (i >= nfree + nchan) {
    *rs = (struct vsph_jobs_spec){"cavity", cavity_base_form(i - nfree - nchan),
                                  16,       1.0,
                                  BASE_TVF, "base"};
    return 2;
  }
  if (i >= nfree) {
    const size_t c = (i - nfree) / VSPH_VISCOUS_FORM_COUNT;
    const int f = (int)((i - nfree) % VSPH_VISCOUS_FORM_COUNT);
    *rs = (struct vsph_jobs_spec){CHANNEL_BASE[c].scene,
                                  vsph_viscous_name(f),
                                  CHANNEL_BASE[c].res,
                                  CHANNEL_BASE[c].t_end,
                                  BASE_BASA,
                                  "base"};
    return 1;
  }
  const int sc = (int)(i / VSPH_VISCOUS_PAPER_COUNT);
  const int f = (int)(i % VSPH_VISCOUS_PAPER_COUNT);
  const struct vsph_report_ladderdef *L = vsph_report_runs_ladder(R, sc, 1);
  *rs = (struct vsph_jobs_spec){
      L->scene, vsph_viscous_name(f), L->res[0], L->t_end, NULL, NULL};
  return 0;
}

int vsph_report_runs_plan_baseline(struct vsph_report_runs *R) {
  int st = VSPH_OK;
  for (size_t i = 0; i < vsph_report_runs_baseline_count() && !st; i++) {
    struct vsph_jobs_spec rs;
    baseline_spec(R, i, &rs);
    st = vsph_jobs_plan_here(&R->jobs, &rs); /* the archive's judge */
  }
  return st;
}

int vsph_report_runs_baseline(struct vsph_report_runs *R, size_t i,
                              struct vsph_report_baseline *b) {
  if (i >= vsph_report_runs_baseline_count())
    VSPH_FAIL(VSPH_EINVAL, "no baseline row %zu", i);
  struct vsph_jobs_spec rs;
  const int kind = baseline_spec(R, i, &rs);
  if (kind == 1 || kind == 2) /* channels: to the series; cavity: itself */
    return velocity_row(R, &rs, kind == 1, b);
  struct vsph_jobs_run r;
  const int st = vsph_report_runs_get(R, &rs, &r);
  if (st) return st;
  snprintf(b->scene, sizeof b->scene, "%s", rs.scene);
  snprintf(b->visc, sizeof b->visc, "%s", rs.visc);
  b->res = rs.res;
  b->t_end = rs.t_end;
  const size_t last = r.nrow - 1;
  if (kind == 3) { /* contact: E_k and the dissipation, relative */
    b->ek_final = r.Ek[last] / r.Ek[0];
    b->diss0 = r.Pv[last] / r.Pv[0];
  } else if (kind == 4) { /* cylinders: from rest (see CYL_BASE) */
    b->ek_final = r.Ek[last] / r.Ek[last / 2];
    b->diss0 = r.Pv[last] * rs.t_end / r.Ek[last];
  } else {
    const int square = !strcmp(rs.scene, "stretching-square");
    b->ek_final =
        square ? r.Ek[last] / r.Ek[0] : (r.Ek[last] - r.Ekr[last]) / r.Ekr[0];
    b->diss0 = vsph_report_runs_diss0(&r);
  }
  b->ok = r.ok;
  vsph_report_runs_free(&r);
  return VSPH_OK;
}
