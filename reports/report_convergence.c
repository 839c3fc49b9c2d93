/* Section 6 of the report: the decay error of each scene and formulation
 * against resolution, with the fitted order. */
#include <math.h>
#include <stdio.h>

#include "../analysis/scaling.h"
#include "../common/status.h"
#include "../io/csv.h"
#include "../io/files.h"
#include "../io/plot.h"
#include "report_internal.h"

#define NFORM VSPH_VISCOUS_FORM_COUNT

static int scene(struct vsph_report *R, int sc) {
  struct vsph_report_ladder lr;
  int st = vsph_report_runs_ladder_figures(R, sc, &lr);
  if (st) return st;
  const struct vsph_report_ladderdef *L = vsph_report_runs_ladder(R, sc, 0);
  char pname[64], title[160];
  snprintf(pname, sizeof pname, "fig_convergence_%s", L->scene);
  snprintf(title, sizeof title, "%s: E_k error against resolution", L->scene);
  struct vsph_plot pl;
  vsph_plot_init(&pl, R->dir, pname, title,
                 "particle spacing dx / reference length",
                 "max_t |E_k - E_{k,ref}| / E_{k,ref}(0)");
  pl.logx = pl.logy = 1;
  /* the ladder's range, not whole decades */
  snprintf(pl.extra, sizeof pl.extra, "set xrange [%g:%g]\n",
           0.8 / L->res[VSPH_REPORT_LADDER - 1], 1.25 / L->res[0]);
  vsph_text_set(&R->tv, "scene", "%s", L->scene);
  if ((st = vsph_report_say(R, "convergence.scene_head"))) return st;
  char files[NFORM][96];
  for (int f = 0; f < NFORM && !st; f++) {
    const double order =
        vsph_scaling_slope(lr.dx[f], lr.err[f], VSPH_REPORT_LADDER);
    snprintf(files[f], sizeof files[f], "convergence_%s_%s.csv", L->scene,
             vsph_viscous_name(f));
    FILE *c = vsph_csv_open(R->dir, files[f], "dx,error,wall_s,pairs,stable");
    if (!c) return VSPH_EIO;
    for (int k = 0; k < VSPH_REPORT_LADDER; k++) {
      fprintf(c, "%.6e,%.6e,%.4f,%.6e,%d\n", lr.dx[f][k], lr.err[f][k],
              lr.wall[f][k], lr.pairs[f][k], lr.ok[f][k]);
      fprintf(R->md, "| %s | %zu | %.3e | %s | |\n", vsph_viscous_name(f),
              L->res[k], lr.err[f][k], lr.ok[f][k] ? "yes" : "no");
    }
    fprintf(R->md, "| %s | ladder | | | **%.2f** |\n", vsph_viscous_name(f),
            order);
    if ((st = vsph_csv_close(c, R->dir, files[f]))) break;
    st = vsph_plot_add(&pl, files[f], "1:2", vsph_viscous_label(f),
                       "linespoints pt 7 lw 2");
  }
  if (!st)
    st = vsph_plot_add(&pl, files[0], "1:($1*0.1)", "first order",
                       "lines dt 2 lc 'black'");
  if (st) return st;
  fprintf(R->md, "\n");
  vsph_text_set(&R->tv, "title", "%s", title);
  vsph_text_set(&R->tv, "scene", "%s", L->scene);
  return vsph_report_figure_say(R, &pl, "convergence.caption");
}

int vsph_report_convergence_write(struct vsph_report *R) {
  int st = vsph_report_say(R, "convergence.intro");
  for (int sc = 0; sc < VSPH_REPORT_NSCENES && !st; sc++) st = scene(R, sc);
  return st;
}
