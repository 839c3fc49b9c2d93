/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
#include "plot.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../common/status.h"
#include "csv.h"
#include "files.h"

/* The shared palette, safe for colour-blind readers: Okabe and Ito's
 * (2008) seven colours first (MGF blue, MEAF vermillion, PVWF bluish
 * green: never red against green), then darker and lighter tones chosen
 * to stay apart from them and from each other on white; black is kept
 * for references (exact solutions, slope guides). */
static const char *const COLOURS[VSPH_PLOT_NSTYLES] = {
    "#0072b2", "#d55e00", "#009e73", "#cc79a7", "#e69f00",
    "#56b4e9", "#f0e442", "#7f7f7f", "#8c564b", "#0b2e6b",
    "#6a3d9a", "#00796b", "#7b0d1e", "#b8860b", "#4d4d4d"};
/* gnuplot's fifteen point shapes, filled ones first */
static const int POINTS[VSPH_PLOT_NSTYLES] = {7, 5,  9,  11, 13, 15, 6, 4,
                                              8, 10, 12, 14, 1,  2,  3};

const char *vsph_plot_colour(size_t k) {
  return COLOURS[k % VSPH_PLOT_NSTYLES];
}

int vsph_plot_point(size_t k) { return POINTS[k % VSPH_PLOT_NSTYLES]; }

void vsph_plot_plain(char *out, size_t n, const char *text) {
  if (!out || !n) return;
  if (!text) text = "";
  size_t k = 0;
  unsigned long drop = 0; /* bit d: the brace at depth d is dropped */
  int depth = 0;
  for (const char *c = text; *c && k + 1 < n; c++) {
    if (*c == '{') {
      const int markup = c > text && (c[-1] == '_' || c[-1] == '^');
      if (depth < 63)
        drop = markup ? drop | 1ul << depth : drop & ~(1ul << depth);
      depth++;
      if (markup) continue;
    } else if (*c == '}' && depth > 0) {
      depth--;
      if (depth < 63 && drop >> depth & 1) continue;
    }
    out[k++] = *c;
  }
  out[k] = '\0';
}

void vsph_plot_init(struct vsph_plot *pl, const char *dir, const char *name,
                    const char *title, const char *xlabel, const char *ylabel) {
  if (!pl) return;
  memset(pl, 0, sizeof *pl);
  snprintf(pl->dir, sizeof pl->dir, "%s", dir ? dir : "");
  snprintf(pl->name, sizeof pl->name, "%s", name ? name : "");
  snprintf(pl->title, sizeof pl->title, "%s", title ? title : "");
  snprintf(pl->xlabel, sizeof pl->xlabel, "%s", xlabel ? xlabel : "");
  snprintf(pl->ylabel, sizeof pl->ylabel, "%s", ylabel ? ylabel : "");
}

int vsph_plot_add(struct vsph_plot *pl, const char *file, const char *using,
                  const char *title, const char *style) {
  if (!pl || !file || !using || !title || !style)
    VSPH_FAIL(VSPH_EINVAL, "vsph_plot_add: a NULL argument");
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

int vsph_plot_add_unkeyed(struct vsph_plot *pl, const char *file,
                          const char *using, const char *hover,
                          const char *style) {
  if (!hover) VSPH_FAIL(VSPH_EINVAL, "vsph_plot_add_unkeyed: a NULL argument");
  if (pl && strlen(hover) >= sizeof pl->s[0].hover)
    VSPH_FAIL(VSPH_EINVAL, "figure %s: a curve's text is too long", pl->name);
  /* one line of text: it is written into a comment of NAME.gp, which a
   * newline would end (the rest run as gnuplot's commands) */
  for (const char *c = hover; *c; c++)
    if ((unsigned char)*c < 0x20 || *c == 0x7f)
      VSPH_FAIL(VSPH_EINVAL,
                "figure %s: a curve's text holds a control character (a "
                "newline, a tab): one line of plain text",
                pl ? pl->name : "(none)");
  const int st = vsph_plot_add(pl, file, using, "", style);
  if (!st)
    vsph_plot_plain(pl->s[pl->n - 1].hover, sizeof pl->s[0].hover, hover);
  return st;
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

/* The script's common head: UTF-8 text (Greek letters as such), CSV data
 * and the shared palette as linetypes 1, 2, ... */
static void head(FILE *f, const char *what, const char *name) {
  fprintf(f,
          "# vsph report %s: `gnuplot %s.gp` makes %s.png, %s.svg and "
          "%s.pdf\nset encoding utf8\nset datafile separator ','\n",
          what, name, name, name, name);
  for (size_t k = 0; k < VSPH_PLOT_NSTYLES; k++)
    fprintf(f, "set linetype %zu lc rgb '%s' pt %d\n", k + 1, COLOURS[k],
            POINTS[k]);
  fprintf(f, "set linetype cycle %d\n", VSPH_PLOT_NSTYLES);
}

/* The SVG's name for figure @p name, which gnuplot takes as an
 * identifier: the file's name, other characters as '_'. */
static void svg_id(char *id, size_t n, const char *name) {
  snprintf(id, n, "%s", name);
  for (char *c = id; *c; c++)
    if (!((*c >= 'a' && *c <= 'z') || (*c >= 'A' && *c <= 'Z') ||
          (*c >= '0' && *c <= '9')))
      *c = '_';
}

/* Open the loop over the three outputs: a W x H pixel PNG, the same as
 * SVG (scalable in a page), a PDF of W/100 x H/100 inches. */
static void outputs_open(FILE *f, const char *name, int w, int h, int font) {
  /* the SVG's title (its name, svg_id), not "Gnuplot"; its text two
   * points larger, as the page draws it across its column (reports/html.c):
   * the figure's words at the body's size */
  char id[128];
  svg_id(id, sizeof id, name);
  fprintf(f,
          "do for [fmt in \"png svg pdf\"] {\n"
          "  if (fmt eq \"png\") {\n"
          "    set terminal pngcairo size %d,%d enhanced font 'DejaVu "
          "Sans,%d'\n"
          "  } else {\n"
          "    if (fmt eq \"svg\") {\n"
          "      set terminal svg size %d,%d name '%s' enhanced font "
          "'DejaVu Sans,%d' background '#ffffff'\n"
          "    } else {\n"
          "      set terminal pdfcairo size %.2fin,%.2fin enhanced font "
          "'DejaVu Sans,%d'\n"
          "    }\n"
          "  }\n"
          "  set output '%s.'.fmt\n",
          w, h, font, w, h, id, font + 2, w / 100.0, h / 100.0, font, name);
}

static void outputs_close(FILE *f) { fprintf(f, "  unset output\n}\n"); }

/* @p using with its y field (the second) wrapped in rl(), the rounding
 * floor: "1:2" -> "1:(rl($2))", "1:($2*3):4" -> "1:(rl(($2*3))):4". */
static void wrap_y(char *out, size_t n, const char *using) {
  int depth = 0;
  const char *c = using, *y = NULL, *end = NULL;
  for (; *c; c++) {
    if (*c == '(') depth++;
    if (*c == ')') depth--;
    if (*c == ':' && !depth) {
      if (!y)
        y = c + 1;
      else if (!end)
        end = c;
    }
  }
  if (!y) {
    snprintf(out, n, "%s", using);
    return;
  }
  if (!end) end = c;
  const int ylen = (int)(end - y);
  const int col = strspn(y, "0123456789") == (size_t)ylen;
  snprintf(out, n, "%.*s(rl(%s%.*s))%s", (int)(y - using), using,
           col ? "$" : "", ylen, y, end);
}

static void plot_cmd(FILE *f, const struct vsph_plot *pl) {
  /* each line that sets no dashes gets its own (solid, then dotted,
   * dash-dot, ...), skipping those other curves set: a curve under another
   * (MGF under PVWF) still shows between the other's dashes */
  unsigned used = 0; /* bit d: dash type d set by a curve */
  for (size_t k = 0; k < pl->n; k++) {
    const char *dt = strstr(pl->s[k].style, " dt ");
    const int d = dt ? atoi(dt + 4) : 0;
    if (d > 0 && d < 32) used |= 1u << d;
  }
  static const int ORDER[] = {1, 3, 4, 5, 2};
  int free_dt[5], nfree = 0;
  for (size_t q = 0; q < 5 && !pl->dashes_mean; q++)
    if (!(used >> ORDER[q] & 1)) free_dt[nfree++] = ORDER[q];
  fprintf(f, "  plot ");
  for (size_t k = 0, line = 0; k < pl->n; k++) {
    char using[300];
    if (pl->rounding > 0.0 && pl->logy)
      wrap_y(using, sizeof using, pl->s[k].using);
    else
      snprintf(using, sizeof using, "%s", pl->s[k].using);
    char dt[16] = "";
    if (nfree && strstr(pl->s[k].style, "lines") &&
        !strstr(pl->s[k].style, " dt "))
      snprintf(dt, sizeof dt, " dt %d", free_dt[line++ % (size_t)nfree]);
    fprintf(f, "%s'%s' skip 1 using %s with %s%s title \"%s\"",
            k ? ", \\\n       " : "", pl->s[k].file, using, pl->s[k].style, dt,
            pl->s[k].title);
  }
  if (pl->rounding > 0.0 && pl->logy)
    fprintf(f,
            ", \\\n       keyentry with boxes fs solid 1.0 fc rgb '#d9d9d9' "
            "title ROUNDING_TITLE");
  fprintf(f, "\n");
}

/* @p v as enhanced text: "10^{-13}" or "2.5×10^{-11}". */
static void power_text(char *buf, size_t n, double v) {
  const int e = (int)floor(log10(v));
  const double m = v / pow(10.0, e);
  if (fabs(m - 1.0) < 1e-9)
    snprintf(buf, n, "10^{%d}", e);
  else
    snprintf(buf, n, "%.2g×10^{%d}", m, e);
}

/* After the dry pass: log axis @p a ('x' or 'y') gets a range and ticks
 * from the data: every decade labelled; 1-2-5 ticks where the data span
 * less than 3 decades, 1...9 under 0.7, so no axis has a single label.
 * @p fixed: the range was set by the caller (kept as set). @p own_ticks:
 * the caller set the ticks (kept, e.g. at the data's resolutions).
 * @p rounding:
 * room below the data for the rounding band (y only). */
static void log_ticks(FILE *f, char a, int fixed, int own_ticks, int rounding) {
  if (fixed)
    fprintf(f, "lo = GPVAL_%c_MIN; hi = GPVAL_%c_MAX\n", a - 32, a - 32);
  else /* the data, padded by 5 % of their span in decades */
    fprintf(f,
            "lo = GPVAL_DATA_%c_MIN; hi = GPVAL_DATA_%c_MAX\n"
            "sp = log10(hi/lo); sp = sp < 0.3 ? 0.3 : sp\n"
            "lo = lo/10**(0.05*sp); hi = hi*10**(0.05*sp)\n",
            a - 32, a - 32);
  if (own_ticks) fprintf(f, "set format %c '%%g'\n", a);
  if (!own_ticks)
    fprintf(f,
            "d = log10(hi/lo)\n"
            "ms = d < 0.7 ? \"1 2 3 4 5 6 7 8 9\" : (d < 3 ? \"1 2 5\" : "
            "\"1\")\n"
            "dec = lo > 0.00999 && hi < 10001\n"
            "set %ctics () out mirror\n"
            "do for [e = floor(log10(lo)):ceil(log10(hi))] {\n"
            "  do for [m in ms] {\n"
            "    v = real(m)*10.0**e\n"
            "    if (v >= lo/1.0001 && v <= hi*1.0001) {\n"
            "      set %ctics add (dec ? sprintf('%%g', v) : (m eq '1' ? "
            "sprintf('10^{%%d}', e) : sprintf('%%s×10^{%%d}', m, e)) v)\n"
            "    }\n"
            "  }\n"
            "  if (ms eq '1' && d < 8) {\n"
            "    do for [k = 2:9] {\n"
            "      v = k*10.0**e\n"
            "      if (v >= lo && v <= hi) { set %ctics add ('' v 1) }\n"
            "    }\n"
            "  }\n"
            "}\n",
            a, a, a);
  if (rounding) /* the band, 0.45 decade under the data, if any is there */
    fprintf(f,
            "if (NRL > 0) {\n"
            "  RB0 = lo/10**0.6; RB1 = lo/10**0.15; RB = lo/10**0.375\n"
            "  set object 1 rectangle from graph 0, first RB0 to graph 1, "
            "first RB1 fc rgb '#d9d9d9' fs solid 1.0 noborder behind\n"
            "  set ytics add ('rounding' RB)\n"
            "  rl(y) = y < RL ? RB : y\n"
            "  lo = RB0\n"
            "} else {\n"
            "  rl(y) = y\n"
            "  ROUNDING_TITLE = ''\n"
            "}\n");
  fprintf(f, "set %crange [lo:hi]\n", a);
}

/* @p text as XML character data into @p out (room for 5 bytes a byte of
 * it): '&', '<' and '>' escaped. Returns the bytes written. */
static size_t xml_text(char *out, const char *text) {
  size_t k = 0;
  for (const char *c = text; *c; c++) {
    const char *e = *c == '&'   ? "&amp;"
                    : *c == '<' ? "&lt;"
                    : *c == '>' ? "&gt;"
                                : NULL;
    if (e) {
      memcpy(out + k, e, strlen(e));
      k += strlen(e);
    } else
      out[k++] = *c;
  }
  return k;
}

/* The title of the rounding band's key entry where no value lies below the
 * rounding level (the .gp then gives it no key title, and gnuplot names its
 * empty group "ID_plot_K" after the curves). */
static const char ROUNDING_NONE[] =
    "rounding band: no value lies below the rounding level here";

/* DIR/NAME.svg's groups of the curves out of the key titled by their
 * hover text (vsph_plot_add_unkeyed), and an empty rounding band's by
 * ROUNDING_NONE: gnuplot titles the group of curve K (1, 2, ... in plot
 * order) without a key title "ID_plot_K" (svg_id). */
static int svg_hover(const struct vsph_plot *pl) {
  size_t nh = 0;
  for (size_t k = 0; k < pl->n; k++) nh += pl->s[k].hover[0] != '\0';
  const int band = pl->logy && pl->rounding > 0.0;
  if (!nh && !band) return VSPH_OK;
  char path[1024], svg_name[160], id[128], want[200];
  snprintf(path, sizeof path, "%s/%s.svg", pl->dir, pl->name);
  snprintf(svg_name, sizeof svg_name, "%s.svg", pl->name);
  svg_id(id, sizeof id, pl->name);
  size_t len = 0;
  char *svg = vsph_files_slurp(path, &len);
  const size_t room = 5 * sizeof pl->s[0].hover + sizeof "<title></title>";
  char *out = svg ? malloc(len + (nh + 1) * room + 1) : NULL;
  if (!out) {
    free(svg);
    VSPH_FAIL(VSPH_EIO, "cannot read %s to title its curves", path);
  }
  const char *in = svg;
  char *o = out;
  for (size_t k = 0; k < pl->n; k++) {
    if (!pl->s[k].hover[0]) continue;
    snprintf(want, sizeof want, "<title>%s_plot_%zu</title>", id, k + 1);
    const char *at = strstr(in, want);
    if (!at) { /* another gnuplot's naming: the figure stands untitled */
      free(svg);
      free(out);
      fprintf(stderr,
              "vsph: %s: gnuplot named no group of curve %zu as %s_plot_%zu; "
              "its hover text is gnuplot's own\n",
              path, k + 1, id, k + 1);
      return VSPH_OK;
    }
    memcpy(o, in, (size_t)(at - in));
    o += at - in;
    memcpy(o, "<title>", 7);
    o += 7;
    o += xml_text(o, pl->s[k].hover);
    memcpy(o, "</title>", 8);
    o += 8;
    in = at + strlen(want);
  }
  snprintf(want, sizeof want, "<title>%s_plot_%zu</title>", id, pl->n + 1);
  const char *at = band ? strstr(in, want) : NULL;
  if (at) { /* the band's key entry, with no title: none is drawn */
    memcpy(o, in, (size_t)(at - in));
    o += at - in;
    o += (size_t)sprintf(o, "<title>%s</title>", ROUNDING_NONE);
    in = at + strlen(want);
  }
  memcpy(o, in, len - (size_t)(in - svg) + 1); /* and its NUL */
  const int st = vsph_files_write(pl->dir, svg_name, out);
  free(svg);
  free(out);
  return st;
}

int vsph_plot_write(const struct vsph_plot *pl) {
  if (!pl) VSPH_FAIL(VSPH_EINVAL, "vsph_plot_write: a NULL argument");
  if (pl->n > VSPH_PLOT_MAXSERIES)
    VSPH_FAIL(VSPH_EINVAL, "figure %s: %zu curves, more than %d", pl->name,
              pl->n, VSPH_PLOT_MAXSERIES);
  char gp[160];
  snprintf(gp, sizeof gp, "%s.gp", pl->name);
  FILE *f = vsph_files_open(pl->dir, gp);
  if (!f) return VSPH_EIO;
  head(f, "figure", pl->name);
  fprintf(f,
          "set title \"%s\"\nset xlabel \"%s\"\nset ylabel \"%s\"\n"
          "set grid lt 1 lc rgb '#cccccc' lw 1 dt 3\nset key below reverse "
          "Left height 1.5\n%s%s%s\n",
          pl->title, pl->xlabel, pl->ylabel,
          pl->logx ? "set logscale x\nset format x '10^{%L}'\n" : "",
          pl->logy ? "set logscale y\nset format y '10^{%L}'\n" : "",
          pl->extra);
  const int rounding = pl->logy && pl->rounding > 0.0;
  if (rounding) {
    char rt[64];
    power_text(rt, sizeof rt, pl->rounding);
    fprintf(f,
            "# below RL: rounding noise, drawn in the grey band under the "
            "data\nRL = %.17g\nROUNDING_TITLE = \"rounding level (values "
            "below %s, drawn in the band)\"\n"
            "NRL = 0 # the dry pass counts them\n"
            "rl(y) = y < RL ? (NRL = NRL + 1, NaN) : y\n",
            pl->rounding, rt);
  }
  if (pl->logx || pl->logy) { /* a dry pass finds the data's range */
    fprintf(f, "set table $DRY\n");
    plot_cmd(f, pl);
    fprintf(f, "unset table\n");
    if (pl->logx)
      log_ticks(f, 'x', strstr(pl->extra, "set xrange") != NULL,
                strstr(pl->extra, "set xtics") != NULL, 0);
    if (pl->logy)
      log_ticks(f, 'y', strstr(pl->extra, "set yrange") != NULL,
                strstr(pl->extra, "set ytics") != NULL, rounding);
  }
  outputs_open(f, pl->name, 900, 600, 11);
  plot_cmd(f, pl);
  outputs_close(f);
  for (size_t k = 0; k < pl->n; k++)
    if (pl->s[k].hover[0])
      fprintf(f,
              "# in %s.svg, curve %zu (out of the key) is titled \"%s\" "
              "by vsph after gnuplot\n",
              pl->name, k + 1, pl->s[k].hover);
  int st = vsph_files_close(f, pl->dir, gp);
  if (!st) st = render(pl->dir, gp, pl->name);
  return st ? st : svg_hover(pl);
}

/* The finite values of column @p col (1-based, as gnuplot counts) of
 * DIR/FILE, read by io/csv, appended to *@p v (*@p n of *@p cap). */
static int column_values(const char *dir, const char *file, int col, double **v,
                         size_t *n, size_t *cap) {
  char path[1024];
  snprintf(path, sizeof path, "%s/%s", dir, file);
  struct vsph_csv *t = vsph_csv_read(path);
  if (!t) return VSPH_EIO;
  if (col < 1 || (size_t)col > t->ncol) {
    vsph_csv_free(t);
    VSPH_FAIL(VSPH_EINVAL, "%s has no column %d", path, col);
  }
  const double *c = t->data + (size_t)(col - 1) * t->nrow;
  for (size_t r = 0; r < t->nrow; r++) {
    if (!isfinite(c[r])) continue;
    if (*n == *cap) {
      const size_t nc = *cap ? 2 * *cap : 4096;
      double *w = realloc(*v, nc * sizeof *w);
      if (!w) {
        vsph_csv_free(t);
        VSPH_FAIL(VSPH_ENOMEM, "cannot read %s", path);
      }
      *v = w, *cap = nc;
    }
    (*v)[(*n)++] = c[r];
  }
  vsph_csv_free(t);
  return VSPH_OK;
}

static int cmp_double(const void *a, const void *b) {
  const double x = *(const double *)a, y = *(const double *)b;
  return (x > y) - (x < y);
}

/* The @p p quantile of the @p n sorted values @p v by nearest rank: the
 * value at rank ceil(p n). */
static double quantile(const double *v, size_t n, double p) {
  size_t r = (size_t)ceil(p * (double)n);
  r = r < 1 ? 1 : r > n ? n : r;
  return v[r - 1];
}

/* The robust colour limits of column @p col over every panel (the rule:
 * vsph_plot_particles): *@p lo and *@p hi, the share of values beyond
 * them, *@p diverging cleared for a field of one sign. */
static int colour_limits(const char *dir, const char *name,
                         const struct vsph_plot_panel *pn, size_t n, int col,
                         int *diverging, double *lo, double *hi, double *share,
                         size_t *npts) {
  double *v = NULL;
  size_t count = 0, cap = 0;
  for (size_t k = 0; k < n; k++) {
    const int st = column_values(dir, pn[k].file, col, &v, &count, &cap);
    if (st) {
      free(v);
      return st;
    }
  }
  if (!count) {
    free(v);
    VSPH_FAIL(VSPH_EINVAL, "picture %s: no finite value in column %d", name,
              col);
  }
  double vmin = v[0], vmax = v[0]; /* one sign: a sequential scale */
  for (size_t k = 1; k < count; k++)
    vmin = fmin(vmin, v[k]), vmax = fmax(vmax, v[k]);
  if (*diverging && (vmin >= 0.0 || vmax <= 0.0)) *diverging = 0;
  size_t beyond = 0;
  if (*diverging) /* one sort, of |value| or of value */
    for (size_t k = 0; k < count; k++) v[k] = fabs(v[k]);
  qsort(v, count, sizeof *v, cmp_double);
  if (*diverging) {
    const double m = quantile(v, count, 0.99);
    *hi = m > 0.0 ? m : 1.0;
    *lo = -*hi;
    for (size_t k = 0; k < count; k++) beyond += v[k] > *hi;
  } else {
    *lo = quantile(v, count, 0.01);
    *hi = quantile(v, count, 0.99);
    for (size_t k = 0; k < count; k++) beyond += v[k] < *lo || v[k] > *hi;
    if (!(*hi > *lo)) { /* a uniform field: a range around it */
      const double d = *lo != 0.0 ? 0.01 * fabs(*lo) : 1.0;
      *lo -= d, *hi += d;
    }
  }
  free(v);
  *share = (double)beyond / (double)count;
  *npts = count;
  return VSPH_OK;
}

int vsph_plot_particles(const char *dir, const char *name, const char *title,
                        const struct vsph_plot_panel *pn, size_t n, int col,
                        const char *cblabel, int diverging, const double box[4],
                        double cb[4]) {
  if (!dir || !name || !title || !pn || !cblabel)
    VSPH_FAIL(VSPH_EINVAL, "vsph_plot_particles: a NULL argument");
  if (n < 1 || n > 8)
    VSPH_FAIL(VSPH_EINVAL, "picture %s: 1 to 8 panels, not %zu", name, n);
  /* one colour scale for the scene, from every particle of every panel:
   * robust limits, the 1st and 99th percentiles (a few surface particles
   * must not set the scale of the whole field), the share beyond them
   * said; a signed field on a diverging scale +-M, M the 99th percentile
   * of |value|; a field of one sign on a sequential one */
  double lo, hi, share;
  size_t npts = 0;
  const int st0 =
      colour_limits(dir, name, pn, n, col, &diverging, &lo, &hi, &share, &npts);
  if (st0) return st0;
  if (cb) cb[2] = share, cb[3] = diverging;
  if (cb) cb[0] = lo, cb[1] = hi;
  /* the layout: panels to scale (the box's aspect), colour bar at right */
  const int rows = n < 3 ? 1 : 2, cols = (int)((n + (size_t)rows - 1) / rows);
  double aspect = box ? (box[3] - box[2]) / (box[1] - box[0]) : 1.0;
  if (!(aspect > 0.25)) aspect = 0.25;
  if (aspect > 3.0) aspect = 3.0;
  const int pw = 340, ph = (int)(pw * aspect);
  const int ml = 70, mr = 130, mt = 50, mb = 10, gx = 80, gy = 90;
  const int w = ml + cols * pw + (cols - 1) * gx + mr;
  /* dots about as wide as the particles' spacing on the page (a panel's
   * particles spread over its box; pngcairo's pt 7 at ps 1 is about 10
   * px across at this width), so a field reads as a field */
  const double per = (double)npts / (double)n;
  double ps = 0.35;
  if (box && per >= 1.0) {
    const double space = (double)pw *
                         sqrt((box[1] - box[0]) * (box[3] - box[2]) / per) /
                         (box[1] - box[0]);
    ps = fmin(1.2, fmax(0.3, space / 10.0));
  }
  const int h = mt + rows * (ph + gy) + mb;
  char gp[160];
  snprintf(gp, sizeof gp, "%s.gp", name);
  FILE *f = vsph_files_open(dir, gp);
  if (!f) return VSPH_EIO;
  head(f, "picture", name);
  fprintf(
      f,
      "set size ratio -1\nunset key\nset xlabel 'x (m)'\n"
      "set ylabel 'y (m)'\nset cblabel \"%s\" offset char 1.5,0\n%s"
      "# one colour scale for every panel: %s over all particles "
      "(beyond them: the end colours)\n"
      "set cbrange [%.17g:%.17g]\n",
      cblabel,
      diverging ? "set palette defined (-1 '#2166ac', 0 '#d9d9d9', 1 "
                  "'#b2182b')\n"
                : "set palette defined (0 '#440154', 0.5 '#21918c', 1 "
                  "'#fde725')\n",
      diverging ? "+-(99th percentile of |value|)" : "[1st, 99th percentile]",
      lo, hi);
  if (box)
    fprintf(f, "set xrange [%.6g:%.6g]\nset yrange [%.6g:%.6g]\n", box[0],
            box[1], box[2], box[3]);
  outputs_open(f, name, w, h, 10);
  fprintf(f,
          "  set multiplot layout %d,%d title \"%s\" margins %.4f,%.4f,%.4f,"
          "%.4f spacing %.4f,%.4f\n",
          rows, cols, title, (double)ml / w, 1.0 - (double)mr / w,
          (double)(mb + gy - 45) / h, 1.0 - (double)mt / h, (double)gx / w,
          (double)gy / h);
  for (size_t k = 0; k < n; k++) {
    if (k + 1 == n) /* the shared colour bar, once, right of the panels */
      fprintf(f,
              "  set colorbox user origin screen %.4f, screen %.4f size "
              "screen %.4f, screen %.4f\n",
              1.0 - (mr - 20.0) / w, 0.15, 18.0 / w, 0.7);
    else
      fprintf(f, "  unset colorbox\n");
    fprintf(f,
            "  set title \"%s\"\n  plot '%s' skip 1 using 1:2:%d with points "
            "pt 7 ps %.2f lc palette title \"%s\"\n",
            pn[k].title, pn[k].file, col, ps, pn[k].title);
  }
  fprintf(f, "  unset multiplot\n");
  outputs_close(f);
  const int st = vsph_files_close(f, dir, gp);
  return st ? st : render(dir, gp, name);
}
