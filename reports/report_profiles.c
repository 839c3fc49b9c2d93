/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
/* Section 2 of the report: the tensors against the depth below the free
 * surface, from half support (depth 0) to full support (depth kappa). */
#include <math.h>
#include <stdio.h>

#include "../analysis/moments.h"
#include "../common/status.h"
#include "../io/csv.h"
#include "../io/plot.h"
#include "../kernels/kernel.h"
#include "report_parts.h"

/* Depth step of the profiles (units of h). */
static const double STEP = 0.05;

/* One kernel and dimension: profiles.csv rows and its own file for the
 * figures (one quadrature per depth). */
static int profile(struct vsph_report *R, FILE *csv, size_t ki, int dim) {
  const struct vsph_kernel_type *k = vsph_kernel_get(ki);
  char name[96];
  snprintf(name, sizeof name, "profile_%s_%dd.csv", k->name, dim);
  FILE *f = vsph_csv_open(R->dir, name, "depth,F_nnn,N_n,G_nnnn,M_nn");
  if (!f) return VSPH_EIO;
  const int n = dim - 1, steps = (int)lround(k->kappa / STEP);
  int st = VSPH_OK;
  for (int s = 0; s <= steps && !st; s++) {
    const double d = STEP * s;
    struct vsph_moments q;
    if ((st = vsph_moments_quadrature(k, dim, d, 1e-10, R->wo, R->wi, &q)))
      break;
    fprintf(csv, "%s,%d,%.4f,%.12e,%.12e,%.12e,%.12e,%.12e,%.12e,%.12e,%.12e\n",
            k->name, dim, d, q.F[n][n][n], q.F[n][0][0], q.N[n],
            q.G[n][n][n][n], q.G[0][0][0][0], q.G[0][0][n][n], q.M[n][n],
            q.M[0][0]);
    fprintf(f, "%.4f,%.10e,%.10e,%.10e,%.10e\n", d, q.F[n][n][n], q.N[n],
            q.G[n][n][n][n], q.M[n][n]);
    if (ki == 0 && dim == 2 && s % 10 == 0)
      fprintf(R->md, "| %.1f | %.6f | %.6f | %.6f | %.6f |\n", d, q.F[n][n][n],
              q.N[n], q.G[n][n][n][n], q.M[n][n]);
  }
  if (st) {
    fclose(f);
    return st;
  }
  return vsph_csv_close(f, R->dir, name);
}

/* F and N (which = 0) or G and M (which = 1) against depth, every kernel:
 * one colour per kernel, solid and dashed alike. */
static int figure(struct vsph_report *R, int dim, int which) {
  char pname[64], title[160];
  snprintf(pname, sizeof pname, "fig_profiles_%s_%dd", which ? "GM" : "FN",
           dim);
  snprintf(title, sizeof title,
           which ? "G_{nnnn} (solid) and M_{nn} (dashed) against depth, %d-D"
                 : "F_{nnn} (solid) and N_n (dashed) against depth, %d-D",
           dim);
  struct vsph_plot pl;
  vsph_plot_init(&pl, R->dir, pname, title,
                 "depth of the point below the surface, δ/h (dimensionless)",
                 which ? "G_{nnnn}, M_{nn} (dimensionless)"
                       : "h F_{nnn}, h N_n (dimensionless, h = 1)");
  pl.dashes_mean = 1; /* solid one tensor, dashed the other */
  int st = VSPH_OK;
  for (int dashed = 0; dashed < 2 && !st; dashed++)
    for (size_t ki = 0; ki < vsph_kernel_count() && !st; ki++) {
      const struct vsph_kernel_type *k = vsph_kernel_get(ki);
      char file[96], style[64];
      snprintf(file, sizeof file, "profile_%s_%dd.csv", k->name, dim);
      /* each kernel its marker too, every 0.25 h: the Gaussian's and the
       * quintic's curves nearly coincide, and one must not hide the other */
      static const int PT[] = {6, 8, 4, 12, 2};
      snprintf(style, sizeof style, "linespoints %slw 2 lc %zu pt %d pi 5",
               dashed ? "dt 2 " : "", ki + 1, PT[ki % 5]);
      const char *using =
          which ? (dashed ? "1:5" : "1:4") : (dashed ? "1:3" : "1:2");
      char hover[64]; /* the dashed tensor is out of the key */
      snprintf(hover, sizeof hover, "%s, %s (dashed)", k->name,
               which ? "M_nn" : "h N_n");
      st = dashed ? vsph_plot_add_unkeyed(&pl, file, using, hover, style)
                  : vsph_plot_add(&pl, file, using, k->name, style);
    }
  if (st) return st;
  vsph_text_set(&R->tv, "title", "%s", title);
  return vsph_report_doc_figure_say(R, &pl, "profiles.caption");
}

int vsph_report_profiles_write(struct vsph_report *R) {
  FILE *csv = vsph_csv_open(R->dir, "profiles.csv",
                            "kernel,dim,depth,F_nnn,F_ntt,N_n,G_nnnn,G_tttt,"
                            "G_ttnn,M_nn,M_tt");
  if (!csv) return VSPH_EIO;
  int st = vsph_report_doc_say(R, "profiles.intro");
  for (size_t ki = 0; ki < vsph_kernel_count() && !st; ki++)
    for (int dim = 2; dim <= 3 && !st; dim++) st = profile(R, csv, ki, dim);
  fprintf(R->md, "\n");
  if (st) {
    fclose(csv);
    return st;
  }
  if ((st = vsph_csv_close(csv, R->dir, "profiles.csv"))) return st;
  for (int dim = 2; dim <= 3 && !st; dim++)
    for (int which = 0; which < 2 && !st; which++) st = figure(R, dim, which);
  return st;
}
