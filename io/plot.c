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
          "set grid\nset key outside right top\n%s%s%s\n",
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
  if (st) return st;
  char cmd[1400];
  snprintf(cmd, sizeof cmd, "cd '%s' && gnuplot '%s' 2> '%s.log'", pl->dir, gp,
           pl->name);
  if (system(cmd) != 0)
    VSPH_FAIL(VSPH_EIO, "gnuplot failed on %s/%s (see %s.log)", pl->dir, gp,
              pl->name);
  return VSPH_OK;
}
