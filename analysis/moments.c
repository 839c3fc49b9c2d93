/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
#include "moments.h"

#include <gsl/gsl_errno.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "../common/consts.h"
#include "../common/params.h"
#include "../common/status.h"
#include "../kernels/kernel.h"
#include "../solver/lattice.h"
#include "../solver/pair.h"
#include "../solver/particles.h"

/* State shared by the nested integrands. */
struct quad {
  const struct vsph_kernel_type *k;
  int dim;
  double depth;   /* units of h */
  int power;      /* radial weight s^power: d-1 for F,N; d for G,M */
  int a, b, c;    /* exponents of the tangential(s) and the normal */
  double r_kappa; /* R_power(kappa), cached */
  double epsrel;
  gsl_integration_workspace *inner;
  int status; /* first GSL failure inside the integrand */
};

static double radial_integrand(double s, void *v) {
  const struct quad *q = v;
  return -vsph_kernel_dw(q->k, q->dim, s) * pow(s, q->power);
}

/* R_p(a) = -int_0^a w'(s) s^p ds, split at integer q where the spline
 * kernels have their knots, so each piece is smooth. */
static double radial(struct quad *q, double a) {
  if (a <= 0.0) return 0.0;
  gsl_function fn = {radial_integrand, q};
  double sum = 0.0, lo = 0.0;
  while (lo < a) {
    const double hi = fmin(a, floor(lo) + 1.0);
    double res, err;
    const int st = gsl_integration_qag(&fn, lo, hi, 0.0, 1e-13, q->inner->limit,
                                       GSL_INTEG_GAUSS41, q->inner, &res, &err);
    /* The inner integrand is smooth per piece; a round-off warning at the
     * 1e-13 request is acceptable, anything else is a failure. */
    if (st && st != GSL_EROUND && !q->status) q->status = st;
    sum += res;
    lo = hi;
  }
  return sum;
}

/* Radial limit along a direction whose normal cosine is mu. */
static double s_max(const struct quad *q, double mu) {
  const double kappa = q->k->kappa;
  if (mu > 0.0 && q->depth < kappa * mu) return q->depth / mu;
  return kappa;
}

static double r_of(struct quad *q, double mu) {
  const double sm = s_max(q, mu);
  return sm >= q->k->kappa ? q->r_kappa : radial(q, sm);
}

static double ipow(double x, int n) {
  double r = 1.0;
  for (int i = 0; i < n; i++) r *= x;
  return r;
}

/* 2-D: direction (sin psi, cos psi), psi in [0, pi] (the other half by
 * reflection symmetry, so only even tangential powers survive). */
static double outer2(double psi, void *v) {
  struct quad *q = v;
  const double mu = cos(psi);
  return ipow(sin(psi), q->a) * ipow(mu, q->c) * r_of(q, mu);
}

/* 3-D: normal cosine mu in [-1, 1]; the azimuth is integrated exactly. */
static double outer3(double mu, void *v) {
  struct quad *q = v;
  const double st2 = fmax(0.0, 1.0 - mu * mu);
  return pow(st2, 0.5 * (q->a + q->b)) * ipow(mu, q->c) * r_of(q, mu);
}

static double dfact(int n) { /* n!!, with (-1)!! = 0!! = 1 */
  double r = 1.0;
  for (int i = n; i > 1; i -= 2) r *= i;
  return r;
}

/* int_0^{2 pi} cos^a(phi) sin^b(phi) dphi for even a, b. */
static double azimuth(int a, int b) {
  return 2.0 * VSPH_PI * dfact(a - 1) * dfact(b - 1) / dfact(a + b);
}

static int outer_integral(struct quad *q, double (*f)(double, void *),
                          double lo, double split, double hi,
                          gsl_integration_workspace *ws, double *out) {
  gsl_function fn = {f, q};
  const double cuts[3] = {lo, split, hi};
  *out = 0.0;
  for (int piece = 0; piece < 2; piece++) {
    const double a = cuts[piece], b = cuts[piece + 1];
    if (!(b > a)) continue;
    double res, err;
    /* Absolute floor: entries that vanish by cancellation cannot meet a
     * relative request; 1e-14 of the full-support radial scale is below
     * anything the reports print. */
    const double epsabs = 1e-14 * fabs(q->r_kappa);
    const int st = gsl_integration_qag(&fn, a, b, epsabs, q->epsrel, ws->limit,
                                       GSL_INTEG_GAUSS41, ws, &res, &err);
    if (st && st != GSL_EROUND)
      VSPH_FAIL(VSPH_ELIB, "moment quadrature: %s", gsl_strerror(st));
    if (q->status)
      VSPH_FAIL(VSPH_ELIB, "radial quadrature: %s", gsl_strerror(q->status));
    *out += res;
  }
  return VSPH_OK;
}

/* Angular integral of x^a y^b z^c R_p over the unit sphere (dim-adapted):
 * a, b tangential exponents, c normal exponent. */
static int angular(struct quad *q, gsl_integration_workspace *ws, double *out) {
  const int dim = q->dim;
  const double kappa = q->k->kappa;
  if (dim == 1) {
    /* Directions -1 (into the fluid, full) and +1 (towards the surface). */
    *out = ipow(-1.0, q->c) * q->r_kappa + r_of(q, 1.0);
    return q->status ? VSPH_ELIB : VSPH_OK;
  }
  if (q->a % 2 || q->b % 2) { /* odd in a tangential direction */
    *out = 0.0;
    return VSPH_OK;
  }
  if (dim == 2) {
    const double split = q->depth < kappa ? acos(q->depth / kappa) : 0.0;
    int st = outer_integral(q, outer2, 0.0, split, VSPH_PI, ws, out);
    *out *= 2.0;
    return st;
  }
  const double split = q->depth < kappa ? q->depth / kappa : 1.0;
  int st = outer_integral(q, outer3, -1.0, split, 1.0, ws, out);
  *out *= azimuth(q->a, q->b);
  return st;
}

/* Exponents (tangential a, b; normal c) of the monomial x_i x_j ... */
static void exponents(int dim, const int *idx, int n, int *a, int *b, int *c) {
  *a = *b = *c = 0;
  for (int m = 0; m < n; m++) {
    if (idx[m] == dim - 1)
      (*c)++;
    else if (idx[m] == 0)
      (*a)++;
    else
      (*b)++;
  }
}

/* Memoised angular integral: many tensor entries share exponents. */
struct memo {
  double val[2][5][5][5];
  unsigned char have[2][5][5][5];
};

static int entry(struct quad *q, struct memo *mm, double r_kappa_p[2],
                 gsl_integration_workspace *ws, int which, const int *idx,
                 int n, double *out) {
  int a, b, c;
  exponents(q->dim, idx, n, &a, &b, &c);
  if (!mm->have[which][a][b][c]) {
    q->power = q->dim - 1 + which;
    q->r_kappa = r_kappa_p[which];
    q->a = a;
    q->b = b;
    q->c = c;
    const int st = angular(q, ws, &mm->val[which][a][b][c]);
    if (st) return st;
    mm->have[which][a][b][c] = 1;
  }
  *out = mm->val[which][a][b][c];
  return VSPH_OK;
}

int vsph_moments_quadrature(const struct vsph_kernel_type *k, int dim,
                            double depth, double epsrel,
                            gsl_integration_workspace *outer,
                            gsl_integration_workspace *inner,
                            struct vsph_moments *out) {
  if (!k || !outer || !inner || !out)
    VSPH_FAIL(VSPH_EINVAL, "no kernel, workspace or result");
  if (dim < 1 || dim > 3)
    VSPH_FAIL(VSPH_EINVAL, "dimension %d outside 1-3", dim);
  if (!(depth >= 0.0) || !isfinite(depth))
    VSPH_FAIL(VSPH_EINVAL, "depth must be >= 0, got %g", depth);
  if (!(epsrel >= 1e-13))
    VSPH_FAIL(VSPH_EINVAL, "epsrel must be >= 1e-13, got %g", epsrel);
  if (outer == inner)
    VSPH_FAIL(VSPH_EINVAL, "outer and inner workspaces must differ");
  struct quad q = {
      .k = k, .dim = dim, .depth = depth, .epsrel = epsrel, .inner = inner};
  double rk[2];
  for (int which = 0; which < 2; which++) {
    q.power = dim - 1 + which;
    rk[which] = radial(&q, k->kappa);
  }
  if (q.status)
    VSPH_FAIL(VSPH_ELIB, "radial quadrature: %s", gsl_strerror(q.status));
  static const struct memo zero_memo;
  struct memo mm = zero_memo;
  memset(out, 0, sizeof *out);
  out->dim = dim;
  const double K = vsph_kernel_mg_factor(dim);
  int st;
  for (int i = 0; i < dim; i++) {
    double v;
    int idx1[1] = {i};
    if ((st = entry(&q, &mm, rk, outer, 0, idx1, 1, &v))) return st;
    out->N[i] = 2.0 * v;
    for (int j = 0; j < dim; j++) {
      int idx2[2] = {i, j};
      if ((st = entry(&q, &mm, rk, outer, 1, idx2, 2, &v))) return st;
      out->M[i][j] = v;
      for (int l = 0; l < dim; l++) {
        int idx3[3] = {i, j, l};
        if ((st = entry(&q, &mm, rk, outer, 0, idx3, 3, &v))) return st;
        out->F[i][j][l] = K * v;
        for (int m = 0; m < dim; m++) {
          int idx4[4] = {i, j, l, m};
          if ((st = entry(&q, &mm, rk, outer, 1, idx4, 4, &v))) return st;
          out->G[i][j][l][m] = 0.5 * K * v;
        }
      }
    }
  }
  return VSPH_OK;
}

static double i_integrand(double qv, void *v) {
  const struct quad *q = v;
  return pow(qv, q->dim - 2) * vsph_kernel_w(q->k, q->dim, qv);
}

int vsph_moments_constants(const struct vsph_kernel_type *k, int dim,
                           double epsrel, gsl_integration_workspace *ws,
                           double *C_F, double *C_N) {
  if (!k || !ws || !C_F || !C_N)
    VSPH_FAIL(VSPH_EINVAL, "no kernel, workspace or result");
  if (dim < 1 || dim > 3)
    VSPH_FAIL(VSPH_EINVAL, "dimension %d outside 1-3", dim);
  const double K = vsph_kernel_mg_factor(dim);
  if (dim == 1) {
    const double w0 = vsph_kernel_w(k, 1, 0.0);
    *C_F = 0.5 * K * w0;
    *C_N = 2.0 * w0;
    return VSPH_OK;
  }
  struct quad q = {.k = k, .dim = dim};
  gsl_function fn = {i_integrand, &q};
  double I = 0.0, lo = 0.0;
  while (lo < k->kappa) { /* split at the spline knots, as in radial() */
    const double hi = fmin(k->kappa, floor(lo) + 1.0);
    double res, err;
    const int st = gsl_integration_qag(&fn, lo, hi, 0.0, epsrel, ws->limit,
                                       GSL_INTEG_GAUSS41, ws, &res, &err);
    if (st && st != GSL_EROUND)
      VSPH_FAIL(VSPH_ELIB, "surface constant quadrature: %s", gsl_strerror(st));
    I += res;
    lo = hi;
  }
  const double beta = dim == 2 ? 2.0 / 3.0 : VSPH_PI / 4.0;
  const double gamma = dim == 2 ? 2.0 : VSPH_PI;
  *C_F = K * (dim - 1) * beta * I;
  *C_N = 2.0 * (dim - 1) * gamma * I;
  return VSPH_OK;
}

void vsph_moments_theory(int dim, int half, double C_F, double C_N,
                         struct vsph_moments *out) {
  if (!out) return;
  memset(out, 0, sizeof *out);
  out->dim = dim;
  const double f = half ? 0.5 : 1.0;
  double n[3] = {0, 0, 0};
  n[dim - 1] = 1.0;
  for (int i = 0; i < dim; i++) {
    out->N[i] = half ? -C_N * n[i] : 0.0;
    for (int j = 0; j < dim; j++) {
      const double dij = i == j;
      out->M[i][j] = f * dij;
      for (int l = 0; l < dim; l++) {
        const double dil = i == l, djl = j == l;
        if (half)
          out->F[i][j][l] = -C_F * (dij * n[l] + dil * n[j] + djl * n[i] -
                                    n[i] * n[j] * n[l]);
        for (int m = 0; m < dim; m++) {
          const double dlm = l == m, dim_ = i == m, djm = j == m;
          out->G[i][j][l][m] = f * (dij * dlm + dil * djm + dim_ * djl);
        }
      }
    }
  }
}

int vsph_moments_sum(const struct vsph_kernel_type *k,
                     const struct vsph_particles *p, size_t centre, double h,
                     struct vsph_moments *out) {
  if (!k || !p || !out)
    VSPH_FAIL(VSPH_EINVAL, "no kernel, particles or result");
  const int dim = p->dim;
  if (centre >= p->n) VSPH_FAIL(VSPH_EINVAL, "centre %zu out of range", centre);
  if (!(h > 0.0)) VSPH_FAIL(VSPH_EINVAL, "h must be positive, got %g", h);
  memset(out, 0, sizeof *out);
  out->dim = dim;
  const double K = vsph_kernel_mg_factor(dim);
  /* The neighbour loop of the operators (solver/pair.h): a truncated kernel
   * whose w' jumps at kappa (the 3h Gaussian) classifies a particle on the
   * support edge the same way here as in the operators. */
  struct vsph_pair_kernel pk;
  struct vsph_pair_ranges rg;
  struct vsph_pair_iter it;
  struct vsph_pair_chunk bt;
  vsph_pair_kernel_init(&pk, k, dim, h);
  vsph_pair_ranges_all(&rg, p->n);
  vsph_pair_begin(&it, &pk, p, &rg, centre);
  while (vsph_pair_gather(&it, dim, pk.dfq_id, &bt))
    for (size_t q = 0; q < bt.m; q++) {
      struct vsph_pair pr;
      vsph_pair_at(&bt, q, dim, &pr);
      const double *x = pr.x;
      const double c1 = -pr.VF;     /* -V W'/s */
      const double c3 = c1 / pr.s2; /* -V W'/s^3 */
      for (int a = 0; a < dim; a++) {
        out->N[a] += 2.0 * c1 * x[a];
        for (int b = 0; b < dim; b++) {
          out->M[a][b] += c1 * x[a] * x[b];
          for (int l = 0; l < dim; l++) {
            out->F[a][b][l] += K * c3 * x[a] * x[b] * x[l];
            for (int m = 0; m < dim; m++)
              out->G[a][b][l][m] += 0.5 * K * c3 * x[a] * x[b] * x[l] * x[m];
          }
        }
      }
    }
  return VSPH_OK;
}

void vsph_moments_gap(const struct vsph_moments *a,
                      const struct vsph_moments *b, double gap[4]) {
  if (!a || !b || !gap) return;
  gap[0] = gap[1] = gap[2] = gap[3] = 0.0;
  const int d = a->dim;
  for (int i = 0; i < d; i++) {
    gap[2] = fmax(gap[2], fabs(a->N[i] - b->N[i]));
    for (int j = 0; j < d; j++) {
      gap[3] = fmax(gap[3], fabs(a->M[i][j] - b->M[i][j]));
      for (int l = 0; l < d; l++) {
        gap[0] = fmax(gap[0], fabs(a->F[i][j][l] - b->F[i][j][l]));
        for (int m = 0; m < d; m++)
          gap[1] = fmax(gap[1], fabs(a->G[i][j][l][m] - b->G[i][j][l][m]));
      }
    }
  }
}

/* ------------------------------------------------ one evaluation (driver) */

/* The "Tensors" section as given; props_init resolves it. */
struct raw {
  char kernel[VSPH_PARAMS_NAME_MAX];
  size_t dim;
  double depth;
  char method[VSPH_PARAMS_NAME_MAX];
  char lattice[VSPH_PARAMS_NAME_MAX];
  double hdx;
  double perturb;
  size_t seed;
  double epsrel;
};

#define P struct raw
static const struct vsph_params_spec TENSORS[] = {
    VSPH_PARAMS_NAME_SPEC(P, kernel, "gaussian",
                          "gaussian, cubic, quintic, wendland2, wendland4"),
    VSPH_PARAMS_INT_SPEC(P, dim, 2, 1, 3, "dimension"),
    VSPH_PARAMS_REAL_SPEC(P, depth, 0.0, 0.0, 1e3,
                          "depth below the surface (units of h): 0 half "
                          "support, >= kappa full support"),
    VSPH_PARAMS_NAME_SPEC(P, method, "quadrature",
                          "quadrature (GSL) or particles (lattice sums, with "
                          "their gap to quadrature)"),
    VSPH_PARAMS_NAME_SPEC(P, lattice, "square",
                          "square, hex (2-D) or perturbed (square shifted by "
                          "up to perturb dx)"),
    VSPH_PARAMS_REAL_SPEC(P, hdx, VSPH_CONSTS_HDX, 0.5, 256.0,
                          "h/dx of the lattice (at most 32 in 3-D)"),
    VSPH_PARAMS_REAL_SPEC(P, perturb, 0.1, 0.0, 0.49,
                          "shift of the perturbed lattice, fraction of dx"),
    VSPH_PARAMS_INT_SPEC(P, seed, VSPH_CONSTS_SEED, 0, 4294967295.0,
                         "seed of that shift (mt19937)"),
    VSPH_PARAMS_REAL_SPEC(P, epsrel, 1e-10, 1e-13, 0.5,
                          "relative accuracy of the quadrature"),
};
#undef P

const struct vsph_params_spec *vsph_moments_params(size_t *n) {
  if (!n) return NULL;
  *n = sizeof TENSORS / sizeof TENSORS[0];
  return TENSORS;
}

int vsph_moments_props_init(struct vsph_moments_props *mp,
                            struct vsph_params *prm) {
  if (!mp) VSPH_FAIL(VSPH_EINVAL, "vsph_moments_props_init: a NULL argument");
  struct raw r;
  memset(mp, 0, sizeof *mp);
  int st = vsph_params_load(prm, "Tensors", TENSORS,
                            sizeof TENSORS / sizeof TENSORS[0], &r, sizeof r);
  if (st) return st;
  if ((st = vsph_kernel_resolve(r.kernel, &mp->kernel))) return st;
  if (!mp->kernel)
    VSPH_FAIL(VSPH_EINVAL,
              "unknown kernel '%s' (gaussian, cubic, quintic, wendland2, "
              "wendland4)",
              r.kernel);
  mp->dim = (int)r.dim;
  mp->depth = r.depth;
  mp->particles = !strcmp(r.method, "particles");
  if (!mp->particles && strcmp(r.method, "quadrature"))
    VSPH_FAIL(VSPH_EINVAL, "unknown method '%s' (quadrature, particles)",
              r.method);
  if ((st = vsph_lattice_resolve(r.lattice, mp->dim, r.perturb,
                                 &mp->lattice_kind, &mp->perturb)))
    return st;
  /* A patch of radius (kappa + 2/hdx) h holds ~(kappa hdx)^d particles:
   * cap it at a few million. */
  const double hdx_max = mp->dim == 3 ? 32.0 : 256.0;
  if (r.hdx > hdx_max)
    VSPH_FAIL(VSPH_EINVAL,
              "Tensors:hdx above %g in %d-D would need too many particles, "
              "got %g",
              hdx_max, mp->dim, r.hdx);
  mp->hdx = r.hdx;
  mp->seed = (unsigned long)r.seed;
  mp->epsrel = r.epsrel;
  return VSPH_OK;
}

/* Props as vsph_moments_props_init leaves them, for callers that fill
 * the struct themselves. */
static int check_props(const struct vsph_moments_props *mp) {
  if (!mp->kernel) VSPH_FAIL(VSPH_EINVAL, "no kernel given");
  if (mp->dim < 1 || mp->dim > 3)
    VSPH_FAIL(VSPH_EINVAL, "dimension %d outside 1-3", mp->dim);
  if (!(mp->depth >= 0.0) || !isfinite(mp->depth))
    VSPH_FAIL(VSPH_EINVAL, "depth must be finite and non-negative, got %g",
              mp->depth);
  if (!(mp->epsrel > 0.0 && mp->epsrel < 1.0))
    VSPH_FAIL(VSPH_EINVAL, "epsrel must lie in (0, 1), got %g", mp->epsrel);
  if (!mp->particles) return VSPH_OK;
  if (mp->lattice_kind < 0 || mp->lattice_kind >= VSPH_LATTICE_KIND_COUNT)
    VSPH_FAIL(VSPH_EINVAL, "unknown lattice kind %d", mp->lattice_kind);
  const double hdx_max = mp->dim == 3 ? 32.0 : 256.0;
  if (!(mp->hdx > 0.0 && mp->hdx <= hdx_max))
    VSPH_FAIL(VSPH_EINVAL, "h/dx must lie in (0, %g] in %d-D, got %g", hdx_max,
              mp->dim, mp->hdx);
  return VSPH_OK;
}

int vsph_moments_compute(const struct vsph_moments_props *mp,
                         struct vsph_moments_result *res) {
  if (!mp || !res) VSPH_FAIL(VSPH_EINVAL, "no props or result");
  memset(res, 0, sizeof *res);
  const int bad = check_props(mp);
  if (bad) return bad;
  const struct vsph_kernel_type *k = mp->kernel;
  gsl_integration_workspace *wo = gsl_integration_workspace_alloc(1000);
  gsl_integration_workspace *wi = gsl_integration_workspace_alloc(1000);
  int st = VSPH_OK;
  if (!wo || !wi) {
    vsph_status_report(VSPH_ENOMEM, __FILE__, __LINE__,
                       "cannot allocate quadrature workspaces");
    st = VSPH_ENOMEM;
  }
  if (!st)
    st = vsph_moments_quadrature(k, mp->dim, mp->depth, mp->epsrel, wo, wi,
                                 &res->quad);
  if (!st)
    st = vsph_moments_constants(k, mp->dim, mp->epsrel, wo, &res->C_F,
                                &res->C_N);
  const int half = mp->depth == 0.0, full = mp->depth >= k->kappa;
  if (!st && (half || full)) {
    vsph_moments_theory(mp->dim, half, res->C_F, res->C_N, &res->theory);
    res->have_theory = 1;
  }
  if (!st && mp->particles) {
    struct vsph_lattice_props lp = {.dim = mp->dim,
                                    .kind = mp->lattice_kind,
                                    .dx = 1.0 / mp->hdx,
                                    .perturb = mp->perturb,
                                    .seed = mp->seed};
    struct vsph_particles *p = NULL;
    size_t centre;
    st = vsph_lattice_halfspace(&lp, k->kappa + 2.0 / mp->hdx, mp->depth, &p,
                                &centre);
    if (!st) st = vsph_moments_sum(k, p, centre, 1.0, &res->sum);
    if (!st) {
      res->n_particles = p->n;
      vsph_moments_gap(&res->sum, &res->quad, res->gap);
    }
    vsph_particles_free(p);
  }
  gsl_integration_workspace_free(wo);
  gsl_integration_workspace_free(wi);
  return st;
}
