/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
/* Section 6 of the report: the decay error of each scene and formulation
 * against resolution, with the fitted order. */
#include <math.h>
#include <stdio.h>

#include "../analysis/scaling.h"
#include "../analysis/series.h"
#include "../common/status.h"
#include "../io/csv.h"
#include "../io/files.h"
#include "../io/plot.h"
#include "report_fv.h"
#include "report_parts.h"

#define NFORM VSPH_VISCOUS_PAPER_COUNT /* the free-surface study's three */

/* The x range of a ladder's figure (dx over the reference length: the
 * ladder's, not whole decades) and its ticks, at the ladder's
 * resolutions: gnuplot commands into @p buf. */
static void ladder_ticks(char *buf, size_t n,
                         const struct vsph_report_ladderdef *L) {
  size_t len =
      (size_t)snprintf(buf, n, "set xrange [%g:%g]\nset xtics (",
                       0.8 / L->res[VSPH_REPORT_LADDER - 1], 1.25 / L->res[0]);
  for (int k = 0; k < VSPH_REPORT_LADDER && len < n; k++)
    len += (size_t)snprintf(buf + len, n - len, "%s'1/%zu' %.6g", k ? ", " : "",
                            L->res[k], 1.0 / L->res[k]);
  if (len < n) snprintf(buf + len, n - len, ")\n");
}

/* Formulation @p f's two curves of a ladder's figure from its CSV
 * @p file (columns: dx, error, ..., stable (5), difference_max (6)): the
 * error (solid) and the difference from the coarser rung (dashed), each
 * point that a stopped run made drawn hollow (vsph_report_runs_hollow):
 * an error where its run stopped, a difference where either run of the
 * pair did (vsph_report_runs_hollow_pairs). */
static int curves(struct vsph_plot *pl, const char *file,
                  const struct vsph_report_ladder *lr, int f, int *said) {
  const char *lf = vsph_viscous_label(f);
  char style[96], lab[96], hover[160];
  vsph_report_runs_style(style, sizeof style, f, "");
  snprintf(lab, sizeof lab, "%s: error against the reference", lf);
  int st = vsph_plot_add(pl, file, "1:2", lab, style);
  snprintf(lab, sizeof lab, "%s: difference from the coarser rung (max)", lf);
  vsph_report_runs_style(style, sizeof style, f, " dt 2");
  if (!st) st = vsph_plot_add(pl, file, "1:6", lab, style);
  int err = 0, diff = 0; /* a hollow point on each curve */
  for (int k = 0; k < VSPH_REPORT_LADDER; k++) {
    err |= !lr->ok[f][k];
    if (k && isfinite(lr->self[f].dmax[k - 1]))
      diff |= !lr->ok[f][k - 1] || !lr->ok[f][k];
  }
  snprintf(hover, sizeof hover,
           "%s: error against the reference, run stopped as unstable (up to "
           "the stop)",
           lf);
  if (!st && err)
    st = vsph_report_runs_hollow(pl, file, "1:($5==0 ? $2 : 1/0)", f, hover,
                                 said);
  snprintf(hover, sizeof hover,
           "%s: difference from the coarser rung, a run of the two stopped as "
           "unstable (up to the first stop)",
           lf);
  if (!st && diff)
    st = vsph_report_runs_hollow_pairs(pl, file, 5, 6, f, hover, said);
  return st;
}

static int scene(struct vsph_report *R, int sc) {
  struct vsph_report_ladder lr;
  int st = vsph_report_runs_ladder_figures(&R->runs, sc, &lr);
  if (st) return st;
  const struct vsph_report_ladderdef *L =
      vsph_report_runs_ladder(&R->runs, sc, 0);
  char pname[64], title[160];
  snprintf(pname, sizeof pname, "fig_convergence_%s", L->scene);
  snprintf(title, sizeof title,
           "%s: E_k error against the reference (solid) and between "
           "successive resolutions (dashed)",
           L->scene);
  struct vsph_plot pl;
  vsph_plot_init(&pl, R->dir, pname, title,
                 "particle spacing dx / reference length (dimensionless)",
                 "max_t of |E_k/E_k(0) - E_{k,ref}/E_{k,ref}(0)| or "
                 "|ΔE_k/E_k(0)|");
  pl.logx = pl.logy = 1;
  pl.dashes_mean = 1; /* solid the error, dashed the differences */
  /* the ladder's range, not whole decades; ticks at its resolutions */
  ladder_ticks(pl.extra, sizeof pl.extra, L);
  vsph_text_set(&R->tv, "scene", "%s", L->scene);
  if ((st = vsph_report_doc_say(R, "convergence.scene_head"))) return st;
  char files[NFORM][96];
  int said = 0; /* the key's entry for hollow markers */
  for (int f = 0; f < NFORM && !st; f++) {
    size_t ns;
    const double order = vsph_series_slope_where(lr.dx[f], lr.err[f], lr.ok[f],
                                                 VSPH_REPORT_LADDER, &ns);
    const struct vsph_series_selfconv *sv = &lr.self[f];
    snprintf(files[f], sizeof files[f], "convergence_%s_%s.csv", L->scene,
             vsph_viscous_name(f));
    /* a rung's successive difference is from the rung before it, drawn
     * at its own dx; the first rung has none (NaN) */
    FILE *c = vsph_csv_open(R->dir, files[f],
                            "dx,error,wall_s,pairs,stable,"
                            "difference_max,difference_rms,span_s");
    if (!c) return VSPH_EIO;
    for (int k = 0; k < VSPH_REPORT_LADDER; k++) {
      const double dm = k ? sv->dmax[k - 1] : (double)NAN;
      const double dr = k ? sv->drms[k - 1] : (double)NAN;
      fprintf(c, "%.6e,%.6e,%.4f,%.6e,%d,%.6e,%.6e,%.6g\n", lr.dx[f][k],
              lr.err[f][k], lr.wall[f][k], lr.pairs[f][k], lr.ok[f][k], dm, dr,
              sv->span);
      char dmb[32] = "–", drb[32] = "–", stable[64] = "yes";
      if (k) {
        snprintf(dmb, sizeof dmb, "%.3e", dm);
        snprintf(drb, sizeof drb, "%.3e", dr);
      }
      if (!lr.ok[f][k])
        snprintf(stable, sizeof stable, "no: stopped at t = %.3g s",
                 lr.t_unstable[f][k]);
      fprintf(R->md, "| %s | %zu | %.3e | %s | %s | %s |\n",
              vsph_viscous_name(f), L->res[k], lr.err[f][k], dmb, drb, stable);
    }
    char span[96];
    if (sv->partial)
      snprintf(span, sizeof span,
               "differences over t <= %.3g s only (a rung "
               "stopped)",
               sv->span);
    else
      snprintf(span, sizeof span, "differences over the whole run");
    char fit[96];
    vsph_report_runs_fitted(fit, sizeof fit, order, ns);
    fprintf(R->md, "| %s | order | %s | **%.2f** | **%.2f** | %s |\n",
            vsph_viscous_name(f), fit, sv->order_max, sv->order_rms, span);
    if ((st = vsph_csv_close(c, R->dir, files[f]))) break;
    st = curves(&pl, files[f], &lr, f, &said);
  }
  if (!st)
    st = vsph_plot_add(&pl, files[0], "1:($1*0.1)", "first order",
                       "lines dt 2 lc 'black'");
  if (st) return st;
  fprintf(R->md, "\n");
  vsph_text_set(&R->tv, "title", "%s", title);
  vsph_text_set(&R->tv, "scene", "%s", L->scene);
  st = vsph_report_doc_figure_say(R, &pl, "convergence.caption");
  if (!st && sc == 1) st = vsph_report_fv_convergence(R, &lr);
  return st;
}

/* The vortex patch on both disc layouts: decay error and initial
 * dissipation error against R/dx, with fitted orders. */
static int vortex_layouts(struct vsph_report *R) {
  const struct vsph_report_ladderdef *L =
      vsph_report_runs_ladder(&R->runs, 0, 0);
  static const char *const lay[2] = {"rings", "cartesian"};
  struct vsph_report_layouts ly;
  int st = vsph_report_runs_layouts(&R->runs, &ly);
  if (st) return st;
  if ((st = vsph_report_doc_say(R, "convergence.layout_head"))) return st;
  struct vsph_plot pl;
  vsph_plot_init(&pl, R->dir, "fig_convergence_vortex-layouts",
                 "vortex-patch: initial dissipation error on rings (solid) "
                 "and on a Cartesian disc (dashed)",
                 "particle spacing dx / R (dimensionless)",
                 "|P_{visc}(0) - dE_{k,ref}/dt(0)| / |dE_{k,ref}/dt(0)|");
  pl.logx = pl.logy = 1;
  pl.dashes_mean = 1; /* solid the rings, dashed the Cartesian disc */
  ladder_ticks(pl.extra, sizeof pl.extra, L);
  for (int l = 0; l < 2 && !st; l++)
    for (int f = 0; f < NFORM && !st; f++) {
      char file[96], lab[64], style[96];
      snprintf(file, sizeof file, "convergence_vortex-patch_%s_%s.csv", lay[l],
               vsph_viscous_name(f));
      FILE *c = vsph_csv_open(R->dir, file,
                              "dx,decay_error,initial_dissipation_error,"
                              "abs_initial_dissipation_error,stable");
      if (!c) return VSPH_EIO;
      for (int k = 0; k < VSPH_REPORT_LADDER; k++) {
        fprintf(c, "%.6e,%.6e,%.6e,%.6e,%d\n", ly.dx[k], ly.err[l][f][k],
                ly.d0[l][f][k], fabs(ly.d0[l][f][k]), ly.ok[l][f][k]);
        char stable[64];
        if (ly.ok[l][f][k])
          snprintf(stable, sizeof stable, "yes");
        else
          snprintf(stable, sizeof stable, "no: stopped at t = %.3g s",
                   ly.tu[l][f][k]);
        char dmb[32] = "–";
        if (k) snprintf(dmb, sizeof dmb, "%.3e", ly.self[l][f].dmax[k - 1]);
        fprintf(R->md, "| %s | %s | %zu | %.3e | %s | %+.3e | %s |\n", lay[l],
                vsph_viscous_name(f), L->res[k], ly.err[l][f][k], dmb,
                ly.d0[l][f][k], stable);
      }
      double a0[VSPH_REPORT_LADDER];
      for (int k = 0; k < VSPH_REPORT_LADDER; k++) a0[k] = fabs(ly.d0[l][f][k]);
      const struct vsph_series_selfconv *sv = &ly.self[l][f];
      char span[96] = "";
      if (sv->partial)
        snprintf(span, sizeof span, "differences over t <= %.3g s only",
                 sv->span);
      size_t ns;
      const double oe = vsph_series_slope_where(
          ly.dx, ly.err[l][f], ly.ok[l][f], VSPH_REPORT_LADDER, &ns);
      const double o0 = vsph_series_slope_where(ly.dx, a0, ly.ok[l][f],
                                                VSPH_REPORT_LADDER, &ns);
      char fit[96], fit0[96];
      vsph_report_runs_fitted(fit, sizeof fit, oe, ns);
      vsph_report_runs_fitted(fit0, sizeof fit0, o0, ns);
      fprintf(R->md,
              "| %s | %s | order | %s | **%.2f** (max), **%.2f** (RMS) | %s | "
              "%s |\n",
              lay[l], vsph_viscous_name(f), fit, sv->order_max, sv->order_rms,
              fit0, span);
      if ((st = vsph_csv_close(c, R->dir, file))) break;
      snprintf(lab, sizeof lab, "%s, %s", vsph_viscous_label(f), lay[l]);
      vsph_report_runs_style(style, sizeof style, f, l ? " dt 2" : "");
      st = vsph_plot_add(&pl, file, "1:4", lab, style);
    }
  if (st) return st;
  fprintf(R->md, "\n");
  return vsph_report_doc_figure_say(R, &pl, "convergence.layout_caption");
}

int vsph_report_convergence_write(struct vsph_report *R) {
  int st = VSPH_OK;
  if (!st) st = vsph_report_doc_say(R, "convergence.intro");
  for (int sc = 0; sc < VSPH_REPORT_NSCENES && !st; sc++)
    if (vsph_report_scene_on(&R->runs, sc)) st = scene(R, sc);
  if (!st && vsph_report_scene_on(&R->runs, 0)) st = vortex_layouts(R);
  return st;
}
