/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
#include "csv.h"

#include <ctype.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "../common/status.h"
#include "files.h"

FILE *vsph_csv_open(const char *dir, const char *name, const char *header) {
  if (!header) {
    vsph_status_report(VSPH_EINVAL, __FILE__, __LINE__,
                       "vsph_csv_open: a NULL argument");
    return NULL;
  }
  FILE *f = vsph_files_open(dir, name);
  if (f) fprintf(f, "%s\n", header);
  return f;
}

int vsph_csv_close(FILE *f, const char *dir, const char *name) {
  return vsph_files_close(f, dir, name);
}

void vsph_csv_free(struct vsph_csv *t) {
  if (!t) return;
  for (size_t c = 0; t->names && c < t->ncol; c++) free(t->names[c]);
  free(t->names);
  free(t->data);
  free(t);
}

/* One field as a number: an empty field or "nan" is NaN; 0 if it is not a
 * number at all. */
static int field(const char *s, size_t len, double *v) {
  char buf[64];
  if (len == 0) {
    *v = (double)NAN;
    return 1;
  }
  if (len >= sizeof buf) return 0;
  memcpy(buf, s, len);
  buf[len] = '\0';
  char *end;
  *v = strtod(buf, &end);
  return *end == '\0';
}

struct vsph_csv *vsph_csv_read(const char *path) {
  if (!path) {
    vsph_status_report(VSPH_EINVAL, __FILE__, __LINE__,
                       "vsph_csv_read: a NULL argument");
    return NULL;
  }
  char *text = vsph_files_slurp(path, NULL);
  if (!text) {
    vsph_status_report(VSPH_EIO, __FILE__, __LINE__, "cannot read %s", path);
    return NULL;
  }
  struct vsph_csv *t = calloc(1, sizeof *t);
  char *eol = strchr(text, '\n');
  if (!t || !eol || eol == text) goto fail;
  *eol = '\0';
  t->ncol = 1;
  for (const char *c = text; *c; c++) t->ncol += *c == ',';
  t->names = calloc(t->ncol, sizeof *t->names);
  if (!t->names) goto fail;
  char *h = text;
  for (size_t c = 0; c < t->ncol; c++) {
    char *comma = strchr(h, ',');
    const size_t len = comma ? (size_t)(comma - h) : strlen(h);
    if (!(t->names[c] = malloc(len + 1))) goto fail;
    memcpy(t->names[c], h, len);
    t->names[c][len] = '\0';
    h += len + (comma != NULL);
  }
  size_t rows = 0;
  for (const char *c = eol + 1; *c; c++) rows += *c == '\n';
  rows++;
  double *row = malloc(t->ncol * sizeof *row);
  t->data = malloc(t->ncol * rows * sizeof *t->data);
  if (!row || !t->data) {
    free(row);
    goto fail;
  }
  /* parse into row-major scratch, then transpose once the count is known */
  double *rm = malloc(t->ncol * rows * sizeof *rm);
  if (!rm) {
    free(row);
    goto fail;
  }
  /* a column whose first row holds a word (centreline's "u(y)") is text:
   * it reads as NaN in every row, so its rows are kept */
  unsigned char *text_col = calloc(t->ncol, 1);
  if (!text_col) {
    free(row);
    free(rm);
    goto fail;
  }
  size_t n = 0;
  for (char *line = eol + 1; line && *line;) {
    char *next = strchr(line, '\n');
    const size_t llen = next ? (size_t)(next - line) : strlen(line);
    size_t c = 0;
    int ok = 1;
    const char *f = line;
    while (ok && c < t->ncol) {
      const char *comma = memchr(f, ',', llen - (size_t)(f - line));
      const size_t len =
          comma ? (size_t)(comma - f) : llen - (size_t)(f - line);
      ok = field(f, len, &row[c]);
      if (n == 0 && !ok && len > 0 && isalpha((unsigned char)f[0]))
        text_col[c] = 1; /* a word, not a broken number */
      if (text_col[c]) row[c] = (double)NAN, ok = 1;
      c++;
      if (!comma) break;
      f = comma + 1;
    }
    if (ok && c == t->ncol)
      memcpy(rm + n++ * t->ncol, row, t->ncol * sizeof *row);
    line = next ? next + 1 : NULL;
  }
  free(text_col);
  free(row);
  t->nrow = n;
  for (size_t r = 0; r < n; r++)
    for (size_t c = 0; c < t->ncol; c++)
      t->data[c * n + r] = rm[r * t->ncol + c];
  free(rm);
  free(text);
  return t;
fail:
  free(text);
  vsph_csv_free(t);
  vsph_status_report(VSPH_EIO, __FILE__, __LINE__, "%s is not a CSV table",
                     path);
  return NULL;
}

size_t vsph_csv_column_number(const struct vsph_csv *t, const char *name) {
  if (!t || !name) return 0;
  for (size_t c = 0; c < t->ncol; c++)
    if (!strcmp(t->names[c], name)) return c + 1;
  return 0;
}

const double *vsph_csv_column(const struct vsph_csv *t, const char *name) {
  if (!t || !name) return NULL;
  for (size_t c = 0; c < t->ncol; c++)
    if (!strcmp(t->names[c], name)) return t->data + c * t->nrow;
  return NULL;
}
