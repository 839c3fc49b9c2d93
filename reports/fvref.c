/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
/* The committed finite-volume references (reference/data), read and
 * judged: reports/fvref.h. */
#include "fvref.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "../analysis/references.h"
#include "../common/status.h"
#include "../io/csv.h"
#include "../io/files.h"

static const int SQ_N[VSPH_FVREF_SQ_GRIDS] = {40, 80, 160, 320};
/* Each grid's run and its run at half that step (reference/README.md):
 * 40 to 160 cells at the common step, dt A0 = 1/1600, and half of it; 320
 * cells at half the common step and a quarter of it (at the common step,
 * Courant 0.2, the step's error after the 4/3 correction is larger than
 * the grid's: square-n320, read as a check) */
static const char *const SQ_RUN[VSPH_FVREF_SQ_GRIDS] = {
    "square-n40", "square-n80", "square-n160", "square-n320-dt0.5"};
static const char *const SQ_HALF[VSPH_FVREF_SQ_GRIDS] = {
    "square-n40-dt0.5", "square-n80-dt0.5", "square-n160-dt0.5",
    "square-n320-dt0.25"};
static const int CAV_N[VSPH_FVREF_CAV_GRIDS] = {32, 64, 128, 256};
static const double CAV_RE[2] = {100, 1000}, CAV_TEND[2] = {30, 80};

/* 1 when @p path names a file */
static int present(const char *path) {
  struct stat sb;
  return stat(path, &sb) == 0;
}

/* A "key: value" number of the meta file @p path, or @p def. */
static double meta_number(const char *path, const char *key, double def) {
  char *text = vsph_files_slurp(path, NULL);
  if (!text) return def;
  double v = def;
  const size_t k = strlen(key);
  for (char *line = text; line && *line;) {
    if (!strncmp(line, key, k) && line[k] == ':') {
      char *end;
      const double x = strtod(line + k + 1, &end);
      if (end != line + k + 1) v = x;
      break;
    }
    line = strchr(line, '\n');
    if (line) line++;
  }
  free(text);
  return v;
}

/* One square series from DIR/NAME.csv (and NAME.txt); s->ok stays 0 when
 * the file is absent. */
static int read_sq(const char *dir, const char *name, double *t,
                   struct vsph_fvref_sqseries *s) {
  char path[4096];
  snprintf(path, sizeof path, "%s/%s.csv", dir, name);
  s->ok = 0;
  if (!present(path)) return VSPH_OK;
  struct vsph_csv *c = vsph_csv_read(path);
  if (!c) return VSPH_EIO;
  const double *ct = vsph_csv_column(c, "t"), *E = vsph_csv_column(c, "Ek"),
               *dE = vsph_csv_column(c, "dEk_dt"),
               *P = vsph_csv_column(c, "P_visc"),
               *V = vsph_csv_column(c, "volume");
  int st = VSPH_OK;
  if (!ct || !E || !dE || !P || !V || c->nrow != VSPH_FVREF_SQ_ROWS) {
    vsph_csv_free(c);
    VSPH_FAIL(VSPH_EIO,
              "%s: not a square reference (t, Ek, dEk_dt, P_visc, volume; "
              "%d rows)",
              path, VSPH_FVREF_SQ_ROWS);
  }
  for (size_t k = 0; k < c->nrow && !st; k++) {
    /* the committed sampling, t A0 = k / 200 */
    if (!(fabs(ct[k] - (double)k / 200.0) < 1e-9) || !isfinite(E[k]) ||
        !isfinite(dE[k]) || !isfinite(P[k]) || !isfinite(V[k]))
      st = VSPH_EIO;
    t[k] = (double)k / 200.0;
    s->E[k] = E[k], s->dE[k] = dE[k], s->P[k] = P[k], s->vol[k] = V[k];
  }
  vsph_csv_free(c);
  if (st)
    VSPH_FAIL(VSPH_EIO,
              "%s: a time off the 0.005 sampling or a value not "
              "finite",
              path);
  snprintf(path, sizeof path, "%s/%s.txt", dir, name);
  s->wall_s = meta_number(path, "wall_s", NAN);
  s->steps = (long)meta_number(path, "steps", -1);
  s->procs = (int)meta_number(path, "processes", 1);
  s->ok = 1;
  return VSPH_OK;
}

/* max over the rows of |a/a0 - b/b0| */
static double maxdiff(const struct vsph_fvref_sqseries *a,
                      const struct vsph_fvref_sqseries *b) {
  if (!a->ok || !b->ok) return NAN;
  double m = 0;
  for (size_t k = 0; k < VSPH_FVREF_SQ_ROWS; k++)
    m = fmax(m, fabs(a->E[k] / a->E[0] - b->E[k] / b->E[0]));
  return m;
}

/* What is known exactly of a square series on n cells per L (the
 * set-up of reference/square/run: rho = 1, mu = 0.05, A0 = 1, L = 1):
 * E_k(0) over (rho A0^2 L^4/12)(1 - (dx/L)^2), and P(0) over
 * -4 mu A0^2 L^2. */
static double e0_ratio(const struct vsph_fvref_sqseries *q, double n) {
  return q->E[0] / ((1 - 1 / (n * n)) / 12.0);
}
static double p0_ratio(const struct vsph_fvref_sqseries *q) {
  return q->P[0] / (-4 * 0.05);
}

static int read_square(const char *dir, struct vsph_fvref_square *s) {
  int st = VSPH_OK;
  int all = 1;
  for (int g = 0; g < VSPH_FVREF_SQ_GRIDS && !st; g++) {
    s->n[g] = SQ_N[g];
    st = read_sq(dir, SQ_RUN[g], s->t, &s->g[g]);
    if (!st) st = read_sq(dir, SQ_HALF[g], s->t, &s->half[g]);
    all &= s->g[g].ok && s->half[g].ok;
  }
  if (!st) st = read_sq(dir, "square-n320", s->t, &s->co2);
  if (!st) st = read_sq(dir, "square-n80-ratio100", s->t, &s->r100);
  if (!st) st = read_sq(dir, "square-n80-ratio10000", s->t, &s->r10000);
  if (!st) st = read_sq(dir, "square-n80-wide", s->t, &s->wide);
  /* the ladder and every check beside it, or nothing: a band without
   * one of its shares would be narrower than measured */
  all &= s->co2.ok && s->r100.ok && s->r10000.ok && s->wide.ok;
  if (st || !all) return st;
  for (int g = 0; g < VSPH_FVREF_SQ_GRIDS; g++) {
    const struct vsph_fvref_sqseries *q = &s->g[g];
    s->e0_ratio[g] = e0_ratio(q, SQ_N[g]);
    s->p0_ratio[g] = p0_ratio(q);
    s->share[g] = 1 - q->E[VSPH_FVREF_SQ_ROWS - 1] / q->E[0];
  }
  /* the step's share: every grid runs the same step, so the Courant
   * number doubles with the grid, and the outer correctors' splitting
   * error with it. d_g(t), the difference from half the step, is measured
   * on every grid. Each grid is corrected as for an error of second order
   * in the step (4/3 d: the order measured by halving the Courant number
   * twice at 40 cells, 1.9, reference/README.md); the correction's
   * uncertainty, up to a first-order error's 2 d, goes into the band. */
  const struct vsph_fvref_sqseries *half = s->half;
  double d[VSPH_FVREF_SQ_LADDER][VSPH_FVREF_SQ_ROWS];
  for (int g = 0; g < VSPH_FVREF_SQ_LADDER; g++) {
    s->time_err[g] = 0;
    for (size_t k = 0; k < VSPH_FVREF_SQ_ROWS; k++) {
      d[g][k] = s->g[g].E[k] / s->g[g].E[0] - half[g].E[k] / half[g].E[0];
      s->time_err[g] = fmax(s->time_err[g], fabs(d[g][k]));
    }
  }
  for (int g = 0; g + 1 < VSPH_FVREF_SQ_LADDER; g++)
    s->time_grow[g] = s->time_err[g + 1] / s->time_err[g];
  struct vsph_series_rung rung[VSPH_FVREF_SQ_LADDER];
  for (int g = 0; g < VSPH_FVREF_SQ_GRIDS; g++) {
    for (size_t k = 0; k < VSPH_FVREF_SQ_ROWS; k++)
      s->Ec[g][k] = s->g[g].E[k] / s->g[g].E[0] -
                    (g < VSPH_FVREF_SQ_LADDER ? 4.0 / 3.0 * d[g][k] : 0.0);
    if (g < VSPH_FVREF_SQ_LADDER)
      rung[g] = (struct vsph_series_rung){s->t, s->Ec[g], VSPH_FVREF_SQ_ROWS,
                                          1.0 / SQ_N[g]};
  }
  if ((st = vsph_series_selfconv(rung, VSPH_FVREF_SQ_LADDER, &s->sc)))
    VSPH_FAIL(st, "the square's finite-volume ladder in %s", dir);
  s->air_err = maxdiff(&s->g[1], &s->r10000);
  s->air_err100 = maxdiff(&s->r100, &s->g[1]);
  s->dom_err = maxdiff(&s->wide, &s->g[1]);
  /* the band: the ladder's remainder, the step correction's uncertainty
   * at the finest grid, the air's and the far sides' shares, added (NaN where
   * one is not measured: nothing is then graded against it) */
  s->band = s->sc.remainder +
            2.0 / 3.0 * s->time_err[VSPH_FVREF_SQ_LADDER - 1] + s->air_err +
            s->dom_err;
  const struct vsph_fvref_sqseries *f = &half[VSPH_FVREF_SQ_LADDER - 1];
  const struct vsph_fvref_sqseries *f4 = &s->co2;
  s->budget = s->budget_full = 0;
  for (size_t k = 0; k < VSPH_FVREF_SQ_ROWS; k++) {
    if (s->t[k] >= 0.05 - 1e-12) {
      s->budget = fmax(s->budget, fabs(f->dE[k] - f->P[k]) / fabs(f->P[k]));
      s->budget_full =
          fmax(s->budget_full, fabs(f4->dE[k] - f4->P[k]) / fabs(f4->P[k]));
    }
    /* Richardson at the observed order of the largest differences (first
     * order when it is not measured) */
    const double p = isfinite(s->sc.order_max) && s->sc.order_max > 0
                         ? s->sc.order_max
                         : 1.0;
    const double ef = s->Ec[VSPH_FVREF_SQ_LADDER - 1][k],
                 ec = s->Ec[VSPH_FVREF_SQ_LADDER - 2][k];
    s->Ex[k] = ef + (ef - ec) / (pow(2.0, p) - 1);
  }
  s->ok = 1;
  return VSPH_OK;
}

/* One cavity grid: DIR/cavity-reRE-nN-ek.csv, -centreline.csv, .txt */
static int read_cavgrid(const char *dir, int re, int n, double t_end,
                        struct vsph_fvref_cavgrid *g) {
  char path[4096];
  g->ok = 0;
  snprintf(path, sizeof path, "%s/cavity-re%d-n%d-ek.csv", dir, re, n);
  if (!present(path)) return VSPH_OK;
  struct vsph_csv *c = vsph_csv_read(path);
  if (!c) return VSPH_EIO;
  const double *t = vsph_csv_column(c, "t"), *E = vsph_csv_column(c, "Ek");
  const size_t want = (size_t)(t_end * 10 + 0.5) + 1;
  int bad = !t || !E || c->nrow != want || want > VSPH_FVREF_CAV_ROWS;
  for (size_t k = 0; !bad && k < c->nrow; k++) {
    bad = !(fabs(t[k] - (double)k / 10.0) < 1e-9) || !(E[k] >= 0);
    g->t[k] = (double)k / 10.0;
    g->E[k] = E[k];
  }
  vsph_csv_free(c);
  if (bad)
    VSPH_FAIL(VSPH_EIO,
              "%s: not a cavity E_k series (t, Ek every 0.1 s to %g s)", path,
              t_end);
  g->nrow = want;
  snprintf(path, sizeof path, "%s/cavity-re%d-n%d-centreline.csv", dir, re, n);
  if (!(c = vsph_csv_read(path))) return VSPH_EIO;
  const double *co = vsph_csv_column(c, "coord"),
               *va = vsph_csv_column(c, "value"),
               *gh = vsph_csv_column(c, "ghia");
  bad = !co || !va || !gh || c->nrow != 2 * VSPH_FVREF_GHIA;
  double s2 = 0, mx = 0;
  for (size_t k = 0; !bad && k < 2 * VSPH_FVREF_GHIA; k++) {
    const size_t i = k % VSPH_FVREF_GHIA;
    const int line = k >= VSPH_FVREF_GHIA;
    bad = !isfinite(co[k]) || !isfinite(va[k]) || !isfinite(gh[k]);
    /* the file lists u_x(y) then u_y(x), each from the coordinate 1 down */
    if (!bad && i > 0) bad = !(co[k] < co[k - 1]);
    (line ? g->v : g->u)[i] = va[k];
    (line ? g->gv : g->gu)[i] = gh[k];
    (line ? g->xv : g->yu)[i] = co[k];
    if (i > 0 && i < VSPH_FVREF_GHIA - 1) { /* interior points */
      const double d = fabs(va[k] - gh[k]);
      s2 += d * d;
      mx = fmax(mx, d);
    }
  }
  vsph_csv_free(c);
  if (bad)
    VSPH_FAIL(VSPH_EIO,
              "%s: not a centreline file (line, coord, value, ghia; %d + %d "
              "rows, each line from the coordinate 1 down)",
              path, VSPH_FVREF_GHIA, VSPH_FVREF_GHIA);
  g->ghia_rms = sqrt(s2 / (2.0 * (VSPH_FVREF_GHIA - 2)));
  g->ghia_max = mx;
  snprintf(path, sizeof path, "%s/cavity-re%d-n%d.txt", dir, re, n);
  g->wall_s = meta_number(path, "wall_s", NAN);
  g->steps = (long)meta_number(path, "steps_run", -1);
  g->ok = 1;
  return VSPH_OK;
}

static int read_cavity(const char *dir, int which,
                       struct vsph_fvref_cavity *c) {
  c->Re = CAV_RE[which];
  c->t_end = CAV_TEND[which];
  int st = VSPH_OK, all = 1;
  for (int g = 0; g < VSPH_FVREF_CAV_GRIDS && !st; g++) {
    c->n[g] = CAV_N[g];
    st = read_cavgrid(dir, (int)c->Re, CAV_N[g], c->t_end, &c->g[g]);
    all &= c->g[g].ok;
  }
  if (st || !all) return st;
  for (int g = 0; g + 1 < VSPH_FVREF_CAV_GRIDS; g++)
    c->dE[g] =
        fabs(c->g[g + 1].E[c->g[g + 1].nrow - 1] - c->g[g].E[c->g[g].nrow - 1]);
  const int m = VSPH_FVREF_CAV_GRIDS - 2;
  c->order = vsph_series_order(c->dE[m - 1], c->dE[m], 2, 2);
  c->remainder = isfinite(c->order) && c->order > 0
                     ? c->dE[m] / (pow(2.0, c->order) - 1)
                     : (double)NAN;
  c->ok = 1;
  return VSPH_OK;
}

int vsph_fvref_read(const char *dir, struct vsph_fvref *fv) {
  memset(fv, 0, sizeof *fv);
  fv->dir = dir;
  if (!dir) return VSPH_OK;
  int st = read_square(dir, &fv->sq);
  for (int w = 0; w < 2 && !st; w++) st = read_cavity(dir, w, &fv->cav[w]);
  return st;
}

double vsph_fvref_square_at(const struct vsph_fvref_square *s, double t) {
  if (!s->ok) return NAN;
  return vsph_series_interp(s->t, s->Ec[VSPH_FVREF_SQ_LADDER - 1],
                            VSPH_FVREF_SQ_ROWS, t);
}

double vsph_fvref_cavity_at(const struct vsph_fvref_cavity *c, double t) {
  if (!c->ok) return NAN;
  const struct vsph_fvref_cavgrid *f = &c->g[VSPH_FVREF_CAV_GRIDS - 1];
  return vsph_series_interp(f->t, f->E, f->nrow, t);
}

/* The index of coordinate @p c in Ghia's line (0: u on x = 1/2, its y;
 * 1: v on y = 1/2, its x), or -1 (the files print 4 decimals, as Ghia). */
static int ghia_index(const struct vsph_references_ghia *g, int line,
                      double c) {
  const double *p = line ? g->x : g->y;
  for (size_t i = 0; i < g->n; i++)
    if (fabs(p[i] - c) < 5e-5) return (int)i;
  return -1;
}

/* Count a failure, and record it in @p why when it is the first there. */
#define FVREF_FAIL(...)                                        \
  do {                                                         \
    if (!bad++ && n && !why[0]) snprintf(why, n, __VA_ARGS__); \
  } while (0)

/* The square's files against what is known of them exactly: the number of
 * failures (the first said in @p why, unless it holds one already). */
static int check_square(const struct vsph_fvref_square *s, char *why,
                        size_t n) {
  int bad = 0;
  {
    /* every run of the ladder, each at half its step, and the 320-cell
     * run at the common step */
    const struct vsph_fvref_sqseries *runs[2 * VSPH_FVREF_SQ_GRIDS + 1];
    int ncells[2 * VSPH_FVREF_SQ_GRIDS + 1];
    for (int g = 0; g < VSPH_FVREF_SQ_GRIDS; g++) {
      runs[2 * g] = &s->g[g], runs[2 * g + 1] = &s->half[g];
      ncells[2 * g] = ncells[2 * g + 1] = s->n[g];
    }
    runs[2 * VSPH_FVREF_SQ_GRIDS] = &s->co2;
    ncells[2 * VSPH_FVREF_SQ_GRIDS] = s->n[VSPH_FVREF_SQ_GRIDS - 1];
    for (int r = 0; r < 2 * VSPH_FVREF_SQ_GRIDS + 1; r++) {
      const struct vsph_fvref_sqseries *q = runs[r];
      const int nc = ncells[r];
      const double e0 = e0_ratio(q, nc), p0 = p0_ratio(q);
      /* E_k(0): the initial field sampled at the cell centres and summed
       * over the cells of the square (aligned with the grid) is exactly
       * (rho A0^2 L^4/12)(1 - (dx/L)^2); written with 13 digits, so 1e-10
       * is rounding */
      if (!(fabs(e0 - 1) <= 1e-10))
        FVREF_FAIL(
            "square, %d cells: E_k(0) %.12e is not (6.42)'s energy "
            "on its cells (ratio %.12f)",
            nc, q->E[0], e0);
      /* P(0): the Gauss gradient of a linear field is exact, so D:D = 2
       * A0^2 in every cell of the square and P(0) = -4 mu A0^2 L^2 to
       * rounding (written with 9 digits: 1e-8) */
      if (!(fabs(p0 - 1) <= 1e-8))
        FVREF_FAIL("square, %d cells: P(0) %.9e is not -4 mu A0^2 L^2", nc,
                   q->P[0]);
      for (size_t k = 0; k < VSPH_FVREF_SQ_ROWS; k++) {
        /* the volume of fluid conserves the liquid to its solvers'
         * tolerance (1e-10 on alpha per step, at most 6400 steps) */
        if (!(fabs(q->vol[k] - 1) <= 1e-6)) {
          FVREF_FAIL(
              "square, %d cells: the liquid's volume %.10f at t A0 "
              "= %g is not 1",
              nc, q->vol[k], s->t[k]);
          break;
        }
        /* nothing drives the square: its E_k can only fall */
        if (k && !(q->E[k] < q->E[k - 1])) {
          FVREF_FAIL("square, %d cells: E_k rises at t A0 = %g", nc, s->t[k]);
          break;
        }
      }
    }
    /* the finest grid's energy budget, dE_k/dt against the viscous power
     * from its own fields (after the start's projection, t A0 >= 0.05):
     * VSPH_FVREF_BUDGET (fvref.h) */
    if (!(s->budget <= VSPH_FVREF_BUDGET))
      FVREF_FAIL(
          "square: the finest grid's energy budget misses by %.2f %% "
          "(at most %.1f %%)",
          100 * s->budget, 100 * VSPH_FVREF_BUDGET);
    /* the ladder converges: its successive differences fall (an order
     * above a half by both measures, the rounding of vsph_grade_orders) */
    if (!(s->sc.order_max > 0.5 && s->sc.order_rms > 0.5))
      FVREF_FAIL("square: the ladder does not converge (orders %.2f, %.2f)",
                 s->sc.order_max, s->sc.order_rms);
  }
  return bad;
}

/* The cavity's files at one Re, likewise. */
static int check_cavity(const struct vsph_fvref_cavity *c, char *why,
                        size_t n) {
  int bad = 0;
  {
    struct vsph_references_ghia gh;
    if (!vsph_references_ghia(c->Re, &gh)) {
      FVREF_FAIL("cavity Re %g: no Ghia table", c->Re);
      return bad;
    }
    for (int g = 0; g < VSPH_FVREF_CAV_GRIDS; g++) {
      const struct vsph_fvref_cavgrid *q = &c->g[g];
      if (q->E[0] != 0)
        FVREF_FAIL("cavity Re %g, %d cells: E_k(0) %g, not 0 (from rest)",
                   c->Re, c->n[g], q->E[0]);
      /* its Ghia column is vsph's own table (analysis/references.c),
       * printed to Ghia's 5 decimals */
      for (int i = 0; i < VSPH_FVREF_GHIA; i++) {
        const int ju = ghia_index(&gh, 0, q->yu[i]),
                  jv = ghia_index(&gh, 1, q->xv[i]);
        if (ju < 0 || jv < 0 ||
            !(fabs(q->gu[i] - gh.u[ju]) <= 5e-6 &&
              fabs(q->gv[i] - gh.v[jv]) <= 5e-6)) {
          FVREF_FAIL(
              "cavity Re %g, %d cells: its Ghia column differs from "
              "vsph's table at point %d",
              c->Re, c->n[g], i);
          break;
        }
      }
    }
    /* the finest grid against Ghia within the two solutions' precision:
     * Ghia's 129 x 129 grid is 0.0057 U (u_min) and 0.012 U (v_min) from
     * Botella & Peyret's spectral values at Re 1000 (1998), and the
     * finest grid here still moves by up to 0.005 U from the coarser in
     * the right-wall layer at Re 1000 (x >= 0.94, six of Ghia's cells
     * across); 0.02 U bounds their sum, at both Re (the same grids) */
    const struct vsph_fvref_cavgrid *f = &c->g[VSPH_FVREF_CAV_GRIDS - 1];
    const double tol = 0.02;
    if (!(f->ghia_max <= tol))
      FVREF_FAIL(
          "cavity Re %g: the finest grid is %.4f U from Ghia at most "
          "(the table's precision: %g U)",
          c->Re, f->ghia_max, tol);
  }
  return bad;
}

int vsph_fvref_check(const struct vsph_fvref *fv, char *why, size_t n) {
  if (n) why[0] = '\0';
  int bad = fv->sq.ok ? check_square(&fv->sq, why, n) : 0;
  for (int w = 0; w < 2; w++)
    if (fv->cav[w].ok) bad += check_cavity(&fv->cav[w], why, n);
  return bad;
}
