/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
#include "lattice.h"

#include <gsl/gsl_rng.h>
#include <math.h>
#include <string.h>

#include "../common/consts.h"
#include "../common/status.h"
#include "particles.h"

static const char *const lattice_names[] = {
    [VSPH_LATTICE_SQUARE] = "square",
    [VSPH_LATTICE_HEX] = "hex",
};
_Static_assert(sizeof lattice_names / sizeof lattice_names[0] ==
                   VSPH_LATTICE_KIND_COUNT,
               "lattice name table out of sync");

const char *vsph_lattice_name(int kind) {
  return kind >= 0 && kind < VSPH_LATTICE_KIND_COUNT ? lattice_names[kind]
                                                     : "unknown";
}

const char *vsph_lattice_label(int kind, double perturb) {
  return perturb > 0.0 ? "perturbed" : vsph_lattice_name(kind);
}

int vsph_lattice_find(const char *name) {
  if (!name) return -1;
  for (int k = 0; k < VSPH_LATTICE_KIND_COUNT; k++)
    if (strcmp(lattice_names[k], name) == 0) return k;
  return -1;
}

int vsph_lattice_resolve(const char *name, int dim, double perturb, int *kind,
                         double *amp) {
  if (!name || !kind || !amp)
    VSPH_FAIL(VSPH_EINVAL, "vsph_lattice_resolve: a NULL argument");
  const int perturbed = !strcmp(name, "perturbed");
  *kind = perturbed ? VSPH_LATTICE_SQUARE : vsph_lattice_find(name);
  if (*kind < 0)
    VSPH_FAIL(VSPH_EINVAL, "unknown lattice '%s' (square, hex, perturbed)",
              name);
  if (*kind == VSPH_LATTICE_HEX && dim != 2)
    VSPH_FAIL(VSPH_EINVAL, "the hex lattice is 2-D only");
  if (!(perturb >= 0 && perturb < 0.5))
    VSPH_FAIL(VSPH_EINVAL, "the perturbation must lie in [0, 0.5), got %g",
              perturb);
  *amp = perturbed ? perturb : 0.0;
  return VSPH_OK;
}

static int check_props(const struct vsph_lattice_props *lp) {
  if (lp->dim < 1 || lp->dim > 3)
    VSPH_FAIL(VSPH_EINVAL, "dimension %d outside 1-3", lp->dim);
  if (!(lp->dx > 0.0) || !isfinite(lp->dx))
    VSPH_FAIL(VSPH_EINVAL, "lattice spacing must be positive, got %g", lp->dx);
  if (lp->kind == VSPH_LATTICE_HEX && lp->dim != 2)
    VSPH_FAIL(VSPH_EINVAL, "the hexagonal lattice is 2-D only");
  if (!(lp->perturb >= 0.0 && lp->perturb < 0.5))
    VSPH_FAIL(VSPH_EINVAL, "perturbation must lie in [0, 0.5), got %g",
              lp->perturb);
  return VSPH_OK;
}

int vsph_lattice_perturb(struct vsph_particles *p, double amp,
                         unsigned long seed, size_t skip) {
  if (!p) VSPH_FAIL(VSPH_EINVAL, "vsph_lattice_perturb: a NULL argument");
  gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937);
  if (!rng) VSPH_FAIL(VSPH_ENOMEM, "cannot allocate a random generator");
  gsl_rng_set(rng, seed);
  for (size_t i = 0; i < p->n; i++) {
    if (i == skip) continue;
    for (int k = 0; k < p->dim; k++)
      p->pos[k][i] += amp * (2.0 * gsl_rng_uniform(rng) - 1.0);
  }
  gsl_rng_free(rng);
  return VSPH_OK;
}

static void set_unit_density(struct vsph_particles *p, double vol) {
  for (size_t i = 0; i < p->n; i++) {
    p->rho[i] = 1.0;
    p->m[i] = vol;
    p->vol[i] = vol;
    p->id[i] = i;
  }
}

static int finish(const struct vsph_lattice_props *lp, struct vsph_particles *p,
                  size_t skip) {
  if (lp->perturb > 0.0)
    return vsph_lattice_perturb(p, lp->perturb * lp->dx, lp->seed, skip);
  return VSPH_OK;
}

int vsph_lattice_halfspace(const struct vsph_lattice_props *lp, double radius,
                           double depth, struct vsph_particles **out,
                           size_t *centre) {
  if (!lp || !out || !centre)
    VSPH_FAIL(VSPH_EINVAL, "vsph_lattice_halfspace: a NULL argument");
  int st = check_props(lp);
  if (st) return st;
  if (!(radius > 0.0) || !(depth >= 0.0))
    VSPH_FAIL(VSPH_EINVAL, "radius %g and depth %g must be positive", radius,
              depth);
  const int dim = lp->dim;
  /* Hexagonal: same area per particle as the square lattice dx^2. */
  const double a =
      lp->kind == VSPH_LATTICE_HEX ? lp->dx * sqrt(2.0 / sqrt(3.0)) : lp->dx;
  const double dy = lp->kind == VSPH_LATTICE_HEX ? a * sqrt(3.0) / 2.0 : a;
  const long mt = (long)ceil(radius / a) + 1;  /* tangential index range */
  const long mn = (long)ceil(radius / dy) + 1; /* normal index range */
  /* Rows above the depth are excluded; the small relative slack keeps a row
   * that sits exactly on the plane despite rounding in depth/dy. */
  const long top = (long)floor(depth / dy * (1.0 + 1e-12) + 1e-12);
  size_t cap = 1;
  for (int k = 0; k < dim - 1; k++) cap *= (size_t)(2 * mt + 2);
  cap *= (size_t)(2 * mn + 1);
  struct vsph_particles *p = vsph_particles_alloc(cap, dim);
  if (!p) return VSPH_ENOMEM;
  size_t n = 0;
  *centre = 0;
  const long t1 = dim >= 2 ? mt : 0, t2 = dim == 3 ? mt : 0;
  for (long kn = -mn; kn <= (top < mn ? top : mn); kn++)
    for (long k2 = -t2; k2 <= t2; k2++)
      for (long k1 = -t1; k1 <= t1; k1++) {
        double x[3] = {0, 0, 0};
        if (dim == 1) {
          x[0] = (double)kn * dy;
        } else {
          const double shift =
              (lp->kind == VSPH_LATTICE_HEX && (kn % 2 != 0)) ? 0.5 : 0.0;
          x[0] = ((double)k1 + shift) * a;
          if (dim == 3) x[1] = (double)k2 * a;
          x[dim - 1] = (double)kn * dy;
        }
        double r2 = 0.0;
        for (int k = 0; k < dim; k++) r2 += x[k] * x[k];
        if (r2 > radius * radius) continue;
        if (kn == 0 && k1 == 0 && k2 == 0) *centre = n;
        for (int k = 0; k < dim; k++) p->pos[k][n] = x[k];
        n++;
      }
  p->n = n;
  set_unit_density(p, pow(lp->dx, dim));
  st = finish(lp, p, *centre);
  if (st) {
    vsph_particles_free(p);
    return st;
  }
  *out = p;
  return VSPH_OK;
}

/* The nodes ((a + 1/2) dx - side/2, (b + 1/2) dx - side/2) of a square
 * of side @p side, dx = side/nacross, b outer and a inner, keeping those
 * with r < @p radius (INFINITY: all), each of volume dx^2. */
static int grid(const struct vsph_lattice_props *lp, double side,
                size_t nacross, double radius, struct vsph_particles **out) {
  const double dx = side / (double)nacross;
  struct vsph_lattice_props l2 = *lp;
  l2.dx = dx;
  int st = check_props(&l2);
  if (st) return st;
  struct vsph_particles *p = vsph_particles_alloc(nacross * nacross, 2);
  if (!p) return VSPH_ENOMEM;
  size_t n = 0;
  for (size_t b = 0; b < nacross; b++)
    for (size_t a = 0; a < nacross; a++) {
      const double x = -0.5 * side + ((double)a + 0.5) * dx;
      const double y = -0.5 * side + ((double)b + 0.5) * dx;
      if (x * x + y * y >= radius * radius) continue;
      p->pos[0][n] = x;
      p->pos[1][n] = y;
      n++;
    }
  p->n = n;
  set_unit_density(p, dx * dx);
  st = finish(&l2, p, (size_t)-1);
  if (st) {
    vsph_particles_free(p);
    return st;
  }
  *out = p;
  return VSPH_OK;
}

int vsph_lattice_square(const struct vsph_lattice_props *lp, double side,
                        size_t nacross, struct vsph_particles **out) {
  if (!lp || !out)
    VSPH_FAIL(VSPH_EINVAL, "vsph_lattice_square: a NULL argument");
  if (lp->dim != 2 || lp->kind != VSPH_LATTICE_SQUARE)
    VSPH_FAIL(VSPH_EINVAL, "the square set is a 2-D square lattice");
  if (nacross < 1 || !(side > 0.0))
    VSPH_FAIL(VSPH_EINVAL, "square needs side > 0 and at least 1 particle");
  return grid(lp, side, nacross, INFINITY, out);
}

int vsph_lattice_disc(const struct vsph_lattice_props *lp, double radius,
                      size_t nacross, struct vsph_particles **out) {
  if (!lp || !out) VSPH_FAIL(VSPH_EINVAL, "vsph_lattice_disc: a NULL argument");
  if (lp->dim != 2) VSPH_FAIL(VSPH_EINVAL, "the disc set is 2-D");
  if (nacross < 2 || !(radius > 0.0))
    VSPH_FAIL(VSPH_EINVAL, "disc needs radius > 0 and at least 2 particles");
  const size_t rings = nacross / 2;
  const double dr = radius / (double)rings;
  struct vsph_lattice_props l2 = *lp;
  l2.dx = dr;
  int st = check_props(&l2);
  if (st) return st;
  size_t cap = 0;
  for (size_t k = 0; k < rings; k++) {
    const double rk = ((double)k + 0.5) * dr;
    cap += (size_t)fmax(1.0, round(2.0 * VSPH_PI * rk / dr));
  }
  struct vsph_particles *p = vsph_particles_alloc(cap, 2);
  if (!p) return VSPH_ENOMEM;
  size_t n = 0;
  for (size_t k = 0; k < rings; k++) {
    const double rk = ((double)k + 0.5) * dr;
    const size_t nk = (size_t)fmax(1.0, round(2.0 * VSPH_PI * rk / dr));
    const double vk = 2.0 * VSPH_PI * rk * dr / (double)nk;
    /* Alternate rings are rotated by half a step to avoid radial spokes. */
    const double off = (k % 2) ? 0.5 : 0.0;
    for (size_t j = 0; j < nk; j++) {
      const double th = 2.0 * VSPH_PI * ((double)j + off) / (double)nk;
      p->pos[0][n] = rk * cos(th);
      p->pos[1][n] = rk * sin(th);
      p->rho[n] = 1.0;
      p->m[n] = p->vol[n] = vk;
      p->id[n] = n;
      n++;
    }
  }
  p->n = n;
  st = finish(&l2, p, (size_t)-1);
  if (st) {
    vsph_particles_free(p);
    return st;
  }
  *out = p;
  return VSPH_OK;
}

int vsph_lattice_disc_cartesian(const struct vsph_lattice_props *lp,
                                double radius, size_t nacross,
                                struct vsph_particles **out) {
  if (!lp || !out)
    VSPH_FAIL(VSPH_EINVAL, "vsph_lattice_disc_cartesian: a NULL argument");
  if (lp->dim != 2) VSPH_FAIL(VSPH_EINVAL, "the disc set is 2-D");
  if (nacross < 2 || !(radius > 0.0))
    VSPH_FAIL(VSPH_EINVAL, "disc needs radius > 0 and at least 2 particles");
  return grid(lp, 2.0 * radius, nacross, radius, out);
}
