#ifndef VSPH_CLI_PLOT_H
#define VSPH_CLI_PLOT_H

#include <stddef.h>

/** @file plot.h
 *  @brief Figures for the report: a gnuplot script per figure (kept beside
 *  the PNG, so a reader can restyle it) run with gnuplot's pngcairo
 *  terminal. Data come from CSV files with a header row. */

/** Most curves in one figure. */
#define VSPH_PLOT_MAXSERIES 24

/** One curve: a CSV file and gnuplot's `using` expression. */
struct vsph_plot_series {
  const char *file;  /*!< CSV file name, relative to the figure's folder */
  const char *using; /*!< gnuplot using, e.g. "1:2" or "1:(abs($3))" */
  const char *title; /*!< legend entry */
  const char *style; /*!< "lines", "points", "linespoints" (+ options) */
};

/** One figure. */
struct vsph_plot {
  const char *dir;    /*!< folder of the data, the script and the PNG */
  const char *name;   /*!< base name: NAME.gp, NAME.png */
  const char *title;  /*!< figure title */
  const char *xlabel; /*!< axis labels, with units */
  const char *ylabel;
  int logx, logy;    /*!< log axes */
  const char *extra; /*!< further gnuplot commands, or NULL */
  size_t n;          /*!< curves */
  struct vsph_plot_series s[VSPH_PLOT_MAXSERIES];
};

/** @brief Write DIR/NAME.gp and run gnuplot on it to make DIR/NAME.png.
 *  @return 0, or VSPH_EIO (script not written, or gnuplot failed). */
int vsph_plot_write(const struct vsph_plot *pl);

/** @brief Render DIR/MD (GitHub-flavoured Markdown: tables) to DIR/HTML
 *  with cmark-gfm, embedding every local PNG as a data URI so the page is
 *  self-contained. Atomic. @return 0 or VSPH_EIO/VSPH_ENOMEM. */
int vsph_plot_html(const char *dir, const char *md, const char *html,
                   const char *title);

#endif /* VSPH_CLI_PLOT_H */
