#ifndef VSPH_IO_PLOT_H
#define VSPH_IO_PLOT_H

#include <stddef.h>

/** @file plot.h
 *  @brief Figures: a gnuplot script per figure, kept beside its PNG so a
 *  reader can restyle it and run `gnuplot NAME.gp`, rendered with gnuplot's
 *  pngcairo terminal. Data come from CSV files with a header row. A figure
 *  owns copies of its strings: callers need no buffers of their own. */

/** Most curves in one figure. */
#define VSPH_PLOT_MAXSERIES 24

/** One curve: a CSV file and gnuplot's `using` expression. */
struct vsph_plot_series {
  char file[128];  /*!< CSV file, relative to the figure's folder */
  char using[128]; /*!< gnuplot using, e.g. "1:2" or "1:(abs($3))" */
  char title[128]; /*!< legend entry ("" for none) */
  char style[128]; /*!< "lines lw 2", "points pt 7", ... */
};

/** One figure. */
struct vsph_plot {
  char dir[512];    /*!< folder of the data, the script and the PNG */
  char name[128];   /*!< base name: NAME.gp, NAME.png */
  char title[256];  /*!< figure title */
  char xlabel[160]; /*!< axis labels, with units */
  char ylabel[160];
  int logx, logy;  /*!< log axes */
  char extra[512]; /*!< further gnuplot commands */
  size_t n;        /*!< curves */
  struct vsph_plot_series s[VSPH_PLOT_MAXSERIES]; /*!< the curves */
};

/** @brief Start a figure DIR/NAME with its title and axis labels (copied);
 *  no curves, linear axes. */
void vsph_plot_init(struct vsph_plot *pl, const char *dir, const char *name,
                    const char *title, const char *xlabel, const char *ylabel);

/** @brief Add a curve (strings copied). @return VSPH_OK or VSPH_EINVAL
 *  (VSPH_PLOT_MAXSERIES reached, or a string too long). */
int vsph_plot_add(struct vsph_plot *pl, const char *file, const char *using,
                  const char *title, const char *style);

/** @brief Write DIR/NAME.gp and run gnuplot on it to make DIR/NAME.png.
 *  @return VSPH_OK, or VSPH_EIO (script not written, or gnuplot failed:
 *  its messages are in DIR/NAME.log). */
int vsph_plot_write(const struct vsph_plot *pl);

/** One panel of a particle picture: a CSV of particles and its title. */
struct vsph_plot_panel {
  char file[128];  /*!< CSV with a header row, relative to the folder */
  char title[128]; /*!< panel title */
};

/** @brief A particle picture DIR/NAME.png (and .gp): @p n panels side by
 *  side (two rows from 3 panels on), each the particles of a CSV drawn as
 *  dots at columns 1:2 (x, y) coloured by the column @p col, axes to
 *  scale. @p diverging: a blue-white-red palette centred on 0 (signed
 *  fields such as vorticity), else a sequential one. @p box: x and y
 *  ranges (xlo, xhi, ylo, yhi) every panel shares, or NULL (each its own).
 *  At most 8 panels.
 *  @return VSPH_OK, VSPH_EINVAL or VSPH_EIO (as vsph_plot_write). */
int vsph_plot_particles(const char *dir, const char *name, const char *title,
                        const struct vsph_plot_panel *pn, size_t n, int col,
                        const char *cblabel, int diverging,
                        const double box[4]);

#endif /* VSPH_IO_PLOT_H */
