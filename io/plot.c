#include "plot.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../common/status.h"
#include "files.h"

void vsph_plot_init(struct vsph_plot *pl, const char *dir, const char *name,
                    const char *title, const char *xlabel, const char *ylabel) {
  memset(pl, 0, sizeof *pl);
  snprintf(pl->dir, sizeof pl->dir, "%s", dir);
  snprintf(pl->name, sizeof pl->name, "%s", name);
  snprintf(pl->title, sizeof pl->title, "%s", title);
  snprintf(pl->xlabel, sizeof pl->xlabel, "%s", xlabel);
  snprintf(pl->ylabel, sizeof pl->ylabel, "%s", ylabel);
}

int vsph_plot_add(struct vsph_plot *pl, const char *file, const char *using,
                  const char *title, const char *style) {
  if (pl->n >= VSPH_PLOT_MAXSERIES)
    VSPH_FAIL(VSPH_EINVAL, "figure %s: more than %d curves", pl->name,
              VSPH_PLOT_MAXSERIES);
  struct vsph_plot_series *s = &pl->s[pl->n];
  const size_t m = sizeof s->file;
  if (strlen(file) >= m || strlen(using) >= m || strlen(title) >= m ||
      strlen(style) >= m)
    VSPH_FAIL(VSPH_EINVAL, "figure %s: a curve's text is too long", pl->name);
  snprintf(s->file, m, "%s", file);
  snprintf(s->using, m, "%s", using);
  snprintf(s->title, m, "%s", title);
  snprintf(s->style, m, "%s", style);
  pl->n++;
  return VSPH_OK;
}

/* Run gnuplot on DIR/GP, its messages into DIR/NAME.log. */
static int render(const char *dir, const char *gp, const char *name) {
  char cmd[1400];
  snprintf(cmd, sizeof cmd, "cd '%s' && gnuplot '%s' 2> '%s.log'", dir, gp,
           name);
  if (system(cmd) != 0)
    VSPH_FAIL(VSPH_EIO, "gnuplot failed on %s/%s (see %s.log)", dir, gp, name);
  return VSPH_OK;
}

int vsph_plot_particles(const char *dir, const char *name, const char *title,
                        const struct vsph_plot_panel *pn, size_t n, int col,
                        const char *cblabel, int diverging,
                        const double box[4]) {
  if (n < 1 || n > 8)
    VSPH_FAIL(VSPH_EINVAL, "picture %s: 1 to 8 panels, not %zu", name, n);
  const size_t rows = n < 3 ? 1 : 2, cols = (n + rows - 1) / rows;
  char gp[160];
  snprintf(gp, sizeof gp, "%s.gp", name);
  FILE *f = vsph_files_open(dir, gp);
  if (!f) return VSPH_EIO;
  fprintf(f,
          "# vsph report picture: gnuplot %s.gp makes %s.png\n"
          "set terminal pngcairo size %zu,%zu enhanced font 'DejaVu Sans,10'\n"
          "set output '%s.png'\nset datafile separator ','\n"
          "set size ratio -1\nunset key\nset cblabel \"%s\"\n%s"
          "set multiplot layout %zu,%zu title \"%s\"\n",
          name, name, 420 * cols, 400 * rows + 40, name, cblabel,
          diverging ? "set palette defined (-1 '#2166ac', 0 '#f7f7f7', 1 "
                      "'#b2182b')\n"
                    : "set palette defined (0 '#440154', 0.5 '#21918c', 1 "
                      "'#fde725')\n",
          rows, cols, title);
  if (box)
    fprintf(f, "set xrange [%.6g:%.6g]\nset yrange [%.6g:%.6g]\n", box[0],
            box[1], box[2], box[3]);
  for (size_t k = 0; k < n; k++) {
    if (diverging) /* symmetric colour range, per panel */
      fprintf(f,
              "stats '%s' skip 1 using %d nooutput\n"
              "M = (abs(STATS_min) > abs(STATS_max) ? abs(STATS_min) : "
              "abs(STATS_max)); if (M == 0) M = 1\n"
              "set cbrange [-M:M]\n",
              pn[k].file, col);
    fprintf(f,
            "set title \"%s\"\nplot '%s' skip 1 using 1:2:%d with points pt "
            "7 ps 0.35 lc palette\n",
            pn[k].title, pn[k].file, col);
  }
  fprintf(f, "unset multiplot\n");
  const int st = vsph_files_close(f, dir, gp);
  return st ? st : render(dir, gp, name);
}

int vsph_plot_write(const struct vsph_plot *pl) {
  char gp[160];
  snprintf(gp, sizeof gp, "%s.gp", pl->name);
  FILE *f = vsph_files_open(pl->dir, gp);
  if (!f) return VSPH_EIO;
  fprintf(f,
          "# vsph report figure: gnuplot %s.gp makes %s.png\n"
          "set terminal pngcairo size 900,600 enhanced font 'DejaVu Sans,11'\n"
          "set output '%s.png'\nset datafile separator ','\n"
          "set title \"%s\"\nset xlabel \"%s\"\nset ylabel \"%s\"\n"
          "set grid\nset key below\n%s%s%s\n",
          pl->name, pl->name, pl->name, pl->title, pl->xlabel, pl->ylabel,
          pl->logx ? "set logscale x\nset format x '10^{%L}'\n" : "",
          pl->logy ? "set logscale y\nset format y '10^{%L}'\n" : "",
          pl->extra);
  fprintf(f, "plot ");
  for (size_t k = 0; k < pl->n; k++)
    fprintf(f, "%s'%s' skip 1 using %s with %s title \"%s\"",
            k ? ", \\\n     " : "", pl->s[k].file, pl->s[k].using,
            pl->s[k].style, pl->s[k].title);
  fprintf(f, "\n");
  const int st = vsph_files_close(f, pl->dir, gp);
  return st ? st : render(pl->dir, gp, pl->name);
}
