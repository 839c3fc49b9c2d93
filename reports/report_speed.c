/* Section 7 of the report: wall time against the decay error, per scene
 * and formulation, over the resolution ladder. */
#include <stdio.h>

#include "../common/status.h"
#include "../io/csv.h"
#include "../io/plot.h"
#include "report_internal.h"

#define NFORM VSPH_VISCOUS_PAPER_COUNT /* the free-surface study's three */

static int scene(struct vsph_report *R, int sc) {
  struct vsph_report_ladder lr;
  int st = vsph_report_runs_ladder_figures(R, sc, &lr);
  if (st) return st;
  const char *scn = vsph_report_runs_ladder(R, sc, 0)->scene;
  char pname[64], title[160];
  snprintf(pname, sizeof pname, "fig_speed_%s", scn);
  snprintf(title, sizeof title, "%s: wall time against E_k error", scn);
  struct vsph_plot pl;
  vsph_plot_init(&pl, R->dir, pname, title,
                 "max_t |E_k/E_k(0) - E_{k,ref}/E_{k,ref}(0)|",
                 "wall time (s, 2 threads)");
  pl.logx = pl.logy = 1;
  for (int f = 0; f < NFORM && !st; f++) {
    char file[96];
    snprintf(file, sizeof file, "speed_%s_%s.csv", scn, vsph_viscous_name(f));
    FILE *c = vsph_csv_open(R->dir, file, "error,wall_s,pairs,cpu_s,load_1min");
    if (!c) return VSPH_EIO;
    for (int k = 0; k < VSPH_REPORT_LADDER; k++)
      fprintf(c, "%.6e,%.4f,%.6e,%.4f,%.2f\n", lr.err[f][k], lr.wall[f][k],
              lr.pairs[f][k], lr.cpu[f][k], lr.load[f][k]);
    if ((st = vsph_csv_close(c, R->dir, file))) break;
    char style[96];
    vsph_report_runs_style(style, sizeof style, f, "");
    st = vsph_plot_add(&pl, file, "1:2", vsph_viscous_label(f), style);
  }
  if (st) return st;
  vsph_text_set(&R->tv, "title", "%s", title);
  return vsph_report_figure_say(R, &pl, "speed.caption");
}

int vsph_report_speed_write(struct vsph_report *R) {
  int st = vsph_report_say(R, "speed.intro");
  for (int sc = 0; sc < VSPH_REPORT_NSCENES && !st; sc++)
    if (vsph_report_scene_on(R, sc)) st = scene(R, sc);
  return st;
}
