/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
#ifndef VSPH_IO_CSV_H
#define VSPH_IO_CSV_H

#include <stddef.h>
#include <stdio.h>

#include "../common/api.h"

/** @file csv.h
 *  @brief Comma-separated tables with one header row, the format every
 *  vsph table and figure keeps its data in (gnuplot, spreadsheets and
 *  pandas open it directly): written atomically, and read back into
 *  columns looked up by their header name. A NULL argument is refused:
 *  VSPH_EINVAL where a status is returned, else NULL (reported) or 0. */

/** @brief Open DIR/NAME for writing (atomically, see files.h) and write
 *  the header row @p header ("t,Ek,Ep"). NULL after reporting. */
VSPH_API FILE *vsph_csv_open(const char *dir, const char *name,
                             const char *header);

/** @brief Close a table from vsph_csv_open. @return VSPH_OK or VSPH_EIO. */
VSPH_API int vsph_csv_close(FILE *f, const char *dir, const char *name);

/** A table read back: numeric columns, stored column by column. */
struct vsph_csv {
  size_t ncol;  /*!< columns */
  size_t nrow;  /*!< data rows (rows that did not parse are skipped) */
  char **names; /*!< header names */
  double *data; /*!< column c is data[c * nrow ...] */
};

/** @brief Read the CSV file @p path (header row, then numbers; an empty
 *  field or "nan" reads as NaN; a column whose first row holds text, as
 *  centreline.csv's "line", reads as NaN throughout; a row with another
 *  field that is no number, or too few fields, is skipped). NULL after
 *  reporting if it cannot be read or has no header. */
VSPH_API struct vsph_csv *vsph_csv_read(const char *path);

/** @brief Free; NULL is a no-op. */
VSPH_API void vsph_csv_free(struct vsph_csv *t);

/** @brief The column called @p name (nrow values), or NULL. */
VSPH_API const double *vsph_csv_column(const struct vsph_csv *t,
                                       const char *name);

/** @brief The position of the column called @p name counted from 1, as
 *  gnuplot's `using` counts, or 0 when there is none. */
VSPH_API size_t vsph_csv_column_number(const struct vsph_csv *t,
                                       const char *name);

#endif /* VSPH_IO_CSV_H */
