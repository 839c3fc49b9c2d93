/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
#include "scaling.h"

#include <gsl/gsl_fit.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "../common/consts.h"
#include "../common/params.h"
#include "../common/status.h"
#include "../kernels/kernel.h"
#include "../solver/cells.h"
#include "../solver/lattice.h"
#include "../solver/particles.h"
#include "../solver/viscous.h"
#include "moments.h"

/* The "Scaling" section as given (names and numbers); props_init checks
 * and resolves it into struct vsph_scaling_props. */
struct raw {
  char kernel[VSPH_PARAMS_NAME_MAX];
  size_t dim;
  char field[VSPH_PARAMS_NAME_MAX];
  char lattice[VSPH_PARAMS_NAME_MAX];
  double perturb;
  size_t seed;
  size_t levels;
  double hdx;
  double mu;
  double h0;
  double max_pairs;
};

#define P struct raw
static const struct vsph_params_spec SCALING[] = {
    VSPH_PARAMS_NAME_SPEC(P, kernel, "gaussian",
                          "gaussian, cubic, quintic, wendland2, wendland4"),
    VSPH_PARAMS_INT_SPEC(P, dim, 2, 1, 3, "dimension"),
    VSPH_PARAMS_NAME_SPEC(P, field, "strain",
                          "strain or rotation (surface sweep), quadratic "
                          "(interior, 2-D)"),
    VSPH_PARAMS_NAME_SPEC(P, lattice, "square",
                          "square, hex (2-D) or perturbed (square shifted by "
                          "up to perturb dx)"),
    VSPH_PARAMS_REAL_SPEC(P, perturb, 0.1, 0.0, 0.49,
                          "shift of the perturbed lattice, fraction of dx"),
    VSPH_PARAMS_INT_SPEC(P, seed, VSPH_CONSTS_SEED, 0, 4294967295.0,
                         "seed of that shift (mt19937)"),
    VSPH_PARAMS_INT_SPEC(P, levels, 5, 2, VSPH_SCALING_MAXLEVELS,
                         "h values, halving from h0 (at most 8 at the "
                         "surface); interior: h/dx values of 1, 4/3, 2, 3, "
                         "4, 6"),
    VSPH_PARAMS_REAL_SPEC(P, hdx, VSPH_CONSTS_HDX, 0.25, 16.0,
                          "h/dx, fixed (at most 4 in 3-D)"),
    VSPH_PARAMS_REAL_SPEC(P, mu, VSPH_CONSTS_MU, 1e-12, 1e6,
                          "dynamic viscosity (Pa s)"),
    VSPH_PARAMS_REAL_SPEC(P, h0, 0.1, 1e-6, 1e3, "largest h (m)"),
    VSPH_PARAMS_REAL_SPEC(P, max_pairs, VSPH_CONSTS_MAX_PAIRS, 1e3, 1e15,
                          "refuse a sweep estimated to need more neighbour "
                          "interactions (every form and level; 1e9: about 15 "
                          "s in 2-D, 30 s in 3-D on one core)"),
};
#undef P

const struct vsph_params_spec *vsph_scaling_params(size_t *n) {
  if (!n) return NULL;
  *n = sizeof SCALING / sizeof SCALING[0];
  return SCALING;
}

static const double HDX_LADDER[] = {1.0, VSPH_CONSTS_HDX, 2.0, 3.0, 4.0, 6.0};

size_t vsph_scaling_hdx_ladder(const double **hdx) {
  if (!hdx) return 0;
  *hdx = HDX_LADDER;
  return sizeof HDX_LADDER / sizeof HDX_LADDER[0];
}

double vsph_scaling_slope(const double *x, const double *y, size_t n) {
  if (!x) return NAN;
  double lx[VSPH_SCALING_MAXLEVELS], ly[VSPH_SCALING_MAXLEVELS];
  size_t m = 0;
  for (size_t k = 0; k < n && m < VSPH_SCALING_MAXLEVELS; k++)
    if (x[k] > 0 && y[k] > 0 && isfinite(x[k]) && isfinite(y[k])) {
      lx[m] = log(x[k]);
      ly[m] = log(y[k]);
      m++;
    }
  if (m < 2) return (double)NAN;
  double c0, c1, c00, c01, c11, ss;
  gsl_fit_linear(lx, 1, ly, 1, m, &c0, &c1, &c00, &c01, &c11, &ss);
  return c1;
}

int vsph_scaling_props_init(struct vsph_scaling_props *sp,
                            struct vsph_params *prm) {
  if (!sp) VSPH_FAIL(VSPH_EINVAL, "vsph_scaling_props_init: a NULL argument");
  struct raw r;
  memset(sp, 0, sizeof *sp);
  int st = vsph_params_load(prm, "Scaling", SCALING,
                            sizeof SCALING / sizeof SCALING[0], &r, sizeof r);
  if (st) return st;
  const int dim = (int)r.dim;
  if ((st = vsph_kernel_resolve(r.kernel, &sp->kernel))) return st;
  if (!sp->kernel)
    VSPH_FAIL(VSPH_EINVAL,
              "unknown kernel '%s' (gaussian, cubic, quintic, wendland2, "
              "wendland4)",
              r.kernel);
  const int fk = vsph_fields_find(r.field);
  if (fk != VSPH_FIELDS_STRAIN && fk != VSPH_FIELDS_ROTATION &&
      fk != VSPH_FIELDS_QUADRATIC)
    VSPH_FAIL(VSPH_EINVAL, "unknown field '%s' (strain, rotation, quadratic)",
              r.field);
  if ((st = vsph_fields_props_init(&sp->field, fk, dim))) return st;
  if ((st = vsph_lattice_resolve(r.lattice, dim, r.perturb, &sp->lattice,
                                 &sp->perturb)))
    return st;
  /* The surface patch has radius (2 kappa + 2/hdx) h, ~(6 hdx)^d particles
   * each with ~(3 hdx)^d neighbours: cost grows like hdx^(2d). These caps
   * keep one level within about 10 s on one core. */
  const double hdx_max = dim == 3 ? 4.0 : 16.0;
  if (r.hdx > hdx_max)
    VSPH_FAIL(VSPH_EINVAL,
              "Scaling:hdx above %g in %d-D would need too many particles, "
              "got %g",
              hdx_max, dim, r.hdx);
  if (fk != VSPH_FIELDS_QUADRATIC && r.levels > 8)
    VSPH_FAIL(VSPH_EINVAL,
              "Scaling:levels above 8 gives h below h0/256: use at most 8");
  sp->seed = (unsigned long)r.seed;
  sp->levels = r.levels;
  sp->h0 = r.h0;
  sp->hdx = r.hdx;
  sp->mu = r.mu;
  sp->round_tol = 1e-9;
  sp->max_pairs = r.max_pairs;
  return VSPH_OK;
}

/* The work of one patch of radius @p R dx (half a ball for @p half): each
 * particle gathers from the ball of radius kappa hdx (in dx) once per pass
 * of every form (eval_forms runs them all: 13 forms, 21 passes). */
static double patch_pairs(const struct vsph_scaling_props *sp, int dim,
                          double R, int half) {
  const double r = sp->kernel->kappa * sp->hdx;
  const double ball = dim == 1 ? 2.0 : dim == 2 ? VSPH_PI : 4.0 / 3.0 * VSPH_PI;
  double passes = 0.0;
  for (int f = 0; f < VSPH_VISCOUS_FORM_COUNT; f++)
    passes += 1.0 + vsph_viscous_first_pass(f);
  return ball * pow(R, dim) * (half ? 0.5 : 1.0) * ball * pow(r, dim) * passes;
}

static int check_pairs(const struct vsph_scaling_props *sp, double pairs,
                       const char *what) {
  if (!(pairs <= sp->max_pairs))
    VSPH_FAIL(VSPH_EINVAL,
              "the %s needs about %.3g neighbour interactions (every form, "
              "every level), more than Scaling:max_pairs = %g: lower hdx or "
              "levels, or raise max_pairs",
              what, pairs, sp->max_pairs);
  return VSPH_OK;
}

/* Evaluate every formulation on patch p; values at particle `id0`. */
static int eval_forms(const struct vsph_scaling_props *sp,
                      struct vsph_particles *p, size_t id0, double h,
                      double vals[VSPH_VISCOUS_FORM_COUNT][3], size_t *centre) {
  const int dim = p->dim;
  struct vsph_cells *cells = vsph_cells_alloc();
  struct vsph_viscous_ws *ws = vsph_viscous_ws_alloc(p->n, dim);
  double *buf = malloc(3 * p->n * sizeof *buf);
  int st = VSPH_OK;
  if (!cells || !ws || !buf) {
    st = VSPH_ENOMEM;
    goto done;
  }
  for (size_t i = 0; i < p->n; i++) {
    double x[3] = {0, 0, 0}, u[3], g[9];
    for (int k = 0; k < dim; k++) x[k] = p->pos[k][i];
    vsph_fields_eval(&sp->field, x, u, g);
    for (int k = 0; k < dim; k++) p->vel[k][i] = u[k];
  }
  if ((st = vsph_cells_build(cells, p, sp->kernel->kappa * h))) goto done;
  size_t c = 0;
  while (c < p->n && p->id[c] != id0) c++;
  *centre = c;
  double *f[3] = {buf, dim > 1 ? buf + p->n : NULL,
                  dim > 2 ? buf + 2 * p->n : NULL};
  for (int form = 0; form < VSPH_VISCOUS_FORM_COUNT; form++) {
    struct vsph_viscous_props vp;
    if ((st = vsph_viscous_props_init(&vp, form, sp->kernel, dim, h, sp->mu)))
      goto done;
    if ((st = vsph_viscous_compute(&vp, p, cells, ws, f, NULL))) goto done;
    for (int k = 0; k < 3; k++) vals[form][k] = k < dim ? f[k][c] : 0.0;
  }
done:
  free(buf);
  vsph_viscous_ws_free(ws);
  vsph_cells_free(cells);
  return st;
}

int vsph_scaling_surface(const struct vsph_scaling_props *sp,
                         struct vsph_scaling_result *res) {
  if (!sp || !res)
    VSPH_FAIL(VSPH_EINVAL, "vsph_scaling_surface: a NULL argument");
  const int dim = sp->field.dim;
  if (sp->levels < 2 || sp->levels > VSPH_SCALING_MAXLEVELS)
    VSPH_FAIL(VSPH_EINVAL, "levels must lie in 2-%d, got %zu",
              VSPH_SCALING_MAXLEVELS, sp->levels);
  if (!(sp->hdx > 0.0) || !isfinite(sp->hdx))
    VSPH_FAIL(VSPH_EINVAL, "h/dx must be positive, got %g", sp->hdx);
  if (sp->field.kind != VSPH_FIELDS_STRAIN &&
      sp->field.kind != VSPH_FIELDS_ROTATION)
    VSPH_FAIL(VSPH_EINVAL, "the surface sweep takes strain or rotation");
  /* every level lays the same patch (radius 2 kappa hdx + 2 in dx) */
  const int st0 = check_pairs(
      sp,
      (double)sp->levels *
          patch_pairs(sp, dim, 2.0 * sp->kernel->kappa * sp->hdx + 2.0, 1),
      "surface sweep");
  if (st0) return st0;
  memset(res, 0, sizeof *res);
  res->levels = sp->levels;
  const double U = sp->field.kind == VSPH_FIELDS_STRAIN ? fabs(sp->field.A)
                                                        : fabs(sp->field.Omega);
  for (size_t l = 0; l < sp->levels; l++) {
    const double h = sp->h0 / pow(2.0, (double)l), dx = h / sp->hdx;
    struct vsph_lattice_props lp = {.dim = dim,
                                    .kind = sp->lattice,
                                    .dx = dx,
                                    .perturb = sp->perturb,
                                    .seed = sp->seed + l};
    struct vsph_particles *p = NULL;
    size_t centre;
    const double radius = 2.0 * sp->kernel->kappa * h + 2.0 * dx;
    int st = vsph_lattice_halfspace(&lp, radius, 0.0, &p, &centre);
    if (st) return st;
    struct vsph_moments mo;
    st = vsph_moments_sum(sp->kernel, p, centre, h, &mo);
    double vals[VSPH_VISCOUS_FORM_COUNT][3];
    size_t c;
    if (!st) st = eval_forms(sp, p, p->id[centre], h, vals, &c);
    vsph_particles_free(p);
    if (st) return st;
    res->h[l] = h;
    res->hF[l] = h * mo.F[dim - 1][dim - 1][dim - 1];
    res->hN[l] = h * mo.N[dim - 1];
    for (int form = 0; form < VSPH_VISCOUS_FORM_COUNT; form++) {
      double t2 = 0.0, m2 = 0.0;
      for (int k = 0; k < dim; k++) {
        m2 += vals[form][k] * vals[form][k];
        if (k != dim - 1) t2 += vals[form][k] * vals[form][k];
      }
      res->normal[form][l] = vals[form][dim - 1];
      res->tangential[form][l] = sqrt(t2);
      res->magnitude[form][l] = sqrt(m2);
    }
  }
  /* Rounding level: the operator of a linear field scales as mu U / h, so
   * anything below round_tol times that at the finest h is noise, whose
   * slope would mean nothing. */
  const double hmin = res->h[sp->levels - 1];
  res->round_level = sp->round_tol * sp->mu * U / hmin;
  for (int form = 0; form < VSPH_VISCOUS_FORM_COUNT; form++) {
    double mx = 0.0;
    for (size_t l = 0; l < sp->levels; l++)
      mx = fmax(mx, res->magnitude[form][l]);
    res->max_magnitude[form] = mx;
    res->rounding[form] = mx <= res->round_level;
    if (res->rounding[form]) {
      res->slope[form] = NAN;
      continue;
    }
    res->slope[form] =
        vsph_scaling_slope(res->h, res->magnitude[form], sp->levels);
  }
  return VSPH_OK;
}

int vsph_scaling_interior(const struct vsph_scaling_props *sp,
                          const double *hdx, size_t n,
                          struct vsph_scaling_interior *res) {
  if (!sp || !hdx || !res)
    VSPH_FAIL(VSPH_EINVAL, "vsph_scaling_interior: a NULL argument");
  if (sp->field.kind != VSPH_FIELDS_QUADRATIC || sp->field.dim != 2)
    VSPH_FAIL(VSPH_EINVAL, "the interior sweep takes the 2-D quadratic field");
  if (n < 1 || n > VSPH_SCALING_MAXLEVELS)
    VSPH_FAIL(VSPH_EINVAL, "between 1 and %d h/dx values",
              VSPH_SCALING_MAXLEVELS);
  memset(res, 0, sizeof *res);
  res->n = n;
  const double h = sp->h0;
  double lap[3], gd[3];
  const double x0[3] = {0, 0, 0};
  vsph_fields_second(&sp->field, x0, lap, gd);
  double t_mgf[2], t_meaf[2];
  for (int k = 0; k < 2; k++) {
    t_mgf[k] = sp->mu * (lap[k] + 2.0 * gd[k]);
    t_meaf[k] = sp->mu * lap[k];
  }
  for (size_t l = 0; l < n; l++) {
    if (!(hdx[l] > 0.0)) VSPH_FAIL(VSPH_EINVAL, "h/dx must be positive");
    const double dx = h / hdx[l];
    struct vsph_lattice_props lp = {.dim = 2,
                                    .kind = sp->lattice,
                                    .dx = dx,
                                    .perturb = sp->perturb,
                                    .seed = sp->seed};
    struct vsph_particles *p = NULL;
    size_t centre, c;
    const double radius = sp->kernel->kappa * h + 2.0 * dx;
    int st = vsph_lattice_halfspace(&lp, radius, radius, &p, &centre);
    if (st) return st;
    double vals[VSPH_VISCOUS_FORM_COUNT][3];
    st = eval_forms(sp, p, p->id[centre], h, vals, &c);
    vsph_particles_free(p);
    if (st) return st;
    res->hdx[l] = hdx[l];
    res->mgf[l] = hypot(vals[VSPH_VISCOUS_MGF][0] - t_mgf[0],
                        vals[VSPH_VISCOUS_MGF][1] - t_mgf[1]) /
                  hypot(t_mgf[0], t_mgf[1]);
    res->meaf[l] = hypot(vals[VSPH_VISCOUS_MEAF][0] - t_meaf[0],
                         vals[VSPH_VISCOUS_MEAF][1] - t_meaf[1]) /
                   hypot(t_meaf[0], t_meaf[1]);
  }
  return VSPH_OK;
}

int vsph_scaling_axis(const struct vsph_scaling_props *sp, size_t nacross,
                      double *y, double *f[VSPH_VISCOUS_FORM_COUNT],
                      size_t *n) {
  if (!sp || !y) VSPH_FAIL(VSPH_EINVAL, "vsph_scaling_axis: a NULL argument");
  if (sp->field.dim != 2)
    VSPH_FAIL(VSPH_EINVAL, "the square's axis needs a 2-D field");
  struct vsph_lattice_props lp = {.dim = 2, .kind = VSPH_LATTICE_SQUARE};
  struct vsph_particles *p = NULL;
  int st = vsph_lattice_square(&lp, 1.0, nacross, &p);
  if (st) return st;
  const double dx = 1.0 / (double)nacross, h = sp->hdx * dx;
  /* the column x = dx/2 (ids on the lattice: b * nacross + a) */
  const size_t a = nacross / 2;
  *n = nacross;
  for (size_t b = 0; b < nacross; b++) y[b] = p->pos[1][b * nacross + a];
  struct vsph_cells *cells = vsph_cells_alloc();
  struct vsph_viscous_ws *ws = vsph_viscous_ws_alloc(p->n, 2);
  double *buf = malloc(2 * p->n * sizeof *buf);
  if (!cells || !ws || !buf) {
    st = VSPH_ENOMEM;
    vsph_status_report(st, __FILE__, __LINE__, "cannot allocate the axis");
  }
  for (size_t i = 0; i < p->n && !st; i++) {
    double x[3] = {p->pos[0][i], p->pos[1][i], 0}, u[3], g[9];
    vsph_fields_eval(&sp->field, x, u, g);
    p->vel[0][i] = u[0];
    p->vel[1][i] = u[1];
  }
  if (!st) st = vsph_cells_build(cells, p, sp->kernel->kappa * h);
  double *out[3] = {buf, buf ? buf + p->n : NULL, NULL};
  for (int form = 0; form < VSPH_VISCOUS_FORM_COUNT && !st; form++) {
    struct vsph_viscous_props vp;
    if ((st = vsph_viscous_props_init(&vp, form, sp->kernel, 2, h, sp->mu)))
      break;
    if ((st = vsph_viscous_compute(&vp, p, cells, ws, out, NULL))) break;
    for (size_t i = 0; i < p->n; i++) { /* sorted by cell: find by id */
      const size_t id = p->id[i];
      if (id % nacross == a) f[form][id / nacross] = out[1][i];
    }
  }
  free(buf);
  vsph_viscous_ws_free(ws);
  vsph_cells_free(cells);
  vsph_particles_free(p);
  return st;
}
