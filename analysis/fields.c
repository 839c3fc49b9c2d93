/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
#include "fields.h"

#include <math.h>
#include <string.h>

#include "../common/consts.h"
#include "../common/status.h"

static const char *const field_names[] = {
    [VSPH_FIELDS_ROTATION] = "rotation",
    [VSPH_FIELDS_STRAIN] = "strain",
    [VSPH_FIELDS_MIXED] = "mixed",
    [VSPH_FIELDS_QUADRATIC] = "quadratic",
};
_Static_assert(sizeof field_names / sizeof field_names[0] ==
                   VSPH_FIELDS_KIND_COUNT,
               "field name table out of sync");

const char *vsph_fields_name(int kind) {
  return kind >= 0 && kind < VSPH_FIELDS_KIND_COUNT ? field_names[kind]
                                                    : "unknown";
}

int vsph_fields_find(const char *name) {
  if (!name) return -1;
  for (int k = 0; k < VSPH_FIELDS_KIND_COUNT; k++)
    if (strcmp(field_names[k], name) == 0) return k;
  return -1;
}

int vsph_fields_props_init(struct vsph_fields_props *fp, int kind, int dim) {
  if (kind < 0 || kind >= VSPH_FIELDS_KIND_COUNT)
    VSPH_FAIL(VSPH_EINVAL, "unknown field %d", kind);
  if (dim < 1 || dim > 3)
    VSPH_FAIL(VSPH_EINVAL, "dimension %d outside 1-3", dim);
  if (kind == VSPH_FIELDS_ROTATION && dim < 2)
    VSPH_FAIL(VSPH_EINVAL, "rotation needs at least 2 dimensions");
  if ((kind == VSPH_FIELDS_MIXED || kind == VSPH_FIELDS_QUADRATIC) && dim != 2)
    VSPH_FAIL(VSPH_EINVAL, "field '%s' is defined in 2-D only",
              field_names[kind]);
  memset(fp, 0, sizeof *fp);
  fp->kind = kind;
  fp->dim = dim;
  fp->A = 1.2348;
  fp->Omega = 0.8731;
  fp->U = 0.4;
  fp->k = VSPH_PI;
  const double c[6] = {0.7, -1.3, 0.45, -0.35, 0.9, 1.1};
  memcpy(fp->c, c, sizeof c);
  return VSPH_OK;
}

void vsph_fields_eval(const struct vsph_fields_props *fp, const double x[3],
                      double u[3], double grad[9]) {
  if (!fp || !x || !u || !grad) return;
  const int d = fp->dim, n = d - 1; /* plane (0, n) */
  for (int a = 0; a < 3; a++) u[a] = 0.0;
  for (int a = 0; a < 9; a++) grad[a] = 0.0;
  switch (fp->kind) {
    case VSPH_FIELDS_ROTATION:
      u[0] = -fp->Omega * x[n];
      u[n] = fp->Omega * x[0];
      grad[0 * d + n] = -fp->Omega;
      grad[n * d + 0] = fp->Omega;
      break;
    case VSPH_FIELDS_STRAIN:
      if (d == 1) { /* 1-D: the only linear field, u = A x */
        u[0] = fp->A * x[0];
        grad[0] = fp->A;
        break;
      }
      if (fp->theta != 0.0) { /* axes turned by theta */
        const double c = fp->A * cos(2.0 * fp->theta);
        const double s = fp->A * sin(2.0 * fp->theta);
        u[0] = c * x[0] + s * x[n];
        u[n] = s * x[0] - c * x[n];
        grad[0] = c;
        grad[0 * d + n] = s;
        grad[n * d + 0] = s;
        grad[n * d + n] = -c;
        break;
      }
      u[0] = fp->A * x[0];
      u[n] = -fp->A * x[n];
      grad[0] = fp->A;
      grad[n * d + n] = -fp->A;
      break;
    case VSPH_FIELDS_MIXED: {
      const double k = fp->k, sx = sin(k * x[0]), cx = cos(k * x[0]);
      const double sy = sin(k * x[1]), cy = cos(k * x[1]);
      u[0] = fp->A * x[0] - fp->Omega * x[1] + fp->U * sx * cy;
      u[1] = -fp->A * x[1] + fp->Omega * x[0] - fp->U * cx * sy;
      grad[0] = fp->A + fp->U * k * cx * cy;
      grad[1] = -fp->Omega - fp->U * k * sx * sy;
      grad[2] = fp->Omega + fp->U * k * sx * sy;
      grad[3] = -fp->A - fp->U * k * cx * cy;
      break;
    }
    case VSPH_FIELDS_QUADRATIC: {
      const double *c = fp->c, X = x[0], Y = x[1];
      u[0] = c[0] * X * X + c[1] * X * Y + c[2] * Y * Y;
      u[1] = c[3] * X * X + c[4] * X * Y + c[5] * Y * Y;
      grad[0] = 2.0 * c[0] * X + c[1] * Y;
      grad[1] = c[1] * X + 2.0 * c[2] * Y;
      grad[2] = 2.0 * c[3] * X + c[4] * Y;
      grad[3] = c[4] * X + 2.0 * c[5] * Y;
      break;
    }
    default:
      break;
  }
}

void vsph_fields_second(const struct vsph_fields_props *fp, const double x[3],
                        double lap[3], double graddiv[3]) {
  if (!fp || !x || !lap || !graddiv) return;
  for (int a = 0; a < 3; a++) lap[a] = graddiv[a] = 0.0;
  if (fp->kind == VSPH_FIELDS_QUADRATIC) {
    const double *c = fp->c;
    lap[0] = 2.0 * (c[0] + c[2]);
    lap[1] = 2.0 * (c[3] + c[5]);
    /* div u = (2 c0 + c4) x + (c1 + 2 c5) y */
    graddiv[0] = 2.0 * c[0] + c[4];
    graddiv[1] = c[1] + 2.0 * c[5];
  } else if (fp->kind == VSPH_FIELDS_MIXED) {
    /* The Taylor-Green cell is an eigenfunction: lap = -2 k^2 u_TG. */
    const double k = fp->k, f = -2.0 * k * k * fp->U;
    lap[0] = f * sin(k * x[0]) * cos(k * x[1]);
    lap[1] = -f * cos(k * x[0]) * sin(k * x[1]);
  }
}
