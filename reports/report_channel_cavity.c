/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
/* Section 11 of the report, the lid-driven cavity (Basa et al. §6.2;
 * Zheng, Ma & Shao 2018): the runs against Ghia et al.'s centrelines and
 * the finite volume's E_k, their table, figure, reading and claims
 * (report_channel.h). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../analysis/references.h"
#include "../analysis/series.h"
#include "../common/status.h"
#include "../io/csv.h"
#include "../io/plot.h"
#include "../solver/viscous.h"
#include "measures.h"
#include "report_channel.h"
#include "report_fv.h"

/* The cavity's averaging window: a run's last fifth, from CAV_TAIL t_end
 * on (its u_min, its Ghia distances and their swings; the claims quote
 * it as t0). */
#define CAV_TAIL 0.8

/* The lid-driven cavity: the transport-velocity scheme with Adami et al.'s
 * wall particles, quintic spline, h = dx. Re 100 to t = 10 s: MEAF at 20
 * and 30, MGF and Cleary's D (xi = 4.24) at 30, MEAF without the transport
 * velocity; MEAF without it but with Basa et al.'s fluid side (summation
 * density, cubic spline at dx/h = 0.637); Re 1000 to 30 s at 30. FULL adds
 * MEAF at 50 x 50: Re 100, 400 (20 s) and 1000 (30 s, and to the paper's
 * 80 s). */
/* every cavity run keeps 10 snapshots: its centreline.csv, which Zheng
 * et al.'s u_min reads, is written with them */
#define CAV_SNAP "Solver:snapshots=10"
static const char *const CAV_TVF[] = {VSPH_REPORT_ADAMI, "Solver:tvf=1",
                                      CAV_SNAP, NULL};
static const char *const CAV_D[] = {VSPH_REPORT_ADAMI, "Solver:tvf=1",
                                    "Solver:xi=4.24", CAV_SNAP, NULL};
static const char *const CAV_PLAIN[] = {VSPH_REPORT_ADAMI, CAV_SNAP, NULL};
static const char *const CAV_SUM[] = {
    VSPH_REPORT_BASA, "Solver:density=summation", CAV_SNAP, NULL};
/* Basa et al.'s own set-up: their walls (density by continuity, Tait,
 * extrapolated tangential velocity), summation density, their kernel and
 * 50 x 50 with their D (xi 4.24); then the kernel swapped for one
 * without the B-splines' pairing mode, at the same h */
#define P000_SET                                                         \
  "Solver:density=summation", "Solver:eos=tait", "Scene:walls=evolving", \
      "Solver:xi=4.24"
static const char *const CAV_P000X[] = {VSPH_REPORT_BASA, P000_SET, CAV_SNAP,
                                        NULL};
static const char *const CAV_P000W[] = {
    "Solver:kernel=wendland2", "Solver:hdx=1.5699", P000_SET, CAV_SNAP, NULL};
static const char *const CAV_P000R[] = {VSPH_REPORT_BASA, P000_SET,
                                        "Scene:Re=1000", CAV_SNAP, NULL};
#undef P000_SET
static const char *const CAV_RE400[] = {VSPH_REPORT_ADAMI, "Solver:tvf=1",
                                        "Scene:Re=400", CAV_SNAP, NULL};
static const char *const CAV_RE1000[] = {VSPH_REPORT_ADAMI, "Solver:tvf=1",
                                         "Scene:Re=1000", CAV_SNAP, NULL};
/* the paper's time at Re 1000: a snapshot every 2 s, so that the last
 * fifth (64-80 s) holds nine, not three, for the centrelines' means and
 * the swing of their distances from Ghia et al.'s two tables */
static const char *const CAV_RE1000_80[] = {VSPH_REPORT_ADAMI, "Solver:tvf=1",
                                            "Scene:Re=1000",
                                            "Solver:snapshots=40", NULL};
#undef CAV_SNAP
/* Basa et al.'s cavity: 50 x 50 (their §6.2) */
#define CAV_PAPER_RES 50
/* the runs, by the role the claims give them; FULL's after CAV_QUICK */
enum {
  CAV_E20,
  CAV_E30,
  CAV_MGF30,
  CAV_D30,
  CAV_PLAIN30,
  CAV_SUM30,
  CAV_E1000,
  CAV_V01, /* Zheng et al.'s Laplacians at their Re 1000 (quick: 20 x 20,
              each costs 2.5 times MEAF's run) */
  CAV_V02,
  CAV_V03,
  CAV_V04,
  CAV_P000, /* Basa et al.'s own set-up, Re 100 and 1000, and with the
               Wendland C2 kernel at Re 100 */
  CAV_P000_1000,
  CAV_P000_W,
  CAV_QUICK,
  CAV_E50 = CAV_QUICK,
  CAV_E400_50,
  CAV_E1000_50,
  CAV_V01_40, /* the same at their coarsest resolution, to their 40 s */
  CAV_V02_40,
  CAV_V03_40,
  CAV_V04_40,
  CAV_E1000_80, /* E at Re 1000, the paper's 50 x 50 to its 80 s */
  NCAV
};
static const struct {
  const char *visc;
  size_t res;
  double t_end;            /* s */
  int Re;                  /* U L/nu */
  const char *tag;         /* folder suffix */
  const char *const *xtra; /* settings */
  const char *scheme;      /* the table's words for the scheme */
  const char *fv;          /* its label beside the finite volume's E_k at
                              Re 1000 (Basa et al.'s Fig. 9; NULL: not
                              there) */
} CAV[NCAV] = {
#define TVFQ "transport velocity (summation), quintic h = dx"
    [CAV_E20] = {.visc = "meaf",
                 .res = 20,
                 .t_end = 10,
                 .Re = 100,
                 .tag = "tvf",
                 .xtra = CAV_TVF,
                 .scheme = TVFQ},
    [CAV_E30] = {.visc = "meaf",
                 .res = 30,
                 .t_end = 10,
                 .Re = 100,
                 .tag = "tvf",
                 .xtra = CAV_TVF,
                 .scheme = TVFQ},
    [CAV_MGF30] = {.visc = "mgf",
                   .res = 30,
                   .t_end = 10,
                   .Re = 100,
                   .tag = "tvf",
                   .xtra = CAV_TVF,
                   .scheme = TVFQ},
    [CAV_D30] = {.visc = "cleary",
                 .res = 30,
                 .t_end = 10,
                 .Re = 100,
                 .tag = "tvf",
                 .xtra = CAV_D,
                 .scheme = TVFQ},
    [CAV_PLAIN30] = {.visc = "meaf",
                     .res = 30,
                     .t_end = 10,
                     .Re = 100,
                     .tag = "plain",
                     .xtra = CAV_PLAIN,
                     .scheme = "continuity, quintic h = dx"},
    [CAV_SUM30] = {.visc = "meaf",
                   .res = 30,
                   .t_end = 10,
                   .Re = 100,
                   .tag = "sum",
                   .xtra = CAV_SUM,
                   .scheme =
                       "summation, cubic dx/h = 0.637 (Basa's fluid side)"},
    [CAV_E1000] = {.visc = "meaf",
                   .res = 30,
                   .t_end = 30,
                   .Re = 1000,
                   .tag = "tvfRe1000",
                   .xtra = CAV_RE1000,
                   .scheme = TVFQ,
                   .fv = "SPH: E (MEAF), 30 x 30, transport velocity"},
    [CAV_V01] = {.visc = "visc01",
                 .res = 20,
                 .t_end = 30,
                 .Re = 1000,
                 .tag = "tvfRe1000",
                 .xtra = CAV_RE1000,
                 .scheme = TVFQ,
                 .fv = "SPH: VISC-01, 20 x 20"},
    [CAV_V02] = {.visc = "visc02",
                 .res = 20,
                 .t_end = 30,
                 .Re = 1000,
                 .tag = "tvfRe1000",
                 .xtra = CAV_RE1000,
                 .scheme = TVFQ,
                 .fv = "SPH: VISC-02, 20 x 20"},
    [CAV_V03] = {.visc = "visc03",
                 .res = 20,
                 .t_end = 30,
                 .Re = 1000,
                 .tag = "tvfRe1000",
                 .xtra = CAV_RE1000,
                 .scheme = TVFQ,
                 .fv = "SPH: VISC-03, 20 x 20"},
    [CAV_V04] = {.visc = "visc04",
                 .res = 20,
                 .t_end = 30,
                 .Re = 1000,
                 .tag = "tvfRe1000",
                 .xtra = CAV_RE1000,
                 .scheme = TVFQ,
                 .fv = "SPH: VISC-04, 20 x 20"},
#define P000S "Basa's own: evolving walls, summation, Tait, "
    [CAV_P000] = {.visc = "cleary",
                  .res = 50,
                  .t_end = 20,
                  .Re = 100,
                  .tag = "p000",
                  .xtra = CAV_P000X,
                  .scheme = P000S "cubic dx/h = 0.637"},
    [CAV_P000_1000] = {.visc = "cleary",
                       .res = 50,
                       .t_end = 80,
                       .Re = 1000,
                       .tag = "p000Re1000",
                       .xtra = CAV_P000R,
                       .scheme = P000S "cubic dx/h = 0.637",
                       .fv = "SPH: D, 50 x 50, Basa's own set-up"},
    [CAV_P000_W] = {.visc = "cleary",
                    .res = 50,
                    .t_end = 20,
                    .Re = 100,
                    .tag = "p000wendland",
                    .xtra = CAV_P000W,
                    .scheme = P000S "Wendland C2 at the same h"},
#undef P000S
    [CAV_E50] = {.visc = "meaf",
                 .res = 50,
                 .t_end = 10,
                 .Re = 100,
                 .tag = "tvf",
                 .xtra = CAV_TVF,
                 .scheme = TVFQ},
    [CAV_E400_50] = {.visc = "meaf",
                     .res = 50,
                     .t_end = 20,
                     .Re = 400,
                     .tag = "tvfRe400",
                     .xtra = CAV_RE400,
                     .scheme = TVFQ},
    [CAV_E1000_50] = {.visc = "meaf",
                      .res = 50,
                      .t_end = 30,
                      .Re = 1000,
                      .tag = "tvfRe1000",
                      .xtra = CAV_RE1000,
                      .scheme = TVFQ,
                      .fv = "SPH: E (MEAF), 50 x 50, transport velocity"},
    [CAV_V01_40] = {.visc = "visc01",
                    .res = 40,
                    .t_end = 40,
                    .Re = 1000,
                    .tag = "tvfRe1000",
                    .xtra = CAV_RE1000,
                    .scheme = TVFQ,
                    .fv = "SPH: VISC-01, 40 x 40"},
    [CAV_V02_40] = {.visc = "visc02",
                    .res = 40,
                    .t_end = 40,
                    .Re = 1000,
                    .tag = "tvfRe1000",
                    .xtra = CAV_RE1000,
                    .scheme = TVFQ,
                    .fv = "SPH: VISC-02, 40 x 40"},
    [CAV_V03_40] = {.visc = "visc03",
                    .res = 40,
                    .t_end = 40,
                    .Re = 1000,
                    .tag = "tvfRe1000",
                    .xtra = CAV_RE1000,
                    .scheme = TVFQ,
                    .fv = "SPH: VISC-03, 40 x 40"},
    [CAV_V04_40] = {.visc = "visc04",
                    .res = 40,
                    .t_end = 40,
                    .Re = 1000,
                    .tag = "tvfRe1000",
                    .xtra = CAV_RE1000,
                    .scheme = TVFQ,
                    .fv = "SPH: VISC-04, 40 x 40"},
    /* no .fv: the finite volume's E_k at Re 1000 ends at 30 s */
    [CAV_E1000_80] = {.visc = "meaf",
                      .res = 50,
                      .t_end = 80,
                      .Re = 1000,
                      .tag = "tvfRe1000to80",
                      .xtra = CAV_RE1000_80,
                      .scheme = TVFQ},
#undef TVFQ
};
/* Zheng et al.'s four forms, VISC-01 to VISC-04, at Re 1000: the quick
 * plan's 20 x 20 and the FULL plan's 40 x 40 */
static const int ZHENG[2][4] = {
    {CAV_V01, CAV_V02, CAV_V03, CAV_V04},
    {CAV_V01_40, CAV_V02_40, CAV_V03_40, CAV_V04_40}};

/* The cavity runs of this fidelity. */
static int ncav(const struct vsph_report *R) {
  return R->runs.full ? NCAV : CAV_QUICK;
}

/* E's run at Re 1000 that the claim cavity_re1000 reads: the FULL plan's
 * at the paper's 50 x 50 to its 80 s, the quick plan's 30 x 30 to 30 s. */
static int re1000_run(const struct vsph_report *R) {
  return R->runs.full ? CAV_E1000_80 : CAV_E1000;
}

/* The runs loaded, and Zheng et al.'s |u_min - u_min,Ghia|/U of each over
 * the output times of its last fifth: mean and swing (NaN: none); E's run
 * at Re 1000: its centrelines' RMS distance from Ghia et al.'s Re 1000
 * and Re 400 tables over the same times, and the swing of their
 * difference over those times (NaN: none). */
struct vsph_report_channel_cavity {
  struct vsph_jobs_run cav[NCAV];
  double umin[NCAV], umin_swing[NCAV];
  double d1000, d400, dswing;
};

static struct vsph_jobs_spec spec(int q) {
  return (struct vsph_jobs_spec){.scene = "cavity",
                                 .visc = CAV[q].visc,
                                 .res = CAV[q].res,
                                 .t_end = CAV[q].t_end,
                                 .extra = CAV[q].xtra,
                                 .tag = CAV[q].tag};
}

int vsph_report_channel_cavity_plan(struct vsph_report *R) {
  int st = VSPH_OK;
  for (int q = 0; q < ncav(R) && !st; q++) {
    const struct vsph_jobs_spec s = spec(q);
    st = vsph_jobs_plan_run(&R->runs.jobs, &s);
  }
  return st;
}

/* The measures of finished cavity run @p q's centreline.csv (read once),
 * each over the output times of its last fifth: Zheng et al.'s u_min
 * error at its Re (vsph_references_cavity_umin), mean and swing; and for
 * E at Re 1000 its RMS distance from Ghia et al.'s Re 1000 and Re 400
 * tables (vsph_references_cavity_rms, the lid at the scene's default U =
 * 1 m/s, which the report's cavities keep), their means and the swing of
 * their difference. NaN where the run stopped early or Ghia et al. have no
 * table for its Re. */
static int cavity_centrelines(struct vsph_report *R,
                              struct vsph_report_channel_cavity *c, int q) {
  const struct vsph_jobs_run *r = &c->cav[q];
  c->umin[q] = c->umin_swing[q] = (double)NAN;
  const int e1000 = q == re1000_run(R);
  if (e1000) c->d1000 = c->d400 = c->dswing = (double)NAN;
  if (!r->ok) return VSPH_OK;
  struct vsph_csv *t =
      vsph_jobs_store_table(&R->runs.jobs, r->dir, "centreline.csv");
  if (!t) return VSPH_EIO;
  const double *tt = vsph_csv_column(t, "t"), *v = vsph_csv_column(t, "vel");
  struct vsph_references_ghia g;
  vsph_references_ghia(100.0, &g); /* the points per line: any table's */
  const size_t cap = t->nrow / (2 * g.n) + 1; /* a time per block */
  double *to = malloc(3 * cap * sizeof *to), *e = to ? to + cap : NULL;
  if (!to) {
    vsph_csv_free(t);
    VSPH_FAIL(VSPH_ENOMEM, "cannot read %s/centreline.csv", r->dir);
  }
  double *const e4 = e + cap;
  size_t m = tt && v ? vsph_references_cavity_umin(
                           tt, v, t->nrow, g.n, (double)CAV[q].Re, to, e, cap)
                     : 0;
  if (m) {
    c->umin[q] = vsph_series_tail_mean(to, e, m, CAV_TAIL);
    c->umin_swing[q] = vsph_series_tail_range(to, e, m, CAV_TAIL);
  }
  m = e1000 && tt && v ? vsph_references_cavity_rms(tt, v, t->nrow, g.n, 1000.0,
                                                    1.0, to, e, cap)
                       : 0;
  if (m && vsph_references_cavity_rms(tt, v, t->nrow, g.n, 400.0, 1.0, to, e4,
                                      cap) == m) {
    c->d1000 = vsph_series_tail_mean(to, e, m, CAV_TAIL);
    c->d400 = vsph_series_tail_mean(to, e4, m, CAV_TAIL);
    for (size_t k = 0; k < m; k++) e4[k] = e[k] - e4[k];
    c->dswing = vsph_series_tail_range(to, e4, m, CAV_TAIL);
  }
  vsph_csv_free(t);
  free(to);
  return VSPH_OK;
}

int vsph_report_channel_cavity_load(struct vsph_report *R,
                                    struct vsph_report_channel_cavity **out) {
  struct vsph_report_channel_cavity *c = calloc(1, sizeof *c);
  *out = c;
  if (!c) VSPH_FAIL(VSPH_ENOMEM, "cannot load the cavity's runs");
  int st = VSPH_OK;
  for (int q = 0; q < ncav(R) && !st; q++) {
    const struct vsph_jobs_spec s = spec(q);
    st = vsph_report_runs_get(&R->runs, &s, &c->cav[q]);
  }
  for (int q = 0; q < NCAV; q++) c->umin[q] = c->umin_swing[q] = (double)NAN;
  c->d1000 = c->d400 = c->dswing = (double)NAN;
  for (int q = 0; q < ncav(R) && !st; q++) st = cavity_centrelines(R, c, q);
  return st;
}

void vsph_report_channel_cavity_free(struct vsph_report_channel_cavity *c) {
  if (!c) return;
  for (int q = 0; q < NCAV; q++) vsph_report_runs_free(&c->cav[q]);
  free(c);
}

/* A finished cavity run's column averaged over its last fifth (the rows
 * from CAV_TAIL t_end on): the single rows of the Ghia error scatter by a few
 * per cent of U with the particle noise. NaN for a run stopped early. */
static double cavity_mean(const struct vsph_jobs_run *r, const char *col) {
  const double *y = vsph_csv_column(r->energy, col);
  if (!r->ok || !y) return (double)NAN;
  return vsph_series_tail_mean(r->t, y, r->nrow, CAV_TAIL);
}

/* A finished cavity run's swing of column @p col over its last fifth
 * (the window cavity_mean averages); NaN for a run stopped early. */
static double cavity_swing(const struct vsph_jobs_run *r, const char *col) {
  const double *y = vsph_csv_column(r->energy, col);
  if (!r->ok || !y) return (double)NAN;
  return vsph_series_tail_range(r->t, y, r->nrow, CAV_TAIL);
}

/* Where a run stopped by pairing: the place's y over the side (NaN: not a
 * pairing stop, or no place named). */
static double pairing_y(const struct vsph_jobs_run *r) {
  double x, y;
  const char *near = strstr(r->reason, " near (");
  if (r->ok || !strstr(r->reason, "pairing") || !near ||
      sscanf(near, " near (%lf, %lf)", &x, &y) != 2)
    return (double)NAN;
  return y;
}

/* What Basa et al.'s three cavity runs say about why they stop. */
static const char *p000_why(const struct vsph_report_channel_cavity *c) {
  const struct vsph_jobs_run *cu = &c->cav[CAV_P000], *we = &c->cav[CAV_P000_W],
                             *re = &c->cav[CAV_P000_1000];
  if (cu->ok && we->ok) return "and so did the cubic spline's: neither stops";
  if (cu->ok) return "where the cubic spline's run held";
  if (we->ok)
    return "so the cubic spline's pairing mode at this h is what stops the "
           "paper's kernel";
  /* both stopped: where? (the lid is y = 1) */
  const double yc = pairing_y(cu), yw = pairing_y(we), yr = pairing_y(re);
  if (yc > 0.9 && yw > 0.9 && (re->ok || yr > 0.9))
    return "also by pairing, and every stop here sits in the lid's rows "
           "(y > 0.9 L) with either kernel: the lid's rows on these walls "
           "end the runs, the kernel only sets how soon";
  return "so the kernel alone does not decide the stop; the places differ "
         "(the table)";
}

/* The rows of the cavity runs against Ghia et al.. */
static void cavity_rows(struct vsph_report *R,
                        const struct vsph_report_channel_cavity *c) {
  for (int q = 0; q < ncav(R); q++) {
    const struct vsph_jobs_run *r = &c->cav[q];
    fprintf(R->md, "| %d | %s | %s | %zu |", CAV[q].Re,
            vsph_viscous_label(vsph_viscous_find(CAV[q].visc)), CAV[q].scheme,
            CAV[q].res);
    vsph_report_channel_stop_cell(R->md, r);
    vsph_report_channel_cell(R->md, vsph_report_channel_final(r, "Ek"), 1.0);
    vsph_report_channel_cell(R->md, cavity_mean(r, "u_err"), 100);
    vsph_report_channel_cell(R->md, cavity_mean(r, "u_err_rel"), 100);
    vsph_report_channel_cell(R->md, c->umin[q], 100);
    fprintf(R->md, " %.1f |\n", r->wall_s);
  }
  fprintf(R->md, "\n");
}

int vsph_report_channel_cavity_write(
    struct vsph_report *R, const struct vsph_report_channel_cavity *c) {
  int st = vsph_report_doc_say(R, "channel.cavity_head");
  if (st) return st;
  cavity_rows(R, c);
  char a[240], b[240], w[240];
  vsph_text_set(
      &R->tv, "p000", "%s",
      vsph_report_channel_stop_phrase(&c->cav[CAV_P000], a, sizeof a));
  vsph_text_set(
      &R->tv, "p000r", "%s",
      vsph_report_channel_stop_phrase(&c->cav[CAV_P000_1000], b, sizeof b));
  vsph_text_set(
      &R->tv, "p000w", "%s",
      vsph_report_channel_stop_phrase(&c->cav[CAV_P000_W], w, sizeof w));
  vsph_text_set(&R->tv, "p000why", "%s", p000_why(c));
  return vsph_report_doc_say(R, "channel.cavity_reading");
}

int vsph_report_channel_cavity_figure(
    struct vsph_report *R, const struct vsph_report_channel_cavity *c) {
  struct vsph_plot pl;
  char title[160];
  snprintf(title, sizeof title,
           "Lid-driven cavity: RMS distance from Ghia et al.'s centrelines "
           "over time");
  vsph_plot_init(&pl, R->dir, "fig_cavity_ghia", title, "t (s)",
                 "RMS distance / U (dimensionless)");
  pl.logy = 1;
  int st = VSPH_OK;
  for (int q = 0; q < ncav(R) && !st; q++) {
    if (!c->cav[q].ok) continue; /* the run without TVF: a few rows */
    char style[96], label[64];
    snprintf(label, sizeof label, "Re %d, %s, %zu x %zu", CAV[q].Re,
             vsph_viscous_label(vsph_viscous_find(CAV[q].visc)), CAV[q].res,
             CAV[q].res);
    vsph_report_runs_style(style, sizeof style, q,
                           CAV[q].Re > 100 ? " dt 2 pi 12" : " pi 12");
    st = vsph_report_channel_plot_add(R, &pl, &c->cav[q], "u_err", 1.0, label,
                                      style);
  }
  vsph_text_set(&R->tv, "title", "%s", title);
  if (!st) st = vsph_report_doc_figure_say(R, &pl, "channel.fig_cavity");
  return st;
}

/* The cavity's Re 1000 runs of this fidelity beside the finite volume's
 * E_k (those with a label there): their rows into @p q, how many. */
static size_t cavity_re1000(const struct vsph_report *R, int q[NCAV]) {
  size_t n = 0;
  for (int k = 0; k < ncav(R); k++)
    if (CAV[k].fv) q[n++] = k;
  return n;
}

/* The cavity against the finite-volume references (reports/fvref.h). */
int vsph_report_channel_cavity_fv(struct vsph_report *R,
                                  const struct vsph_report_channel_cavity *c) {
  int q[NCAV];
  const char *lab[NCAV];
  const struct vsph_jobs_run *runs[NCAV];
  const size_t n = cavity_re1000(R, q);
  for (size_t k = 0; k < n; k++) {
    runs[k] = &c->cav[q[k]];
    lab[k] = CAV[q[k]].fv;
  }
  return vsph_report_fv_cavity(R, runs, lab, n);
}

/* The claims: blocks of reports/claims/channel.md, graded there on the
 * measures and words set below (the grammar: reports/claim.h). */

/* Zheng et al.'s four Laplacian forms in the cavity at Re 1000: their
 * metric at the finest resolution run (their 40 x 40 to 40 s at FULL,
 * 20 x 20 to 30 s quick). The forms that ran to their end compete; a
 * stopped one gives no flow result (its u_min counts as infinite, and the
 * verdict says when it stopped). */
int vsph_report_channel_cavity_visc(struct vsph_report *R,
                                    const struct vsph_report_channel_cavity *c,
                                    struct vsph_claim_vals *v) {
  const int *z = ZHENG[R->runs.full ? 1 : 0];
  double u[4], w[4];
  int ok[4];
  for (int f = 0; f < 4; f++) {
    u[f] = c->umin[z[f]];
    w[f] = c->umin_swing[z[f]];
    ok[f] = c->cav[z[f]].ok;
  }
  int all = 1;
  for (int f = 0; f < 4; f++) all &= ok[f];
  struct vsph_measures_closest cl; /* the closest, as the text names it */
  vsph_measures_closest(u, w, ok, 4, &cl);
  vsph_claim_clear(v);
  /* each form's figure, or "stopped" where its run did not end; which
   * stopped, and when (their figure: nan) */
  char stopped[200] = "";
  for (int f = 0, m = 0; f < 4; f++) {
    char key[8];
    snprintf(key, sizeof key, "u%d", f + 1);
    vsph_claim_num(v, key, ok[f] ? u[f] : (double)INFINITY);
    snprintf(key, sizeof key, "fig%d", f + 1);
    if (ok[f] && isfinite(u[f]))
      vsph_claim_str(v, key, "%.1f %%", 100 * u[f]);
    else
      vsph_claim_str(v, key, "stopped");
    if (!ok[f] && m >= 0 && (size_t)m < sizeof stopped)
      m += snprintf(stopped + m, sizeof stopped - (size_t)m,
                    "%sVISC-0%d stopped at t = %.3g s", m ? "; " : " (", f + 1,
                    c->cav[z[f]].t_unstable);
  }
  if (!all) strncat(stopped, ")", sizeof stopped - strlen(stopped) - 1);
  vsph_claim_str(v, "stopped", "%s", stopped);
  vsph_claim_num(v, "ok4", (double)ok[3]);
  vsph_claim_num(v, "next", cl.next);
  vsph_claim_num(v, "gap", cl.gap);
  vsph_claim_num(v, "swing", cl.swing);
  vsph_claim_str(v, "best", "%d", cl.best + 1);
  vsph_claim_num(v, "res", (double)CAV[z[0]].res);
  vsph_claim_num(v, "t1", CAV[z[0]].t_end);
  vsph_claim_num(v, "t0", CAV_TAIL * CAV[z[0]].t_end);
  vsph_claim_str(v, "ours_res", "%s",
                 R->runs.full ? "ours its coarsest"
                              : "ours 20 x 20 to 30 s, a quick report's cost");
  return vsph_report_doc_grade(R, "claims/channel.visc_best", v);
}

/* VISC-02 in a flow, at the paper's coarsest cavity (FULL): the four
 * forms at Re 1000, 40 x 40 to 40 s; each form's time to its stop or its
 * end (whether disorder is VISC-02's cause is not shown). */
int vsph_report_channel_cavity_visc02(
    struct vsph_report *R, const struct vsph_report_channel_cavity *c,
    struct vsph_claim_vals *v) {
  vsph_claim_clear(v);
  vsph_claim_num(v, "full", R->runs.full);
  if (!R->runs.full) { /* not planned: nothing measured */
    static const char *const NONE[] = {"ok2", "t1", "t2", "t3", "t4", "t_end"};
    for (size_t k = 0; k < sizeof NONE / sizeof NONE[0]; k++)
      vsph_claim_num(v, NONE[k], (double)NAN);
    return vsph_report_doc_grade(R, "claims/channel.visc02", v);
  }
  const double t_end = CAV[CAV_V02_40].t_end;
  double t[4];
  int coarse = 0; /* the forms that run to their end at 20 x 20 */
  for (int f = 0; f < 4; f++) {
    const struct vsph_jobs_run *r = &c->cav[ZHENG[1][f]];
    char s[256], key[4];
    t[f] = r->ok ? t_end : r->t_unstable;
    snprintf(key, sizeof key, "s%d", f + 1);
    vsph_claim_str(v, key, "%s",
                   vsph_report_channel_stop_phrase(r, s, sizeof s));
    coarse += c->cav[ZHENG[0][f]].ok;
  }
  vsph_claim_num(v, "ok2", (double)c->cav[CAV_V02_40].ok);
  for (int f = 0; f < 4; f++) { /* each form's time: its stop, or the end */
    char key[4];
    snprintf(key, sizeof key, "t%d", f + 1);
    vsph_claim_num(v, key, t[f]);
  }
  vsph_claim_num(v, "t_end", t_end);
  vsph_claim_num(v, "t_coarse", CAV[CAV_V01].t_end);
  vsph_claim_num(v, "coarse", coarse);
  return vsph_report_doc_grade(R, "claims/channel.visc02", v);
}

/* Basa et al.'s own cavity set-up, as far as the paper gives it. */
static int cavity_p000_claim(struct vsph_report *R,
                             const struct vsph_report_channel_cavity *c,
                             struct vsph_claim_vals *v) {
  static const struct {
    int q;
    const char *word, *ok;
  } RUN[3] = {{.q = CAV_P000, .word = "re100", .ok = "ok100"},
              {.q = CAV_P000_1000, .word = "re1000", .ok = "ok1000"},
              {.q = CAV_P000_W, .word = "wendland", .ok = "okW"}};
  vsph_claim_clear(v);
  for (int k = 0; k < 3; k++) {
    char s[240];
    vsph_claim_str(
        v, RUN[k].word, "%s",
        vsph_report_channel_stop_phrase(&c->cav[RUN[k].q], s, sizeof s));
    vsph_claim_num(v, RUN[k].ok, (double)c->cav[RUN[k].q].ok);
  }
  return vsph_report_doc_grade(R, "claims/channel.cavity_p000", v);
}

/* The words the cavity's rows on Adami et al.'s scheme share. */
static void cavity_vals(const struct vsph_report *R,
                        struct vsph_claim_vals *v) {
  vsph_claim_clear(v);
  vsph_claim_str(v, "cav_res", "%s",
                 R->runs.full ? "E at 50 x 50 as the paper's, D at 30 x 30"
                              : "30 x 30 (the paper: 50 x 50)");
}

/* The cavity at Re 100: E's distance from Ghia et al. (RMS over both
 * centrelines' 30 interior points, last fifth of the run) at the paper's
 * 50 x 50 where the FULL plan runs it, else at the finest quick 30 x 30;
 * D against E at 30 x 30; E at Re 1000 (Basa et al. compare at t = 80 s;
 * the quick run stops at 30). */
static int cavity_claims(struct vsph_report *R,
                         const struct vsph_report_channel_cavity *c,
                         struct vsph_claim_vals *v) {
  int st = cavity_p000_claim(R, c, v);
  const struct vsph_jobs_run *rE =
      R->runs.full ? &c->cav[CAV_E50] : &c->cav[CAV_E30];
  const double eE = cavity_mean(rE, "u_err"),
               eE30 = cavity_mean(&c->cav[CAV_E30], "u_err"),
               eD = cavity_mean(&c->cav[CAV_D30], "u_err");
  cavity_vals(R, v);
  vsph_claim_str(v, "res", "%s", R->runs.full ? "50 x 50" : "30 x 30");
  vsph_claim_num(v, "eE", eE);
  vsph_claim_num(v, "mE", cavity_mean(rE, "u_err_rel"));
  vsph_claim_str(v, "at30", "%s", "");
  if (R->runs.full)
    vsph_claim_str(v, "at30", ", %.1f %% at 30 x 30", 100 * eE30);
  vsph_claim_num(v, "eD", eD);
  vsph_claim_num(v, "t_plain", c->cav[CAV_PLAIN30].t_unstable);
  vsph_claim_num(v, "t_sum", c->cav[CAV_SUM30].t_unstable);
  if (!st) st = vsph_report_doc_grade(R, "claims/channel.cavity_re100", v);
  /* D against E at one resolution, 30 x 30 in both fidelities (the FULL
   * plan has no D at 50 x 50); a gap below the runs' own swing over the
   * averaging window decides nothing (docs/theory.md section 13) */
  const double sE = cavity_swing(&c->cav[CAV_E30], "u_err"),
               sD = cavity_swing(&c->cav[CAV_D30], "u_err");
  cavity_vals(R, v);
  vsph_claim_str(v, "cav_res", "%s", "30 x 30 (the paper: 50 x 50)");
  vsph_claim_num(v, "eD", eD);
  vsph_claim_num(v, "eE", eE30);
  vsph_claim_num(v, "sD", sD);
  vsph_claim_num(v, "sE", sE);
  if (!st) st = vsph_report_doc_grade(R, "claims/channel.cavity_d_best", v);
  const int q1 = re1000_run(R);
  const struct vsph_jobs_run *r1 = &c->cav[q1];
  cavity_vals(R, v);
  vsph_claim_num(v, "res", (double)CAV[q1].res);
  vsph_claim_num(v, "t1", CAV[q1].t_end);
  vsph_claim_num(v, "t0", CAV_TAIL * CAV[q1].t_end);
  vsph_claim_str(v, "re1000_run", "%s",
                 R->runs.full ? "50 x 50 to 80 s, as the paper's"
                              : "30 x 30 (the paper: 50 x 50), to 30 s (the "
                                "paper compares at 80 s)");
  vsph_claim_num(v, "e1", cavity_mean(r1, "u_err"));
  vsph_claim_num(v, "e1swing", cavity_swing(r1, "u_err"));
  vsph_claim_num(v, "m1", cavity_mean(r1, "u_err_rel"));
  vsph_claim_num(v, "ek", vsph_report_channel_final(r1, "Ek"));
  vsph_claim_num(v, "ok", (double)r1->ok);
  vsph_claim_num(v, "t_stop", r1->t_unstable);
  /* the fluid at rest's (the run's start) distance from Ghia et al. */
  vsph_claim_num(v, "rest", vsph_references_ghia_rest(1000.0));
  /* its centrelines against their Re 1000 and Re 400 tables */
  vsph_claim_num(v, "d1000", c->d1000);
  vsph_claim_num(v, "d400", c->d400);
  vsph_claim_num(v, "dswing", c->dswing);
  vsph_claim_num(v, "t_run", r1->nrow ? r1->t[r1->nrow - 1] : (double)NAN);
  if (!st) st = vsph_report_doc_grade(R, "claims/channel.cavity_re1000", v);
  return st;
}

/* The claim cavity_ek with nothing measured (no finite-volume reference
 * read): its test fv says so. */
static int cavity_ek_none(struct vsph_report *R, struct vsph_claim_vals *v) {
  static const char *const NUMS[] = {"fv_n",     "band",   "peak",   "under",
                                     "measured", "n",      "lo",     "hi",
                                     "e_seen",   "d_seen", "n_paper"};
  static const char *const WORDS[] = {"quick_runs", "full_runs", "hist"};
  for (size_t k = 0; k < sizeof NUMS / sizeof *NUMS; k++)
    vsph_claim_num(v, NUMS[k], (double)NAN);
  for (size_t k = 0; k < sizeof WORDS / sizeof *WORDS; k++)
    vsph_claim_str(v, WORDS[k], "%s", "");
  return vsph_report_doc_grade(R, "claims/channel.cavity_ek", v);
}

/* The words of the claim cavity_ek on the runs' last times, as the list
 * prints them (one figure where both ends print alike). */
static void cavity_ek_hist(struct vsph_claim_vals *v, int measured, double t_lo,
                           double t_hi) {
  char t0[32], t1[32];
  snprintf(t0, sizeof t0, "%.3g", t_lo);
  snprintf(t1, sizeof t1, "%.3g", t_hi);
  if (!measured)
    vsph_claim_str(v, "hist", "-");
  else if (!strcmp(t0, t1))
    vsph_claim_str(v, "hist", "%s", t0);
  else
    vsph_claim_str(v, "hist", "%s-%s", t0, t1);
}

/* Basa et al.'s Fig. 9: every model under-predicts the cavity's E_k at
 * Re 1000, against the finite-volume E_k history (reports/fvref.h): each
 * run's whole history from t = 1 s (after the lid's start) to its end or
 * stop over the finite volume's, beside the finite volume's own error
 * (the larger of its Richardson remainder and its last grid difference,
 * relative); the ratio at each run's last time in the text. */
static int cavity_ek_claim(struct vsph_report *R,
                           const struct vsph_report_channel_cavity *c,
                           struct vsph_claim_vals *v) {
  const struct vsph_fvref_cavity *fv = &R->fv->cav[1];
  vsph_claim_clear(v);
  vsph_claim_num(v, "fv_read", fv->ok);
  if (!fv->ok) return cavity_ek_none(R, v);
  int q[NCAV];
  const size_t n = cavity_re1000(R, q);
  const struct vsph_fvref_cavgrid *fg = &fv->g[VSPH_FVREF_CAV_GRIDS - 1];
  const double band = fmax(isfinite(fv->remainder) ? fv->remainder : 0,
                           fv->dE[VSPH_FVREF_CAV_GRIDS - 2]) /
                      fg->E[fg->nrow - 1];
  /* the runs of the quick plan, then those the FULL plan adds (a word
   * each, to keep within a word's length) */
  char list[2][1024] = {"", ""};
  size_t m[2] = {0, 0};
  /* each run's E_k over the finite volume's from 1 s (after the lid's
   * start), and its groups: E's (bit 0), D's (1), at the paper's 50 x 50
   * (2) */
  struct vsph_series_ratio hs[NCAV];
  int group[NCAV];
  for (size_t k = 0; k < n; k++) {
    const struct vsph_jobs_run *r = &c->cav[q[k]];
    struct vsph_series_ratio *hr = &hs[k];
    int st = vsph_series_ratio_history(r->t, r->Ek, r->nrow, fg->t, fg->E,
                                       fg->nrow, 1.0, fv->t_end, 1 - band, hr);
    if (st) return st;
    group[k] = (q[k] == CAV_E1000 || q[k] == CAV_E1000_50) |
               (q[k] == CAV_P000_1000) << 1 |
               (CAV[q[k]].res == CAV_PAPER_RES) << 2;
    const int seen = hr->seen, below = hr->below;
    const double t = hr->t_last, ratio = hr->last;
    const int h = q[k] >= CAV_QUICK;
    if (m[h] < sizeof list[h])
      m[h] += (size_t)snprintf(
          list[h] + m[h], sizeof list[h] - m[h], "%s %s %.3f at %.3g s%s%s",
          k ? ";" : "", CAV[q[k]].fv + 5, ratio, t, r->ok ? "" : " (stopped)",
          !seen   ? " (stopped before 1 s)"
          : below ? ""
                  : " (not below throughout)");
  }
  vsph_claim_num(v, "fv_n", fv->n[VSPH_FVREF_CAV_GRIDS - 1]);
  vsph_claim_num(v, "band", band);
  vsph_claim_str(v, "quick_runs", "%s", list[0]);
  vsph_claim_str(v, "full_runs", "%s", list[1]);
  struct vsph_measures_ratios g;
  vsph_measures_ratios(hs, group, n, &g);
  vsph_claim_num(v, "peak", g.peak);
  vsph_claim_num(v, "under", g.under);
  vsph_claim_num(v, "measured", g.measured);
  vsph_claim_num(v, "n", (double)n);
  vsph_claim_num(v, "lo", g.lo);
  vsph_claim_num(v, "hi", g.hi);
  vsph_claim_num(v, "e_seen", g.seen_in[0] > 0);
  vsph_claim_num(v, "d_seen", g.seen_in[1] > 0);
  vsph_claim_num(v, "n_paper", g.seen_in[2]);
  cavity_ek_hist(v, g.measured, g.t_lo, g.t_hi);
  return vsph_report_doc_grade(R, "claims/channel.cavity_ek", v);
}

int vsph_report_channel_cavity_claims(
    struct vsph_report *R, const struct vsph_report_channel_cavity *c,
    struct vsph_claim_vals *v) {
  int st = cavity_claims(R, c, v);
  if (!st) st = cavity_ek_claim(R, c, v);
  return st;
}
