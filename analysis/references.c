/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
#include "references.h"

#include <complex.h>
/* C11's CMPLX, which glibc's complex.h defines for GCC only (clang, which
 * make fuzz builds with, lacks __builtin_complex); both parts here are
 * finite, so x + I y gives the same value */
#ifndef CMPLX
#define CMPLX(x, y) ((double complex)((double)(x) + I * (double)(y)))
#endif
#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>
#include <gsl/gsl_sf_bessel.h>
#include <math.h>
#include <stdlib.h>

#include "../common/consts.h"
#include "../common/status.h"
#include "../kernels/kernel.h"
#include "../solver/particles.h"
#include "../solver/scene.h"

/* Quadrature limits of the private workspace and the accuracy asked. */
static const size_t QUAD_LIMIT = 500;
static const double QUAD_EPSREL = 1e-12;
/* Absolute floor of the coefficient numerators, in units of omega0 R^4:
 * far below the 1e-8 accuracy of the truncated series. */
static const double NUM_EPSABS = 1e-17;

double vsph_references_vortex_initial(const struct vsph_references_vortex *v,
                                      double r) {
  if (!v) return NAN;
  /* the scene's profile: one definition (THEORY 6.1, [reconstructed]) */
  return vsph_vortex_patch_omega(v->omega0, v->l2, v->a, v->R, r);
}

/* phi(x) = 2 J_1(x)/x, with its series near 0 (J_1(x)/x = 1/2 - x^2/16 +
 * ..., relative error x^4/384 < 1e-18 for x < 1e-4). */
static double phi(double x) {
  return x < 1e-4 ? 1.0 - x * x / 8.0 : 2.0 * gsl_sf_bessel_J1(x) / x;
}
/* d phi/dx = -2 J_2(x)/x */
static double dphi(double x) {
  return x < 1e-4 ? -x / 4.0 : -2.0 * gsl_sf_bessel_Jn(2, x) / x;
}

struct coef_ctx {
  const struct vsph_references_vortex *v;
  double k;
};

static double coef_integrand(double r, void *p) { /* omega(r,0) r^3 */
  const struct coef_ctx *c = p;
  return vsph_references_vortex_initial(c->v, r) * r * r * r;
}

static double num_integrand(double r, void *p) { /* omega(r,0) phi r^3 */
  const struct coef_ctx *c = p;
  return vsph_references_vortex_initial(c->v, r) * phi(c->k * r) * r * r * r;
}

static int integrate(gsl_integration_workspace *ws,
                     double (*fn)(double, void *), void *ctx, double a,
                     double b, double *out) {
  gsl_function f = {fn, ctx};
  double err;
  const int st = gsl_integration_qag(&f, a, b, 0.0, QUAD_EPSREL, QUAD_LIMIT,
                                     GSL_INTEG_GAUSS61, ws, out, &err);
  if (st && st != GSL_EROUND)
    VSPH_FAIL(VSPH_ELIB, "vortex reference quadrature: %s", gsl_strerror(st));
  return VSPH_OK;
}

struct vsph_references_vortex *vsph_references_vortex_alloc(
    double R, double l2, double a, double omega0, double nu, size_t nterms) {
  if (!(R > 0.0) || !(l2 > 0.0) || !(nu >= 0.0) || !isfinite(omega0) ||
      !isfinite(a) || nterms < 1) {
    vsph_status_report(VSPH_EINVAL, __FILE__, __LINE__,
                       "vortex reference: need R > 0, l^2 > 0, nu >= 0, "
                       "terms >= 1");
    return NULL;
  }
  struct vsph_references_vortex *v = calloc(1, sizeof *v);
  if (!v) goto nomem;
  v->R = R;
  v->l2 = l2;
  v->a = a;
  v->omega0 = omega0;
  v->nu = nu;
  v->nterms = nterms;
  v->k = malloc(nterms * sizeof *v->k);
  v->c = malloc(nterms * sizeof *v->c);
  v->norm = malloc(nterms * sizeof *v->norm);
  v->ws = gsl_integration_workspace_alloc(QUAD_LIMIT);
  if (!v->k || !v->c || !v->norm || !v->ws) goto nomem;
  gsl_integration_workspace *ws = v->ws;
  /* c_0 = int omega r^3 dr / int r^3 dr = 4 int omega r^3 dr / R^4 */
  struct coef_ctx cx = {v, 0.0};
  double num, den;
  if (integrate(ws, coef_integrand, &cx, 0.0, R, &num)) goto fail;
  v->c0 = 4.0 * num / (R * R * R * R);
  for (size_t n = 0; n < nterms; n++) {
    gsl_sf_result z;
    if (gsl_sf_bessel_zero_Jnu_e(2.0, (unsigned)(n + 1), &z)) {
      vsph_status_report(VSPH_ELIB, __FILE__, __LINE__,
                         "zero %zu of J_2 not found", n + 1);
      goto fail;
    }
    v->k[n] = z.val / R;
    /* Numerator by adaptive quadrature with an absolute floor: for large
     * n it is a tiny remainder of an oscillatory integrand (~1e-16 at
     * n = 200), which fixed-order rules do not resolve. */
    cx.k = v->k[n];
    gsl_function fn = {num_integrand, &cx};
    double err;
    const double epsabs = NUM_EPSABS * fabs(omega0) * R * R * R * R;
    const int st =
        gsl_integration_qag(&fn, 0.0, R, epsabs, QUAD_EPSREL, QUAD_LIMIT,
                            GSL_INTEG_GAUSS61, ws, &num, &err);
    if (st && st != GSL_EROUND) {
      vsph_status_report(VSPH_ELIB, __FILE__, __LINE__,
                         "vortex coefficient %zu: %s", n + 1, gsl_strerror(st));
      goto fail;
    }
    /* int_0^R phi_n^2 r^3 dr = (4/k^2) int_0^R J_1(kr)^2 r dr
     * = 2 R^2 J_1(kR)^2 / k^2, using J_1' = J_1/x where J_2(x) = 0. */
    const double J1 = gsl_sf_bessel_J1(v->k[n] * R);
    den = 2.0 * R * R * J1 * J1 / (v->k[n] * v->k[n]);
    v->c[n] = num / den;
    v->norm[n] = den;
  }
  return v;
nomem:
  vsph_status_report(VSPH_ENOMEM, __FILE__, __LINE__,
                     "cannot allocate the vortex reference");
fail:
  vsph_references_vortex_free(v);
  return NULL;
}

void vsph_references_vortex_free(struct vsph_references_vortex *v) {
  if (!v) return;
  free(v->k);
  free(v->c);
  free(v->norm);
  gsl_integration_workspace_free(v->ws);
  free(v);
}

void vsph_references_vortex_eval(const struct vsph_references_vortex *v,
                                 double r, double t, double *omega,
                                 double *domega_dr) {
  if (!v || !omega) return;
  double w = v->c0, dw = 0.0;
  for (size_t n = 0; n < v->nterms; n++) {
    const double k = v->k[n], e = v->c[n] * exp(-v->nu * k * k * t);
    w += e * phi(k * r);
    dw += e * k * dphi(k * r);
  }
  *omega = w;
  if (domega_dr) *domega_dr = dw;
}

struct energy_ctx {
  const struct vsph_references_vortex *v;
  double t;
  int rate;
};

static double energy_integrand(double r, void *p) {
  const struct energy_ctx *e = p;
  double w, dw;
  vsph_references_vortex_eval(e->v, r, e->t, &w, &dw);
  return e->rate ? r * r * r * dw * dw : w * w * r * r * r;
}

int vsph_references_vortex_energy(struct vsph_references_vortex *v, double t,
                                  double rho, double *Ek, double *dEk_dt) {
  if (!v || !Ek || !dEk_dt)
    VSPH_FAIL(VSPH_EINVAL, "vsph_references_vortex_energy: a NULL argument");
  struct energy_ctx e = {v, t, 0};
  double a, b;
  int st = integrate(v->ws, energy_integrand, &e, 0.0, v->R, &a);
  e.rate = 1;
  if (!st) st = integrate(v->ws, energy_integrand, &e, 0.0, v->R, &b);
  if (st) return st;
  *Ek = VSPH_PI * rho * a;
  /* -mu int (r w')^2 dV = -2 pi rho nu int r^3 w'^2 dr (Eq. 6.41) */
  *dEk_dt = -2.0 * VSPH_PI * rho * v->nu * b;
  return VSPH_OK;
}

void vsph_references_vortex_energy_series(
    const struct vsph_references_vortex *v, double t, double rho, double *Ek,
    double *dEk_dt) {
  if (!v || !Ek || !dEk_dt) return;
  const double R4 = v->R * v->R * v->R * v->R;
  double e = v->c0 * v->c0 * R4 / 4.0, de = 0.0;
  for (size_t n = 0; n < v->nterms; n++) {
    const double k2 = v->k[n] * v->k[n];
    const double a =
        v->c[n] * v->c[n] * v->norm[n] * exp(-2.0 * v->nu * k2 * t);
    e += a;
    de += k2 * a;
  }
  *Ek = VSPH_PI * rho * e;
  *dEk_dt = -2.0 * VSPH_PI * rho * v->nu * de;
}

double vsph_references_lighthill(const struct vsph_scene_wave *w, double rho,
                                 double t) {
  if (!w) return NAN;
  const double A = w->A, k = w->k;
  return rho * w->g * A * A * w->L / 8.0 * exp(-4.0 * w->nu * k * k * t) *
         (1.0 + cos(2.0 * w->omega * t));
}

struct vsph_references_scene *vsph_references_scene_alloc(
    const struct vsph_scene *sc) {
  if (!sc) return NULL;
  struct vsph_references_scene *r = calloc(1, sizeof *r);
  if (!r) {
    vsph_status_report(VSPH_ENOMEM, __FILE__, __LINE__,
                       "cannot allocate a reference");
    return NULL;
  }
  r->scene = sc;
  /* channels: 64-point Gauss-Legendre for E_k, made once */
  if (vsph_scene_is_channel(sc->type) &&
      !(r->gl = gsl_integration_glfixed_table_alloc(64))) {
    free(r);
    vsph_status_report(VSPH_ENOMEM, __FILE__, __LINE__,
                       "cannot allocate a quadrature table");
    return NULL;
  }
  if (sc->type == &vsph_vortex_patch_type) {
    const struct vsph_scene_vortex *vp = &sc->u.vortex;
    /* 80 terms: the initial profile to ~3e-7, better at every t > 0 */
    r->vortex = vsph_references_vortex_alloc(vp->R, vp->l2, vp->a, vp->omega0,
                                             vp->nu, 80);
    if (!r->vortex) {
      free(r);
      return NULL;
    }
  }
  return r;
}

void vsph_references_scene_free(struct vsph_references_scene *r) {
  if (!r) return;
  vsph_references_vortex_free(r->vortex);
  if (r->gl) gsl_integration_glfixed_table_free(r->gl);
  free(r);
}

/* The start-up series in two forms (docs/theory.md, section 9). The
 * Fourier series converge like exp(-n^2 pi^2 tau), tau = nu t/W^2: fast
 * once tau is not small, but at tau -> 0 they need ever more terms (t =
 * 1e-300 ran a million terms per call, 74 s for one energy row of a
 * 1600-particle channel) and their rate sums do not converge at all. For
 * tau < TAU_IMAGES the method of images (Carslaw & Jaeger, the heat
 * equation on a slab) is used instead: its terms fall like exp(-n^2/(4
 * tau)). At the switch the Fourier terms fall below 1e-17 by n = 9 and the
 * image terms by n = 3; both forms agree to rounding there (tested). */
static const double TAU_IMAGES = 0.05;

/* Terms of either form are summed until they fall below this (relative to
 * the scale U0 or v0, and their rates to U0/t). */
static const double SERIES_TOL = 1e-17;

/* i^2 erfc(z) = ((1 + 2 z^2) erfc(z) - 2 z exp(-z^2)/sqrt(pi))/4, the
 * second repeated integral of erfc (Abramowitz & Stegun 7.2.5-7.2.6):
 * 1/4 at z = 0. At large z its two parts cancel, but their absolute
 * error stays at rounding of exp(-z^2), far below the sums' scale. */
static double i2erfc(double z) {
  return 0.25 * ((1.0 + 2.0 * z * z) * erfc(z) -
                 2.0 * z * exp(-z * z) / sqrt(VSPH_PI));
}

/* Poiseuille by images: with the drive g = 2 nu U0/d^2, u = g t - v, where
 * v solves the heat equation with v = g t on both walls from v = 0; one
 * wall's answer is V(s) = 4 g t i^2erfc(s/(2 sqrt(nu t))) at distance s,
 * and the slab's is sum_n (-1)^n [V(y + n W) + V((n + 1) W - y)]. Its rate
 * is g - g sum_n (-1)^n [erfc(...) + erfc(...)]. */
static double poiseuille_images(double y, double t, double W, double nu,
                                double U0, double *dudt) {
  const double d = 0.5 * W, g = 2.0 * nu * U0 / (d * d);
  const double s = 2.0 * sqrt(nu * t);
  double v = 0.0, dv = 0.0;
  for (int n = 0; n < 64; n++) {
    const double z1 = (y + n * W) / s, z2 = ((n + 1) * W - y) / s;
    const double sg = n % 2 ? -1.0 : 1.0;
    v += sg * (i2erfc(z1) + i2erfc(z2));
    dv += sg * (erfc(z1) + erfc(z2));
    /* later terms: below erfc(z) < exp(-z^2) of the nearer image */
    if (fmin(z1, z2) > 0.0 && exp(-fmin(z1, z2) * fmin(z1, z2)) < SERIES_TOL)
      break;
  }
  if (dudt) *dudt = g * (1.0 - dv);
  return g * t * (1.0 - 4.0 * v);
}

double vsph_references_poiseuille(double y, double t, double W, double nu,
                                  double U0, double *dudt) {
  const double d = 0.5 * W, yc = y - d;
  if (t <= 0.0) {
    if (dudt) *dudt = 2.0 * nu * U0 / (d * d);
    return 0.0;
  }
  if (nu * t / (W * W) < TAU_IMAGES)
    return poiseuille_images(y, t, W, nu, U0, dudt);
  double sum = 0.0, dsum = 0.0;
  const double a = VSPH_PI * VSPH_PI * nu * t / (4.0 * d * d);
  for (int n = 0; n < 1000; n++) {
    const double m = 2.0 * n + 1.0, e = exp(-m * m * a);
    const double c =
        (n % 2 ? -1.0 : 1.0) / (m * m * m) * cos(m * VSPH_PI * yc / (2.0 * d));
    sum += c * e;
    dsum += c * e * m * m;
    if (e < SERIES_TOL * m) break; /* later terms of both sums below e/m */
  }
  const double k = 32.0 / (VSPH_PI * VSPH_PI * VSPH_PI);
  if (dudt) *dudt = U0 * k * dsum * VSPH_PI * VSPH_PI * nu / (4.0 * d * d);
  return U0 * (1.0 - (yc / d) * (yc / d) - k * sum);
}

/* Couette by images: the wall y = W steps to v0, the wall y = 0 stays;
 * u = v0 sum_n [erfc(((2n+1) W - y)/s) - erfc(((2n+1) W + y)/s)], s =
 * 2 sqrt(nu t), and d/dt erfc(x/s) = (x/s) exp(-(x/s)^2)/(sqrt(pi) t). */
static double couette_images(double y, double t, double W, double nu, double v0,
                             double *dudt) {
  const double s = 2.0 * sqrt(nu * t);
  double u = 0.0, du = 0.0;
  for (int n = 0; n < 64; n++) {
    const double z1 = ((2 * n + 1) * W - y) / s, z2 = ((2 * n + 1) * W + y) / s;
    u += erfc(z1) - erfc(z2);
    du += z1 * exp(-z1 * z1) - z2 * exp(-z2 * z2);
    if (z1 > 1.0 && exp(-z1 * z1) * z1 < SERIES_TOL) break;
  }
  if (dudt) *dudt = v0 * du / (sqrt(VSPH_PI) * t);
  return v0 * u;
}

double vsph_references_couette(double y, double t, double W, double nu,
                               double v0, double *dudt) {
  if (t <= 0.0) {
    if (dudt) *dudt = NAN;
    return y >= W ? v0 : 0.0;
  }
  if (nu * t / (W * W) < TAU_IMAGES)
    return couette_images(y, t, W, nu, v0, dudt);
  double sum = 0.0, dsum = 0.0;
  const double a = VSPH_PI * VSPH_PI * nu * t / (W * W);
  for (int n = 1; n < 1000; n++) {
    const double e = exp(-(double)n * n * a);
    const double c =
        (n % 2 ? -1.0 : 1.0) * 2.0 / (n * VSPH_PI) * sin(n * VSPH_PI * y / W);
    sum += c * e;
    dsum -= c * e * n * n * a / t;
    if (e * n < SERIES_TOL) break; /* later terms below e n (rate) */
  }
  if (dudt) *dudt = v0 * dsum;
  return v0 * (y / W + sum);
}

double vsph_references_channel(const struct vsph_scene_channel *ch, double y,
                               double t, double *dudt) {
  if (!ch) return NAN;
  return ch->couette
             ? vsph_references_couette(y, t, ch->W, ch->nu, ch->U, dudt)
             : vsph_references_poiseuille(y, t, ch->W, ch->nu, ch->U, dudt);
}

void vsph_references_profile_error(const struct vsph_scene *sc,
                                   const struct vsph_particles *p,
                                   size_t n_fluid, double t,
                                   struct vsph_references_profile_err *e) {
  if (!sc || !p || !e) return;
  e->rms = e->rms_rel = e->v_rms = NAN;
  if (!vsph_scene_is_channel(sc->type)) return;
  const struct vsph_scene_channel *ch = &sc->u.channel;
  double s = 0.0, sr = 0.0, sv = 0.0;
  size_t n = 0;
  for (size_t i = 0; i < p->n; i++) {
    if (p->id[i] >= n_fluid) continue;
    const double U = vsph_references_channel(ch, p->pos[1][i], t, NULL);
    const double du = p->vel[0][i] - U;
    s += du * du;
    sr += du * du / (U * U); /* inf or NaN where U = 0: reported so */
    sv += p->vel[1][i] * p->vel[1][i];
    n++;
  }
  if (n == 0) return;
  e->rms = sqrt(s / n) / ch->U;
  e->rms_rel = isfinite(sr) ? sqrt(sr / n) : (double)NAN;
  e->v_rms = sqrt(sv / n) / ch->U;
}

void vsph_references_profile_zigzag(const double *y, const double *u,
                                    const double *U, size_t nb, double scale,
                                    struct vsph_references_zigzag *z) {
  if (!y || !u || !U || !z) return;
  double s2 = 0.0;
  z->max = z->y_max = (double)NAN;
  z->n = 0;
  for (size_t k = 1; k + 1 < nb; k++) {
    const double zk =
        (2.0 * (u[k] - U[k]) - (u[k - 1] - U[k - 1]) - (u[k + 1] - U[k + 1])) /
        (4.0 * scale);
    if (!isfinite(zk)) continue;
    s2 += zk * zk;
    if (!(fabs(zk) <= z->max)) z->max = fabs(zk), z->y_max = y[k];
    z->n++;
  }
  z->rms = z->n ? sqrt(s2 / (double)z->n) : (double)NAN;
}

int vsph_references_profile_bins(const struct vsph_scene *sc,
                                 const struct vsph_particles *p, size_t n_fluid,
                                 double t, size_t nb, double *y, double *u,
                                 double *U, size_t *count) {
  if (!sc || !p || !y || !u || !U || !count)
    VSPH_FAIL(VSPH_EINVAL, "vsph_references_profile_bins: a NULL argument");
  if (!vsph_scene_is_channel(sc->type) || nb == 0)
    VSPH_FAIL(VSPH_EINVAL, "scene '%s' has no velocity profile",
              sc->type->name);
  const struct vsph_scene_channel *ch = &sc->u.channel;
  for (size_t k = 0; k < nb; k++) y[k] = u[k] = 0.0, count[k] = 0;
  for (size_t i = 0; i < p->n; i++) {
    if (p->id[i] >= n_fluid) continue;
    const double yi = p->pos[1][i];
    long k = (long)floor(yi / ch->W * (double)nb);
    k = k < 0 ? 0 : k >= (long)nb ? (long)nb - 1 : k;
    y[k] += yi;
    u[k] += p->vel[0][i];
    count[k]++;
  }
  for (size_t k = 0; k < nb; k++) {
    if (count[k]) {
      y[k] /= (double)count[k];
      u[k] /= (double)count[k];
    } else {
      y[k] = (k + 0.5) * ch->W / (double)nb;
      u[k] = NAN;
    }
    U[k] = vsph_references_channel(ch, y[k], t, NULL);
  }
  return VSPH_OK;
}

/* Channel E_k = (rho/2) length int_0^W U^2 dy and its rate
 * rho length int U dU/dt dy, by Gauss-Legendre quadrature on the table
 * made with the reference (the series is smooth for t > 0; exact zeros at
 * t = 0). */
static void channel_energy(const struct vsph_references_scene *r, double t,
                           double *Ek, double *dEk) {
  const struct vsph_scene_channel *ch = &r->scene->u.channel;
  *Ek = *dEk = 0.0;
  if (t <= 0.0) return;
  const gsl_integration_glfixed_table *gl = r->gl;
  for (size_t k = 0; k < gl->n; k++) {
    double x, w, ut;
    gsl_integration_glfixed_point(0.0, ch->W, k, &x, &w, gl);
    const double U = vsph_references_channel(ch, x, t, &ut);
    *Ek += w * U * U;
    *dEk += w * U * ut;
  }
  *Ek *= 0.5 * r->scene->rho0 * ch->length;
  *dEk *= r->scene->rho0 * ch->length;
}

int vsph_references_scene_eval(struct vsph_references_scene *r, double t,
                               double *Ek, double *dEk_dt) {
  if (!r || !Ek || !dEk_dt)
    VSPH_FAIL(VSPH_EINVAL, "vsph_references_scene_eval: a NULL argument");
  const struct vsph_scene *sc = r->scene;
  *Ek = *dEk_dt = NAN;
  if (r->gl) {
    channel_energy(r, t, Ek, dEk_dt);
    return VSPH_OK;
  }
  if (r->vortex) {
    vsph_references_vortex_energy_series(r->vortex, t, sc->rho0, Ek, dEk_dt);
    return VSPH_OK;
  }
  if (sc->type == &vsph_stretching_square_type) {
    if (t == 0.0) { /* THEORY 6.2: exact initial values */
      const double L = sc->u.square.L, A0 = sc->u.square.A0;
      *Ek = sc->rho0 * A0 * A0 * L * L * L * L / 12.0;
      *dEk_dt = -4.0 * sc->mu * A0 * A0 * L * L;
    }
    return VSPH_OK;
  }
  if (sc->type == &vsph_standing_wave_type) {
    const struct vsph_scene_wave *w = &sc->u.wave;
    const double k = w->k, om = w->omega, A = w->A, nu = w->nu;
    const double L = sc->ref_length;
    *Ek = vsph_references_lighthill(w, sc->rho0, t);
    if (t == 0.0) {
      /* The exact viscous power of the initial potential flow: with
       * D = Hess(phi0), -2 mu int D:D over the tank integrates to
       * -2 rho nu k^2 g A^2 L (= -8 nu k^2 E_k(0), any depth). d/dt of
       * Lighthill's envelope gives half of it: the envelope omits an
       * O(nu/omega) phase shift. */
      *dEk_dt = -2.0 * sc->rho0 * nu * k * k * sc->g * A * A * L;
      return VSPH_OK;
    }
    /* d/dt of (rho g A^2 L/8) e^{-4 nu k^2 t} [1 + cos 2 omega t] */
    const double a = sc->rho0 * sc->g * A * A * L / 8.0;
    const double e = exp(-4.0 * nu * k * k * t);
    *dEk_dt = a * e *
              (-4.0 * nu * k * k * (1.0 + cos(2.0 * om * t)) -
               2.0 * om * sin(2.0 * om * t));
  }
  return VSPH_OK;
}

int vsph_references_scene_mech(struct vsph_references_scene *r, double t,
                               double *Em, double *dEm_dt) {
  if (!r || !Em || !dEm_dt)
    VSPH_FAIL(VSPH_EINVAL, "vsph_references_scene_mech: a NULL argument");
  const struct vsph_scene *sc = r->scene;
  if (sc->type != &vsph_standing_wave_type)
    return vsph_references_scene_eval(r, t, Em, dEm_dt);
  const struct vsph_scene_wave *w = &sc->u.wave;
  const double gam = 4.0 * w->nu * w->k * w->k;
  *Em = sc->rho0 * sc->g * w->A * w->A * sc->ref_length / 4.0 * exp(-gam * t);
  *dEm_dt = -gam * *Em;
  return VSPH_OK;
}

/* Ghia, Ghia & Shin (1982), J. Comput. Phys. 48, 387-411, Tables I and II
 * (Re = 100, 400, 1000), as printed. */
static const double GHIA_Y[17] = {
    1.0000, 0.9766, 0.9688, 0.9609, 0.9531, 0.8516, 0.7344, 0.6172, 0.5000,
    0.4531, 0.2813, 0.1719, 0.1016, 0.0703, 0.0625, 0.0547, 0.0000};
static const double GHIA_U[3][17] = {
    {1.00000, 0.84123, 0.78871, 0.73722, 0.68717, 0.23151, 0.00332, -0.13641,
     -0.20581, -0.21090, -0.15662, -0.10150, -0.06434, -0.04775, -0.04192,
     -0.03717, 0.00000},
    {1.00000, 0.75837, 0.68439, 0.61756, 0.55892, 0.29093, 0.16256, 0.02135,
     -0.11477, -0.17119, -0.32726, -0.24299, -0.14612, -0.10338, -0.09266,
     -0.08186, 0.00000},
    {1.00000, 0.65928, 0.57492, 0.51117, 0.46604, 0.33304, 0.18719, 0.05702,
     -0.06080, -0.10648, -0.27805, -0.38289, -0.29730, -0.22220, -0.20196,
     -0.18109, 0.00000}};
static const double GHIA_X[17] = {
    1.0000, 0.9688, 0.9609, 0.9531, 0.9453, 0.9063, 0.8594, 0.8047, 0.5000,
    0.2344, 0.2266, 0.1563, 0.0938, 0.0781, 0.0703, 0.0625, 0.0000};
static const double GHIA_V[3][17] = {
    {0.00000, -0.05906, -0.07391, -0.08864, -0.10313, -0.16914, -0.22445,
     -0.24533, 0.05454, 0.17527, 0.17507, 0.16077, 0.12317, 0.10890, 0.10091,
     0.09233, 0.00000},
    {0.00000, -0.12146, -0.15663, -0.19254, -0.22847, -0.23827, -0.44993,
     -0.38598, 0.05186, 0.30174, 0.30203, 0.28124, 0.22965, 0.20920, 0.19713,
     0.18360, 0.00000},
    {0.00000, -0.21388, -0.27669, -0.33714, -0.39188, -0.51550, -0.42665,
     -0.31966, 0.02526, 0.32235, 0.33075, 0.37095, 0.32627, 0.30353, 0.29012,
     0.27485, 0.00000}};

int vsph_references_ghia(double Re, struct vsph_references_ghia *g) {
  static const double RE[3] = {100.0, 400.0, 1000.0};
  for (int k = 0; k < 3; k++)
    if (fabs(Re - RE[k]) <= 1e-9 * RE[k]) {
      *g = (struct vsph_references_ghia){
          .y = GHIA_Y, .u = GHIA_U[k], .x = GHIA_X, .v = GHIA_V[k], .n = 17};
      return 1;
    }
  return 0;
}

void vsph_references_shepard(const struct vsph_particles *p, size_t n_fluid,
                             const struct vsph_kernel_type *k, double h,
                             const double x[3], double u[3]) {
  if (!p || !k || !x || !u) return;
  const int d = p->dim;
  double S = 0.0, su[3] = {0, 0, 0};
  for (size_t i = 0; i < p->n; i++) {
    if (p->id[i] >= n_fluid) continue;
    double s2 = 0.0;
    for (int a = 0; a < d; a++) {
      const double dx = p->pos[a][i] - x[a];
      s2 += dx * dx;
    }
    const double w = vsph_kernel_w(k, d, sqrt(s2) / h);
    if (w <= 0.0) continue;
    S += w;
    for (int a = 0; a < d; a++) su[a] += w * p->vel[a][i];
  }
  for (int a = 0; a < 3; a++) u[a] = a < d && S > 0.0 ? su[a] / S : (double)NAN;
}

size_t vsph_references_cavity_umin(const double *t, const double *vel, size_t n,
                                   size_t npts, double Re, double *t_out,
                                   double *err, size_t cap) {
  struct vsph_references_ghia g;
  if (!vsph_references_ghia(Re, &g) || npts == 0 || n % (2 * npts)) return 0;
  double ref = INFINITY;
  for (size_t q = 0; q < g.n; q++) ref = fmin(ref, g.u[q]);
  size_t m = 0;
  for (size_t b = 0; b < n && m < cap; b += 2 * npts) {
    double u = INFINITY;
    for (size_t q = 0; q < 2 * npts; q++)
      if (t[b + q] != t[b]) return 0; /* a block of one time */
    for (size_t q = 0; q < npts; q++) u = fmin(u, vel[b + q]);
    t_out[m] = t[b];
    err[m++] = fabs(u - ref);
  }
  return m;
}

size_t vsph_references_cavity_rms(const double *t, const double *vel, size_t n,
                                  size_t npts, double Re, double U,
                                  double *t_out, double *err, size_t cap) {
  struct vsph_references_ghia g;
  if (!vsph_references_ghia(Re, &g) || npts != g.n || n % (2 * npts) || !t ||
      !vel || !t_out || !err || !(U > 0.0) || !isfinite(U))
    return 0;
  size_t m = 0;
  for (size_t b = 0; b < n && m < cap; b += 2 * npts) {
    for (size_t q = 0; q < 2 * npts; q++)
      if (t[b + q] != t[b]) return 0; /* a block of one time */
    double s2 = 0.0;
    for (size_t q = 1; q + 1 < npts; q++) { /* the walls' points left out */
      const double du = vel[b + q] / U - g.u[q],
                   dv = vel[b + npts + q] / U - g.v[q];
      s2 += du * du + dv * dv;
    }
    t_out[m] = t[b];
    err[m++] = sqrt(s2 / (double)(2 * (npts - 2)));
  }
  return m;
}

double vsph_references_ghia_rest(double Re) {
  struct vsph_references_ghia g;
  if (!vsph_references_ghia(Re, &g)) return NAN;
  double s2 = 0.0;
  size_t n = 0;
  for (size_t q = 1; q + 1 < g.n; q++) { /* the walls' own points left out */
    s2 += g.u[q] * g.u[q] + g.v[q] * g.v[q];
    n += 2;
  }
  return sqrt(s2 / (double)n);
}

double vsph_references_cavity_point(
    const struct vsph_scene_cavity *cv, const struct vsph_references_ghia *g,
    int line, size_t q, const struct vsph_particles *p, size_t n_fluid,
    const struct vsph_kernel_type *k, double h, double *sph, double *ref) {
  if (!cv || !g || !p || !k || !sph || !ref) return NAN;
  const double s = (line ? g->x[q] : g->y[q]) * cv->L;
  double x[3] = {0.5 * cv->L, 0.5 * cv->L, 0.0}, u[3];
  x[line ? 0 : 1] = s;
  vsph_references_shepard(p, n_fluid, k, h, x, u);
  *sph = u[line];
  *ref = (line ? g->v[q] : g->u[q]) * cv->U;
  return s;
}

void vsph_references_cavity_error(const struct vsph_scene *sc,
                                  const struct vsph_particles *p,
                                  size_t n_fluid,
                                  const struct vsph_kernel_type *k, double h,
                                  struct vsph_references_profile_err *e) {
  if (!sc || !p || !k || !e) return;
  e->rms = e->rms_rel = e->v_rms = NAN;
  struct vsph_references_ghia g;
  if (sc->type != &vsph_cavity_type) return;
  const struct vsph_scene_cavity *cv = &sc->u.cavity;
  if (!vsph_references_ghia(cv->Re, &g)) return;
  double s2 = 0.0, mx = 0.0;
  size_t n = 0;
  for (size_t q = 1; q + 1 < g.n; q++) /* the walls' own points left out */
    for (int line = 0; line < 2; line++) {
      double sph, ref;
      vsph_references_cavity_point(cv, &g, line, q, p, n_fluid, k, h, &sph,
                                   &ref);
      const double err = sph - ref;
      s2 += err * err;
      mx = fmax(mx, fabs(err));
      n++;
    }
  e->rms = sqrt(s2 / (double)n) / cv->U;
  e->rms_rel = mx / cv->U;
}

/* Lamb's relation, its residual at s */
static double complex lamb_f(double complex s, double k, double nu,
                             double w02) {
  const double complex a = s + 2.0 * nu * k * k;
  return a * a + w02 - 4.0 * nu * nu * k * k * k * csqrt(k * k + s / nu);
}

int vsph_references_wave_decay(double g, double k, double H, double nu,
                               double *gamma, double *omega) {
  if (!(g > 0.0 && k > 0.0 && H > 0.0 && nu >= 0.0) || !isfinite(nu))
    VSPH_FAIL(VSPH_EINVAL, "wave decay: need g, k, H > 0 and nu >= 0");
  const double w02 = g * k * tanh(k * H);
  if (nu == 0.0) { /* inviscid: no decay */
    *gamma = 0.0;
    *omega = sqrt(w02);
    return VSPH_OK;
  }
  double complex s = CMPLX(-2.0 * nu * k * k, sqrt(w02));
  for (int it = 0; it < 60; it++) {
    const double complex f = lamb_f(s, k, nu, w02);
    /* the derivative in closed form: 2a - 2 nu k^3 / sqrt(k^2 + s/nu) */
    const double complex df = 2.0 * (s + 2.0 * nu * k * k) -
                              2.0 * nu * k * k * k / csqrt(k * k + s / nu);
    const double complex ds = f / df;
    s -= ds;
    if (cabs(ds) <= 1e-14 * cabs(s)) {
      *gamma = -creal(s);
      *omega = cimag(s);
      return VSPH_OK;
    }
  }
  VSPH_FAIL(VSPH_ENOCONV,
            "wave decay: Newton's method did not converge "
            "(nu = %g, k = %g)",
            nu, k);
}
