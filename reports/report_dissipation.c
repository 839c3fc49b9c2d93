/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
/* Section 4 of the report: the dissipation integrals of MGF, MEAF and PVWF
 * on analytic fields (THEORY 4), against resolution, h/dx and a perturbed
 * lattice, with the error split into consistency, lattice and surface. */
#include <math.h>
#include <stdio.h>

#include "../analysis/dissipation.h"
#include "../common/consts.h"
#include "../common/status.h"
#include "../io/csv.h"
#include "../io/files.h"
#include "../io/plot.h"
#include "report_parts.h"

#define NFORM VSPH_VISCOUS_PAPER_COUNT /* the free-surface study's three */
/* The fields of this section: rotation, strain, mixed. */
#define NFIELD 3

/* Resolutions, h/dx values and the lattice perturbation of the tables. */
static const size_t RES[4] = {20, 40, 80, 160};
static const double HDX[5] = {1.0, VSPH_CONSTS_HDX, 2.0, 3.0, 4.0};
static const size_t RES_HDX = 80;
static const double PERTURB = 0.1;

/* The tables of the section: dissipation.csv and the figure data. */
struct tables {
  FILE *csv;
  FILE *res[NFORM];         /* strain on the square against resolution */
  FILE *hdx[NFORM][NFIELD]; /* each field against h/dx */
  char res_name[NFORM][64], hdx_name[NFORM][NFIELD][64];
  double res_rel[NFORM]; /* the largest |relative error| of res[form] */
};

/* One evaluation: its row in dissipation.csv and the Markdown table, and
 * (if plot) its point (x, |rel|, |lattice|, |surface|) of a figure, and
 * (if rel_max) the largest |relative error| so far. */
static int row(struct vsph_report *R, FILE *csv,
               const struct vsph_dissipation_props *dp, FILE *plot, double x,
               double *rel_max) {
  struct vsph_dissipation_result r;
  const int st = vsph_dissipation_compute(dp, &r);
  if (st) return st;
  const char *form = vsph_viscous_name(dp->form);
  const char *field = vsph_fields_name(dp->field.kind);
  const char *shape = vsph_dissipation_shape_name(dp->shape);
  fprintf(csv,
          "%s,%s,%s,%zu,%.6f,%.2f,%zu,%.12e,%.12e,%.12e,%.6e,%.6e,%.6e,%.6e\n",
          form, field, shape, dp->nacross, dp->hdx, dp->perturb, r.n_particles,
          r.P, r.P_exact, r.P_grad, r.rel_error, r.consistency_error,
          r.lattice_error, r.surface_error);
  fprintf(R->md,
          "| %s | %s | %s | %zu | %.3f | %+.4e | %+.4e | %+.4e | %+.4e |\n",
          form, field, shape, dp->nacross, dp->hdx, r.rel_error,
          r.consistency_error, r.lattice_error, r.surface_error);
  if (plot)
    fprintf(plot, "%.6g,%.6e,%.6e,%.6e\n", x, fabs(r.rel_error),
            fabs(r.lattice_error), fabs(r.surface_error));
  if (rel_max) *rel_max = fmax(*rel_max, fabs(r.rel_error));
  return VSPH_OK;
}

/* The default props with formulation, field, shape, resolution, h/dx and
 * perturbation set. */
static int props(struct vsph_dissipation_props *dp, int form, int field,
                 int shape, size_t res, double hdx, double perturb) {
  int st = vsph_dissipation_props_init(dp, NULL);
  if (!st) st = vsph_fields_props_init(&dp->field, field, 2);
  dp->form = form;
  dp->shape = shape;
  dp->nacross = res;
  dp->hdx = hdx;
  dp->perturb = perturb;
  return st;
}

static int open_tables(struct vsph_report *R, struct tables *tb) {
  tb->csv = vsph_csv_open(R->dir, "dissipation.csv",
                          "formulation,field,shape,res,hdx,perturb,"
                          "n_particles,P,P_exact,P_grad,rel_error,"
                          "consistency_error,lattice_error,surface_error");
  if (!tb->csv) return VSPH_EIO;
  for (int form = 0; form < NFORM; form++) {
    snprintf(tb->res_name[form], 64, "dissip_res_%s.csv",
             vsph_viscous_name(form));
    if (!(tb->res[form] = vsph_csv_open(R->dir, tb->res_name[form],
                                        "res,rel,lattice,surface")))
      return VSPH_EIO;
    for (int field = 0; field < NFIELD; field++) {
      snprintf(tb->hdx_name[form][field], 64, "dissip_hdx_%s_%s.csv",
               vsph_viscous_name(form), vsph_fields_name(field));
      if (!(tb->hdx[form][field] = vsph_csv_open(
                R->dir, tb->hdx_name[form][field], "hdx,rel,lattice,surface")))
        return VSPH_EIO;
    }
  }
  return VSPH_OK;
}

/* Close every table; discard them all after a failure. */
static int close_tables(struct vsph_report *R, struct tables *tb, int st) {
  FILE *f[1 + NFORM + NFORM * NFIELD];
  const char *n[1 + NFORM + NFORM * NFIELD];
  size_t m = 0;
  f[m] = tb->csv, n[m++] = "dissipation.csv";
  for (int form = 0; form < NFORM; form++) {
    f[m] = tb->res[form], n[m++] = tb->res_name[form];
    for (int field = 0; field < NFIELD; field++)
      f[m] = tb->hdx[form][field], n[m++] = tb->hdx_name[form][field];
  }
  for (size_t k = 0; k < m; k++) {
    if (!f[k]) continue;
    if (st)
      vsph_files_discard(f[k], R->dir, n[k]);
    else
      st = vsph_csv_close(f[k], R->dir, n[k]);
  }
  return st;
}

static int tables(struct vsph_report *R, struct tables *tb) {
  struct vsph_dissipation_props dp;
  int st = vsph_dissipation_props_init(&dp, NULL);
  if (!st) {
    vsph_text_set(&R->tv, "mu", "%g", dp.mu);
    st = vsph_report_doc_say(R, "dissipation.intro");
  }
  if (!st) st = vsph_report_doc_say(R, "dissipation.table_head");
  for (int form = 0; form < NFORM && !st; form++)
    for (int field = 0; field < NFIELD && !st; field++)
      for (int shape = 0; shape < VSPH_DISSIPATION_SHAPE_COUNT && !st; shape++)
        for (int r = 0; r < 4 && !st; r++) {
          const int fig =
              field == VSPH_FIELDS_STRAIN && shape == VSPH_DISSIPATION_SQUARE;
          if (!(st = props(&dp, form, field, shape, RES[r], VSPH_CONSTS_HDX,
                           0.0)))
            st = row(R, tb->csv, &dp, fig ? tb->res[form] : NULL,
                     (double)RES[r], fig ? &tb->res_rel[form] : NULL);
        }
  vsph_text_set(&R->tv, "res", "%zu", RES_HDX);
  if (!st) st = vsph_report_doc_say(R, "dissipation.by_hdx");
  if (!st) st = vsph_report_doc_say(R, "dissipation.table_head");
  for (int form = 0; form < NFORM && !st; form++)
    for (int field = 0; field < NFIELD && !st; field++)
      for (int h = 0; h < 5 && !st; h++)
        if (!(st = props(&dp, form, field, VSPH_DISSIPATION_SQUARE, RES_HDX,
                         HDX[h], 0.0)))
          st = row(R, tb->csv, &dp, tb->hdx[form][field], HDX[h], NULL);
  vsph_text_set(&R->tv, "res", "%zu", RES_HDX);
  vsph_text_set(&R->tv, "percent", "%g", 100 * PERTURB);
  vsph_text_set(&R->tv, "seed", "%lu", dp.seed);
  if (!st) st = vsph_report_doc_say(R, "dissipation.perturbed");
  if (!st) st = vsph_report_doc_say(R, "dissipation.table_head");
  for (int form = 0; form < NFORM && !st; form++)
    for (int field = 0; field < NFIELD && !st; field++)
      if (!(st = props(&dp, form, field, VSPH_DISSIPATION_SQUARE, RES_HDX,
                       VSPH_CONSTS_HDX, PERTURB)))
        st = row(R, tb->csv, &dp, NULL, 0.0, NULL);
  fprintf(R->md, "\n");
  return st;
}

/* Every formulation of the descriptor table (the free-surface study's
 * three in bold): rel on the square and the disc, each field, at
 * RES_HDX across and h/dx = 4/3. The others' rows go to dissipation.csv
 * too (the three's are there from the tables above). */
static int every_form(struct vsph_report *R, FILE *csv) {
  vsph_text_set(&R->tv, "res", "%zu", RES_HDX);
  int st = vsph_report_doc_say(R, "dissipation.every_head");
  for (int form = 0; form < VSPH_VISCOUS_FORM_COUNT && !st; form++) {
    const int paper =
        vsph_viscous_types[form]->flags & VSPH_VISCOUS_FREE_SURFACE;
    fprintf(R->md, "| %s%s%s", paper ? "**" : "", vsph_viscous_label(form),
            paper ? "**" : "");
    for (int shape = VSPH_DISSIPATION_SHAPE_COUNT - 1; shape >= 0 && !st;
         shape--) /* square first */
      for (int field = 0; field < NFIELD && !st; field++) {
        struct vsph_dissipation_props dp;
        struct vsph_dissipation_result r;
        st = props(&dp, form, field, shape, RES_HDX, VSPH_CONSTS_HDX, 0.0);
        if (!st) st = vsph_dissipation_compute(&dp, &r);
        if (st) break;
        fprintf(R->md, " | %+.3e", r.rel_error);
        if (!paper)
          fprintf(csv,
                  "%s,%s,%s,%zu,%.6f,%.2f,%zu,%.12e,%.12e,%.12e,%.6e,%.6e,"
                  "%.6e,%.6e\n",
                  vsph_viscous_name(form), vsph_fields_name(field),
                  vsph_dissipation_shape_name(shape), dp.nacross, dp.hdx,
                  dp.perturb, r.n_particles, r.P, r.P_exact, r.P_grad,
                  r.rel_error, r.consistency_error, r.lattice_error,
                  r.surface_error);
      }
    fprintf(R->md, " |\n");
  }
  return st ? st : vsph_report_doc_say(R, "dissipation.every_note");
}

static int figures(struct vsph_report *R, const struct tables *tb) {
  struct vsph_plot a;
  vsph_plot_init(&a, R->dir, "fig_dissipation_res",
                 "Pure strain on the square: dissipation error against "
                 "resolution, h/dx = 4/3",
                 "particles across the square, L/dx",
                 "relative error of P (dimensionless)");
  a.logx = a.logy = 1;
  /* PVWF's error is exact to rounding (about 1e-15, sums of O(N) terms of
   * size 1 each rounded at 1.1e-16): below 1e-13 it is shown in the
   * rounding band, not on an axis stretched down to 1e-16 */
  a.rounding = 1e-13;
  /* ticks at the resolutions computed */
  snprintf(a.extra, sizeof a.extra,
           "set xrange [15:200]\nset xtics (%zu, %zu, %zu, %zu)\n", RES[0],
           RES[1], RES[2], RES[3]);
  int st = VSPH_OK;
  for (int form = 0; form < NFORM && !st; form++) {
    char title[64], style[96];
    snprintf(title, sizeof title, "%s total", vsph_viscous_label(form));
    vsph_report_runs_style(style, sizeof style, form, "");
    st = vsph_plot_add(&a, tb->res_name[form], "1:2", title, style);
    /* a form whose dissipation is exact to rounding (PVWF's identity) has
     * no surface part to show: its total sits in the rounding band */
    if (!st && tb->res_rel[form] >= a.rounding) {
      snprintf(title, sizeof title, "%s surface part",
               vsph_viscous_label(form));
      /* the formulation's colour and its open point shape */
      snprintf(style, sizeof style, "linespoints pt %d dt 2 %s",
               vsph_report_runs_point(form) - 1, vsph_report_runs_colour(form));
      st = vsph_plot_add(&a, tb->res_name[form], "1:4", title, style);
    }
  }
  if (!st)
    st = vsph_plot_add(&a, tb->res_name[0], "1:(0.5/$1)", "slope -1",
                       "lines dt 3 lc 'black'");
  if (!st) st = vsph_report_doc_figure_say(R, &a, "dissipation.caption_res");
  if (st) return st;
  struct vsph_plot b;
  char title[160];
  snprintf(title, sizeof title,
           "Lattice error of the dissipation against h/dx (square, %zu "
           "across)",
           RES_HDX);
  vsph_plot_init(&b, R->dir, "fig_dissipation_hdx", title,
                 "h/dx (dimensionless)", "|lattice error| (dimensionless)");
  b.logx = b.logy = 1;
  b.rounding = 1e-13; /* PVWF's strain: zero to rounding, as above */
  snprintf(b.extra, sizeof b.extra,
           "set xrange [0.9:4.4]\nset xtics (1, '4/3' %.17g, 2, 3, 4)\n",
           VSPH_CONSTS_HDX);
  for (int form = 0; form < NFORM && !st; form++)
    for (int field = 1; field < NFIELD && !st; field++) { /* strain, mixed */
      char tl[64];
      snprintf(tl, sizeof tl, "%s, %s", vsph_viscous_label(form),
               vsph_fields_name(field));
      /* the formulation's colour; mixed: dashed, its open point shape */
      char style[96];
      snprintf(style, sizeof style, "linespoints pt %d lw 2 %s%s",
               vsph_report_runs_point(form) - (field == 2),
               vsph_report_runs_colour(form), field == 2 ? " dt 2" : "");
      st = vsph_plot_add(&b, tb->hdx_name[form][field], "1:3", tl, style);
    }
  vsph_text_set(&R->tv, "res", "%zu", RES_HDX);
  if (!st) st = vsph_report_doc_figure_say(R, &b, "dissipation.caption_hdx");
  return st ? st : vsph_report_doc_say(R, "dissipation.reading");
}

/* The lattice error of pure strain against the angle of its axes to the
 * square lattice (0: u = A(x, -y); 45 degrees: pure shear, the azimuthal
 * shear of a disc laid in rings), each formulation, h/dx = 4/3. */
static int angle_figure(struct vsph_report *R) {
  enum { NANG = 19 }; /* 0, 5, ..., 90 degrees */
  static const char *const name = "dissip_angle.csv";
  FILE *c = vsph_csv_open(R->dir, name,
                          "angle_deg,mgf_lattice,meaf_lattice,pvwf_lattice");
  if (!c) return VSPH_EIO;
  int st = VSPH_OK;
  /* each form's lattice error at 0 and 45 degrees, {{NAME0}} and
   * {{NAME45}} for the text (which quotes MGF's) */
  double at0[NFORM] = {0}, at45[NFORM] = {0};
  for (int a = 0; a < NANG && !st; a++) {
    const double deg = 5.0 * a;
    fprintf(c, "%g", deg);
    for (int form = 0; form < NFORM && !st; form++) {
      struct vsph_dissipation_props dp;
      struct vsph_dissipation_result r;
      st = props(&dp, form, VSPH_FIELDS_STRAIN, VSPH_DISSIPATION_SQUARE,
                 RES_HDX, VSPH_CONSTS_HDX, 0.0);
      dp.field.theta = deg * VSPH_PI / 180.0;
      if (!st) st = vsph_dissipation_compute(&dp, &r);
      if (st) break;
      fprintf(c, ",%.6e", r.lattice_error);
      if (a == 0) at0[form] = r.lattice_error;
      if (a == 9) at45[form] = r.lattice_error;
    }
    fprintf(c, "\n");
  }
  if (st) {
    vsph_files_discard(c, R->dir, name);
    return st;
  }
  if ((st = vsph_csv_close(c, R->dir, name))) return st;
  for (int form = 0; form < NFORM; form++) {
    char key[32];
    snprintf(key, sizeof key, "%s0", vsph_viscous_name(form));
    vsph_text_set(&R->tv, key, "%+.2f", 100 * at0[form]);
    snprintf(key, sizeof key, "%s45", vsph_viscous_name(form));
    vsph_text_set(&R->tv, key, "%+.2f", 100 * at45[form]);
  }
  vsph_text_set(&R->tv, "res", "%zu", RES_HDX);
  if ((st = vsph_report_doc_say(R, "dissipation.angle_head"))) return st;
  struct vsph_plot pl;
  vsph_plot_init(&pl, R->dir, "fig_dissipation_angle",
                 "Lattice error of pure strain against the angle of its axes "
                 "to the square lattice, h/dx = 4/3",
                 "angle of the strain's axes to the lattice (degrees)",
                 "lattice error (negative: more dissipation)");
  snprintf(pl.extra, sizeof pl.extra, "set xrange [0:90]\nset xtics 0,15,90\n");
  for (int form = 0; form < NFORM && !st; form++) {
    char cols[16], style[96];
    snprintf(cols, sizeof cols, "1:%d", form + 2);
    vsph_report_runs_style(style, sizeof style, form, "");
    st = vsph_plot_add(&pl, name, cols, vsph_viscous_label(form), style);
  }
  return st ? st
            : vsph_report_doc_figure_say(R, &pl, "dissipation.angle_caption");
}

int vsph_report_dissipation_write(struct vsph_report *R) {
  struct tables tb = {0};
  int st = open_tables(R, &tb);
  if (!st) st = tables(R, &tb);
  if (!st) st = every_form(R, tb.csv);
  st = close_tables(R, &tb, st);
  if (!st) st = figures(R, &tb);
  return st ? st : angle_figure(R);
}
