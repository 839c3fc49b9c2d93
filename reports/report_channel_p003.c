/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
/* Section 11 of the report, Vukčević et al.'s own set-up (their sec. 3):
 * Morris' Poiseuille and Couette to 1 s with their two-pass form (B) and
 * with E beside it, then with ghost walls; their time step against the
 * sound speed; the tables, their readings and their claims
 * (report_channel.h). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../analysis/references.h"
#include "../common/status.h"
#include "../io/csv.h"
#include "measures.h"
#include "report_channel.h"

/* Vukcevic et al.'s own set-up (their sec. 3): summation density, p =
 * c^2 rho, XSPH 0.3, leapfrog, fixed wall particles, the cubic spline at
 * h = 2.2 dx, 40 rows; Morris' Poiseuille and Couette to 1 s, with their
 * Liu two-pass form (B) and with E beside it */
/* (their printed sound speed, c^2 = 5e-12 m^2/s^2: Mach 11, the pressure
 * nearly inert, a misprint suspected; the sweep below tries others; one
 * snapshot, at the end: its profile.csv, whose rows the claims measure) */
#define P003_SET                                                       \
  "Solver:kernel=cubic", "Solver:hdx=2.2", "Solver:density=summation", \
      "Solver:eos=isothermal", "Solver:integrator=leapfrog",           \
      "Solver:xsph=0.3", "Scene:walls=fixed", "Solver:snapshots=1",    \
      "Scene:c0=2.236e-6"
#define P003_POIS_SET                                             \
  P003_SET, "Scene:W=1e-3", "Scene:length=5e-4", "Scene:nu=1e-6", \
      "Scene:rho0=1000", "Scene:Re=0.0125"
static const char *const P003_POIS[] = {P003_POIS_SET, NULL};
static const char *const P003_COU[] = {P003_SET, NULL};
/* the same with the ghost walls of the other channel runs in place of the
 * fixed particles (the last setting wins): what the walls do */
static const char *const P003_GHOST[] = {P003_POIS_SET, "Scene:walls=linear",
                                         NULL};
/* Morris' v0 (both flows): the scale of the profiles' zigzag */
#define P003_V0 2.5e-5
/* A finished run is non-physical when its transverse agitation v_rms
 * (energy.csv, over v0) reaches v0 itself: transverse speeds on the scale
 * of the flow's own peak, which no laminar channel flow at Re 0.0125 has
 * (the physical value is 0; a run's particle noise is a few per cent) */
#define P003_AGITATED 1.0

/* The runs on their set-up, 40 rows to 1 s, by the names the readings and
 * the claims give them: the table's words (flow | form) and, for the four
 * on the paper's walls, the claim's word for the zigzag of its rows (the
 * claim p003_osc). The claim p003 names each w0, w1, ... in this order. */
enum { P3_POIS_B, P3_POIS_E, P3_COU_B, P3_COU_E, P3_GHOST_E, P3_GHOST_B, NP3 };
static const struct {
  const char *scene, *visc;
  const char *const *xtra; /* settings, NULL-ended */
  const char *tag;         /* folder suffix */
  const char *label;       /* the table's "flow | formulation" */
  const char *zkey;        /* the zigzag's word in the claim (NULL: none) */
  const char *ekey;        /* its RMS error at 1 s, a measure of the claim */
} P3[NP3] = {
    [P3_POIS_B] = {.scene = "poiseuille",
                   .visc = "twopass",
                   .xtra = P003_POIS,
                   .tag = "p003",
                   .label = "Poiseuille | B (their form)",
                   .zkey = "zpb",
                   .ekey = "e_pb"},
    [P3_POIS_E] = {.scene = "poiseuille",
                   .visc = "meaf",
                   .xtra = P003_POIS,
                   .tag = "p003",
                   .label = "Poiseuille | E (MEAF)",
                   .zkey = "zpe",
                   .ekey = "e_pe"},
    [P3_COU_B] = {.scene = "couette",
                  .visc = "twopass",
                  .xtra = P003_COU,
                  .tag = "p003",
                  .label = "Couette | B (their form)",
                  .zkey = "zcb",
                  .ekey = "e_cb"},
    [P3_COU_E] = {.scene = "couette",
                  .visc = "meaf",
                  .xtra = P003_COU,
                  .tag = "p003",
                  .label = "Couette | E (MEAF)",
                  .zkey = "zce",
                  .ekey = "e_ce"},
    [P3_GHOST_E] = {.scene = "poiseuille",
                    .visc = "meaf",
                    .xtra = P003_GHOST,
                    .tag = "p003ghost",
                    .label = "Poiseuille, ghost walls | E (MEAF)",
                    .ekey = "e_ge"},
    [P3_GHOST_B] = {.scene = "poiseuille",
                    .visc = "twopass",
                    .xtra = P003_GHOST,
                    .tag = "p003ghost",
                    .label = "Poiseuille, ghost walls | B (their form)",
                    .ekey = "e_gb"},
};

/* Vukcevic et al.'s time step against the sound speed (their abstract:
 * "some combinations ... non-physical"; they fix dt = 1e-6 s): their
 * Poiseuille with B over c = their printed 2.236e-6 m/s, 10 v0, Morris et
 * al.'s criterion 4.5e-3 (with 1 % density variation), 0.1 and 1 m/s,
 * each at a fixed dt of 4e-4 s (Morris' viscous bound 0.125 h^2/nu is
 * 3.8e-4 s; the leapfrog's own is a quarter of it), 1e-4 s and, FULL
 * only, 2e-5 s; to their 1 s (the runs at 10 v0 and Morris' c agitate
 * only after 0.5 s). A run per c (the rows) and dt (the columns): its c
 * and dt, its settings and its folder suffix, all from the two numbers as
 * written here. */
#define NSWC 5
#define NSWD 3
#define SW_TEND 1.0 /* s: every run of the sweep */
struct sw_run {
  double c0, dt; /* m/s, s */
  const char *xtra[18];
  const char *tag;
};
#define SW_RUN(cs, dts)                                          \
  {                                                              \
    .c0 = cs, .dt = dts,                                         \
    .xtra = {P003_POIS_SET, "Scene:c0=" #cs, "Solver:dt=" #dts}, \
    .tag = "p003-c" #cs "-dt" #dts                               \
  }
#define SW_ROW(cs) \
  { SW_RUN(cs, 4e-4), SW_RUN(cs, 1e-4), SW_RUN(cs, 2e-5) }
static const struct sw_run SW[NSWC][NSWD] = {
    SW_ROW(2.236e-6), SW_ROW(2.5e-4), SW_ROW(4.5e-3), SW_ROW(0.1), SW_ROW(1)};
#undef SW_ROW
#undef SW_RUN
#undef P003_POIS_SET
#undef P003_SET

/* the time steps run: quick the two larger (2e-5 s to 1 s is 50 000
 * steps) */
#define SW_ND(R) ((R)->runs.full ? NSWD : NSWD - 1)

/* The runs loaded, and what their profiles measure. */
struct vsph_report_channel_p003 {
  struct vsph_jobs_run p3[NP3];        /* Vukcevic et al.'s set-up */
  struct vsph_jobs_run sw[NSWC][NSWD]; /* its dt against c */
  int nd;                              /* the sweep's time steps run (SW_ND) */
  /* the zigzag of each finished run's last profile (NaN: none), and its
   * slowest row's u over v0 (negative: a row flowing backwards) */
  struct vsph_references_zigzag z3[NP3], zsw[NSWC][NSWD];
  double back3[NP3], backsw[NSWC][NSWD];
};

/* Every run of this file, in the plan's order: into @p s (NP3 + NSWC *
 * NSWD at most) and, where @p p is not NULL, where each is loaded to. */
static size_t specs(const struct vsph_report *R,
                    struct vsph_report_channel_p003 *p,
                    struct vsph_jobs_spec *s, struct vsph_jobs_run **to) {
  size_t k = 0;
  for (int q = 0; q < NP3; q++) {
    if (p) to[k] = &p->p3[q];
    s[k++] = (struct vsph_jobs_spec){.scene = P3[q].scene,
                                     .visc = P3[q].visc,
                                     .res = 40,
                                     .t_end = 1.0,
                                     .extra = P3[q].xtra,
                                     .tag = P3[q].tag};
  }
  for (int a = 0; a < NSWC; a++)
    for (int b = 0; b < SW_ND(R); b++) {
      if (p) to[k] = &p->sw[a][b];
      s[k++] = (struct vsph_jobs_spec){.scene = "poiseuille",
                                       .visc = "twopass",
                                       .res = 40,
                                       .t_end = SW_TEND,
                                       .extra = SW[a][b].xtra,
                                       .tag = SW[a][b].tag};
    }
  return k;
}
#define NSPECS (NP3 + NSWC * NSWD)

int vsph_report_channel_p003_plan(struct vsph_report *R) {
  struct vsph_jobs_spec s[NSPECS];
  const size_t n = specs(R, NULL, s, NULL);
  int st = VSPH_OK;
  for (size_t k = 0; k < n && !st; k++)
    st = vsph_jobs_plan_run(&R->runs.jobs, &s[k]);
  return st;
}

/* The zigzag of a finished channel run's last profile (its profile.csv's
 * last snapshot, the end), over Morris' v0, and its slowest row's u over
 * v0 (*back); n = 0 and NaN for a run stopped early. */
static int profile(struct vsph_report *R, const struct vsph_jobs_run *r,
                   struct vsph_references_zigzag *z, double *back) {
  *z =
      (struct vsph_references_zigzag){(double)NAN, (double)NAN, (double)NAN, 0};
  *back = (double)NAN;
  if (!r->ok) return VSPH_OK;
  struct vsph_csv *t =
      vsph_jobs_store_table(&R->runs.jobs, r->dir, "profile.csv");
  const double *tt = t ? vsph_csv_column(t, "t") : NULL,
               *y = t ? vsph_csv_column(t, "y") : NULL,
               *u = t ? vsph_csv_column(t, "u") : NULL,
               *U = t ? vsph_csv_column(t, "u_ref") : NULL;
  if (!tt || !y || !u || !U || t->nrow == 0) {
    vsph_csv_free(t);
    VSPH_FAIL(VSPH_EIO, "cannot read the profile of %s/profile.csv", r->dir);
  }
  size_t k0 = t->nrow; /* the last snapshot's rows */
  while (k0 > 0 && tt[k0 - 1] == tt[t->nrow - 1]) k0--;
  vsph_references_profile_zigzag(y + k0, u + k0, U + k0, t->nrow - k0, P003_V0,
                                 z);
  for (size_t k = k0; k < t->nrow; k++)
    if (isfinite(u[k]) && !(u[k] / P003_V0 >= *back)) *back = u[k] / P003_V0;
  vsph_csv_free(t);
  return VSPH_OK;
}

int vsph_report_channel_p003_load(struct vsph_report *R,
                                  struct vsph_report_channel_p003 **out) {
  struct vsph_report_channel_p003 *p = calloc(1, sizeof *p);
  *out = p;
  if (!p) VSPH_FAIL(VSPH_ENOMEM, "cannot load Vukcevic et al.'s runs");
  struct vsph_jobs_spec s[NSPECS];
  struct vsph_jobs_run *to[NSPECS];
  const size_t n = specs(R, p, s, to);
  int st = VSPH_OK;
  for (size_t k = 0; k < n && !st; k++)
    st = vsph_report_runs_get(&R->runs, &s[k], to[k]);
  p->nd = SW_ND(R);
  for (int q = 0; q < NP3 && !st; q++)
    st = profile(R, &p->p3[q], &p->z3[q], &p->back3[q]);
  for (int a = 0; a < NSWC && !st; a++)
    for (int b = 0; b < p->nd && !st; b++)
      st = profile(R, &p->sw[a][b], &p->zsw[a][b], &p->backsw[a][b]);
  return st;
}

void vsph_report_channel_p003_free(struct vsph_report_channel_p003 *p) {
  if (!p) return;
  for (int q = 0; q < NP3; q++) vsph_report_runs_free(&p->p3[q]);
  for (int a = 0; a < NSWC; a++)
    for (int b = 0; b < NSWD; b++) vsph_report_runs_free(&p->sw[a][b]);
  free(p);
}

/* A zigzag cell: RMS and largest in % of v0, with the largest's row
 * (y over W: both flows have W = 1 mm) */
static void zig_cell(FILE *md, const struct vsph_references_zigzag *z) {
  if (z->n)
    fprintf(md, " %.2f / %.2f (y = %.2f W) |", 100 * z->rms, 100 * z->max,
            z->y_max / 1e-3);
  else
    fprintf(md, " - |");
}

/* The rows of Vukcevic et al.'s own set-up at t = 1 s. */
static void p003_rows(struct vsph_report *R,
                      const struct vsph_report_channel_p003 *p) {
  for (int q = 0; q < NP3; q++) {
    const struct vsph_jobs_run *r = &p->p3[q];
    fprintf(R->md, "| %s |", P3[q].label);
    vsph_report_channel_stop_cell(R->md, r);
    vsph_report_channel_cell(R->md, vsph_report_channel_at(r, "u_err", 0.5),
                             100);
    vsph_report_channel_cell(R->md, vsph_report_channel_final(r, "u_err"), 100);
    zig_cell(R->md, &p->z3[q]);
    vsph_report_channel_cell(R->md, p->back3[q], 1.0);
    vsph_report_channel_cell(R->md, vsph_report_channel_final(r, "v_rms"), 100);
    fprintf(R->md, " %zu | %.1f |\n", r->steps, r->wall_s);
  }
  fprintf(R->md, "\n");
}

/* How a sweep run ended: 's' stopped by the solver, 'a' ran to its end
 * with its transverse agitation at the flow's own scale (P003_AGITATED),
 * 'r' ran to its end without. */
static char sweep_outcome(const struct vsph_jobs_run *r) {
  if (!r->ok) return 's';
  return vsph_report_channel_last(r, "v_rms") >= P003_AGITATED ? 'a' : 'r';
}

/* The rows of the time step against the sound speed: per c, per dt the
 * errors, or the stop. */
static void sweep_rows(struct vsph_report *R,
                       const struct vsph_report_channel_p003 *p) {
  const double h = 2.2 * 2.5e-5; /* 2.2 dx, dx = W/40 */
  fprintf(R->md, "| c (m/s) | c/v0 |");
  for (int b = 0; b < p->nd; b++) fprintf(R->md, " dt = %.0e s |", SW[0][b].dt);
  fprintf(R->md, "\n|---:|---:|");
  for (int b = 0; b < p->nd; b++) fprintf(R->md, ":---|");
  fprintf(R->md, "\n");
  for (int a = 0; a < NSWC; a++) {
    const double c0 = SW[a][0].c0, m = c0 / P003_V0;
    fprintf(R->md, m < 100 ? "| %g | %.3g |" : "| %g | %.0f |", c0, m);
    for (int b = 0; b < p->nd; b++) {
      const struct vsph_jobs_run *r = &p->sw[a][b];
      char why[200];
      fprintf(R->md, " c dt/h %.2g: ", SW[a][b].c0 * SW[a][b].dt / h);
      if (r->ok)
        fprintf(R->md, "%serror %.3g %%, zigzag %.2f %%, v_rms %.3g %% |",
                sweep_outcome(r) == 'a' ? "**agitated**: " : "",
                100 * vsph_report_channel_last(r, "u_err"),
                100 * p->zsw[a][b].rms,
                100 * vsph_report_channel_last(r, "v_rms"));
      else
        fprintf(R->md, "**stopped** at t = %.3g s (%s) |", r->t_unstable,
                vsph_report_channel_stop_words(r, why, sizeof why));
    }
    fprintf(R->md, "\n");
  }
  fprintf(R->md, "\n");
}

/* The sweep's figures the reading and the claims share. */
_Static_assert(NSWC <= VSPH_MEASURES_SWEEP_MAXC &&
                   NSWD <= VSPH_MEASURES_SWEEP_MAXD,
               "the sweep fits the measures' arrays");

/* The sweep's figures (reports/measures.h): each run's outcome, final
 * error and stop, and the smallest dt's zigzag, per c and dt. */
static void sweep_figures(const struct vsph_report_channel_p003 *p,
                          struct vsph_measures_sweep *w) {
  struct vsph_measures_sweep_in in = {.nc = NSWC, .nd = p->nd};
  for (int a = 0; a < NSWC; a++) {
    for (int b = 0; b < p->nd; b++) {
      in.out[a][b] = sweep_outcome(&p->sw[a][b]);
      in.err[a][b] = vsph_report_channel_last(&p->sw[a][b], "u_err");
      in.t_stop[a][b] = p->sw[a][b].t_unstable;
    }
    in.zig[a] = p->zsw[a][p->nd - 1].rms;
  }
  vsph_measures_sweep(&in, w); /* within its arrays: asserted above */
}

/* What the sweep's table says (the section's reading and the claim),
 * from its figures @p w (sweep_figures). */
static void sweep_read(const struct vsph_report_channel_p003 *p,
                       const struct vsph_measures_sweep *w, char *buf,
                       size_t len) {
  static const char *const WORD[] = {['r'] = "runs",
                                     ['a'] = "runs but agitates",
                                     ['s'] = "stops",
                                     ['m'] = "ends differently with dt"};
  size_t k = (size_t)snprintf(buf, len,
                              "by t = 1 s, %d of the %d runs are "
                              "non-physical (stopped, or v_rms >= v0):",
                              w->nbad, w->ntot);
  for (int a = 0; a < NSWC && k < len; a++)
    k += (size_t)snprintf(buf + k, len - k, "%s c = %g m/s %s%s", a ? ";" : "",
                          SW[a][0].c0, WORD[(unsigned char)w->out[a]],
                          w->out[a] == 'm' ? "" : " at every dt");
  if (k < len)
    k += (size_t)snprintf(
        buf + k, len - k, "%s",
        w->mixed < 0 ? "; c alone decides at every dt here" : "");
  if (k < len && isfinite(w->acc))
    k += (size_t)snprintf(buf + k, len - k,
                          "; where every dt runs, the error changes by at "
                          "most %.2g %% of itself over dt",
                          100 * w->acc);
  if (k < len && w->alo >= 0 && w->ahi != w->alo)
    k += (size_t)snprintf(buf + k, len - k,
                          "; the zigzag (dt = %g s) is %.2f %% at c = %g m/s "
                          "and %.2f %% at %g m/s",
                          SW[0][p->nd - 1].dt, 100 * w->zlo, SW[w->alo][0].c0,
                          100 * w->zhi, SW[w->ahi][0].c0);
  if (k < len) snprintf(buf + k, len - k, ".");
}

/* What the P003 rows say, in a sentence or two (the section's reading). */
static void p003_read(const struct vsph_report_channel_p003 *p, char *buf,
                      size_t len) {
  const struct vsph_jobs_run *bp = &p->p3[P3_POIS_B], *ep = &p->p3[P3_POIS_E],
                             *eg = &p->p3[P3_GHOST_E], *bg = &p->p3[P3_GHOST_B];
  if (!bp->ok || !ep->ok || !eg->ok || !bg->ok) {
    snprintf(buf, len, "a run on this set-up stopped (the table says when).");
    return;
  }
  const double e = vsph_report_channel_last(ep, "u_err"),
               g = vsph_report_channel_last(eg, "u_err");
  const struct vsph_references_zigzag *zb = &p->z3[P3_POIS_B],
                                      *zg = &p->z3[P3_GHOST_B];
  const double ze = p->z3[P3_POIS_E].rms;
  char back[160] = "";
  if (p->back3[P3_POIS_B] < 0)
    snprintf(back, sizeof back, "; its slowest row flows backwards, at %.2f v0",
             p->back3[P3_POIS_B]);
  snprintf(buf, len,
           "E's Poiseuille error is %.2f %% with the fixed particles and "
           "%.2f %% with ghost walls, and its zigzag %.2f %%: %s. B's rows "
           "zigzag by %.2f %% RMS, most at y = %.2f W%s%s; its error %s "
           "from 0.5 s to 1 s. With ghost walls B's error is %.2f %% and "
           "its zigzag %.2f %%: %s.",
           100 * e, 100 * g, 100 * ze,
           ze < 0.2 * e ? "the fixed particles' error is smooth (a slip or a "
                          "tilt, which the zigzag leaves out)"
                        : "much of it is row to row",
           100 * zb->rms, zb->y_max / 1e-3,
           zb->y_max < 0.1e-3 || zb->y_max > 0.9e-3
               ? " (within a tenth of W of a wall)"
               : "",
           back,
           vsph_report_channel_last(bp, "u_err") >
                   1.05 * vsph_report_channel_at(bp, "u_err", 0.5)
               ? "still grows"
               : "holds",
           100 * vsph_report_channel_last(bg, "u_err"), 100 * zg->rms,
           zg->rms > 1e-3 ? "B's rows zigzag beside any wall here, most "
                            "beside the fixed particles"
                          : "the zigzag comes with the fixed particles");
}

int vsph_report_channel_p003_write(struct vsph_report *R,
                                   const struct vsph_report_channel_p003 *p) {
  int st = vsph_report_doc_say(R, "channel.p003_head");
  if (st) return st;
  p003_rows(R, p);
  char t[1536];
  p003_read(p, t, sizeof t);
  vsph_text_set(&R->tv, "p003read", "%s", t);
  if ((st = vsph_report_doc_say(R, "channel.p003_reading"))) return st;
  vsph_text_set(&R->tv, "swdt", "%s",
                p->nd > 2 ? "4e-4 s (Morris' viscous bound 0.125 h²/nu is "
                            "3.8e-4 s; the leapfrog's own a quarter of it), "
                            "1e-4 and 2e-5 s"
                          : "4e-4 s (Morris' viscous bound 0.125 h²/nu is "
                            "3.8e-4 s; the leapfrog's own a quarter of it) "
                            "and 1e-4 s (FULL adds 2e-5 s, 50 000 steps)");
  if ((st = vsph_report_doc_say(R, "channel.sweep_head"))) return st;
  sweep_rows(R, p);
  struct vsph_measures_sweep w;
  sweep_figures(p, &w);
  sweep_read(p, &w, t, sizeof t);
  vsph_text_set(&R->tv, "swread", "%s", t);
  return vsph_report_doc_say(R, "channel.sweep_reading");
}

/* The claims: blocks of reports/claims/channel.md, graded there on the
 * measures and words set below (the grammar: reports/claim.h). */

/* The set-up differences shared by the rows graded on Vukcevic et al.'s
 * set-up */
#define P003_DIFFS                                                          \
  "40 rows at dx/2 from the walls x 20 (the paper: 41 x 21); the "          \
  "leapfrog's mid-step velocity predicted, XSPH's velocity in both drifts " \
  "[reconstructed]; the fixed particles two supports deep, their density "  \
  "summed and their pressure by the same absolute law, the two-pass "       \
  "form's first pass (its strain rate) taken at them too [reconstructed: "  \
  "the paper says none of these]"

/* Vukcevic et al.'s own set-up: Poiseuille and Couette against Morris'
 * series at 1 s. */
static int p003_claim(struct vsph_report *R,
                      const struct vsph_report_channel_p003 *p,
                      struct vsph_claim_vals *v) {
  double e[NP3];
  int ok = 1;
  vsph_claim_clear(v);
  for (int q = 0; q < NP3; q++) { /* a stopped run: when, not an error */
    char key[4];
    snprintf(key, sizeof key, "w%d", q);
    e[q] = p->p3[q].ok ? vsph_report_channel_last(&p->p3[q], "u_err")
                       : (double)NAN;
    ok &= p->p3[q].ok;
    vsph_claim_num(v, P3[q].ekey, e[q]);
    if (p->p3[q].ok)
      vsph_claim_str(v, key, "%.2f %% (0.5 s: %.2f %%)", 100 * e[q],
                     100 * vsph_report_channel_at(&p->p3[q], "u_err", 0.5));
    else
      vsph_claim_str(v, key, "stopped at %.3g s", p->p3[q].t_unstable);
  }
  vsph_claim_str(v, "p003_diffs", "%s", P003_DIFFS);
  vsph_claim_num(v, "all_ok", ok);
  vsph_claim_num(v, "e_pb_half",
                 vsph_report_channel_at(&p->p3[P3_POIS_B], "u_err", 0.5));
  return vsph_report_doc_grade(R, "claims/channel.p003", v);
}

/* Vukcevic et al.'s small oscillations, measured as the rows' zigzag. */
static int p003_osc_claim(struct vsph_report *R,
                          const struct vsph_report_channel_p003 *p,
                          struct vsph_claim_vals *v) {
  const struct vsph_references_zigzag *z = p->z3;
  vsph_claim_clear(v);
  for (int q = 0; q < NP3; q++) { /* the runs on the paper's walls */
    if (!P3[q].zkey) continue;
    char key[16];
    vsph_claim_num(v, P3[q].zkey, z[q].rms);
    snprintf(key, sizeof key, "%s_max", P3[q].zkey);
    vsph_claim_num(v, key, z[q].max);
  }
  vsph_claim_num(v, "zpb_y", z[P3_POIS_B].y_max / 1e-3);
  vsph_claim_num(v, "n_pb", (double)z[P3_POIS_B].n);
  vsph_claim_num(v, "n_pe", (double)z[P3_POIS_E].n);
  vsph_claim_num(v, "n_cb", (double)z[P3_COU_B].n);
  vsph_claim_num(v, "back_p", p->back3[P3_POIS_B]);
  vsph_claim_num(v, "back_c", p->back3[P3_COU_B]);
  vsph_claim_str(v, "p003_diffs", "%s", P003_DIFFS);
  return vsph_report_doc_grade(R, "claims/channel.p003_osc", v);
}

/* The words the sweep's rows share. */
static void sweep_vals(const struct vsph_report_channel_p003 *p,
                       struct vsph_claim_vals *v) {
  vsph_claim_clear(v);
  vsph_claim_str(v, "dt_span", "%s",
                 p->nd > 2 ? "2e-5 to 4e-4" : "1e-4 and 4e-4");
  vsph_claim_str(v, "p003_diffs", "%s", P003_DIFFS);
}

/* The measures of the claim p003_dt on the first c where a smaller dt
 * ends better (@p first; -1: none): its c, whether its smallest dt's run
 * still stops, when, and the larger dts' latest stop there (the block's
 * words say it). */
static void sweep_stab(const struct vsph_report_channel_p003 *p, int first,
                       struct vsph_claim_vals *v) {
  const struct vsph_jobs_run *rb = first >= 0 ? &p->sw[first][p->nd - 1] : NULL;
  double ts[NSWD]; /* the larger dts' stops there, and their latest */
  for (int b = 0; rb && b + 1 < p->nd; b++) ts[b] = p->sw[first][b].t_unstable;
  const double tb = rb ? vsph_measures_largest(ts, (size_t)p->nd - 1, 0.0) : 0;
  vsph_claim_num(v, "stab_c", rb ? SW[first][0].c0 : (double)NAN);
  vsph_claim_num(v, "stab_stops", rb && !rb->ok);
  vsph_claim_num(v, "stab_t", rb ? rb->t_unstable : (double)NAN);
  vsph_claim_num(v, "stab_tmax", rb ? tb : (double)NAN);
  vsph_claim_num(v, "t_end", SW_TEND);
}

/* Vukcevic et al.'s time step against the sound speed. */
static int p003_sweep_claims(struct vsph_report *R,
                             const struct vsph_report_channel_p003 *p,
                             struct vsph_claim_vals *v) {
  static const char *const DT = "claims/channel.p003_dt";
  struct vsph_measures_sweep w;
  sweep_figures(p, &w);
  char read[1024];
  sweep_read(p, &w, read, sizeof read);
  sweep_vals(p, v);
  vsph_claim_str(v, "dts", "%s",
                 p->nd > 2 ? "4e-4, 1e-4 and 2e-5" : "4e-4 and 1e-4");
  vsph_claim_str(v, "read", "%s", read);
  vsph_claim_num(v, "nbad", w.nbad);
  vsph_claim_num(v, "ntot", w.ntot);
  vsph_claim_num(v, "c_mixed", w.mixed >= 0 ? SW[w.mixed][0].c0 : (double)NAN);
  int st = vsph_report_doc_grade(R, "claims/channel.p003_combos", v);
  /* their §5: a smaller dt is "more accurate and more stable" */
  /* lag, the delay the block's rule weighs: the largest over the c
   * before the first that turns (from that c on, it is named first) */
  const int n_lag = w.turn >= 0 ? w.turn : NSWC;
  const double lag = vsph_measures_largest(w.lag, (size_t)n_lag, (double)NAN);
  /* the words name the first c where a smaller dt helps: the first that
   * turns, or one before it that meets the block's rule on lag */
  int first = -1;
  for (int a = 0; a < NSWC && first < 0 && !st; a++) {
    int later = 0; /* the block's own rule 'later' on this c's lag */
    if (a < n_lag) {
      vsph_claim_num(v, "lag", w.lag[a]);
      st = vsph_claim_test_text(DT, vsph_text_get(DT), "later", v, &later);
      later = later == 1;
    }
    if (a == w.turn || later) first = a;
  }
  sweep_vals(p, v);
  sweep_stab(p, first, v);
  vsph_claim_num(v, "acc_change", w.acc);
  vsph_claim_num(v, "rise", w.rise);
  vsph_claim_num(v, "lag", lag);
  vsph_claim_num(v, "turn", w.turn >= 0);
  vsph_claim_num(v, "turn_stop", w.turn >= 0 && !p->sw[w.turn][p->nd - 1].ok);
  vsph_claim_str(v, "dt_run", "%s",
                 p->nd > 2 ? "4e-4 to 2e-5" : "4e-4 and 1e-4");
  if (!st) st = vsph_report_doc_grade(R, DT, v);
  return st;
}

int vsph_report_channel_p003_claims(struct vsph_report *R,
                                    const struct vsph_report_channel_p003 *p,
                                    struct vsph_claim_vals *v) {
  int st = p003_claim(R, p, v);
  if (!st) st = p003_osc_claim(R, p, v);
  if (!st) st = p003_sweep_claims(R, p, v);
  return st;
}
