/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
/* Section 3 of the report: the 1/h truncation-error scaling of the viscous
 * operators at the surface (THEORY 2, Appendix B of the paper), and their
 * interior convergence on a quadratic field. */
#include <math.h>
#include <stdio.h>

#include "../analysis/moments.h"
#include "../analysis/scaling.h"
#include "../common/consts.h"
#include "../common/status.h"
#include "../io/csv.h"
#include "../io/files.h"
#include "../io/plot.h"
#include "../kernels/kernel.h"
#include "report_parts.h"

/* The three tables the sweeps fill. */
struct tables {
  FILE *csv, *sl, *in;
  double round[4][2]; /* the 3h Gaussian's rounding level, [dim][field] */
  /* the 3h Gaussian's slope of every formulation, [dim][field][form];
   * NaN: rounding */
  double every[4][2][VSPH_VISCOUS_FORM_COUNT];
};

/* One kernel, dimension and field: the sweep, its rows and (3h Gaussian)
 * its figure data. */
static int sweep(struct vsph_report *R, struct tables *tb,
                 const struct vsph_kernel_type *k, int dim, int fk) {
  struct vsph_scaling_props sp;
  int st = vsph_scaling_props_init(&sp, NULL);
  sp.kernel = k;
  if (!st) st = vsph_fields_props_init(&sp.field, fk, dim);
  struct vsph_scaling_result r;
  if (!st) st = vsph_scaling_surface(&sp, &r);
  double C_F = 0, C_N = 0;
  if (!st) st = vsph_moments_constants(k, dim, 1e-12, R->wo, &C_F, &C_N);
  if (st) return st;
  const char *fn = vsph_fields_name(fk);
  if (k == vsph_kernel_get(0)) { /* the 3h Gaussian's sweep, for figures */
    for (int f = 0; f < VSPH_VISCOUS_FORM_COUNT; f++)
      tb->every[dim][fk][f] = r.rounding[f] ? (double)NAN : r.slope[f];
    char name[64];
    snprintf(name, sizeof name, "scaling_%s_%dd.csv", fn, dim);
    FILE *f =
        vsph_csv_open(R->dir, name, "h,mgf,meaf,pvwf,hF,hN,rounding_level");
    if (!f) return VSPH_EIO;
    /* the level below which an operator counts as rounding (scaling.c) */
    const double U =
        fk == VSPH_FIELDS_STRAIN ? fabs(sp.field.A) : fabs(sp.field.Omega);
    const double round = sp.round_tol * sp.mu * U / r.h[r.levels - 1];
    tb->round[dim][fk] = round;
    for (size_t l = 0; l < r.levels; l++)
      fprintf(f, "%.6e,%.6e,%.6e,%.6e,%.10f,%.10f,%.6e\n", r.h[l],
              r.magnitude[0][l], r.magnitude[1][l], r.magnitude[2][l], r.hF[l],
              r.hN[l], round);
    if ((st = vsph_csv_close(f, R->dir, name))) return st;
  }
  for (size_t l = 0; l < r.levels; l++)
    fprintf(tb->csv,
            "%s,%d,%s,%.6e,%.10f,%.10f,%.6e,%.6e,%.6e,%.6e,%.6e,%.6e\n",
            k->name, dim, fn, r.h[l], r.hF[l], r.hN[l], r.normal[0][l],
            r.normal[1][l], r.normal[2][l], r.magnitude[0][l],
            r.magnitude[1][l], r.magnitude[2][l]);
  fprintf(tb->sl, "%s,%d,%s", k->name, dim, fn);
  fprintf(R->md, "| %s | %d | %s", k->name, dim, fn);
  for (int f = 0; f < VSPH_VISCOUS_PAPER_COUNT; f++) {
    if (r.rounding[f]) {
      fprintf(tb->sl, ",");
      fprintf(R->md, " | round");
    } else {
      fprintf(tb->sl, ",%.6f", r.slope[f]);
      fprintf(R->md, " | %.4f", r.slope[f]);
    }
  }
  fprintf(tb->sl, "\n");
  /* half-support theory: h F_ddd = -2 C_F, h N_d = -C_N */
  fprintf(R->md, " | %.4f | %.4f | %.4f | %.4f |\n", r.hF[0], -2 * C_F, r.hN[0],
          -C_N);
  return VSPH_OK;
}

/* Every formulation of the descriptor table (the free-surface study's
 * three in bold): its slopes with the 3h Gaussian, each dimension and
 * field. */
static int every_form(struct vsph_report *R, const struct tables *tb) {
  struct vsph_scaling_props sp;
  int st = vsph_scaling_props_init(&sp, NULL);
  vsph_text_set(&R->tv, "hdx", "%.4g", sp.hdx);
  if (!st) st = vsph_report_doc_say(R, "scaling.every_head");
  for (int f = 0; f < VSPH_VISCOUS_FORM_COUNT && !st; f++) {
    const int paper = vsph_viscous_types[f]->flags & VSPH_VISCOUS_FREE_SURFACE;
    fprintf(R->md, "| %s%s%s", paper ? "**" : "", vsph_viscous_label(f),
            paper ? "**" : "");
    for (int dim = 2; dim <= 3; dim++)
      for (int fk = 0; fk < 2; fk++) {
        const double s = tb->every[dim][fk][f];
        if (isnan(s))
          fprintf(R->md, " | round");
        else
          fprintf(R->md, " | %.4f", s);
      }
    fprintf(R->md, " |\n");
  }
  return st ? st : vsph_report_doc_say(R, "scaling.every_note");
}

static int figure(struct vsph_report *R, const struct tables *tb, int dim,
                  int fk) {
  const char *fn = vsph_fields_name(fk);
  char pname[64], data[64], title[200];
  snprintf(pname, sizeof pname, "fig_scaling_%s_%dd", fn, dim);
  snprintf(data, sizeof data, "scaling_%s_%dd.csv", fn, dim);
  snprintf(title, sizeof title,
           "Surface operators, %s field, %d-D, 3h Gaussian, h/dx = 4/3", fn,
           dim);
  struct vsph_plot pl;
  vsph_plot_init(&pl, R->dir, pname, title, "smoothing length h (m)",
                 "|(div V)_i| at the surface particle (N/m^d)");
  pl.logx = pl.logy = 1;
  /* below this, values are rounding noise (no slope is fitted): shown in
   * a band under the data, not on the axis down to 1e-20 */
  pl.rounding = tb->round[dim][fk];
  /* the sweep's h range (h0 = 0.1 halved 4 times), not whole decades */
  snprintf(pl.extra, sizeof pl.extra, "set xrange [0.0045:0.14]\n");
  int st = VSPH_OK;
  for (int f = 0; f < VSPH_VISCOUS_PAPER_COUNT && !st; f++) {
    char using[16], style[96];
    snprintf(using, sizeof using, "1:%d", f + 2);
    vsph_report_runs_style(style, sizeof style, f, "");
    st = vsph_plot_add(&pl, data, using, vsph_viscous_label(f), style);
  }
  if (!st)
    st = vsph_plot_add(&pl, data, "1:(1e-3*$1**-1)", "slope -1",
                       "lines dt 2 lc 'black'");
  if (st) return st;
  vsph_text_set(&R->tv, "field", "%s", fn);
  vsph_text_set(&R->tv, "dim", "%d", dim);
  vsph_text_set(&R->tv, "data", "%s", data);
  vsph_text_set(&R->tv, "round", "%.2g", tb->round[dim][fk]);
  return vsph_report_doc_figure_say(R, &pl, "scaling.caption");
}

/* The viscous term along the square's symmetry axis at the stretching
 * square's start, for decreasing h (paper Fig. 7): one figure per
 * formulation, one curve per resolution. */
static int axis(struct vsph_report *R) {
  static const size_t RES[3] = {20, 40, 80};
  struct vsph_scaling_props sp;
  int st = vsph_scaling_props_init(&sp, NULL);
  if (!st) st = vsph_fields_props_init(&sp.field, VSPH_FIELDS_STRAIN, 2);
  if (st) return st;
  double y[80], v[VSPH_VISCOUS_FORM_COUNT][80];
  double *f[VSPH_VISCOUS_FORM_COUNT];
  for (int k = 0; k < VSPH_VISCOUS_FORM_COUNT; k++) f[k] = v[k];
  char name[3][64];
  for (int r = 0; r < 3 && !st; r++) {
    size_t n = 0;
    if ((st = vsph_scaling_axis(&sp, RES[r], y, f, &n))) break;
    snprintf(name[r], sizeof name[r], "axis_%zu.csv", RES[r]);
    FILE *c = vsph_csv_open(R->dir, name[r], "y,mgf,meaf,pvwf");
    if (!c) return VSPH_EIO;
    for (size_t k = 0; k < n; k++)
      fprintf(c, "%.8g,%.8e,%.8e,%.8e\n", y[k], v[0][k], v[1][k], v[2][k]);
    if ((st = vsph_csv_close(c, R->dir, name[r]))) break;
  }
  vsph_text_set(&R->tv, "A", "%g", sp.field.A);
  vsph_text_set(&R->tv, "mu", "%g", sp.mu);
  if (!st) st = vsph_report_doc_say(R, "scaling.axis_head");
  for (int form = 0; form < VSPH_VISCOUS_PAPER_COUNT && !st; form++) {
    char pname[64], title[160];
    snprintf(pname, sizeof pname, "fig_axis_%s", vsph_viscous_name(form));
    snprintf(title, sizeof title,
             "%s: (div V)_y along the square's axis x = dx/2, pure strain",
             vsph_viscous_label(form));
    struct vsph_plot pl;
    vsph_plot_init(&pl, R->dir, pname, title,
                   "y (m), free surfaces at -0.5 and 0.5",
                   "(div V)_y (N/m^2), exact 0");
    for (int r = 0; r < 3 && !st; r++) {
      char cols[16], lab[48], style[96];
      snprintf(cols, sizeof cols, "1:%d", form + 2);
      snprintf(lab, sizeof lab, "L/dx = %zu", RES[r]);
      /* a colour and point type per resolution, none a formulation's */
      snprintf(style, sizeof style, "linespoints pt %d ps 0.6 lw %d lc %d",
               vsph_plot_point((size_t)r + 3), r + 1, r + 4);
      st = vsph_plot_add(&pl, name[r], cols, lab, style);
    }
    if (!st) {
      vsph_text_set(&R->tv, "title", "%s", title);
      st = vsph_report_doc_figure_say(R, &pl, "scaling.axis_caption");
    }
  }
  return st;
}

static int interior(struct vsph_report *R, FILE *in) {
  int st = vsph_report_doc_say(R, "scaling.interior");
  for (size_t ki = 0; ki < vsph_kernel_count() && !st; ki++) {
    struct vsph_scaling_props sp;
    st = vsph_scaling_props_init(&sp, NULL);
    sp.kernel = vsph_kernel_get(ki);
    if (!st) st = vsph_fields_props_init(&sp.field, VSPH_FIELDS_QUADRATIC, 2);
    const double *hdx;
    const size_t nh = vsph_scaling_hdx_ladder(&hdx);
    struct vsph_scaling_interior r;
    if (!st) st = vsph_scaling_interior(&sp, hdx, nh, &r);
    for (size_t l = 0; !st && l < r.n; l++) {
      fprintf(in, "%s,%.6f,%.6e,%.6e\n", sp.kernel->name, r.hdx[l], r.mgf[l],
              r.meaf[l]);
      fprintf(R->md, "| %s | %.3f | %.2e | %.2e |\n", sp.kernel->name, r.hdx[l],
              r.mgf[l], r.meaf[l]);
    }
  }
  return st ? st : vsph_report_doc_say(R, "scaling.interior_note");
}

int vsph_report_scaling_write(struct vsph_report *R) {
  struct tables tb = {
      vsph_csv_open(R->dir, "scaling.csv",
                    "kernel,dim,field,h,hF_nnn,hN_n,mgf_n,meaf_n,pvwf_n,"
                    "mgf_abs,meaf_abs,pvwf_abs"),
      vsph_csv_open(R->dir, "slopes.csv",
                    "kernel,dim,field,slope_mgf,slope_meaf,slope_pvwf"),
      vsph_csv_open(R->dir, "interior.csv",
                    "kernel,hdx,mgf_rel_error,meaf_rel_error"),
      {{0}},
      {{{0}}}};
  struct vsph_scaling_props sp;
  int st =
      tb.csv && tb.sl && tb.in ? vsph_scaling_props_init(&sp, NULL) : VSPH_EIO;
  struct vsph_fields_props fp;
  if (!st) st = vsph_fields_props_init(&fp, VSPH_FIELDS_STRAIN, 2);
  if (!st) {
    struct vsph_text_vars *tv = &R->tv;
    vsph_text_set(tv, "hdx", "%.4g", sp.hdx);
    vsph_text_set(tv, "halvings", "%zu", sp.levels - 1);
    vsph_text_set(tv, "h0", "%g", sp.h0);
    vsph_text_set(tv, "mu", "%g", sp.mu);
    vsph_text_set(tv, "A", "%g", fp.A);
    vsph_text_set(tv, "Omega", "%g", fp.Omega);
    vsph_text_set(tv, "round_tol", "%g", sp.round_tol);
    st = vsph_report_doc_say(R, "scaling.intro");
  }
  for (size_t ki = 0; ki < vsph_kernel_count() && !st; ki++)
    for (int dim = 2; dim <= 3 && !st; dim++)
      for (int fk = 0; fk < 2 && !st; fk++)
        st = sweep(R, &tb, vsph_kernel_get(ki), dim, fk);
  if (!st) st = vsph_report_doc_say(R, "scaling.patch");
  if (!st) st = every_form(R, &tb);
  for (int dim = 2; dim <= 3 && !st; dim++)
    for (int fk = 0; fk < 2 && !st; fk++) st = figure(R, &tb, dim, fk);
  if (!st) st = axis(R);
  if (!st) st = interior(R, tb.in);
  const char *names[3] = {"scaling.csv", "slopes.csv", "interior.csv"};
  FILE *files[3] = {tb.csv, tb.sl, tb.in};
  for (int k = 0; k < 3; k++) {
    if (!files[k]) continue;
    if (st)
      vsph_files_discard(files[k], R->dir, names[k]);
    else
      st = vsph_csv_close(files[k], R->dir, names[k]);
  }
  return st;
}
