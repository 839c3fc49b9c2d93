#include "references.h"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>
#include <gsl/gsl_sf_bessel.h>
#include <math.h>
#include <stdlib.h>

#include "../common/consts.h"
#include "../common/status.h"

/* Quadrature limits of the private workspace and the accuracy asked. */
static const size_t QUAD_LIMIT = 500;
static const double QUAD_EPSREL = 1e-12;

double vsph_references_vortex_initial(const struct vsph_references_vortex *v,
                                      double r) {
  const double l2 = v->l2, R2 = v->R * v->R;
  return v->omega0 * l2 *
         (1.0 / (l2 + r * r) + r * r / ((l2 + R2) * (l2 + R2)));
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
  int which; /* 0: omega0 phi r^3, 1: phi^2 r^3, 2: omega0 r^3 */
};

static double coef_integrand(double r, void *p) {
  const struct coef_ctx *c = p;
  const double f = phi(c->k * r), r3 = r * r * r;
  if (c->which == 0) return vsph_references_vortex_initial(c->v, r) * f * r3;
  if (c->which == 1) return f * f * r3;
  return vsph_references_vortex_initial(c->v, r) * r3;
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

struct vsph_references_vortex *vsph_references_vortex_alloc(double R, double l2,
                                                            double omega0,
                                                            double nu,
                                                            size_t nterms) {
  if (!(R > 0.0) || !(l2 > 0.0) || !(nu >= 0.0) || !isfinite(omega0) ||
      nterms < 1) {
    vsph_status_report(VSPH_EINVAL, __FILE__, __LINE__,
                       "vortex reference: need R > 0, l^2 > 0, nu >= 0, "
                       "terms >= 1");
    return NULL;
  }
  struct vsph_references_vortex *v = calloc(1, sizeof *v);
  if (!v) goto nomem;
  v->R = R;
  v->l2 = l2;
  v->omega0 = omega0;
  v->nu = nu;
  v->nterms = nterms;
  v->k = malloc(nterms * sizeof *v->k);
  v->c = malloc(nterms * sizeof *v->c);
  v->ws = gsl_integration_workspace_alloc(QUAD_LIMIT);
  if (!v->k || !v->c || !v->ws) goto nomem;
  gsl_integration_workspace *ws = v->ws;
  /* c_0 = int omega r^3 dr / int r^3 dr = 4 int omega r^3 dr / R^4 */
  struct coef_ctx cx = {v, 0.0, 2};
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
    cx.k = v->k[n];
    cx.which = 0;
    if (integrate(ws, coef_integrand, &cx, 0.0, R, &num)) goto fail;
    cx.which = 1;
    if (integrate(ws, coef_integrand, &cx, 0.0, R, &den)) goto fail;
    v->c[n] = num / den;
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
  gsl_integration_workspace_free(v->ws);
  free(v);
}

void vsph_references_vortex_eval(const struct vsph_references_vortex *v,
                                 double r, double t, double *omega,
                                 double *domega_dr) {
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

double vsph_references_lighthill(double rho, double g, double A, double L,
                                 double nu, double k, double omega, double t) {
  return rho * g * A * A * L / 8.0 * exp(-4.0 * nu * k * k * t) *
         (1.0 + cos(2.0 * omega * t));
}

void vsph_references_wave_velocity(double A, double g, double k, double H,
                                   double omega, double x, double y,
                                   double u[2]) {
  const double a = A * g / omega * k / cosh(k * H);
  u[0] = -a * cosh(k * (y + H)) * sin(k * x);
  u[1] = a * sinh(k * (y + H)) * cos(k * x);
}
