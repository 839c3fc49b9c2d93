/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
/* io/plot: the particle pictures' shared colour scale, every figure in
 * three formats, the shared palette. Needs gnuplot (scripts/install-deps). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "../common/status.h"
#include "../io/csv.h"
#include "../io/plot.h"
#include "../reports/html.h"
#include "check_suites.h"

static char dir[64];

static void setup(void) {
  snprintf(dir, sizeof dir, "/tmp/vsph_check_plot_XXXXXX");
  ck_assert_ptr_nonnull(mkdtemp(dir));
}

static void teardown(void) {
  char cmd[128];
  snprintf(cmd, sizeof cmd, "rm -rf '%s'", dir);
  if (system(cmd) != 0) fprintf(stderr, "cannot remove %s\n", dir);
}

/* Three panels of n particles: x, y, pressure, vorticity. Panel 2 holds
 * the largest |vorticity|, at a particle far outside the box the picture
 * is drawn in; panel 1 the largest positive value, so a limit from one
 * panel, from the box only, or from one sign, each comes out smaller. */
enum { NPANEL = 3, NPART = 37 };
static double X[NPANEL][NPART], Y[NPANEL][NPART], P[NPANEL][NPART],
    W[NPANEL][NPART];

static void panels(struct vsph_plot_panel pn[NPANEL]) {
  for (int k = 0; k < NPANEL; k++) {
    snprintf(pn[k].file, sizeof pn[k].file, "panel_%d.csv", k);
    snprintf(pn[k].title, sizeof pn[k].title, "panel %d", k);
    char path[128];
    snprintf(path, sizeof path, "%s/%s", dir, pn[k].file);
    FILE *f = fopen(path, "w");
    ck_assert_ptr_nonnull(f);
    fprintf(f, "x,y,pressure,vorticity,free_surface\n");
    for (int i = 0; i < NPART; i++) {
      const double s = 0.1 * i - 1.8; /* inside the box [-2, 2]^2 */
      X[k][i] = s;
      Y[k][i] = 0.7 * s;
      P[k][i] = 101325.0 + 2.385 * (k + 1) * sin(1.2348 * i);
      W[k][i] = 0.6 * (k + 1) * cos(2.385 * i) - 0.3 * k;
    }
    X[1][5] = 7.5, Y[1][5] = -9.25; /* outside the box */
    W[1][5] = -4.71238898;
    W[0][9] = 1.9 * 1.2348;
    for (int i = 0; i < NPART; i++)
      fprintf(f, "%.17g,%.17g,%.17g,%.17g,0\n", X[k][i], Y[k][i], P[k][i],
              W[k][i]);
    fclose(f);
  }
}

/* The cbrange written into DIR/NAME.gp. */
static void script_cbrange(const char *name, double *lo, double *hi) {
  char path[128], line[512];
  snprintf(path, sizeof path, "%s/%s.gp", dir, name);
  FILE *f = fopen(path, "r");
  ck_assert_ptr_nonnull(f);
  int found = 0;
  while (fgets(line, sizeof line, f))
    if (sscanf(line, "set cbrange [%lf:%lf]", lo, hi) == 2) found++;
  fclose(f);
  ck_assert_int_eq(found, 1); /* one scale for every panel */
}

static int exists(const char *name, const char *ext, const char *magic) {
  char path[160], buf[16] = {0};
  snprintf(path, sizeof path, "%s/%s.%s", dir, name, ext);
  FILE *f = fopen(path, "rb");
  if (!f) return 0;
  const size_t n = fread(buf, 1, sizeof buf - 1, f);
  fclose(f);
  return n >= strlen(magic) && !memcmp(buf, magic, strlen(magic));
}

static int cmp_d(const void *a, const void *b) {
  const double x = *(const double *)a, y = *(const double *)b;
  return (x > y) - (x < y);
}

/* The colour scale of every panel together, robust (io/plot.h): a signed
 * field on +-M, M the 99th percentile of |value| by nearest rank (here the
 * 110th of 111 sorted, so the largest, far outside the box, is the one
 * value beyond and takes the end colour), worked out here independently
 * of the code's sort. */
START_TEST(test_vorticity_limit_all_panels) {
  struct vsph_plot_panel pn[NPANEL];
  panels(pn);
  double a[NPANEL * NPART];
  for (int k = 0; k < NPANEL; k++)
    for (int i = 0; i < NPART; i++) a[k * NPART + i] = fabs(W[k][i]);
  qsort(a, NPANEL * NPART, sizeof *a, cmp_d);
  const double M = a[110 - 1]; /* rank ceil(0.99 x 111) = 110 */
  const double box[4] = {-2.0, 2.0, -2.0, 2.0};
  double cb[4];
  ck_assert_int_eq(vsph_plot_particles(dir, "pic_w", "vorticity", pn, NPANEL, 4,
                                       "ω (1/s)", 1, box, cb),
                   VSPH_OK);
  double lo, hi;
  script_cbrange("pic_w", &lo, &hi);
  /* exact: the CSV holds %.17g (a double's round trip) and the script
   * writes the limit with %.17g too, so nothing rounds on the way */
  ck_assert_double_eq(hi, M);
  ck_assert_double_eq(lo, -M);
  ck_assert(cb[0] == -M && cb[1] == M && cb[3] == 1.0);
  ck_assert_double_eq_tol(cb[2], 1.0 / 111.0, 1e-15); /* the largest */
  ck_assert(exists("pic_w", "png", "\x89PNG"));
  ck_assert(exists("pic_w", "svg", "<?xml"));
  ck_assert(exists("pic_w", "pdf", "%PDF"));
  /* each panel's points are titled by the panel's title in the SVG (what
   * a pointer over them shows), not by gnuplot's plot command */
  static char svg[1 << 20];
  char path[160];
  snprintf(path, sizeof path, "%s/pic_w.svg", dir);
  vsph_test_slurp(path, svg, sizeof svg);
  for (int k = 0; k < NPANEL; k++) {
    char want[64];
    snprintf(want, sizeof want, "<title>panel %d</title>", k);
    ck_assert_msg(strstr(svg, want) != NULL, "no %s", want);
  }
  ck_assert_ptr_null(strstr(svg, "skip 1 using"));
}
END_TEST

/* A field of one sign on a sequential scale from the 1st to the 99th
 * percentile (ranks 2 and 110 of 111): the pressure, and the vorticity
 * asked for a diverging scale but made one-signed (a vortex patch's). */
START_TEST(test_pressure_range_all_panels) {
  struct vsph_plot_panel pn[NPANEL];
  panels(pn);
  double a[NPANEL * NPART];
  for (int k = 0; k < NPANEL; k++)
    for (int i = 0; i < NPART; i++) a[k * NPART + i] = P[k][i];
  qsort(a, NPANEL * NPART, sizeof *a, cmp_d);
  double cb[4];
  ck_assert_int_eq(vsph_plot_particles(dir, "pic_p", "pressure", pn, NPANEL, 3,
                                       "p (Pa)", 0, NULL, cb),
                   VSPH_OK);
  double glo, ghi;
  script_cbrange("pic_p", &glo, &ghi);
  ck_assert_double_eq(glo, a[2 - 1]); /* exact, as above */
  ck_assert_double_eq(ghi, a[110 - 1]);
  ck_assert(cb[3] == 0.0);
  ck_assert_double_eq_tol(cb[2], 2.0 / 111.0, 1e-15);
  /* one sign, a diverging scale asked: sequential all the same */
  ck_assert_int_eq(vsph_plot_particles(dir, "pic_q", "pressure", pn, NPANEL, 3,
                                       "p (Pa)", 1, NULL, cb),
                   VSPH_OK);
  script_cbrange("pic_q", &glo, &ghi);
  ck_assert(cb[3] == 0.0 && glo == a[1] && ghi == a[109]);
}
END_TEST

START_TEST(test_figure_three_formats) {
  char path[128];
  snprintf(path, sizeof path, "%s/line.csv", dir);
  FILE *f = fopen(path, "w");
  ck_assert_ptr_nonnull(f);
  fprintf(f, "h,err\n");
  for (int i = 0; i < 5; i++) /* a third of a decade, and one rounding */
    fprintf(f, "%.6g,%.6g\n", 0.1 / (1 << i), i == 4 ? 2.385e-18 : 1.2348 + i);
  fclose(f);
  struct vsph_plot pl;
  vsph_plot_init(&pl, dir, "fig_line", "η_{num} against h", "h (m)", "ν");
  pl.logx = pl.logy = 1;
  pl.rounding = 1e-13;
  ck_assert_int_eq(
      vsph_plot_add(&pl, "line.csv", "1:2", "P_{visc}", "linespoints lt 1"),
      VSPH_OK);
  ck_assert_int_eq(vsph_plot_write(&pl), VSPH_OK);
  ck_assert(exists("fig_line", "png", "\x89PNG"));
  ck_assert(exists("fig_line", "svg", "<?xml"));
  ck_assert(exists("fig_line", "pdf", "%PDF"));
  /* the SVG is titled by the figure's name, not "Gnuplot" */
  static char svg[1 << 16];
  snprintf(path, sizeof path, "%s/fig_line.svg", dir);
  vsph_test_slurp(path, svg, sizeof svg);
  ck_assert_ptr_nonnull(strstr(svg, "<title>fig_line</title>"));
  ck_assert_ptr_null(strstr(svg, "<title>Gnuplot</title>"));
  /* its text two points above the PNG's 11 (drawn across the page) */
  ck_assert_ptr_nonnull(strstr(svg, "font-size=\"13.00\""));
  ck_assert_ptr_null(strstr(svg, "font-size=\"11.00\""));
  /* gnuplot said nothing: no warning, no error */
  char log[256];
  snprintf(log, sizeof log, "%s/fig_line.log", dir);
  vsph_test_slurp(log, path, sizeof path);
  ck_assert_str_eq(path, "");
  /* every group titled: the band's key entry by its words; where no value
   * lies below the rounding level (1e-20 here) the .gp gives the entry no
   * title, and its empty group is titled as such, not gnuplot's
   * "fig_none_plot_2" */
  ck_assert_ptr_nonnull(strstr(svg, "<title>rounding level (values below"));
  ck_assert_ptr_null(strstr(svg, "_plot_2</title>"));
  vsph_plot_init(&pl, dir, "fig_none", "none below", "h (m)", "ν");
  pl.logx = pl.logy = 1;
  pl.rounding = 1e-20;
  ck_assert_int_eq(
      vsph_plot_add(&pl, "line.csv", "1:2", "P_{visc}", "linespoints lt 1"),
      VSPH_OK);
  ck_assert_int_eq(vsph_plot_write(&pl), VSPH_OK);
  snprintf(path, sizeof path, "%s/fig_none.svg", dir);
  vsph_test_slurp(path, svg, sizeof svg);
  ck_assert_msg(strstr(svg,
                       "<title>rounding band: no value lies below the "
                       "rounding level here</title>"),
                "no band title in %s", path);
  ck_assert_ptr_null(strstr(svg, "_plot_2</title>"));
}
END_TEST

START_TEST(test_html_embeds_svg) {
  char path[128];
  snprintf(path, sizeof path, "%s/d.csv", dir);
  FILE *f = fopen(path, "w");
  ck_assert_ptr_nonnull(f);
  fprintf(f, "x,y\n1.2348,2.385\n2.385,1.2348\n");
  fclose(f);
  struct vsph_plot pl;
  vsph_plot_init(&pl, dir, "fig_d", "d", "x (m)", "y (m)");
  ck_assert_int_eq(vsph_plot_add(&pl, "d.csv", "1:2", "d", "lines"), VSPH_OK);
  ck_assert_int_eq(vsph_plot_write(&pl), VSPH_OK);
  snprintf(path, sizeof path, "%s/r.md", dir);
  f = fopen(path, "w");
  ck_assert_ptr_nonnull(f);
  fprintf(f, "![d](fig_d.svg)\n");
  fclose(f);
  ck_assert_int_eq(vsph_html_render(dir, "r.md", "r.html", "r"), VSPH_OK);
  static char html[1 << 16];
  snprintf(path, sizeof path, "%s/r.html", dir);
  vsph_test_slurp(path, html, sizeof html);
  /* the SVG itself, embedded, not a link to the file */
  ck_assert_ptr_nonnull(strstr(html, "src=\"data:image/svg+xml;base64,"));
  ck_assert_ptr_null(strstr(html, "src=\"fig_d.svg\""));
}
END_TEST

/* The report's mathematics set in its HTML without JavaScript (reports/html.c):
 * a subscript (E_k, eta_num), a Greek name as its letter, a superscript,
 * the signs written in ASCII (n.D.n != 0, ->, sqrt, -int), sum_j, pbar,
 * a Greek letter in UTF-8 with a subscript, superscripts of letters and
 * of a bracket ((-1)^(i+j)), each by hand; code spans,
 * file names and multi-underscore names stay as written, and docs/X.md is
 * a link where the source tree's docs/ is found (from the test's folder,
 * the repository's top). */
START_TEST(test_html_mathematics) {
  char path[128];
  snprintf(path, sizeof path, "%s/m.md", dir);
  FILE *f = fopen(path, "w");
  ck_assert_ptr_nonnull(f);
  fprintf(f,
          "E_k and eta_num at nu = 0.1, in m^2/s, when n.D.n != 0 -> "
          "u_theta; `E_k` and snap_0000.vtp and u_err_rel; see "
          "docs/theory.md; [a link about docs/theory.md](#x).\n\n"
          "u_\u03b8(r) and \u03b7_eff^num, U_j^R, pbar_i = sum_j x, "
          "(-1)^(i+j), K/(3 sqrt pi), sqrt(10) times, P -> -int V:D; "
          "the sum of a_b^c; the sqrt of two, no-int here, "
          "\u03b7_eff.csv, u_\n");
  fclose(f);
  ck_assert_int_eq(vsph_html_render(dir, "m.md", "m.html", "m"), VSPH_OK);
  static char html[1 << 16];
  snprintf(path, sizeof path, "%s/m.html", dir);
  vsph_test_slurp(path, html, sizeof html);
  static const char *const want[] = {
      "E<sub>k</sub> and \u03b7<sub>num</sub> at \u03bd = 0.1, in "
      "m<sup>2</sup>/s, when n\u00b7D\u00b7n \u2260 0 \u2192 "
      "u<sub>\u03b8</sub>;",
      "<code>E_k</code>", "snap_0000.vtp", "u_err_rel",
      "u<sub>\u03b8</sub>(r) and \u03b7<sub>eff</sub><sup>num</sup>, "
      "U<sub>j</sub><sup>R</sup>, p\u0304<sub>i</sub> = \u03a3<sub>j</sub> "
      "x, (-1)<sup>i+j</sup>, K/(3 \u221a\u03c0), \u221a(10) times, P "
      "\u2192 \u2212\u222b V:D; the sum of a<sub>b</sub><sup>c</sup>; "
      "the sqrt of two, no-int here, \u03b7_eff.csv, u_</p>",
      "docs/theory.md\">docs/theory.md</a>",
      /* inside a link's text: no link of its own */
      "<a href=\"#x\">a link about docs/theory.md</a>"};
  for (size_t k = 0; k < sizeof want / sizeof want[0]; k++)
    ck_assert_msg(strstr(html, want[k]) != NULL, "no '%s' in\n%s", want[k],
                  strstr(html, "<body>"));
}
END_TEST

/* Curves that would hide one another get their own dashes (io/plot.c):
 * lines without dashes of their own become solid, dotted (3), ...,
 * skipping a dash type another curve sets (here 3: the second line takes
 * 4); a curve's own dashes are kept. */
START_TEST(test_dashes_distinct_per_curve) {
  char path[128];
  snprintf(path, sizeof path, "%s/two.csv", dir);
  FILE *f = fopen(path, "w");
  ck_assert_ptr_nonnull(f);
  fprintf(f, "x,a,b,c\n1,1,1,1\n2,2,2,2\n");
  fclose(f);
  static char gp[1 << 14];
  struct vsph_plot pl;
  vsph_plot_init(&pl, dir, "fig_two", "two", "x (m)", "y (m)");
  ck_assert_int_eq(vsph_plot_add(&pl, "two.csv", "1:2", "a", "lines lw 2"),
                   VSPH_OK);
  ck_assert_int_eq(
      vsph_plot_add(&pl, "two.csv", "1:3", "b", "linespoints pt 7"), VSPH_OK);
  ck_assert_int_eq(vsph_plot_add(&pl, "two.csv", "1:4", "c", "lines dt 3"),
                   VSPH_OK);
  ck_assert_int_eq(vsph_plot_write(&pl), VSPH_OK);
  snprintf(path, sizeof path, "%s/fig_two.gp", dir);
  vsph_test_slurp(path, gp, sizeof gp);
  ck_assert_msg(strstr(gp, "with lines lw 2 dt 1 title") &&
                    strstr(gp, "with linespoints pt 7 dt 4 title") &&
                    strstr(gp, "with lines dt 3 title"),
                "%s", gp);
  /* a figure whose title gives its dashes a meaning: none added */
  pl.dashes_mean = 1;
  ck_assert_int_eq(vsph_plot_write(&pl), VSPH_OK);
  vsph_test_slurp(path, gp, sizeof gp);
  ck_assert_msg(strstr(gp, "with lines lw 2 title") &&
                    strstr(gp, "with linespoints pt 7 title"),
                "%s", gp);
}
END_TEST

/* Curves out of the key (vsph_plot_add_unkeyed: overlays such as the
 * hollow markers of stopped runs): no key entry (title ""), yet a pointer
 * over them in the SVG reads their hover text, plain and XML-escaped, not
 * gnuplot's "NAME_plot_K"; a keyed curve keeps its title. Refused: a NULL
 * or too long hover (no curve added). */
START_TEST(test_unkeyed_curves_hover) {
  char path[128];
  snprintf(path, sizeof path, "%s/h.csv", dir);
  FILE *f = fopen(path, "w");
  ck_assert_ptr_nonnull(f);
  fprintf(f, "x,a,b\n1,1,2\n2,2,3\n");
  fclose(f);
  struct vsph_plot pl;
  vsph_plot_init(&pl, dir, "fig_hover-1", "hover", "x (m)", "y (m)");
  ck_assert_int_eq(
      vsph_plot_add(&pl, "h.csv", "1:2", "MGF: a", "linespoints pt 7"), 0);
  ck_assert_int_eq(
      vsph_plot_add_unkeyed(&pl, "h.csv", "1:2", "MGF: stopped", "points pt 6"),
      0);
  ck_assert_int_eq(vsph_plot_add_unkeyed(&pl, "h.csv", "1:3", "E_{k} < 1 & > 0",
                                         "points pt 4"),
                   0);
  vsph_test_silence();
  char big[200];
  memset(big, 'x', sizeof big - 1);
  big[sizeof big - 1] = '\0';
  ck_assert_int_eq(vsph_plot_add_unkeyed(&pl, "h.csv", "1:3", big, "points"),
                   VSPH_EINVAL);
  ck_assert_int_eq(vsph_plot_add_unkeyed(&pl, "h.csv", "1:3", NULL, "points"),
                   VSPH_EINVAL);
  /* a newline would end the .gp's comment that names the hover text, the
   * rest run as gnuplot's commands: refused, and a tab */
  ck_assert_int_eq(vsph_plot_add_unkeyed(&pl, "h.csv", "1:3",
                                         "x\nsystem 'touch PWNED'", "points"),
                   VSPH_EINVAL);
  ck_assert_int_eq(vsph_plot_add_unkeyed(&pl, "h.csv", "1:3", "a\tb", "points"),
                   VSPH_EINVAL);
  ck_assert_uint_eq(pl.n, 3);
  ck_assert_int_eq(vsph_plot_write(&pl), 0);
  static char gp[1 << 14], svg[1 << 16];
  snprintf(path, sizeof path, "%s/fig_hover-1.gp", dir);
  vsph_test_slurp(path, gp, sizeof gp);
  ck_assert_msg(strstr(gp, "using 1:2 with points pt 6 title \"\"") &&
                    strstr(gp, "using 1:3 with points pt 4 title \"\""),
                "%s", gp);
  snprintf(path, sizeof path, "%s/fig_hover-1.svg", dir);
  vsph_test_slurp(path, svg, sizeof svg);
  static const char *const want[] = {
      "<g id=\"fig_hover_1_plot_1\" ><title>MGF: a</title>",
      "<g id=\"fig_hover_1_plot_2\" ><title>MGF: stopped</title>",
      "<g id=\"fig_hover_1_plot_3\" ><title>E_k &lt; 1 &amp; &gt; 0</title>"};
  for (size_t k = 0; k < sizeof want / sizeof want[0]; k++)
    ck_assert_msg(strstr(svg, want[k]), "no '%s' in %s", want[k], path);
  ck_assert_ptr_null(strstr(svg, "_plot_2</title>"));
  ck_assert_ptr_null(strstr(svg, "_plot_3</title>"));
  /* one key entry: the keyed curve's text alone is drawn */
  ck_assert_ptr_nonnull(strstr(svg, ">MGF: a</tspan>"));
  ck_assert_ptr_null(strstr(svg, ">MGF: stopped</tspan>"));
}
END_TEST

START_TEST(test_plain_text) {
  char out[64];
  vsph_plot_plain(out, sizeof out, "E_{k,ref}/E_{k,ref}(0), u_θ, 10^{-13}");
  ck_assert_str_eq(out, "E_k,ref/E_k,ref(0), u_θ, 10^-13");
  vsph_plot_plain(out, sizeof out, "{a_{b}} c^{d{e}}");
  ck_assert_str_eq(out, "{a_b} c^d{e}");
  vsph_plot_plain(out, 5, "P_{visc}");
  ck_assert_str_eq(out, "P_vi");
}
END_TEST

START_TEST(test_palette_distinct) {
  for (size_t a = 0; a < VSPH_PLOT_NSTYLES; a++)
    for (size_t b = a + 1; b < VSPH_PLOT_NSTYLES; b++) {
      ck_assert_str_ne(vsph_plot_colour(a), vsph_plot_colour(b));
      ck_assert_int_ne(vsph_plot_point(a), vsph_plot_point(b));
    }
  /* the formulations' colours, Okabe and Ito's: MGF blue, MEAF
   * vermillion, PVWF bluish green (no red against green) */
  ck_assert_str_eq(vsph_plot_colour(0), "#0072b2");
  ck_assert_str_eq(vsph_plot_colour(1), "#d55e00");
  ck_assert_str_eq(vsph_plot_colour(2), "#009e73");
  ck_assert_str_eq(vsph_plot_colour(VSPH_PLOT_NSTYLES), vsph_plot_colour(0));
}
END_TEST

START_TEST(test_plot_particles_bad_input_refused) {
  vsph_test_silence();
  struct vsph_plot_panel pn[1] = {{"missing.csv", "none"}};
  ck_assert_int_eq(
      vsph_plot_particles(dir, "x", "x", pn, 0, 4, "", 1, NULL, NULL),
      VSPH_EINVAL);
  ck_assert_int_eq(
      vsph_plot_particles(dir, "x", "x", pn, 1, 4, "", 1, NULL, NULL),
      VSPH_EIO);
}
END_TEST

/* A table read back: its columns by name, and their positions as
 * gnuplot's "using" counts them (from 1; 0 for none), so that a figure
 * names the column it draws. */
START_TEST(test_csv_columns) {
  char sdir[] = "/tmp/vsph-csv-XXXXXX", path[64];
  vsph_test_scratch(sdir);
  snprintf(path, sizeof path, "%s/e.csv", sdir);
  FILE *f = fopen(path, "w");
  ck_assert_ptr_nonnull(f);
  fputs("t,Ek,u_err\n0,1,0.5\n1,2,nan\n", f);
  fclose(f);
  struct vsph_csv *t = vsph_csv_read(path);
  ck_assert_ptr_nonnull(t);
  ck_assert_uint_eq(vsph_csv_column_number(t, "t"), 1);
  ck_assert_uint_eq(vsph_csv_column_number(t, "u_err"), 3);
  ck_assert_uint_eq(vsph_csv_column_number(t, "v_rms"), 0);
  const double *u = vsph_csv_column(t, "u_err");
  ck_assert_double_eq(u[0], 0.5);
  ck_assert(isnan(u[1]));
  vsph_csv_free(t);
  /* a text column (centreline.csv's "line"): NaN, its rows kept; a row
   * with text in a number column, or a field short, is skipped */
  f = fopen(path, "w");
  ck_assert_ptr_nonnull(f);
  fputs("t,line,vel\n0,u(y),0.5\n1,v(x),-0.25\n2,u(y),x\n3,u(y)\n", f);
  fclose(f);
  t = vsph_csv_read(path);
  ck_assert_ptr_nonnull(t);
  ck_assert_uint_eq(t->nrow, 2);
  ck_assert(isnan(vsph_csv_column(t, "line")[1]));
  ck_assert_double_eq(vsph_csv_column(t, "vel")[1], -0.25);
  ck_assert_double_eq(vsph_csv_column(t, "t")[1], 1.0);
  vsph_csv_free(t);
  vsph_test_rm_tree(sdir);
}
END_TEST

/* The dots' size (io/plot.c): about the particles' spacing on the page.
 * One panel of a 60 x 30 lattice filling the box [0, 2] x [0, 1]: the
 * panel is 340 px wide, so the spacing is 340 sqrt(2 / 1800) / 2 = 5.67 px
 * and the point size a tenth of it, 0.57 (the script writes two decimals);
 * with a tenth of the particles (one panel of 180) 1.79, clamped to 1.2;
 * without a box, the fixed 0.35. */
static double script_ps(const char *name) {
  char path[128], line[512];
  snprintf(path, sizeof path, "%s/%s.gp", dir, name);
  FILE *f = fopen(path, "r");
  ck_assert_ptr_nonnull(f);
  double ps = -1.0;
  while (fgets(line, sizeof line, f)) {
    const char *q = strstr(line, " ps ");
    if (q && strstr(line, "plot '"))
      ck_assert_int_eq(sscanf(q, " ps %lf", &ps), 1);
  }
  fclose(f);
  return ps;
}

START_TEST(test_dot_size_follows_spacing) {
  const int every[2] = {1, 10};
  const double want[2] = {0.57, 1.2};
  for (int c = 0; c < 2; c++) {
    struct vsph_plot_panel pn[1];
    snprintf(pn[0].file, sizeof pn[0].file, "lattice_%d.csv", c);
    snprintf(pn[0].title, sizeof pn[0].title, "lattice");
    char path[300];
    snprintf(path, sizeof path, "%s/%s", dir, pn[0].file);
    FILE *f = fopen(path, "w");
    ck_assert_ptr_nonnull(f);
    fprintf(f, "x,y,pressure\n");
    for (int i = 0; i < 60 * 30; i += every[c])
      fprintf(f, "%.6f,%.6f,%d\n", (i % 60 + 0.5) / 30.0, (i / 60 + 0.5) / 30.0,
              i % 7);
    fclose(f);
    const double box[4] = {0.0, 2.0, 0.0, 1.0};
    double cb[4];
    ck_assert_int_eq(vsph_plot_particles(dir, "pic_dots", "dots", pn, 1, 3,
                                         "p (Pa)", 0, box, cb),
                     VSPH_OK);
    ck_assert_double_eq_tol(script_ps("pic_dots"), want[c], 1e-9);
    ck_assert_int_eq(vsph_plot_particles(dir, "pic_dots", "dots", pn, 1, 3,
                                         "p (Pa)", 0, NULL, cb),
                     VSPH_OK);
    ck_assert_double_eq_tol(script_ps("pic_dots"), 0.35, 1e-9);
  }
}
END_TEST

Suite *vsph_plot_suite(void) {
  Suite *s = suite_create("plot");
  TCase *tc = tcase_create("core");
  tcase_add_checked_fixture(tc, setup, teardown);
  /* gnuplot makes three files per figure: a few tenths of a second each */
  tcase_set_timeout(tc, 60);
  tcase_add_test(tc, test_vorticity_limit_all_panels);
  tcase_add_test(tc, test_csv_columns);
  tcase_add_test(tc, test_pressure_range_all_panels);
  tcase_add_test(tc, test_figure_three_formats);
  tcase_add_test(tc, test_html_embeds_svg);
  tcase_add_test(tc, test_html_mathematics);
  tcase_add_test(tc, test_dashes_distinct_per_curve);
  tcase_add_test(tc, test_unkeyed_curves_hover);
  tcase_add_test(tc, test_plain_text);
  tcase_add_test(tc, test_palette_distinct);
  tcase_add_test(tc, test_plot_particles_bad_input_refused);
  tcase_add_test(tc, test_dot_size_follows_spacing);
  suite_add_tcase(s, tc);
  return s;
}
