/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
#include "dissipation.h"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>
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

static const char *const shape_names[] = {
    [VSPH_DISSIPATION_DISC] = "disc",
    [VSPH_DISSIPATION_SQUARE] = "square",
};
_Static_assert(sizeof shape_names / sizeof shape_names[0] ==
                   VSPH_DISSIPATION_SHAPE_COUNT,
               "shape name table out of sync");

/* Both shapes span 1 m: square side, disc diameter. */
static const double EXTENT = 1.0;

const char *vsph_dissipation_shape_name(int shape) {
  return shape >= 0 && shape < VSPH_DISSIPATION_SHAPE_COUNT ? shape_names[shape]
                                                            : "unknown";
}

int vsph_dissipation_shape_find(const char *name) {
  if (!name) return -1;
  for (int k = 0; k < VSPH_DISSIPATION_SHAPE_COUNT; k++)
    if (strcmp(shape_names[k], name) == 0) return k;
  return -1;
}

/* The "Dissipation" section as given; props_init resolves it. */
struct raw {
  char formulation[VSPH_PARAMS_NAME_MAX];
  char field[VSPH_PARAMS_NAME_MAX];
  char shape[VSPH_PARAMS_NAME_MAX];
  char kernel[VSPH_PARAMS_NAME_MAX];
  size_t res;
  double hdx;
  double mu;
  double perturb;
  size_t seed;
  double angle;
  double epsrel;
  double max_memory;
  double max_pairs;
};

#define P struct raw
static const struct vsph_params_spec DISSIPATION[] = {
    VSPH_PARAMS_NAME_SPEC(P, formulation, "mgf",
                          "viscous formulation: " VSPH_VISCOUS_NAMES),
    VSPH_PARAMS_NAME_SPEC(P, field, "strain",
                          "rotation (exact P = 0), strain (exact -4 mu A^2 "
                          "|S|) or mixed"),
    VSPH_PARAMS_NAME_SPEC(P, shape, "square",
                          "square (side 1 m) or disc (diameter 1 m, rings)"),
    VSPH_PARAMS_NAME_SPEC(P, kernel, "gaussian",
                          "gaussian, cubic, quintic, wendland2, wendland4"),
    VSPH_PARAMS_INT_SPEC(P, res, 40, 2, 4000, "particles across the shape"),
    VSPH_PARAMS_REAL_SPEC(P, hdx, VSPH_CONSTS_HDX, 0.25, 16.0, "h/dx"),
    VSPH_PARAMS_REAL_SPEC(P, mu, VSPH_CONSTS_MU, 1e-12, 1e6,
                          "dynamic viscosity (Pa s)"),
    VSPH_PARAMS_REAL_SPEC(P, perturb, 0.0, 0.0, 0.49,
                          "random shift of the lattice, fraction of dx"),
    VSPH_PARAMS_INT_SPEC(P, seed, VSPH_CONSTS_SEED, 0, 4294967295.0,
                         "seed of that shift (mt19937)"),
    VSPH_PARAMS_REAL_SPEC(P, angle, 0.0, -180.0, 180.0,
                          "strain only: angle of its axes to the lattice "
                          "(degrees; 0: u = A(x, -y), 45: pure shear)"),
    VSPH_PARAMS_REAL_SPEC(P, epsrel, 1e-10, 1e-13, 1e-3,
                          "relative accuracy of the exact integrals"),
    VSPH_PARAMS_REAL_SPEC(P, max_memory, VSPH_CONSTS_MAX_MEMORY, 1e-3, 4096,
                          "refuse a set estimated to need more memory (GiB)"),
    VSPH_PARAMS_REAL_SPEC(P, max_pairs, VSPH_CONSTS_MAX_PAIRS, 1e3, 1e15,
                          "refuse a set estimated to need more neighbour "
                          "interactions (particles x neighbours x passes; "
                          "1e9: about 40 s on one core)"),
};
#undef P

const struct vsph_params_spec *vsph_dissipation_params(size_t *n) {
  if (!n) return NULL;
  *n = sizeof DISSIPATION / sizeof DISSIPATION[0];
  return DISSIPATION;
}

int vsph_dissipation_props_init(struct vsph_dissipation_props *dp,
                                struct vsph_params *prm) {
  if (!dp)
    VSPH_FAIL(VSPH_EINVAL, "vsph_dissipation_props_init: a NULL argument");
  struct raw r;
  memset(dp, 0, sizeof *dp);
  int st = vsph_params_load(prm, "Dissipation", DISSIPATION,
                            sizeof DISSIPATION / sizeof DISSIPATION[0], &r,
                            sizeof r);
  if (st) return st;
  if ((st = vsph_viscous_resolve(r.formulation, &dp->form))) return st;
  const int fk = vsph_fields_find(r.field);
  if (fk != VSPH_FIELDS_ROTATION && fk != VSPH_FIELDS_STRAIN &&
      fk != VSPH_FIELDS_MIXED)
    VSPH_FAIL(VSPH_EINVAL, "unknown field '%s' (rotation, strain, mixed)",
              r.field);
  if ((st = vsph_fields_props_init(&dp->field, fk, 2))) return st;
  if (r.angle != 0.0 && fk != VSPH_FIELDS_STRAIN)
    VSPH_FAIL(VSPH_EINVAL, "angle applies to the strain field only");
  dp->field.theta = r.angle * VSPH_PI / 180.0;
  const int sh = vsph_dissipation_shape_find(r.shape);
  if (sh < 0)
    VSPH_FAIL(VSPH_EINVAL, "unknown shape '%s' (disc, square)", r.shape);
  dp->shape = sh;
  if ((st = vsph_kernel_resolve(r.kernel, &dp->kernel))) return st;
  if (!dp->kernel)
    VSPH_FAIL(VSPH_EINVAL,
              "unknown kernel '%s' (gaussian, cubic, quintic, wendland2, "
              "wendland4)",
              r.kernel);
  dp->nacross = r.res;
  dp->hdx = r.hdx;
  /* the lattice's nearest neighbours lie at dx: a support that does not
   * reach past them holds none, and every sum is 0/0 */
  if (!(dp->kernel->kappa * dp->hdx > 1.0))
    VSPH_FAIL(VSPH_EINVAL,
              "Dissipation:hdx = %g: the %s kernel reaches %g h = %g dx, so "
              "its support holds no neighbour of the lattice; raise hdx above "
              "%g",
              dp->hdx, r.kernel, dp->kernel->kappa, dp->kernel->kappa * dp->hdx,
              1.0 / dp->kernel->kappa);
  dp->mu = r.mu;
  dp->perturb = r.perturb;
  dp->seed = (unsigned long)r.seed;
  dp->epsrel = r.epsrel;
  dp->max_memory = r.max_memory;
  dp->max_pairs = r.max_pairs;
  return VSPH_OK;
}

/* Dissipation densities at x: V:D = 2 mu D:D + lambda (tr D)^2 with the
 * Stokes lambda = -2 mu / d, 2 mu D:D and tr D apart (for a form's own
 * lambda), mu |grad u|^2, and -u . mu lap u. */
struct densities {
  double vd_stokes, dd2, tr2, grad2, ulap;
};

static struct densities densities_at(const struct vsph_fields_props *fp,
                                     double mu, const double x[3]) {
  double u[3], g[9], lap[3], graddiv[3];
  vsph_fields_eval(fp, x, u, g);
  vsph_fields_second(fp, x, lap, graddiv);
  const int d = fp->dim;
  double DD = 0.0, tr = 0.0, G2 = 0.0;
  for (int a = 0; a < d; a++) {
    tr += g[a * d + a];
    for (int b = 0; b < d; b++) {
      const double D = 0.5 * (g[a * d + b] + g[b * d + a]);
      DD += D * D;
      G2 += g[a * d + b] * g[a * d + b];
    }
  }
  double ul = 0.0;
  for (int a = 0; a < d; a++) ul += u[a] * lap[a];
  struct densities r = {2.0 * mu * DD - 2.0 * mu / d * tr * tr, 2.0 * mu * DD,
                        tr * tr, mu * G2, -mu * ul};
  return r;
}

/* The continuum limit of a formulation's dissipation density (its
 * descriptor's limit, with its lambda for the stress limit). */
static double limit_density(const struct densities *d, int limit,
                            double lambda) {
  switch (limit) {
    case VSPH_VISCOUS_LIMIT_GRADIENT:
      return d->grad2;
    case VSPH_VISCOUS_LIMIT_LAPLACIAN:
      return d->ulap;
    default:
      return d->dd2 + lambda * d->tr2;
  }
}

struct exact_ctx {
  const struct vsph_dissipation_props *dp;
  int which;        /* 0: V:D (Stokes), 1: |grad u|^2, 2: -u . lap u */
  double outer_var; /* r (disc) or x (square) */
  gsl_integration_workspace *inner;
  double epsrel;
  int status;
};

static double exact_density(const struct exact_ctx *e, const double x[3]) {
  const struct densities d = densities_at(&e->dp->field, e->dp->mu, x);
  return e->which == 2 ? d.ulap : e->which ? d.grad2 : d.vd_stokes;
}

static double inner_fn(double t, void *v) {
  struct exact_ctx *e = v;
  double x[3] = {0, 0, 0};
  if (e->dp->shape == VSPH_DISSIPATION_DISC) {
    x[0] = e->outer_var * cos(t);
    x[1] = e->outer_var * sin(t);
    return e->outer_var * exact_density(e, x); /* r dr dtheta */
  }
  x[0] = e->outer_var;
  x[1] = t;
  return exact_density(e, x);
}

static double outer_fn(double s, void *v) {
  struct exact_ctx *e = v;
  e->outer_var = s;
  gsl_function fn = {inner_fn, e};
  const int disc = e->dp->shape == VSPH_DISSIPATION_DISC;
  const double lo = disc ? 0.0 : -0.5 * EXTENT;
  const double hi = disc ? 2.0 * VSPH_PI : 0.5 * EXTENT;
  double res, err;
  const int st =
      gsl_integration_qag(&fn, lo, hi, 1e-300, 0.1 * e->epsrel, e->inner->limit,
                          GSL_INTEG_GAUSS41, e->inner, &res, &err);
  if (st && st != GSL_EROUND && !e->status) e->status = st;
  return res;
}

/* The first n of -int V:D, -mu int |grad u|^2 and mu int u . lap u over
 * the shape into out[0..n-1]. */
static int exact_integrals(const struct vsph_dissipation_props *dp, int n,
                           double out[3]) {
  gsl_integration_workspace *wo = gsl_integration_workspace_alloc(200);
  gsl_integration_workspace *wi = gsl_integration_workspace_alloc(200);
  if (!wo || !wi) {
    gsl_integration_workspace_free(wo);
    gsl_integration_workspace_free(wi);
    VSPH_FAIL(VSPH_ENOMEM, "cannot allocate quadrature workspaces");
  }
  const int disc = dp->shape == VSPH_DISSIPATION_DISC;
  const double lo = disc ? 0.0 : -0.5 * EXTENT, hi = 0.5 * EXTENT;
  int rc = VSPH_OK;
  for (int which = 0; which < n && !rc; which++) {
    struct exact_ctx e = {dp, which, 0.0, wi, dp->epsrel, 0};
    gsl_function fn = {outer_fn, &e};
    double err;
    /* epsabs 1e-300: an integrand that is identically zero (D = 0 for a
     * rotation) still terminates, with the exact result 0. */
    const int st =
        gsl_integration_qag(&fn, lo, hi, 1e-300, dp->epsrel, wo->limit,
                            GSL_INTEG_GAUSS41, wo, &out[which], &err);
    if ((st && st != GSL_EROUND) || e.status) {
      vsph_status_report(VSPH_ELIB, __FILE__, __LINE__,
                         "dissipation quadrature: %s",
                         gsl_strerror(st ? st : e.status));
      rc = VSPH_ELIB;
    }
  }
  gsl_integration_workspace_free(wo);
  gsl_integration_workspace_free(wi);
  /* 0.0 - x, not -x: an integral of zero prints as 0, not -0 */
  for (int which = 0; which < n; which++) out[which] = 0.0 - out[which];
  return rc;
}

int vsph_dissipation_exact(const struct vsph_dissipation_props *dp,
                           double *P_exact, double *P_grad) {
  if (!dp || !P_exact || !P_grad)
    VSPH_FAIL(VSPH_EINVAL, "vsph_dissipation_exact: a NULL argument");
  double out[3];
  const int rc = exact_integrals(dp, 2, out);
  if (rc) return rc;
  *P_exact = out[0];
  *P_grad = out[1];
  return VSPH_OK;
}

/* Distance from x to the edge of the shape (positive inside). */
static double edge_distance(int shape, const double x[3]) {
  if (shape == VSPH_DISSIPATION_DISC) return 0.5 * EXTENT - hypot(x[0], x[1]);
  return 0.5 * EXTENT - fmax(fabs(x[0]), fabs(x[1]));
}

/* (div V)_i into f and the pairwise density into dens for every particle
 * of p (sorted by cell on the way), through a cell list and workspace of
 * its own; PVWF's fallback count into *nfb. */
static int evaluate(const struct vsph_viscous_props *vp,
                    struct vsph_particles *p, double *const f[3], double *dens,
                    size_t *nfb) {
  struct vsph_cells *cells = vsph_cells_alloc();
  struct vsph_viscous_ws *ws = vsph_viscous_ws_alloc(p->n, vp->dim);
  int st = VSPH_ENOMEM;
  if (cells && ws &&
      !(st = vsph_cells_build(cells, p, vp->kernel->kappa * vp->h)) &&
      !(st = vsph_viscous_compute(vp, p, cells, ws, f, dens)))
    *nfb = vsph_viscous_first_pass(vp->form) ? ws->n_fallback : 0;
  vsph_viscous_ws_free(ws);
  vsph_cells_free(cells);
  return st;
}

int vsph_dissipation_particles(const struct vsph_viscous_props *vp,
                               const struct vsph_particles *p,
                               struct vsph_dissipation_power *out) {
  if (!vp || !p || !out) VSPH_FAIL(VSPH_EINVAL, "no props, set or result");
  if (!vsph_viscous_type_get(vp->form))
    VSPH_FAIL(VSPH_EINVAL, "unknown viscous formulation %d", vp->form);
  if (!vp->kernel) VSPH_FAIL(VSPH_EINVAL, "no kernel given");
  if (!(vp->h > 0.0) || !isfinite(vp->h))
    VSPH_FAIL(VSPH_EINVAL, "smoothing length must be positive, got %g", vp->h);
  if (vp->dim != p->dim)
    VSPH_FAIL(VSPH_EINVAL, "props in %d-D, particles in %d-D", vp->dim, p->dim);
  const int dim = p->dim;
  for (size_t i = 0; i < p->n; i++) {
    if (!(p->m[i] > 0.0) || !(p->rho[i] > 0.0) || !isfinite(p->m[i]) ||
        !isfinite(p->rho[i]))
      VSPH_FAIL(VSPH_EINVAL,
                "particle %zu: mass %g and density %g must be positive", i,
                p->m[i], p->rho[i]);
    for (int k = 0; k < dim; k++)
      if (!isfinite(p->pos[k][i]) || !isfinite(p->vel[k][i]))
        VSPH_FAIL(VSPH_EINVAL,
                  "particle %zu: position and velocity must be finite", i);
  }
  /* a copy of the set: the cell list sorts it, the caller's stays as it
   * is */
  struct vsph_particles *q = vsph_particles_alloc(p->n ? p->n : 1, dim);
  const size_t n = p->n ? p->n : 1;
  double *buf = q ? malloc(4 * n * sizeof *buf) : NULL;
  if (!buf) {
    vsph_particles_free(q);
    VSPH_FAIL(VSPH_ENOMEM, "cannot copy a set of %zu particles", p->n);
  }
  q->n = p->n;
  for (size_t i = 0; i < p->n; i++) {
    for (int k = 0; k < dim; k++) {
      q->pos[k][i] = p->pos[k][i];
      q->vel[k][i] = p->vel[k][i];
    }
    q->m[i] = p->m[i];
    q->rho[i] = p->rho[i];
    q->id[i] = i;
  }
  vsph_particles_refresh_vol(q);
  double *f[3] = {buf, buf + n, buf + 2 * n}, *dens = buf + 3 * n;
  struct vsph_dissipation_power pw = {0.0, 0.0, 0};
  int st = evaluate(vp, q, f, dens, &pw.n_fallback);
  if (!st) { /* serial sums in the copy's order: any thread count */
    for (size_t i = 0; i < q->n; i++) {
      double ud = 0.0;
      for (int k = 0; k < dim; k++) ud += q->vel[k][i] * f[k][i];
      pw.P += q->vol[i] * ud;
      pw.P_pair += q->vol[i] * dens[i];
    }
    if (!isfinite(pw.P) || !isfinite(pw.P_pair)) {
      vsph_status_report(VSPH_EINVAL, __FILE__, __LINE__,
                         "the dissipation is not finite: two particles at "
                         "one place?");
      st = VSPH_EINVAL;
    }
  }
  if (!st) *out = pw;
  free(buf);
  vsph_particles_free(q);
  return st;
}

/* Its inputs and the work they ask, refused where wrong or too large
 * (one message); VSPH_OK where they hold. */
static int refuse(const struct vsph_dissipation_props *dp) {
  if (dp->field.dim != 2)
    VSPH_FAIL(VSPH_EINVAL, "the dissipation sets are 2-D");
  if (dp->field.kind == VSPH_FIELDS_QUADRATIC)
    VSPH_FAIL(VSPH_EINVAL,
              "the dissipation fields are rotation, strain, mixed");
  if (!(dp->hdx > 0.0) || !isfinite(dp->hdx))
    VSPH_FAIL(VSPH_EINVAL, "h/dx must be positive, got %g", dp->hdx);
  if (dp->nacross < 2)
    VSPH_FAIL(VSPH_EINVAL, "need at least 2 particles across, got %zu",
              dp->nacross);
  /* Per particle: the set's arrays and id, the cell scratch and at most 8
   * cells, the PVWF workspace and the three result columns. */
  const double n = (double)dp->nacross * (double)dp->nacross;
  const double per = (11 + 1 + 4 + 16 + 5 + 3) * 8.0 + 1;
  const double gib = n * per / (1024.0 * 1024.0 * 1024.0);
  if (!(gib <= dp->max_memory))
    VSPH_FAIL(VSPH_EINVAL,
              "res %zu needs up to about %.3g GiB (%.3g particles), more than "
              "Dissipation:max_memory = %g GiB: lower res or raise "
              "max_memory",
              dp->nacross, gib, n, dp->max_memory);
  /* The work: every particle gathers from the pi (kappa hdx)^2 lattice
   * points of its support, twice for a form with a first pass (PVWF, model
   * A, B, VISC-01..04) */
  const double r = dp->kernel->kappa * dp->hdx;
  const double nb = VSPH_PI * r * r;
  const double pairs = n * nb * (1.0 + vsph_viscous_first_pass(dp->form));
  if (!(pairs <= dp->max_pairs))
    VSPH_FAIL(VSPH_EINVAL,
              "res %zu at h/dx = %g needs about %.3g neighbour interactions "
              "(%.3g particles x %.3g neighbours%s), more than "
              "Dissipation:max_pairs = %g: lower res or hdx, or raise "
              "max_pairs",
              dp->nacross, dp->hdx, pairs, n, nb,
              vsph_viscous_first_pass(dp->form) ? " x 2 passes" : "",
              dp->max_pairs);
  return VSPH_OK;
}

/* The set's dissipation from its forces @p f and pair densities @p dens,
 * against the continuum limit @p limit (the form's, lambda @p lambda):
 * the whole, the interior's, and the errors they split into, into
 * @p res (whose P_exact, P_grad and P_limit are set). */
static void sum_up(const struct vsph_dissipation_props *dp,
                   const struct vsph_particles *p, double *const f[3],
                   const double *dens, int limit, double lambda, double h,
                   struct vsph_dissipation_result *res) {
  /* Serial sums in particle order: reproducible for any thread count. */
  const double H = dp->kernel->kappa * h;
  double P = 0.0, Pp = 0.0, Pint = 0.0, Pint_lim = 0.0, Pint_grad = 0.0;
  double mom[2] = {0, 0}, mom_abs = 0.0, ang = 0.0, ang_abs = 0.0;
  for (size_t i = 0; i < p->n; i++) {
    const double V = p->vol[i], x[3] = {p->pos[0][i], p->pos[1][i], 0.0};
    P += V * (p->vel[0][i] * f[0][i] + p->vel[1][i] * f[1][i]);
    Pp += V * dens[i];
    mom[0] += V * f[0][i];
    mom[1] += V * f[1][i];
    mom_abs += V * hypot(f[0][i], f[1][i]);
    ang += V * (x[0] * f[1][i] - x[1] * f[0][i]);
    ang_abs += V * hypot(x[0], x[1]) * hypot(f[0][i], f[1][i]);
    if (edge_distance(dp->shape, x) >= H) {
      const struct densities d = densities_at(&dp->field, dp->mu, x);
      const double lim = limit_density(&d, limit, lambda);
      res->n_interior++;
      Pint += V * dens[i];
      Pint_lim -= V * lim;
      Pint_grad -= V * d.grad2;
    }
  }
  res->n_particles = p->n;
  res->P = P;
  res->P_pair = Pp;
  res->momentum = mom_abs > 0.0 ? hypot(mom[0], mom[1]) / mom_abs : 0.0;
  res->angular = ang_abs > 0.0 ? fabs(ang) / ang_abs : 0.0;

  /* "Zero" exact dissipation: the field has D = 0 (rigid rotation), where
   * the quadrature returns 0 exactly; normalise by |P_grad| then. */
  const int exact_zero = fabs(res->P_exact) <= 1e-12 * fabs(res->P_grad);
  const double norm = exact_zero ? fabs(res->P_grad) : fabs(res->P_exact);
  res->rel_error = exact_zero ? P / norm : (P - res->P_exact) / norm;
  const double P_limit = res->P_limit;
  res->consistency_error = (P_limit - res->P_exact) / norm;
  if (res->n_interior > 0) {
    const double nint = fabs(Pint_lim) > 1e-12 * fabs(Pint_grad)
                            ? fabs(Pint_lim)
                            : fabs(Pint_grad);
    res->lattice_error = (Pint - Pint_lim) / nint;
    res->surface_error = (P - P_limit) / norm - res->lattice_error;
  } else {
    res->lattice_error = NAN;
    res->surface_error = NAN;
  }
}

int vsph_dissipation_compute(const struct vsph_dissipation_props *dp,
                             struct vsph_dissipation_result *res) {
  if (!dp || !res)
    VSPH_FAIL(VSPH_EINVAL, "vsph_dissipation_compute: a NULL argument");
  const int bad = refuse(dp);
  if (bad) return bad;
  memset(res, 0, sizeof *res);
  const double dx = EXTENT / (double)dp->nacross, h = dp->hdx * dx;
  res->dx = dx;
  res->h = h;
  struct vsph_lattice_props lp = {.dim = 2,
                                  .kind = VSPH_LATTICE_SQUARE,
                                  .dx = dx,
                                  .perturb = dp->perturb,
                                  .seed = dp->seed};
  struct vsph_particles *p = NULL;
  int st = dp->shape == VSPH_DISSIPATION_DISC
               ? vsph_lattice_disc(&lp, 0.5 * EXTENT, dp->nacross, &p)
               : vsph_lattice_square(&lp, EXTENT, dp->nacross, &p);
  if (st) return st;
  struct vsph_viscous_props vp;
  double *buf = malloc(3 * p->n * sizeof *buf);
  if (!buf) {
    st = VSPH_ENOMEM;
    goto done;
  }
  if ((st = vsph_viscous_props_init(&vp, dp->form, dp->kernel, 2, h, dp->mu)))
    goto done;
  for (size_t i = 0; i < p->n; i++) {
    double x[3] = {p->pos[0][i], p->pos[1][i], 0.0}, u[3], g[9];
    vsph_fields_eval(&dp->field, x, u, g);
    p->vel[0][i] = u[0];
    p->vel[1][i] = u[1];
  }
  double *f[3] = {buf, buf + p->n, NULL}, *dens = buf + 2 * p->n;
  if ((st = evaluate(&vp, p, f, dens, &res->n_fallback))) goto done;
  /* the continuum limit this form's dissipation tends to (its descriptor) */
  const int limit = vsph_viscous_types[dp->form]->limit;
  double ex[3];
  if ((st = exact_integrals(dp, limit == VSPH_VISCOUS_LIMIT_LAPLACIAN ? 3 : 2,
                            ex)))
    goto done;
  res->P_exact = ex[0];
  res->P_grad = ex[1];
  /* All dissipation fields are divergence-free, so a stress limit is
   * P_exact whatever the form's lambda. */
  res->P_limit = limit == VSPH_VISCOUS_LIMIT_GRADIENT    ? ex[1]
                 : limit == VSPH_VISCOUS_LIMIT_LAPLACIAN ? ex[2]
                                                         : ex[0];

  sum_up(dp, p, f, dens, limit, vp.lambda, h, res);
done:
  free(buf);
  vsph_particles_free(p);
  return st;
}
