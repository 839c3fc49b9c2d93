/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
#include "materials.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "../common/consts.h"
#include "../common/status.h"

/* Parshikov et al.'s Table 1, transcribed by hand from the paper and checked by
 * the ratios eta_num/(Z D0) it implies: 0.0894 +- 0.0025 with Wendland C2 and
 * 0.1078 +- 0.002 with the B-spline for 18 of the 20 rows, paraffin and
 * nitromethane the paper's own outliers (tests/check_contact.c).
 * Viscosities in mPa s here, Pa s in the struct. */
#define ROW(n, l, r, c, e, w, b) \
  { n, l, r, c, (double)(e)*1e-3, (w)*1e-3, (b)*1e-3 }
static const struct vsph_material TABLE[] = {
    ROW("lithium", "Lithium", 534, 4718, 0.566, 2.262, 2.72),
    ROW("benzene", "Benzene", 880, 1571.8, 0.604, 1.235, 1.469),
    ROW("paraffin", "Paraffin", 910, 895.6, 80.0, 0.863, 0.947),
    ROW("water", "Water", 1000, 1483, 1.004, 1.353, 1.58),
    ROW("nitromethane", "Nitromethane", 1128, 1144.7, 0.63, 1.264, 1.45),
    ROW("glycerol", "Glycerol", 1250, 1902.6, 1480, 2.074, 2.524),
    ROW("nacl", "Sodium chloride", 2160, 3496, 1.03, 6.672, 8.145),
    ROW("silica", "Silica", 2480, 4181.18, 10.0, 9.29, 11.206),
    ROW("lif", "Lithium fluoride", 2650, 5132.2, NAN, 12.206, 14.675),
    ROW("aluminium", "Aluminum", 2688.9, 5416, 1.24, 13.075, 15.719),
    ROW("corundum", "Corundum", 3920, 5779.8, NAN, 20.226, 24.471),
    ROW("titanium", "Titanium", 4510, 4924, 4.42, 20.047, 23.969),
    ROW("zinc", "Zinc", 6577, 3057, 3.737, 17.942, 21.580),
    ROW("iron", "Iron", 7880, 4660, 5.22, 32.96, 39.643),
    ROW("nickel", "Nickel", 8902, 4999.9, 5.01, 40.165, 48.015),
    ROW("copper", "Copper", 8920, 4118.5, 3.92, 32.852, 39.702),
    ROW("lead", "Lead", 11350, 1931.7, 2.3, 19.173, 23.278),
    ROW("tantalum", "Tantalum", 16600, 3481.5, 8.5, 51.034, 62.332),
    ROW("uranium", "\"Uranus\" (uranium)", 19100, 3056.88, 6.5, 52.103, 62.668),
    ROW("tungsten", "Tungsten", 19350, 3937.5, 7.0, 67.786, 82.332),
};
#undef ROW
#define NROWS ((int)(sizeof TABLE / sizeof TABLE[0]))

int vsph_materials_count(void) { return NROWS; }

const struct vsph_material *vsph_materials_get(int i) {
  return i >= 0 && i < NROWS ? &TABLE[i] : NULL;
}

int vsph_materials_resolve(const char *name, const struct vsph_material **out) {
  if (!out) VSPH_FAIL(VSPH_EINVAL, "vsph_materials_resolve: a NULL argument");
  *out = NULL;
  if (!name) VSPH_FAIL(VSPH_EINVAL, "vsph_materials_resolve: a NULL argument");
  for (int i = 0; i < NROWS; i++)
    if (strcmp(name, TABLE[i].name) == 0) {
      *out = &TABLE[i];
      return VSPH_OK;
    }
  char list[400] = "";
  size_t len = 0;
  for (int i = 0; i < NROWS && len < sizeof list; i++)
    len += (size_t)snprintf(list + len, sizeof list - len, "%s%s",
                            i ? ", " : "", TABLE[i].name);
  VSPH_FAIL(VSPH_EINVAL, "unknown material '%s' (%s)", name, list);
}

double vsph_materials_drag_row(double d_over_S) {
  const double w = 0.5 * VSPH_PI * d_over_S, w2 = w * w;
  /* the coefficients of w^2, w^4, ..., w^14 */
  const double c[7] = {2.0 / 3.0,          -1.0 / 9.0,
                       8.0 / 135.0,        -53.0 / 1350.0,
                       1112.0 / 42525.0,   -241643.0 / 13395375.0,
                       18776.0 / 1488375.0};
  double s = 0.0; /* Horner in w^2 */
  for (int k = 6; k >= 0; k--) s = (s + c[k]) * w2;
  const double a0 = 1.0 / (1.0 - 2.0 * log(2.0 * w) + s);
  return 8.0 * VSPH_PI * a0;
}

double vsph_materials_drag_square(double d_over_S) {
  const double c = 0.25 * VSPH_PI * d_over_S * d_over_S;
  return 4.0 * VSPH_PI /
         (-0.5 * log(c) - 0.738 + c - 0.887 * c * c + 2.038 * c * c * c);
}
