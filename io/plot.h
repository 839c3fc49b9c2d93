/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
#ifndef VSPH_IO_PLOT_H
#define VSPH_IO_PLOT_H

#include <stddef.h>

#include "../common/api.h"

/** @file plot.h
 *  @brief Figures: a gnuplot script per figure, kept beside its outputs so
 *  a reader can restyle it and run `gnuplot NAME.gp`, which remakes all
 *  three: NAME.png (pngcairo), NAME.svg (svg, embedded in report.html) and
 *  NAME.pdf (pdfcairo, for papers). Data come from CSV files with a header
 *  row. Every script shares one palette (VSPH_PLOT_NSTYLES distinct
 *  colours and point types as gnuplot linetypes 1, 2, ...). A figure owns
 *  copies of its strings: callers need no buffers of their own. A NULL
 *  argument is refused: VSPH_EINVAL (reported) where a status is
 *  returned; vsph_plot_init and vsph_plot_plain read a NULL string as
 *  "" and do nothing without a figure or a buffer. */

/** Most curves in one figure. */
#define VSPH_PLOT_MAXSERIES 24

/** Distinct colours (and point types) of the shared palette: linetype k
 *  (1-based) of every script is vsph_plot_colour(k - 1) with point type
 *  vsph_plot_point(k - 1); past the last, they cycle. */
#define VSPH_PLOT_NSTYLES 15

/** One curve: a CSV file and gnuplot's `using` expression. */
struct vsph_plot_series {
  char file[128];  /*!< CSV file, relative to the figure's folder */
  char using[128]; /*!< gnuplot using, e.g. "1:2" or "1:(abs($3))" */
  char title[128]; /*!< legend entry ("" for none), gnuplot enhanced text */
  char style[128]; /*!< "lines lw 2", "points pt 7", ... */
  char hover[128]; /*!< a curve out of the key (title ""): what a pointer
                        over it in the SVG shows (plain text), not
                        gnuplot's "NAME_plot_K"; "" for that */
};

/** One figure. */
struct vsph_plot {
  char dir[512];    /*!< folder of the data, the script and the outputs */
  char name[128];   /*!< base name: NAME.gp, NAME.png, NAME.svg, NAME.pdf */
  char title[256];  /*!< figure title (enhanced text) */
  char xlabel[160]; /*!< axis labels, with units (enhanced text) */
  char ylabel[160];
  int logx, logy;  /*!< log axes: every decade labelled, and 1-2-5 (or
                        1...9) ticks labelled where the data span less than
                        3 decades (0.7); a `set xtics` or `set ytics` in
                        extra (e.g. at the data's resolutions) wins */
  double rounding; /*!< with logy: y values below this (same unit as y) are
                        rounding noise, drawn in a shaded "rounding level"
                        band under the data instead of stretching the axis
                        down to them; 0: none */
  char extra[512]; /*!< further gnuplot commands */
  int dashes_mean; /*!< 1: the curves' dashes carry a meaning the title
                        states ("solid" one quantity, "dashed" another), so
                        none are added to tell hidden curves apart */
  size_t n;        /*!< curves */
  struct vsph_plot_series s[VSPH_PLOT_MAXSERIES]; /*!< the curves */
};

/** @brief Colour @p k of the shared palette, "#rrggbb" (k modulo
 *  VSPH_PLOT_NSTYLES). The first three are the free-surface study's
 *  formulations' (MGF blue, MEAF vermillion, PVWF bluish green). */
VSPH_API const char *vsph_plot_colour(size_t k);

/** @brief Point type @p k of the shared palette (gnuplot's pt, filled
 *  shapes first; k modulo VSPH_PLOT_NSTYLES). For k < 6 the point type
 *  one less is the same shape open (a second series of one colour). */
VSPH_API int vsph_plot_point(size_t k);

/** @brief Enhanced text @p text as plain text for Markdown (captions, alt
 *  text): the braces of `_{...}` and `^{...}` dropped ("E_{k,ref}" ->
 *  "E_k,ref"), the rest (UTF-8 Greek included) kept; truncated to fit
 *  @p n bytes. */
VSPH_API void vsph_plot_plain(char *out, size_t n, const char *text);

/** @brief Start a figure DIR/NAME with its title and axis labels (copied);
 *  no curves, linear axes. */
VSPH_API void vsph_plot_init(struct vsph_plot *pl, const char *dir,
                             const char *name, const char *title,
                             const char *xlabel, const char *ylabel);

/** @brief Add a curve (strings copied). @return VSPH_OK or VSPH_EINVAL
 *  (VSPH_PLOT_MAXSERIES reached, or a string too long). */
VSPH_API int vsph_plot_add(struct vsph_plot *pl, const char *file,
                           const char *using, const char *title,
                           const char *style);

/** @brief Add a curve left out of the key (title "", as an overlay on
 *  another curve's points) whose SVG group is titled @p hover, one line
 *  of text (its gnuplot markup, _{...} and ^{...}, set plain as the key's
 *  titles are), for a pointer over it: gnuplot titles a curve's group in
 *  the SVG by its key title and one without by "NAME_plot_K", so
 *  vsph_plot_write sets @p hover in NAME.svg after gnuplot (running
 *  NAME.gp again by hand leaves gnuplot's; a gnuplot that names the group
 *  otherwise leaves the figure as it drew it, with a warning).
 *  @return as vsph_plot_add (@p hover too long, or holding a control
 *  character such as a newline: VSPH_EINVAL). */
VSPH_API int vsph_plot_add_unkeyed(struct vsph_plot *pl, const char *file,
                                   const char *using, const char *hover,
                                   const char *style);

/** @brief Write DIR/NAME.gp and run gnuplot on it to make DIR/NAME.png,
 *  .svg and .pdf, then title the SVG's curves out of the key
 *  (vsph_plot_add_unkeyed). @return VSPH_OK, VSPH_EINVAL (more than
 *  VSPH_PLOT_MAXSERIES curves), or VSPH_EIO (script not written, gnuplot
 *  failed: its messages are in DIR/NAME.log, or NAME.svg not retitled). */
VSPH_API int vsph_plot_write(const struct vsph_plot *pl);

/** One panel of a particle picture: a CSV of particles and its title. */
struct vsph_plot_panel {
  char file[128];  /*!< CSV with a header row, relative to the folder */
  char title[128]; /*!< panel title */
};

/** @brief A particle picture DIR/NAME (.gp, .png, .svg, .pdf): @p n
 *  panels (two rows from 3 panels on), each the particles of a CSV drawn
 *  as dots at columns 1:2 (x, y, in m) coloured by the column @p col, axes
 *  to scale and labelled. The panels share one colour scale, fixed in the
 *  script as `set cbrange [lo:hi]` from every value of column @p col in
 *  every panel's file (all particles, inside the box or not; non-finite
 *  values skipped), robust to a few extreme particles: @p diverging and
 *  values of both signs: a blue-white-red palette on [-M, M], M the 99th
 *  percentile of |value| (M = 1 if it is 0); else (one sign, or not
 *  diverging) a sequential one from the 1st to the 99th percentile
 *  (nearest rank); a value beyond them takes the end colour. @p box: x
 *  and y ranges (xlo, xhi, ylo, yhi) every panel shares, or NULL (each
 *  its own); the canvas follows its aspect. At most 8 panels. @p cb, for
 *  a caption, or NULL: the range (lo, hi), the share of the values beyond
 *  it, and 1 where the scale is diverging.
 *  @return VSPH_OK, VSPH_EINVAL (panels, or no finite value in column
 *  @p col), VSPH_EIO (a CSV unreadable, or as vsph_plot_write). */
VSPH_API int vsph_plot_particles(const char *dir, const char *name,
                                 const char *title,
                                 const struct vsph_plot_panel *pn, size_t n,
                                 int col, const char *cblabel, int diverging,
                                 const double box[4], double cb[4]);

#endif /* VSPH_IO_PLOT_H */
