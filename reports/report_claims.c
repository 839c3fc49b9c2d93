/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
/* Section 9 of the report: the paper's claims beside our figures, each with
 * a verdict. The analysis claims (THEORY 2-4) are recomputed here (they are
 * cheap), so the table is complete even when those parts come from the
 * cache; the scene claims read the runs of sections 5-8. */
#include "report_claims.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "../analysis/dissipation.h"
#include "../analysis/fields.h"
#include "../analysis/moments.h"
#include "../analysis/references.h"
#include "../analysis/scaling.h"
#include "../common/consts.h"
#include "../common/status.h"
#include "../kernels/kernel.h"
#include "../solver/lattice.h"
#include "../solver/particles.h"
#include "../solver/scene.h"
#include "../solver/viscous.h"
#include "grade.h"
#include "report.h"
#include "report_fv.h"
#include "report_parts.h"

#define NFORM VSPH_VISCOUS_PAPER_COUNT /* the free-surface study's three */
enum {
  MGF = VSPH_VISCOUS_MGF,
  MEAF = VSPH_VISCOUS_MEAF,
  PVWF = VSPH_VISCOUS_PVWF
};

static const char *yes_no(int ok, const char *yes, const char *no) {
  return ok ? yes : no;
}

/* Append to @p buf of @p len bytes at offset *m (the length so far, which
 * may pass len: the text is then cut, never written past the end, and no
 * pointer is formed beyond it). */
static void append(char *buf, size_t len, size_t *m, const char *fmt, ...) {
  va_list ap;
  va_start(ap, fmt);
  const size_t at = *m < len ? *m : len - 1;
  const int n = vsnprintf(buf + at, len - at, fmt, ap);
  va_end(ap);
  if (n > 0) *m = at + (size_t)n;
}

/* ---------------------------------------------------- analysis (THEORY 2-4) */

static int scaling_claims(struct vsph_report *R) {
  double slope[2][NFORM];
  int round_[2][NFORM];
  for (int fk = 0; fk < 2; fk++) { /* rotation, strain */
    struct vsph_scaling_props sp;
    int st = vsph_scaling_props_init(&sp, NULL);
    if (!st) st = vsph_fields_props_init(&sp.field, fk, 2);
    struct vsph_scaling_result r;
    if (!st) st = vsph_scaling_surface(&sp, &r);
    if (st) return st;
    for (int f = 0; f < NFORM; f++) {
      slope[fk][f] = r.slope[f];
      round_[fk][f] = r.rounding[f];
    }
  }
  char ours[VSPH_REPORT_CLAIM_BUF];
  snprintf(ours, sizeof ours,
           "pure strain, 2-D, h/dx 4/3, h halved 4 times from 0.1: slopes "
           "MGF %.3f, MEAF %.3f, PVWF %.3f",
           slope[1][MGF], slope[1][MEAF], slope[1][PVWF]);
  int st = vsph_report_claim(
      R,
      "All three operators diverge like 1/h at the surface when n.D.n != 0 "
      "(App. B)",
      "slope -1", ours,
      "none (the paper's result is analytic; ours are particle sums, "
      "Gaussian kernel, h/dx 4/3)",
      /* an order claim: the nearest integer decides (grade.h) */
      yes_no(vsph_grade_order_is(slope[1][MGF], -1) == 1 &&
                 vsph_grade_order_is(slope[1][MEAF], -1) == 1 &&
                 vsph_grade_order_is(slope[1][PVWF], -1) == 1,
             "reproduced", "differs: a slope that does not round to -1"));
  snprintf(ours, sizeof ours,
           "rigid rotation, same ladder: MGF %s, PVWF %s, MEAF slope %.3f "
           "(its term is tangential)",
           round_[0][MGF] ? "rounding level" : "grows",
           round_[0][PVWF] ? "rounding level" : "grows", slope[0][MEAF]);
  if (!st)
    st = vsph_report_claim(
        R,
        "Rigid rotation (n.D.n = 0): MGF and PVWF stay bounded, MEAF "
        "diverges like 1/h (App. B)",
        "MEAF ~ -mu C_N/h du/dn", ours, "none (as above)",
        yes_no(round_[0][MGF] && round_[0][PVWF] &&
                   vsph_grade_order_is(slope[0][MEAF], -1) == 1,
               "reproduced", "differs"));
  return st;
}

static int dissipation_claims(struct vsph_report *R) {
  /* MGF, MEAF, PVWF at h/dx 4/3 on 160 across; MGF at h/dx 3; MGF at
   * h/dx 4/3 on 80 across (the surface part's fall with h/L) */
  enum { ND = 5 };
  struct vsph_dissipation_result d[ND];
  static const int forms[ND] = {MGF, MEAF, PVWF, MGF, MGF};
  static const int fields[ND] = {VSPH_FIELDS_STRAIN, VSPH_FIELDS_ROTATION,
                                 VSPH_FIELDS_STRAIN, VSPH_FIELDS_STRAIN,
                                 VSPH_FIELDS_STRAIN};
  static const double hdxs[ND] = {VSPH_CONSTS_HDX, VSPH_CONSTS_HDX,
                                  VSPH_CONSTS_HDX, 3.0, VSPH_CONSTS_HDX};
  static const size_t across[ND] = {160, 160, 160, 160, 80};
  for (int k = 0; k < ND; k++) {
    struct vsph_dissipation_props dp;
    int st = vsph_dissipation_props_init(&dp, NULL);
    dp.form = forms[k];
    dp.nacross = across[k];
    dp.hdx = hdxs[k];
    if (!st) st = vsph_fields_props_init(&dp.field, fields[k], 2);
    if (!st) st = vsph_dissipation_compute(&dp, &d[k]);
    if (st) return st;
  }
  /* the surface part's order in h/L from 80 to 160 across */
  const double so = log2(fabs(d[4].surface_error) / fabs(d[0].surface_error));
  char ours[VSPH_REPORT_CLAIM_BUF];
  snprintf(ours, sizeof ours,
           "square: lattice error %+.2f %% at h/dx 4/3, %+.2f %% at h/dx 3; "
           "surface part %+.2f %% at 80 across, %+.2f %% at 160 (order %.2f "
           "in h/L)",
           100 * d[0].lattice_error, 100 * d[3].lattice_error,
           100 * d[4].surface_error, 100 * d[0].surface_error, so);
  /* consistent up to O(h): the surface part falls at first order in h/L
   * (the nearest-integer rule) and the lattice part falls as h/dx grows */
  const int cons = vsph_grade_order_is(so, 1) == 1 &&
                   fabs(d[3].lattice_error) < fabs(d[0].lattice_error);
  int st = vsph_report_claim(
      R,
      "MGF is globally consistent: P -> -int V:D despite the 1/h surface "
      "force (5.35)",
      "consistent up to O(h)", ours,
      "none (a property of the operator, measured on an analytic strain "
      "field: squares of 80 and 160 across, h/dx 4/3 and 3)",
      yes_no(cons,
             "reproduced in the limit: the surface part falls at first order "
             "in h/L and the lattice part with h/dx (docs/theory.md §4: "
             "about 6 % at h/dx 4/3)",
             "differs: the surface part does not fall at first order, or "
             "the lattice part does not fall with h/dx"));
  snprintf(ours, sizeof ours,
           "rigid rotation, square, 160 across, h/dx 4/3: P/|P_grad| = %.3f",
           d[1].rel_error);
  /* -1 within the discrete sums' own lattice error at this h/dx (MGF's on
   * strain, section 4: about 6 %) */
  if (!st)
    st = vsph_report_claim(
        R,
        "MEAF converges to -mu int |grad u|^2 and dissipates rigid rotation "
        "(5.36)",
        "wrong limit", ours, "none (as above)",
        yes_no(
            vsph_grade_within(d[1].rel_error, -1.0, fabs(d[0].lattice_error)),
            "reproduced: -1 within the lattice error of the sums at this "
            "h/dx (section 4)",
            "differs"));
  snprintf(ours, sizeof ours,
           "pure strain, square, 160 across, h/dx 4/3: rel. error %.1e",
           d[2].rel_error);
  if (!st)
    st = vsph_report_claim(
        R,
        "PVWF's dissipation is -int V:D exactly at the discrete level (4.18)",
        "exact", ours, "none (as above)",
        yes_no(fabs(d[2].rel_error) < VSPH_GRADE_ROUNDING, "reproduced",
               "differs"));
  return st;
}

/* ------------------------------ the moment tensors and the operators */

/* The largest gap of tensor k (0 F, 1 G, 2 N, 3 M) between quadrature and
 * theory over every kernel, in 2-D and 3-D, at half (@p half = 1) or full
 * support. */
static int tensor_gaps(struct vsph_report *R, int half, double gmax[4]) {
  for (int t = 0; t < 4; t++) gmax[t] = 0.0;
  for (size_t ki = 0; ki < vsph_kernel_count(); ki++) {
    const struct vsph_kernel_type *k = vsph_kernel_get(ki);
    for (int dim = 2; dim <= 3; dim++) {
      double C_F, C_N, g[4];
      struct vsph_moments q, th;
      int st = vsph_moments_constants(k, dim, 1e-12, R->wo, &C_F, &C_N);
      if (!st)
        st = vsph_moments_quadrature(k, dim, half ? 0.0 : k->kappa, 1e-10,
                                     R->wo, R->wi, &q);
      if (st) return st;
      vsph_moments_theory(dim, half, C_F, C_N, &th);
      vsph_moments_gap(&q, &th, g);
      for (int t = 0; t < 4; t++) gmax[t] = fmax(gmax[t], g[t]);
    }
  }
  return VSPH_OK;
}

/* The quadrature asks 1e-10 relative of its outer integrals; a tensor
 * entry of order 1 then carries at most about 1e-9 (ten times that, for
 * the nested inner integrals): the tolerance of "exactly" here. */
#define TENSOR_QUAD_TOL 1e-9

static int tensor_claims(struct vsph_report *R) {
  double gh[4], gf[4];
  int st = tensor_gaps(R, 1, gh);
  if (!st) st = tensor_gaps(R, 0, gf);
  if (st) return st;
  const size_t nk = vsph_kernel_count();
  char ours[VSPH_REPORT_CLAIM_BUF];
  snprintf(ours, sizeof ours,
           "largest entry gap to S (full support) and S/2 (half), by "
           "quadrature, over the %zu kernels in 2-D and 3-D: %.1e and %.1e",
           nk, gf[1], gh[1]);
  const char *setup =
      "the paper's result is analytic and kernel-free; ours by GSL "
      "quadrature (1e-10) for every kernel vsph has (section 1 adds the "
      "particle sums and their lattice error)";
  st = vsph_report_claim(
      R,
      "G = S in the interior and S/2 at the surface, whatever the kernel "
      "(App. A)",
      "exactly", ours, setup,
      yes_no(gf[1] < TENSOR_QUAD_TOL && gh[1] < TENSOR_QUAD_TOL,
             "reproduced: to the quadrature's accuracy, for every kernel",
             "differs: a gap above the quadrature's accuracy"));
  snprintf(ours, sizeof ours,
           "largest entry gap to delta (full) and delta/2 (half), as above: "
           "%.1e and %.1e",
           gf[3], gh[3]);
  if (!st)
    st = vsph_report_claim(
        R, "M = delta inside and delta/2 at the surface (IV C)", "exactly",
        ours, setup,
        yes_no(gf[3] < TENSOR_QUAD_TOL && gh[3] < TENSOR_QUAD_TOL,
               "reproduced: to the quadrature's accuracy, for every kernel",
               "differs: a gap above the quadrature's accuracy"));
  /* Appendix B's constants for the untruncated Gaussian in 2-D, C_F =
   * K/(3 sqrt pi) and C_N = 2/sqrt pi, against ours for the renormalised
   * 3h Gaussian: the two differ by its factor I/I_inf = (erf 3 - 6 e^-9 /
   * sqrt pi)/(1 - 10 e^-9) exactly (THEORY 2's formula), so ours over the
   * paper's times that factor's inverse is 1 to the quadrature */
  const struct vsph_kernel_type *gk = vsph_kernel_find("gaussian");
  double C_F, C_N;
  if (!gk) VSPH_FAIL(VSPH_EINVAL, "no gaussian kernel");
  if ((st = vsph_moments_constants(gk, 2, 1e-12, R->wo, &C_F, &C_N))) return st;
  const double e9 = exp(-9.0);
  const double trunc = (erf(3.0) - 6.0 * e9 / VSPH_SQRTPI) / (1.0 - 10.0 * e9);
  const double CF_paper = vsph_kernel_mg_factor(2) / (3.0 * VSPH_SQRTPI),
               CN_paper = 2.0 / VSPH_SQRTPI;
  const double rf = C_F / (CF_paper * trunc) - 1.0,
               rn = C_N / (CN_paper * trunc) - 1.0;
  snprintf(ours, sizeof ours,
           "2-D, renormalised 3h Gaussian: C_F = %.7f, C_N = %.7f; the "
           "paper's untruncated K/(3 sqrt pi) = %.7f and 2/sqrt pi = %.7f, "
           "times the truncation's factor %.6f: ours over those %+.1e and "
           "%+.1e; the half-support quadrature's N and F against -(C/h) n "
           "and F's form: gaps %.1e and %.1e",
           C_F, C_N, CF_paper, CN_paper, trunc, rf, rn, gh[2], gh[0]);
  if (!st)
    st = vsph_report_claim(
        R,
        "At the surface N = -(C_N/h) n and F = -(C_F/h)(...), with C_F = "
        "K/(3 sqrt pi), C_N = 2/sqrt pi for the 2-D Gaussian (App. B)",
        "K/(3 sqrt pi), 2/sqrt pi (untruncated Gaussian)", ours,
        "the paper's constants are for the untruncated Gaussian, ours for "
        "the renormalised 3h Gaussian the paper's runs use: they differ by "
        "the truncation's factor, computed in closed form",
        yes_no(fabs(rf) < TENSOR_QUAD_TOL && fabs(rn) < TENSOR_QUAD_TOL &&
                   gh[0] < TENSOR_QUAD_TOL && gh[2] < TENSOR_QUAD_TOL,
               "reproduced on a substitute: the constants are the paper's "
               "times the 3h kernel's truncation factor, to the quadrature",
               "differs"));
  return st;
}

/* MGF's tangential share bounded while its normal share diverges (App. B,
 * Conclusions): the surface sweep on pure strain, whose top face has
 * tau.D.n = 0 and n.D.n != 0. */
static int tangential_claim(struct vsph_report *R) {
  struct vsph_scaling_props sp;
  struct vsph_scaling_result r;
  int st = vsph_scaling_props_init(&sp, NULL);
  if (!st) st = vsph_fields_props_init(&sp.field, VSPH_FIELDS_STRAIN, 2);
  if (!st) st = vsph_scaling_surface(&sp, &r);
  if (st) return st;
  double nn[VSPH_SCALING_MAXLEVELS], tt[VSPH_SCALING_MAXLEVELS], tmax = 0.0;
  for (size_t l = 0; l < r.levels; l++) {
    nn[l] = fabs(r.normal[MGF][l]);
    tt[l] = r.tangential[MGF][l];
    tmax = fmax(tmax, tt[l] / nn[l]);
  }
  const double sn = vsph_scaling_slope(r.h, nn, r.levels);
  const double stt = vsph_scaling_slope(r.h, tt, r.levels);
  char ours[VSPH_REPORT_CLAIM_BUF];
  char tang[96];
  if (tmax < 1e-9)
    snprintf(tang, sizeof tang, "at rounding level (at most %.1e of it)", tmax);
  else
    snprintf(tang, sizeof tang, "at most %.1e of it, slope %.2f", tmax, stt);
  snprintf(ours, sizeof ours,
           "pure strain, 2-D, h/dx 4/3, h halved %zu times from %g: MGF's "
           "normal share slope %.3f; its tangential share %s",
           r.levels - 1, r.h[0], sn, tang);
  /* diverges: the normal share's order rounds to -1; bounded: the
   * tangential one is rounding (below 1e-9 of the normal: sums of order 1
   * terms that cancel exactly, to rounding) or its order rounds to 0 or
   * above (a slope above -1/2) */
  const int bounded = tmax < 1e-9 || stt > -1.0 + VSPH_GRADE_ORDER_HALFWIDTH;
  return vsph_report_claim(
      R,
      "MGF's tangential component stays bounded at the surface while its "
      "normal one diverges like 1/h (App. B, Conclusions)",
      "tangential bounded, normal ~ 1/h", ours,
      "none (the paper's result is analytic; ours are particle sums, "
      "Gaussian kernel, h/dx 4/3)",
      yes_no(vsph_grade_order_is(sn, -1) == 1 && bounded, "reproduced",
             "differs"));
}

/* MGF implies lambda = mu (4.21): it dissipates an isotropic expansion u
 * = A x, for which the Stokes hypothesis (lambda = -2 mu/d) gives no
 * dissipation in 2-D. On a square of 160 across at h/dx 4/3: MGF's P
 * against its continuum limit -(2 mu D:D + mu (tr D)^2)|Omega| = -8 mu A^2
 * L^2; PVWF (lambda = -2 mu/d, exact on linear fields) against 0. */
static int stokes_claim(struct vsph_report *R) {
  const size_t n = 160;
  const double A = 1.2348, L = 1.0, mu = 0.0137;
  struct vsph_lattice_props lp = {.dim = 2};
  struct vsph_particles *p = NULL;
  int st = vsph_lattice_square(&lp, L, n, &p);
  if (st) return st;
  for (size_t i = 0; i < p->n; i++)
    for (int k = 0; k < 2; k++) p->vel[k][i] = A * p->pos[k][i];
  const struct vsph_kernel_type *gk = vsph_kernel_find("gaussian");
  const double dx = L / (double)n, h = VSPH_CONSTS_HDX * dx;
  struct vsph_dissipation_power pw[2];
  const int forms[2] = {MGF, PVWF};
  for (int f = 0; f < 2 && !st; f++) {
    struct vsph_viscous_props vp;
    st = vsph_viscous_props_init(&vp, forms[f], gk, 2, h, mu);
    if (!st) st = vsph_dissipation_particles(&vp, p, &pw[f]);
  }
  vsph_particles_free(p);
  if (st) return st;
  const double P_mg = -8.0 * mu * A * A * L * L;  /* lambda = mu */
  const double P_div = -4.0 * mu * A * A * L * L; /* 2 mu D:D alone */
  char ours[VSPH_REPORT_CLAIM_BUF];
  snprintf(ours, sizeof ours,
           "isotropic expansion u = A x, square of %zu across, h/dx 4/3: MGF "
           "dissipates %.4f of -(2 mu D:D + mu (tr D)^2)|Omega| (its lambda "
           "= mu limit; Stokes' lambda = -mu gives 0 in 2-D); PVWF (lambda "
           "= -mu) %.1e of 2 mu D:D |Omega|",
           n, pw[0].P / P_mg, fabs(pw[1].P / P_div));
  /* which second viscosity MGF's dissipation shows: of the hypotheses
   * lambda = mu (1 of the limit above), lambda = 0 (1/2) and Stokes'
   * lambda = -mu (0), the nearest (no band chosen: the midpoint 3/4
   * decides); PVWF's zero to rounding */
  const double q = pw[0].P / P_mg;
  const int ok = q > 0.75 && fabs(pw[1].P / P_div) < VSPH_GRADE_ROUNDING;
  return vsph_report_claim(
      R,
      "MGF implies lambda = mu and does not satisfy the Stokes hypothesis "
      "(4.21)",
      "lambda = mu", ours,
      "none (a property of the operator, measured on an analytic field; "
      "graded by the nearest of lambda = mu, 0 and -mu)",
      yes_no(ok,
             "reproduced: MGF dissipates an isotropic expansion as lambda = "
             "mu says (nearer 1 than lambda = 0's 1/2 or Stokes' 0), where "
             "Stokes' lambda gives none (PVWF: zero to rounding)",
             "differs"));
}

/* PVWF takes both signs near the surface (VI B, Fig. 6 right), MGF and
 * MEAF one: the y component of the operator along the stretching square's
 * axis at t = 0 (section 3's axis data), over the rows within kappa h of
 * the top surface. */
static int signs_claim(struct vsph_report *R) {
  struct vsph_scaling_props sp;
  int st = vsph_scaling_props_init(&sp, NULL);
  if (!st) st = vsph_fields_props_init(&sp.field, VSPH_FIELDS_STRAIN, 2);
  if (st) return st;
  const size_t nacross = 80;
  double y[80], *f[VSPH_VISCOUS_FORM_COUNT] = {NULL};
  double buf[VSPH_VISCOUS_FORM_COUNT][80];
  for (int k = 0; k < VSPH_VISCOUS_FORM_COUNT; k++) f[k] = buf[k];
  size_t n = 0;
  if ((st = vsph_scaling_axis(&sp, nacross, y, f, &n))) return st;
  const double dx = 1.0 / (double)nacross, h = sp.hdx * dx;
  int changes[NFORM] = {0};
  for (int fm = 0; fm < NFORM; fm++) {
    int last = 0;
    for (size_t k = 0; k < n; k++) {
      if (0.5 - y[k] > 3.0 * h) continue; /* within kappa h of the top */
      /* a value at rounding level of the surface row's has no sign: the
       * exact value is 0 inside (a linear field) and the sums of order-1
       * terms cancel there to about 1e-15 of them */
      if (fabs(f[fm][k]) < 1e-12 * fabs(f[fm][n - 1])) continue;
      const int s = f[fm][k] > 0 ? 1 : -1;
      changes[fm] += last && s != last;
      last = s;
    }
  }
  char ours[VSPH_REPORT_CLAIM_BUF];
  snprintf(ours, sizeof ours,
           "sign changes of the y component along the stretching square's "
           "axis at t = 0, over the rows within 3h of the top (%zu across, "
           "h/dx 4/3): PVWF %d, MGF %d, MEAF %d",
           nacross, changes[PVWF], changes[MGF], changes[MEAF]);
  return vsph_report_claim(
      R,
      "PVWF's operator takes both signs near the surface, MGF's and MEAF's "
      "one (VI B, Fig. 6)",
      "PVWF both signs; MGF, MEAF not", ours,
      "none (the operators on the stretching square's initial field, "
      "section 3's axis; the paper's Fig. 6 shows L/dx = 80 too)",
      yes_no(changes[PVWF] > 0 && changes[MGF] == 0 && changes[MEAF] == 0,
             "reproduced", "differs"));
}

static int theory_claims(struct vsph_report *R) {
  int st = tensor_claims(R);
  if (!st) st = tangential_claim(R);
  if (!st) st = stokes_claim(R);
  if (!st) st = signs_claim(R);
  if (!st)
    st = vsph_report_claim(
        R,
        "On the vortex patch n.D.n = 0 at the surface, so MGF is locally "
        "consistent there (VI A)",
        "n.D.n = 0 (analytic)",
        "not measured: for any u = omega(r) r e_theta, D_rr = du_r/dr = 0 "
        "exactly, so the claim holds for the continuous field; the "
        "particles' own strain rate at the disc's surface is not output",
        "the discrete strain rate at the surface particles of either disc "
        "layout (PVWF's first pass computes it; vsph keeps it internal)",
        "not tested: it needs the discrete strain rate at the disc's surface "
        "particles, which vsph's PVWF first pass computes but does not "
        "expose");
  return st;
}

/* --------------------------------------------------- scenes (THEORY 5-6) */

/* The finest run of each scene and formulation, with its decay error. */
struct finest {
  struct vsph_jobs_run run[VSPH_REPORT_NSCENES][NFORM];
  double err[VSPH_REPORT_NSCENES][NFORM];
  struct vsph_report_ladder lr[VSPH_REPORT_NSCENES];
};

static int load_finest(struct vsph_report *R, struct finest *fi) {
  struct vsph_report_richardson rr;
  int st = vsph_report_runs_richardson(&R->runs, &rr);
  for (int sc = 0; sc < VSPH_REPORT_NSCENES && !st; sc++)
    for (int f = 0; f < NFORM && !st; f++) {
      const struct vsph_report_ladderdef *L =
          vsph_report_runs_ladder(&R->runs, sc, 0);
      struct vsph_jobs_spec rs = {L->scene,
                                  vsph_viscous_name(f),
                                  L->res[VSPH_REPORT_LADDER - 1],
                                  L->t_end,
                                  NULL,
                                  NULL};
      st = vsph_report_runs_get(&R->runs, &rs, &fi->run[sc][f]);
      if (!st)
        fi->err[sc][f] =
            vsph_report_runs_error(&fi->run[sc][f], sc == 1 ? &rr : NULL);
    }
  for (int sc = 0; sc < VSPH_REPORT_NSCENES && !st; sc++)
    st = vsph_report_runs_ladder_figures(&R->runs, sc, &fi->lr[sc]);
  return st;
}

/* The stretching square's PVWF at the ladder's coarsest rung with
 * delta-SPH (0.1): the scene runs without density diffusion, a choice the
 * paper does not state, so its stop is checked against it. */
static const char *const SQ_DELTA[2] = {"Solver:delta=0.1", NULL};

static struct vsph_jobs_spec square_delta_spec(const struct vsph_report *R) {
  const struct vsph_report_ladderdef *L =
      vsph_report_runs_ladder(&R->runs, 1, 0);
  return (struct vsph_jobs_spec){L->scene, "pvwf",   L->res[0],
                                 L->t_end, SQ_DELTA, "delta0.1"};
}

/* PVWF's onset on the stretching square over the ladder (VI B), judged
 * at the finest resolution. */
static int square_onset_claim(struct vsph_report *R,
                              const struct vsph_report_ladder *lr,
                              const struct vsph_report_richardson *rr) {
  int st = VSPH_OK;
  char ours[VSPH_REPORT_CLAIM_BUF];
  const struct vsph_report_ladderdef *L =
      vsph_report_runs_ladder(&R->runs, 1, 0);
  int pv_unstable = 0;
  /* the reference rate: the finite-volume solution's where read, else
   * the extrapolated MGF's */
  const int fvok = R->fv->sq.ok;
  double tpv = INFINITY, on_lo = INFINITY, on_hi = -INFINITY;
  double on_fine = (double)NAN, on_first = (double)NAN;
  for (int k = 0; k < VSPH_REPORT_LADDER && !st; k++) {
    if (!lr->ok[PVWF][k]) {
      pv_unstable++;
      tpv = fmin(tpv, lr->t_unstable[PVWF][k]);
    }
    struct vsph_jobs_spec spec = {L->scene, "pvwf", L->res[k],
                                  L->t_end, NULL,   NULL};
    struct vsph_jobs_run r;
    if ((st = vsph_report_runs_get(&R->runs, &spec, &r))) break;
    const double on = fvok ? vsph_report_fv_onset(R, &r, VSPH_REPORT_ONSET)
                           : vsph_report_runs_onset(&r, rr, VSPH_REPORT_ONSET);
    vsph_report_runs_free(&r);
    if (isfinite(on)) {
      on_lo = fmin(on_lo, on);
      on_hi = fmax(on_hi, on);
    }
    on_fine = on; /* the finest last */
    if (k == 0) on_first = on;
  }
  if (st) return st;
  /* the coarsest rung again with delta-SPH */
  const struct vsph_jobs_spec ds = square_delta_spec(R);
  struct vsph_jobs_run dr;
  if ((st = vsph_report_runs_get(&R->runs, &ds, &dr))) return st;
  const double don = fvok ? vsph_report_fv_onset(R, &dr, VSPH_REPORT_ONSET)
                          : vsph_report_runs_onset(&dr, rr, VSPH_REPORT_ONSET);
  const int dok = dr.ok;
  const double dtu = dr.t_unstable;
  vsph_report_runs_free(&dr);
  char dtxt[160], dons[64];
  if (dok)
    snprintf(dtxt, sizeof dtxt, "runs to t A0 = %g", L->t_end);
  else
    snprintf(dtxt, sizeof dtxt, "stopped at t A0 = %.2f", dtu);
  if (isfinite(don))
    snprintf(dons, sizeof dons, "onset %.2f", don);
  else
    snprintf(dons, sizeof dons, "no departure");
  snprintf(ours, sizeof ours,
           "L/dx %zu-%zu: dissipation departs from the reference by > %g %% "
           "at t A0 = %.2f-%.2f (onset); stopped by pairing in %d of %d "
           "runs, earliest at t A0 = %.2f; with delta-SPH (0.1) at L/dx = "
           "%zu: %s, %s",
           L->res[0], L->res[2], 100 * VSPH_REPORT_ONSET, on_lo, on_hi,
           pv_unstable, VSPH_REPORT_LADDER, pv_unstable ? tpv : (double)NAN,
           L->res[0], dons, dtxt);
  /* the stop goes with the scheme's missing density diffusion where the
   * coarsest rung stopped without it and runs to its end with it */
  const int stop_is_scheme = !lr->ok[PVWF][0] && dok;
  char verdict[VSPH_REPORT_CLAIM_BUF], setup[VSPH_REPORT_CLAIM_BUF],
      dclause[400];
  snprintf(dclause, sizeof dclause,
           "; at L/dx = %zu the stop goes with the scheme's lack of density "
           "diffusion [reconstructed: off], the departure survives it (with "
           "delta-SPH it departs at %.2f against %.2f without, and runs to "
           "its end)",
           L->res[0], don, on_first);
  /* judged at the finest resolution: a coarse run departs early from its
   * own truncation error, not from pairing; the paper's "about 0.1" read
   * as 0.15 at most */
  if (!isfinite(on_fine))
    snprintf(verdict, sizeof verdict,
             "not reproduced at L/dx = %zu: no departure", L->res[2]);
  else if (on_fine < 0.15)
    snprintf(verdict, sizeof verdict,
             "reproduced on a substitute: at L/dx = %zu the dissipation "
             "departs at t A0 = %.2f, the run is stopped later",
             L->res[2], on_fine);
  else
    snprintf(verdict, sizeof verdict,
             "partly: PVWF departs and is stopped by pairing, but later "
             "than the paper's 0.1 (t A0 = %.2f at L/dx = %zu)%s",
             on_fine, L->res[2],
             stop_is_scheme && isfinite(don) && isfinite(on_first) ? dclause
             : stop_is_scheme && !isfinite(don)
                 ? "; with delta-SPH the coarsest rung neither departs nor "
                   "stops: both go with the scheme's lack of density "
                   "diffusion [reconstructed: off]"
                 : "");
  snprintf(setup, sizeof setup,
           "reference: %s; onset: first departure of "
           "dE_k/dt by > %g %% of the reference's [reconstructed: the paper "
           "reads it off its figure]; L/dx %zu-%zu (the paper's 320); the "
           "stop against the time step: the CFL sweep does not move the step "
           "here (the viscous bound sets it), so fixed steps of a half and a "
           "quarter of the rule's at the FULL ladder's L/dx = 80 and of a half "
           "at 160 were run by hand, and the lattice shifted by 1e-9 dx: each "
           "stops as the FULL ladder's run does (docs/theory.md §5)",
           fvok ? "the finite-volume solution's viscous power, its dE_k/dt "
                  "to 1 % (OpenFOAM interFoam, 320 cells per L at Courant "
                  "0.05, as the paper's 320)"
                : "MGF extrapolated in h and h/dx [reconstructed] (the "
                  "paper's: a finite-volume solution, not read here)",
           100 * VSPH_REPORT_ONSET, L->res[0], L->res[2]);
  st = vsph_report_claim(
      R, "PVWF on the stretching square becomes unstable (VI B)",
      "deviates after t A0 of about 0.1", ours, setup, verdict);
  return st;
}

static int square_claims(struct vsph_report *R, const struct finest *fi) {
  const struct vsph_jobs_run *run = fi->run[1];
  const size_t rs = vsph_report_runs_ladder(&R->runs, 1, 0)->res[2];
  char ours[VSPH_REPORT_CLAIM_BUF];
  /* P/P_exact = 1 - d, with d = (P - P_exact)/|P_exact| and P_exact < 0 */
  const double d_m = vsph_report_runs_diss0(&run[MGF]);
  const double d_e = vsph_report_runs_diss0(&run[MEAF]);
  const double d_p = vsph_report_runs_diss0(&run[PVWF]);
  snprintf(ours, sizeof ours,
           "(P - P_exact)/|P_exact| at t = 0, L/dx = %zu: PVWF %+.1e, MGF "
           "%+.2f %% (negative: more dissipation than exact), MEAF at %.1f "
           "%% of exact",
           rs, d_p, 100 * d_m, 100 * (1 - d_e));
  char setup[VSPH_REPORT_CLAIM_BUF];
  snprintf(setup, sizeof setup,
           "t = 0 only, the discrete initial field (Poisson pressure by FFT); "
           "L/dx = %zu%s",
           rs,
           R->runs.full ? ""
                        : " (the paper's 320: the surface deficit "
                          "falls like h/L)");
  /* each figure within the precision the paper writes it to: PVWF's
   * 0.04 % an upper bound (ours is exact), MGF's "about 5 %" and MEAF's
   * "about half" to one digit (0.05 +- 0.005, 0.5 +- 0.05) */
  const int ok0 =
      fabs(d_p) <= 4e-4 + vsph_grade_halfunit(4e-4, 1) &&
      vsph_grade_within(fabs(d_m), 0.05, vsph_grade_halfunit(0.05, 1)) &&
      vsph_grade_within(1 - d_e, 0.5, vsph_grade_halfunit(0.5, 1));
  int st = vsph_report_claim(
      R, "Stretching square, initial dissipation error (VI B)",
      "PVWF 0.04 %, MGF about 5 %, MEAF about half", ours, setup,
      yes_no(ok0,
             R->runs.full
                 ? "reproduced: PVWF exact, MEAF half, MGF within the paper's "
                   "'about 5 %' (its lattice error, -6 %, section 4, less a "
                   "surface deficit)"
                 : "reproduced on a substitute: PVWF exact, MEAF half, MGF "
                   "within 'about 5 %' (its lattice error, -6 %, section 4, "
                   "less a surface deficit that falls like h/L)",
             R->runs.full
                 ? "differs: a figure outside the precision the paper gives "
                   "it (0.04 %; 5 % and one half to one digit)"
                 : "differs at this resolution: a figure outside the "
                   "precision the paper gives it (0.04 %; 5 % and one half "
                   "to one digit); MGF's surface deficit, which falls like "
                   "h/L, offsets its lattice error more here than at the "
                   "paper's 320 (the FULL report)"));
  const struct vsph_report_ladder *lr = &fi->lr[1];
  struct vsph_report_richardson rr;
  if (!st) st = vsph_report_runs_richardson(&R->runs, &rr);
  if (st) return st;
  const struct vsph_report_ladderdef *L =
      vsph_report_runs_ladder(&R->runs, 1, 0);
  st = square_onset_claim(R, lr, &rr);
  /* MGF "converges linearly": the ladder's self-convergence (successive
   * resolutions), the paper's "linear convergence"; its 0.55 % is a level
   * against a finite-volume solution: the committed OpenFOAM one where
   * read (reports/fvref.h), judged with its own error band */
  const struct vsph_series_selfconv *sv = &lr->self[MGF];
  const struct vsph_fvref_square *fv = &R->fv->sq;
  double m[5];
  vsph_report_fv_measures(R, &run[MGF], m);
  /* what moves MGF's level, at L/dx 80 (report_fv.c): h/dx 3 and the
   * largest move of the other choices */
  double why[VSPH_REPORT_FV_NWHY];
  for (int w = 0; w < VSPH_REPORT_FV_NWHY && !st; w++) {
    const struct vsph_jobs_spec ws = vsph_report_fv_why_spec(R, w);
    struct vsph_jobs_run wr;
    if ((st = vsph_report_runs_get(&R->runs, &ws, &wr))) break;
    why[w] = wr.ok ? wr.Ek[wr.nrow - 1] / wr.Ek[0] : (double)NAN;
    vsph_report_runs_free(&wr);
  }
  if (st) return st;
  double other = 0; /* the start, integrator, c0, delta-SPH */
  int whyok = isfinite(why[0]) && isfinite(why[1]) && isfinite(why[2]);
  for (int w = 3; w < VSPH_REPORT_FV_NWHY; w++) {
    whyok &= isfinite(why[w]); /* a stopped run leaves it unmeasured */
    other = fmax(other, fabs(why[w] - why[0]));
  }
  const double fv_end = vsph_fvref_square_at(fv, 1.0);
  /* the extrapolated stand-in against the finite volume */
  const double sd = vsph_report_fv_standin_gap(R, &rr);
  snprintf(ours, sizeof ours,
           "MGF, L/dx %zu-%zu: successive differences of E_k/E_k(0) %.2e, "
           "%.2e (orders %.2f largest, %.2f RMS; the finest rung about "
           "%.1e from the limit by Richardson)",
           L->res[0], L->res[2], sv->dmax[0], sv->dmax[1], sv->order_max,
           sv->order_rms, sv->remainder);
  size_t n = strlen(ours);
  if (fv->ok)
    snprintf(ours + n, sizeof ours - n,
             "; against the finite-volume solution (OpenFOAM, 320 cells per "
             "L, step-corrected, error band %.1e of E_k(0), as the paper's) "
             "at L/dx = %zu: %.2f %% of E_k(0) "
             "at most over time, %+.2f %% at t A0 = 1, %.2f %% RMS; the "
             "dissipated share %+.1f %% of the finite volume's. At L/dx 80 "
             "h/dx 2 and 3 move E_k(1)/E_k(0) by %+.3f and %+.3f (the finite "
             "volume's %.3f, MGF's %.3f), the Poisson start, the integrator, "
             "c0 and delta-SPH by %.3f at most%s",
             fv->band, L->res[2], 100 * m[0], 100 * m[1], 100 * m[2],
             100 * m[3], why[1] - why[0], why[2] - why[0], fv_end, why[0],
             other, whyok ? "" : " (a run of these stopped: see section 5)");
  else
    snprintf(ours + n, sizeof ours - n,
             "; error against MGF extrapolated in h and h/dx %.2e at L/dx = "
             "%zu",
             lr->err[MGF][2], L->res[2]);
  if (fv->ok) { /* the paper's Fig. 8 (right): the error at each rung */
    n = strlen(ours);
    snprintf(ours + n, sizeof ours - n,
             "; its error against the finite volume rung by rung:");
    for (int k = 0; k < VSPH_REPORT_LADDER && !st; k++) {
      struct vsph_jobs_spec ks = {L->scene, "mgf", L->res[k],
                                  L->t_end, NULL,  NULL};
      struct vsph_jobs_run kr;
      if ((st = vsph_report_runs_get(&R->runs, &ks, &kr))) break;
      n = strlen(ours);
      snprintf(ours + n, sizeof ours - n, "%s %.2f %%", k ? "," : "",
               100 * vsph_report_fv_error(R, &kr));
      vsph_report_runs_free(&kr);
    }
    if (st) return st;
  }
  snprintf(setup, sizeof setup,
           "order: successive resolutions, no reference needed; level: %s; "
           "L/dx %zu-%zu (the paper's 320); the paper does not say of which "
           "quantity its 0.55 %% is (five definitions in section 5)",
           fv->ok ? "against the finest grid of an OpenFOAM volume-of-fluid "
                    "ladder (40-320 cells per L, each corrected for its step "
                    "by a run at half of it; the step's correction is the "
                    "largest share of its band) on the paper's set-up, as "
                    "the paper's STAR-CCM+ solution"
                  : "the finite-volume solution is not read here (its "
                    "stand-in: MGF extrapolated in h and h/dx "
                    "[reconstructed])",
           L->res[0], L->res[2]);
  const enum vsph_grade g =
      vsph_grade_orders(sv->order_max, sv->order_rms, 1, sv->partial);
  /* the level: within the paper's 0.55 % (two digits) and the finite
   * volume's own band, by the report's measure */
  const int band_ok = fv->ok && fv->band < 0.0055 / 2;
  const int level_ok =
      band_ok && m[0] <= 0.0055 + vsph_grade_halfunit(0.0055, 2) + fv->band;
  /* a band too wide to certify 0.55 % can still show a level beyond it:
   * only a level within 0.55 % plus the band is left untested then */
  const int beyond =
      fv->ok && !(m[0] <= 0.0055 + vsph_grade_halfunit(0.0055, 2) + fv->band);
  char verdict[VSPH_REPORT_CLAIM_BUF];
  if (g == VSPH_GRADE_AGREES && !fv->ok)
    snprintf(verdict, sizeof verdict,
             "partly: MGF converges at first order between successive "
             "resolutions (both orders round to 1); the paper's 0.55 %% "
             "against its finite-volume solution is not tested here (the "
             "committed references were not read)");
  else if (g == VSPH_GRADE_AGREES && !band_ok && !beyond)
    snprintf(verdict, sizeof verdict,
             "partly: MGF converges at first order between successive "
             "resolutions; the level is not tested: the finite volume's own "
             "band (%.1e of E_k(0)) is not below half the paper's 0.55 %%",
             fv->band);
  else if (g == VSPH_GRADE_AGREES && level_ok)
    snprintf(verdict, sizeof verdict,
             "partly: MGF converges at first order, and at L/dx = %zu it is "
             "within 0.55 %% of E_k(0) of the finite-volume solution by the "
             "report's measure (the largest difference over time); the paper "
             "does not say which quantity its 0.55 %% is",
             L->res[2]);
  else if (g == VSPH_GRADE_AGREES) {
    /* every definition beyond 0.55 % and the band; h/dx the cause where
     * h/dx 3 moves the level toward the finite volume by more than twice
     * any other choice */
    int all = 1;
    for (int k = 0; k < 5; k++)
      all &=
          !(fabs(m[k]) <= 0.0055 + vsph_grade_halfunit(0.0055, 2) + fv->band);
    const int hdx = whyok && (why[2] - why[0]) * (fv_end - why[0]) > 0 &&
                    fabs(why[2] - why[0]) > 2 * other &&
                    fabs(why[2] - why[0]) >= 0.5 * fabs(fv_end - why[0]);
    snprintf(verdict, sizeof verdict,
             "partly: MGF converges at first order between successive "
             "resolutions (both orders round to 1), but to a level %.1f %% of "
             "E_k(0) from the finite-volume solution at L/dx = %zu, not "
             "0.55 %% (%s, beyond the finite volume's band of %.1e)%s; the "
             "extrapolated stand-in is %.1f %% from the finite volume at most "
             "and is kept beside it",
             100 * m[0], L->res[2],
             all ? "by every definition in section 5"
                 : "by the report's measure; another definition in section 5 "
                   "comes within it",
             fv->band,
             hdx ? ": h/dx is the main lever on its level (at L/dx 80, h/dx 3 "
                   "closes more than half the gap, more than twice any other "
                   "choice: the start, the integrator, c0, delta-SPH; MGF's "
                   "lattice error at the paper's 4/3, section 4, does not "
                   "fall with dx)"
                 : ": no single choice of section 5's runs accounts for most "
                   "of it",
             100 * sd);
  } else if (g == VSPH_GRADE_UNMEASURED)
    snprintf(verdict, sizeof verdict,
             "not tested: a rung of MGF's ladder stopped (t <= %.3g s only), "
             "so its differences do not cover the run",
             sv->span);
  else
    snprintf(verdict, sizeof verdict,
             "differs: MGF's successive differences fall at first order by "
             "%s (orders %.2f of the largest, %.2f of the RMS)",
             g == VSPH_GRADE_PARTLY ? "one measure only" : "neither measure",
             sv->order_max, sv->order_rms);
  if (!st)
    st = vsph_report_claim(
        R, "MGF converges linearly on the stretching square (VI B)",
        "linear convergence; 0.55 % error at L/dx = 320 against a "
        "finite-volume solution",
        ours, setup, verdict);
  const double share_m = 1 - run[MGF].Ek[run[MGF].nrow - 1] / run[MGF].Ek[0];
  const double share_p = 1 - run[PVWF].Ek[run[PVWF].nrow - 1] / run[PVWF].Ek[0];
  const double share_r = 1 - rr.E[100] / rr.E[0];
  const double share_f =
      fv->ok ? 1 - fv->Ec[VSPH_FVREF_SQ_LADDER - 1][VSPH_FVREF_SQ_ROWS - 1]
             : (double)NAN;
  double sh_lo = INFINITY, sh_hi = -INFINITY; /* every FV series */
  if (fv->ok) {
    const struct vsph_fvref_sqseries *all[] = {
        &fv->g[0],    &fv->g[1],    &fv->g[2],    &fv->g[3],
        &fv->half[0], &fv->half[1], &fv->half[2], &fv->half[3],
        &fv->co2,     &fv->r100,    &fv->r10000,  &fv->wide};
    for (size_t k = 0; k < sizeof all / sizeof all[0]; k++) {
      const double x = 1 - all[k]->E[VSPH_FVREF_SQ_ROWS - 1] / all[k]->E[0];
      sh_lo = fmin(sh_lo, x);
      sh_hi = fmax(sh_hi, x);
    }
  }
  if (fv->ok)
    snprintf(ours, sizeof ours,
             "finite volume (OpenFOAM, 320 cells per L, step-corrected, as "
             "the paper's) %.1f %% (its ladder's limit %.1f %%; every grid "
             "and variant, uncorrected, %.1f-%.1f %%); MGF "
             "extrapolated in h and h/dx %.0f %%; at L/dx = %zu: MGF %.0f %%, "
             "PVWF %.0f %%",
             100 * share_f, 100 * (1 - fv->Ex[VSPH_FVREF_SQ_ROWS - 1]),
             100 * sh_lo, 100 * sh_hi, 100 * share_r, L->res[2], 100 * share_m,
             100 * share_p);
  else
    snprintf(ours, sizeof ours,
             "reference (MGF extrapolated in h and h/dx) %.0f %%; at L/dx = "
             "%zu: MGF %.0f %%, PVWF %.0f %%",
             100 * share_r, L->res[2], 100 * share_m, 100 * share_p);
  if (!run[PVWF].ok) { /* how far it got, in t A0 (t_end is t A0 = 1) */
    n = strlen(ours);
    snprintf(ours + n, sizeof ours - n,
             " (by t A0 = %.3g: PVWF stopped, unstable)",
             run[PVWF].t_unstable / L->t_end);
  }
  /* "about 80 %": one digit, 0.8 +- 0.05 */
  const double share = fv->ok ? share_f : share_r;
  if (!st)
    st = vsph_report_claim(
        R, "Stretching square: share of E_k dissipated by t A0 = 1 (VI B)",
        "about 80 %", ours,
        fv->ok ? "the share is the finite-volume solution's (OpenFOAM "
                 "interFoam, the paper's: STAR-CCM+), on the paper's square, "
                 "Re and initial velocity, with air at 1/1000 of the liquid's "
                 "density and viscosity in a quarter domain 1.2 L x 0.7 L "
                 "(their shares measured, section 5: the finite volume's "
                 "band)"
               : "the share is our reference's (MGF extrapolated in h and h/dx "
                 "[reconstructed]), not a finite-volume solution's",
        yes_no(vsph_grade_within(share, 0.8, vsph_grade_halfunit(0.8, 1)),
               fv->ok ? "reproduced: the finite-volume solution dissipates "
                        "within the paper's 'about 80 %' (80 +- 5 %)"
                      : "reproduced on a substitute: by the extrapolated "
                        "reference, within the paper's 'about 80 %' (80 +- "
                        "5 %)",
               "differs: the reference's share lies outside 80 +- 5 %"));
  return st;
}

/* The Cartesian disc's stops against the time step and rounding: its
 * coarsest rung again at CFL 0.5, 1 and 1.5 (the ladder's own run is at
 * the scene's CFL 2) and with the lattice shifted by 1e-9 dx, each
 * formulation; a stop that comes or goes among them is marginal. */
#define NCART 4
static const char *const CART_SET[NCART][3] = {
    {"Scene:layout=cartesian", "Solver:cfl=0.5", NULL},
    {"Scene:layout=cartesian", "Solver:cfl=1", NULL},
    {"Scene:layout=cartesian", "Solver:cfl=1.5", NULL},
    {"Scene:layout=cartesian", "Solver:perturb=1e-9", NULL}};
static const char *const CART_TAG[NCART] = {
    "cartesian-step0.5", "cartesian-step1", "cartesian-step1.5",
    "cartesian-perturb1e-9"};
static const char *const CART_WHAT[NCART] = {"CFL 0.5", "CFL 1", "CFL 1.5",
                                             "a 1e-9 dx shift"};

static struct vsph_jobs_spec cart_spec(const struct vsph_report *R, int f,
                                       int v) {
  const struct vsph_report_ladderdef *L =
      vsph_report_runs_ladder(&R->runs, 0, 0);
  return (struct vsph_jobs_spec){L->scene, vsph_viscous_name(f), L->res[0],
                                 L->t_end, CART_SET[v],          CART_TAG[v]};
}

static int cart_plan(struct vsph_report *R) {
  int st = VSPH_OK;
  for (int f = 0; f < NFORM && !st; f++)
    for (int v = 0; v < NCART && !st; v++) {
      const struct vsph_jobs_spec rs = cart_spec(R, f, v);
      st = vsph_jobs_plan_run(&R->runs.jobs, &rs);
    }
  return st;
}

/* Whether form @p f's stop (or run to the end) on the Cartesian disc's
 * coarsest rung holds across the variants above (@p holds), said into
 * @p buf where the rung stopped or some variant did: "its stop at R/dx
 * = 25 holds at CFL 0.5, 1, 1.5, 2 and a 1e-9 dx shift (t = a-b s)" or
 * "marginal: ...". */
static int cart_holds(struct vsph_report *R,
                      const struct vsph_report_layouts *ly, int f, char *buf,
                      size_t len, int *holds) {
  const struct vsph_report_ladderdef *L =
      vsph_report_runs_ladder(&R->runs, 0, 0);
  int s[NCART + 1];
  double tlo = INFINITY, thi = -INFINITY;
  s[NCART] = !ly->ok[1][f][0];
  if (s[NCART]) tlo = thi = ly->tu[1][f][0];
  for (int v = 0; v < NCART; v++) {
    const struct vsph_jobs_spec rs = cart_spec(R, f, v);
    struct vsph_jobs_run r;
    const int st = vsph_report_runs_get(&R->runs, &rs, &r);
    if (st) return st;
    s[v] = !r.ok;
    if (!r.ok) {
      tlo = fmin(tlo, r.t_unstable);
      thi = fmax(thi, r.t_unstable);
    }
    vsph_report_runs_free(&r);
  }
  *holds = vsph_grade_stop_holds(s, NCART + 1);
  buf[0] = '\0';
  size_t m = 0;
  if (*holds && !s[NCART]) return VSPH_OK; /* none stopped: nothing to say */
  if (*holds) {
    char a[32], b[32];
    snprintf(a, sizeof a, "%.3g", tlo);
    snprintf(b, sizeof b, "%.3g", thi);
    append(buf, len, &m,
           "%s's Cartesian stop at R/dx = %zu holds at CFL 0.5, 1, 1.5 and 2 "
           "and with a 1e-9 dx shift (t = %s%s%s s)",
           vsph_viscous_label(f), L->res[0], a, strcmp(a, b) ? "-" : "",
           strcmp(a, b) ? b : "");
    return VSPH_OK;
  }
  append(buf, len, &m,
         "%s's Cartesian run at R/dx = %zu is marginal: it %s at CFL 2 but "
         "%s under",
         vsph_viscous_label(f), L->res[0],
         s[NCART] ? "stops" : "runs to the end",
         s[NCART] ? "runs to the end" : "stops");
  for (int v = 0, n = 0; v < NCART; v++)
    if (s[v] != s[NCART])
      append(buf, len, &m, "%s %s", n++ ? "," : "", CART_WHAT[v]);
  return VSPH_OK;
}

/* What stopped where on one vortex layout, over the whole ladder: "" when
 * every run ran to its end, else "; PVWF stopped at R/dx = 25, 50, 100
 * (t = 0.79, 5.44, 3.85 s)". */
static void vortex_stops(char *buf, size_t len,
                         const struct vsph_report_layouts *ly, int l,
                         const struct vsph_report_ladderdef *L) {
  static const char *const lay[2] = {"rings", "Cartesian"};
  size_t m = 0;
  buf[0] = '\0';
  for (int f = 0; f < NFORM && m < len; f++) {
    int any = 0;
    for (int k = 0; k < VSPH_REPORT_LADDER; k++) any |= !ly->ok[l][f][k];
    if (!any) continue;
    append(buf, len, &m, "; on %s %s stopped at R/dx =", lay[l],
           vsph_viscous_label(f));
    for (int k = 0, n = 0; k < VSPH_REPORT_LADDER; k++)
      if (!ly->ok[l][f][k])
        append(buf, len, &m, "%s %zu", n++ ? "," : "", L->res[k]);
    append(buf, len, &m, " (t =");
    for (int k = 0, n = 0; k < VSPH_REPORT_LADDER; k++)
      if (!ly->ok[l][f][k])
        append(buf, len, &m, "%s %.3g", n++ ? "," : "", ly->tu[l][f][k]);
    append(buf, len, &m, " s)");
  }
}

static int vortex_claims(struct vsph_report *R, const struct finest *fi) {
  (void)fi;
  static const char *const lay[2] = {"rings", "Cartesian"};
  const struct vsph_report_ladderdef *L =
      vsph_report_runs_ladder(&R->runs, 0, 0);
  const int K = VSPH_REPORT_LADDER - 1; /* the finest rung */
  struct vsph_report_layouts ly;
  int st = vsph_report_runs_layouts(&R->runs, &ly);
  if (st) return st;
  /* the profile's own figures, which its weight was chosen to meet */
  struct vsph_scene scene;
  if ((st = vsph_scene_init(&scene, &vsph_vortex_patch_type, NULL))) return st;
  const struct vsph_scene_vortex *vp = &scene.u.vortex;
  struct vsph_references_vortex *ref = vsph_references_vortex_alloc(
      vp->R, vp->l2, vp->a, vp->omega0, vp->nu, 10);
  if (!ref) return VSPH_ELIB;
  const double winf = ref->c0 / vp->omega0;
  const double Re =
      vp->R * vp->R * vsph_references_vortex_initial(ref, vp->R) / vp->nu;
  vsph_references_vortex_free(ref);
  char setup[VSPH_REPORT_CLAIM_BUF], ours[VSPH_REPORT_CLAIM_BUF],
      verdict[VSPH_REPORT_CLAIM_BUF], stops[2][600];
  snprintf(setup, sizeof setup,
           "initial profile (6.39) [reconstructed] to meet the paper's "
           "stated Re and omega_inf (Re %.1f, omega_inf %.4f omega0); disc "
           "layout [reconstructed: not stated], both run: rings and "
           "Cartesian; R/dx = %zu to %g s%s",
           Re, winf, L->res[K], L->t_end,
           R->runs.full ? "" : " (the paper's 100 to 100 s)");
  for (int l = 0; l < 2; l++)
    vortex_stops(stops[l], sizeof stops[l], &ly, l, L);
  /* the Cartesian stops against the time step and rounding */
  char cart[NFORM][400], cartall[1200] = "";
  int cholds[NFORM];
  size_t cm = 0;
  for (int f = 0; f < NFORM && !st; f++) {
    st = cart_holds(R, &ly, f, cart[f], sizeof cart[f], &cholds[f]);
    if (!st && cart[f][0])
      append(cartall, sizeof cartall, &cm, "%s%s", cm ? "; " : "", cart[f]);
  }
  if (st) return st;
  /* (1) MGF and PVWF follow the reference, MEAF departs: by the energy
   * lost over the reference's loss at the end (the decay error is diluted
   * by the rigid rotation, which does not decay), layout by layout */
  int follows[2], departs[2];
  for (int l = 0; l < 2; l++) {
    const double em = fabs(ly.loss[l][MGF][K] - 1),
                 ep = fabs(ly.loss[l][PVWF][K] - 1),
                 ee = fabs(ly.loss[l][MEAF][K] - 1);
    follows[l] = ly.ok[l][MGF][K] && ly.ok[l][PVWF][K];
    departs[l] = vsph_grade_apart(ee, fmax(em, ep));
  }
  snprintf(ours, sizeof ours,
           "energy lost by t = %g s over the reference's loss (1 exact), R/dx "
           "= %zu: rings MGF %.3f, PVWF %.3f, MEAF %.3f%s; Cartesian MGF "
           "%.3f, PVWF %.3f, MEAF %.3f%s (a stopped run: its figure by its "
           "stop)%s%s",
           L->t_end, L->res[K], ly.loss[0][MGF][K], ly.loss[0][PVWF][K],
           ly.loss[0][MEAF][K], stops[0], ly.loss[1][MGF][K],
           ly.loss[1][PVWF][K], ly.loss[1][MEAF][K], stops[1],
           cartall[0] ? "; " : "", cartall);
  /* which of MGF and PVWF stop on a layout, and whether it is marginal */
  char who[2][400];
  for (int l = 0; l < 2; l++) {
    const int sm = !ly.ok[l][MGF][K], sp = !ly.ok[l][PVWF][K];
    const int marginal =
        l == 1 && ((sm && !cholds[MGF]) || (sp && !cholds[PVWF]));
    snprintf(who[l], sizeof who[l], "%s stop%s (above)%s",
             sm && sp ? "MGF and PVWF"
             : sm     ? "MGF"
                      : "PVWF",
             sm && sp ? "" : "s",
             marginal ? "; at the coarsest rung that stop is marginal" : "");
  }
  if (follows[0] && follows[1] && departs[0] && departs[1])
    snprintf(verdict, sizeof verdict,
             "reproduced on a substitute on both layouts: MEAF's departure "
             "from 1 is at least sqrt(10) times MGF's and PVWF's");
  else if ((follows[0] && departs[0]) || (follows[1] && departs[1]))
    snprintf(verdict, sizeof verdict,
             "partly: on %s MGF and PVWF run to the end and MEAF departs "
             "sqrt(10) times more; on %s %s",
             follows[0] && departs[0] ? lay[0] : lay[1],
             follows[0] && departs[0] ? lay[1] : lay[0],
             !(follows[0] && follows[1]) ? who[follows[0] && departs[0] ? 1 : 0]
                                         : "MEAF is not that far apart");
  else
    snprintf(verdict, sizeof verdict,
             "differs: on neither layout do MGF and PVWF run to the end with "
             "MEAF sqrt(10) times further off");
  st = vsph_report_claim(
      R,
      "Vortex patch: MGF and PVWF follow the reference, MEAF diverges (VI A)",
      "MGF, PVWF close to the analytical u_theta up to t = 100 s; MEAF "
      "departs quickly",
      ours, setup, verdict);
  /* (2) PVWF's E_k error below MGF's (Fig. 5, right: the relative E_k
   * error), layout by layout; a stopped PVWF run is not measured */
  /* "smaller" beyond the noise: how far MGF's own error moved between the
   * last two rungs (the level's swing with resolution) */
  int below[2];
  for (int l = 0; l < 2; l++) {
    const double noise = fabs(ly.err[l][MGF][K] - ly.err[l][MGF][K - 1]);
    below[l] = !ly.ok[l][PVWF][K] ? -1
               : vsph_grade_larger(ly.err[l][MGF][K], ly.err[l][PVWF][K], noise)
                   ? 1
                   : 0;
  }
  snprintf(ours, sizeof ours,
           "max |E_k/E_k(0) - E_ref/E_ref(0)| at R/dx = %zu: rings PVWF "
           "%.3e, MGF %.3e; Cartesian PVWF %.3e, MGF %.3e%s%s",
           L->res[K], ly.err[0][PVWF][K], ly.err[0][MGF][K], ly.err[1][PVWF][K],
           ly.err[1][MGF][K], stops[0], stops[1]);
  if (below[0] == 1 && below[1] == 1)
    snprintf(verdict, sizeof verdict,
             "reproduced on a substitute on both layouts (smaller beyond MGF's "
             "own change between the last two rungs)");
  else if (below[0] == 1 || below[1] == 1)
    snprintf(verdict, sizeof verdict, "partly: on %s; on %s %s",
             below[0] == 1 ? lay[0] : lay[1], below[0] == 1 ? lay[1] : lay[0],
             below[below[0] == 1 ? 1 : 0] < 0
                 ? "PVWF stops before the end (above), so not measured there"
                 : "PVWF's error is not the smaller beyond the noise");
  else if (below[0] < 0 && below[1] < 0)
    snprintf(verdict, sizeof verdict,
             "not tested: PVWF stops before the end on both layouts");
  else
    snprintf(verdict, sizeof verdict,
             "differs: where PVWF runs to the end its error is not the "
             "smaller beyond the noise%s",
             below[0] < 0 || below[1] < 0 ? " (elsewhere it stops)" : "");
  if (!st)
    st = vsph_report_claim(
        R, "Vortex patch: PVWF's E_k error is smaller than MGF's (VI A)",
        "yes (Fig. 5, right)", ours, setup, verdict);
  /* (3) MGF converges with resolution: its ladder's self-convergence on
   * both layouts, beside its level against the reference */
  enum vsph_grade g[2];
  for (int l = 0; l < 2; l++)
    g[l] = vsph_grade_converges(ly.self[l][MGF].order_max,
                                ly.self[l][MGF].order_rms,
                                ly.self[l][MGF].partial);
  snprintf(
      ours, sizeof ours,
      "MGF, R/dx %zu-%zu: successive differences of E_k/E_k(0) on "
      "rings %.2e, %.2e (orders %.2f largest, %.2f RMS), E_k error "
      "against the reference %.2e at %zu; Cartesian %.2e, %.2e (orders "
      "%.2f, %.2f), error %.2e",
      L->res[0], L->res[K], ly.self[0][MGF].dmax[0], ly.self[0][MGF].dmax[1],
      ly.self[0][MGF].order_max, ly.self[0][MGF].order_rms, ly.err[0][MGF][K],
      L->res[K], ly.self[1][MGF].dmax[0], ly.self[1][MGF].dmax[1],
      ly.self[1][MGF].order_max, ly.self[1][MGF].order_rms, ly.err[1][MGF][K]);
  char setup2[VSPH_REPORT_CLAIM_BUF + 256];
  snprintf(setup2, sizeof setup2,
           "measure: the ladder's self-convergence (successive resolutions, "
           "no reference) and the error against the Bessel series at the "
           "finest (the paper: u_theta against the series at R/dx = 100, "
           "Fig. 4); %s",
           setup);
  static const char *const gname[4] = {
      "converges by both measures", "converges by one measure only",
      "does not converge", "not measured (a rung stopped)"};
  const int both = g[0] == VSPH_GRADE_AGREES && g[1] == VSPH_GRADE_AGREES;
  const int none = g[0] != VSPH_GRADE_AGREES && g[0] != VSPH_GRADE_PARTLY &&
                   g[1] != VSPH_GRADE_AGREES && g[1] != VSPH_GRADE_PARTLY;
  /* the paper's claim is closeness at R/dx = 100; converging is half of
   * it: the other half is whether the limit is the reference, i.e.
   * whether the error against it falls with resolution as the successive
   * differences do. It falls when the finest rung's error is at most half
   * the coarsest's (a documented choice: first order over the ladder's
   * fourfold refinement gives a quarter, and half leaves room for a level
   * that is partly reached) */
  int falls[2], grows = 0, pvwf_level = 1;
  for (int l = 0; l < 2; l++) {
    falls[l] = ly.err[l][MGF][K] <= 0.5 * ly.err[l][MGF][0];
    grows |= ly.err[l][MGF][K] > ly.err[l][MGF][0];
    /* PVWF's error levels off too where its ladder ran to the end and its
     * error does not fall by the same rule */
    int pok = 1;
    for (int k = 0; k < VSPH_REPORT_LADDER; k++) pok &= ly.ok[l][PVWF][k];
    pvwf_level &= pok && ly.err[l][PVWF][K] > 0.5 * ly.err[l][PVWF][0];
  }
  char level[400];
  snprintf(level, sizeof level,
           "but the paper's closeness is on u_theta (Fig. 4), and the E_k "
           "error measured here %s with resolution%s",
           grows ? "does not fall" : "stays level",
           pvwf_level ? ", as PVWF's does (a limit off the series not shown "
                        "to be MGF's own)"
                      : "");
  snprintf(verdict, sizeof verdict,
           "%s: on rings MGF %s, on a Cartesian disc it %s; %s (rings %.2e "
           "at R/dx = %zu, %.2e at %zu; Cartesian %.2e, %.2e); the paper "
           "states no precision for its closeness",
           both && falls[0] && falls[1] ? "reproduced on a substitute"
           : none
               ? (g[0] == VSPH_GRADE_UNMEASURED && g[1] == VSPH_GRADE_UNMEASURED
                      ? "not tested"
                      : "differs")
               : "partly",
           gname[g[0]], gname[g[1]],
           falls[0] && falls[1]
               ? "its E_k error against the series falls with resolution too"
           : !falls[0] && !falls[1]
               ? level
               : "its E_k error against the series falls on one layout only",
           ly.err[0][MGF][0], L->res[0], ly.err[0][MGF][K], L->res[K],
           ly.err[1][MGF][0], ly.err[1][MGF][K]);
  if (!st)
    st = vsph_report_claim(
        R,
        "Vortex patch: MGF close to the reference at R/dx = 100, and "
        "converging with resolution (VI A)",
        "MGF close to the reference at R/dx = 100 (layout not stated)", ours,
        setup2, verdict);
  /* (4) the final rigid rotation: an input of the reconstruction */
  snprintf(ours, sizeof ours,
           "omega_inf = %.4f omega0 and Re = %.1f for the reconstructed "
           "profile (the reference series' c_0; R^2 omega(R, 0)/nu)",
           winf, Re);
  if (!st)
    st = vsph_report_claim(
        R, "Vortex patch: final rigid rotation omega_inf (VI A)",
        "0.2848 omega0, Re = 256 (the paper's own profile)", ours,
        "initial profile (6.39) [reconstructed]: its weight was chosen to "
        "meet these two figures (docs/theory.md §6), so they are an input "
        "here, not a result",
        "not tested: agreement is by construction (the profile was "
        "reconstructed from these figures; -0.27 % and +0.27 %); a test "
        "needs the paper's own (6.39)");
  return st;
}

/* Whether formulation @p f's stops on scene @p sc hold when only the time
 * step changes, on the step study's two rungs (vsph_grade_stop_holds),
 * and (the standing wave) when only the rounding does, at section 12's
 * rung: 1 they hold, 0 one moves (marginal), and a phrase saying which
 * into @p buf ("" when none moved). The scene's own CFL is the study's
 * last (2). */
static int stops_hold(struct vsph_report *R, int sc, int f, char *buf,
                      size_t len, int *holds) {
  const struct vsph_report_ladderdef *L =
      vsph_report_runs_ladder(&R->runs, sc, 0);
  static const char *const cfl[VSPH_REPORT_SPEED_NCFL] = {"0.5", "1", "1.5",
                                                          "2"};
  *holds = 1;
  buf[0] = '\0';
  size_t m = 0;
  for (int k = 0; k < 2; k++) {
    int s[VSPH_REPORT_SPEED_NCFL];
    double t[VSPH_REPORT_SPEED_NCFL];
    const int st = vsph_report_speed_stops(R, sc, f, k, s, t);
    if (st) return st;
    if (vsph_grade_stop_holds(s, VSPH_REPORT_SPEED_NCFL)) continue;
    *holds = 0;
    append(buf, len, &m, "%s at %s/dx = %zu it stops at CFL", m ? ";" : "",
           vsph_scene_find(L->scene)->length_name, L->res[k]);
    int first = 1;
    for (int c = 0; c < VSPH_REPORT_SPEED_NCFL; c++)
      if (s[c]) {
        append(buf, len, &m, "%s %s (%.2g s)", first ? "" : ",", cfl[c], t[c]);
        first = 0;
      }
    append(buf, len, &m, " but not at");
    first = 1;
    for (int c = 0; c < VSPH_REPORT_SPEED_NCFL; c++)
      if (!s[c]) {
        append(buf, len, &m, "%s %s", first ? "" : ",", cfl[c]);
        first = 0;
      }
  }
  if (sc != 2) return VSPH_OK;
  /* with rounding: the run at the scene's own step against the same run
   * with its lattice shifted by 1e-9 dx (section 12) */
  struct vsph_jobs_spec rs;
  int k;
  int st = vsph_report_choices_rounding(R, f, &rs, &k);
  if (st) return st;
  int s[VSPH_REPORT_SPEED_NCFL];
  double t[VSPH_REPORT_SPEED_NCFL];
  if ((st = vsph_report_speed_stops(R, sc, f, k, s, t))) return st;
  struct vsph_jobs_run r;
  if ((st = vsph_report_runs_get(&R->runs, &rs, &r))) return st;
  const int shifted = !r.ok, own = s[VSPH_REPORT_SPEED_NCFL - 1];
  if (shifted != own) {
    *holds = 0;
    append(buf, len, &m,
           "%s at %s/dx = %zu it stops %s its lattice shifted by 1e-9 dx "
           "(another rounding) and runs on %s",
           m ? ";" : "", vsph_scene_find(L->scene)->length_name, L->res[k],
           shifted ? "with" : "without", shifted ? "without" : "with");
  }
  vsph_report_runs_free(&r);
  return VSPH_OK;
}

/* The noise of the wave's damping figure (the energy lost over
 * Lighthill's loss): a difference decides beyond it. The spread of MGF's
 * figure over the time step (CFL 0.5 to 2 at the ladder's middle rung,
 * section 7), at least 0.005 (half a per cent of the loss: a documented
 * floor, above the rounding and time-step spreads measured, 0.0006-0.004) */
static int wave_noise(struct vsph_report *R, double *noise) {
  double nlo = INFINITY, nhi = -INFINITY;
  for (int c = 0; c < VSPH_REPORT_SPEED_NCFL; c++) {
    const struct vsph_jobs_spec cs = vsph_report_speed_spec(R, 2, MGF, 1, c);
    struct vsph_jobs_run r;
    const int st = vsph_report_runs_get(&R->runs, &cs, &r);
    if (st) return st;
    const double q = vsph_report_runs_loss_ratio(&r, r.nrow - 1);
    nlo = fmin(nlo, q);
    nhi = fmax(nhi, q);
    vsph_report_runs_free(&r);
  }
  *noise = fmax(nhi - nlo, 0.005);
  return VSPH_OK;
}

static int wave_claims(struct vsph_report *R, const struct finest *fi) {
  const struct vsph_report_ladder *lr = &fi->lr[2];
  const struct vsph_report_ladderdef *WL =
      vsph_report_runs_ladder(&R->runs, 2, 0);
  const int K = VSPH_REPORT_LADDER - 1;
  char ours[VSPH_REPORT_CLAIM_BUF], body[800], setup[VSPH_REPORT_CLAIM_BUF],
      verdict[VSPH_REPORT_CLAIM_BUF];
  snprintf(setup, sizeof setup,
           "steepness eps = 0.05 [reconstructed] (illegible in the source, "
           "which bounds Lighthill's decay to eps < 0.01); free-slip bottom "
           "[reconstructed]; lattice start, no delta-SPH, RK4 at CFL 2 "
           "[reconstructed: the paper names none of them; section 12 varies "
           "each alone]; H/dx %zu-%zu to %g s%s",
           WL->res[0], WL->res[K], WL->t_end,
           R->runs.full ? "" : " (the paper's 240 to 8 s)");
  /* (1) every form converges linearly: each ladder's self-convergence */
  enum vsph_grade g[NFORM];
  int holds[NFORM], worst = VSPH_GRADE_AGREES, st = VSPH_OK;
  char marg[NFORM][600];
  size_t m = 0;
  for (int f = 0; f < NFORM && !st; f++) {
    const struct vsph_series_selfconv *sv = &lr->self[f];
    g[f] = vsph_grade_orders(sv->order_max, sv->order_rms, 1, sv->partial);
    st = stops_hold(R, 2, f, marg[f], sizeof marg[f], &holds[f]);
    append(body, sizeof body, &m, "%s%s %.2e, %.2e (orders %.2f, %.2f)",
           f ? "; " : "", vsph_viscous_label(f), sv->dmax[0], sv->dmax[1],
           sv->order_max, sv->order_rms);
    if (sv->partial)
      append(body, sizeof body, &m, " over t <= %.2g s only (a rung stopped)",
             sv->span);
    if (g[f] == VSPH_GRADE_DIFFERS) worst = VSPH_GRADE_DIFFERS;
    if (g[f] != VSPH_GRADE_AGREES && worst == VSPH_GRADE_AGREES)
      worst = VSPH_GRADE_PARTLY;
  }
  if (st) return st;
  snprintf(ours, sizeof ours,
           "successive differences of E_k/E_k(0) over H/dx %zu-%zu, the "
           "largest over the run (orders: of the largest, of the RMS): %s; "
           "MGF's finest rung about %.1e from its limit (Richardson at its "
           "order)",
           WL->res[0], WL->res[K], body, lr->self[MGF].remainder);
  /* beside E_k's differences, the energy lost by t_end (the damping the
   * next row grades), rung by rung: does it close in as E_k does? */
  /* the ladder's own losses (read with it), NaN where a rung stopped */
  double qr[NFORM][VSPH_REPORT_LADDER];
  for (int f = 0; f < NFORM; f++)
    for (int k = 0; k < VSPH_REPORT_LADDER; k++)
      qr[f][k] = lr->ok[f][k] ? lr->loss[f][k] : (double)NAN;
  m = strlen(ours);
  append(ours, sizeof ours, &m,
         "; the energy lost by t_end over Lighthill's loss, rung by rung:");
  for (int f = 0; f < NFORM; f++) {
    append(ours, sizeof ours, &m, "%s %s", f ? ";" : "", vsph_viscous_label(f));
    for (int k = 0; k < VSPH_REPORT_LADDER; k++)
      if (isfinite(qr[f][k]))
        append(ours, sizeof ours, &m, "%s %.4f", k ? "," : "", qr[f][k]);
      else
        append(ours, sizeof ours, &m, "%s stopped", k ? "," : "");
  }
  double wnoise = NAN;
  if ((st = wave_noise(R, &wnoise))) return st;
  static const char *const gw[4] = {
      "first order by both measures",
      "first order by the largest difference only", "not first order",
      "not measured"};
  m = 0;
  append(verdict, sizeof verdict, &m, "%s: ",
         worst == VSPH_GRADE_AGREES    ? "reproduced on a substitute"
         : worst == VSPH_GRADE_DIFFERS ? "differs"
                                       : "partly");
  for (int f = 0; f < NFORM; f++) {
    const double d1 = fabs(qr[f][1] - qr[f][0]), d2 = fabs(qr[f][2] - qr[f][1]);
    append(verdict, sizeof verdict, &m, "%s%s %s", f ? "; " : "",
           vsph_viscous_label(f),
           g[f] == VSPH_GRADE_PARTLY &&
                   vsph_grade_order_is(lr->self[f].order_rms, 1) == 1
               ? "first order by the RMS only"
               : gw[g[f]]);
    /* the damping's own successive differences, where all rungs ended,
     * judged beyond the damping figure's noise */
    if (isfinite(d1) && isfinite(d2))
      append(verdict, sizeof verdict, &m,
             d1 <= wnoise && d2 <= wnoise
                 ? ", its damping the same within the noise (differences "
                   "%.1e, then %.1e)"
             : d2 > d1 ? ", its damping moving apart with resolution "
                         "(differences %.1e, then %.1e)"
                       : ", its damping closing in (differences %.1e, then "
                         "%.1e)",
             d1, d2);
    if (!holds[f])
      append(verdict, sizeof verdict, &m, " (its stability marginal:%s)",
             marg[f]);
  }
  append(verdict, sizeof verdict, &m,
         "; 'converged at 240' is not graded (the paper gives no precision; "
         "ours above)");
  st = vsph_report_claim(
      R,
      "Standing wave: all formulations converge linearly, converged at "
      "H/dx = 240 (VI C)",
      "linear convergence; converged at H/dx = 240", ours, setup, verdict);
  /* (2) damping, the paper's way: the energy lost by t_end over
   * Lighthill's phase-free loss (1 exact, above 1 too much damping) */
  const struct vsph_jobs_run *w = fi->run[2];
  double loss[NFORM];
  char stopped[200] = "";
  size_t sl = 0;
  for (int f = 0; f < NFORM; f++) {
    loss[f] = vsph_report_runs_loss_ratio(&w[f], w[f].nrow - 1);
    if (!w[f].ok)
      append(stopped, sizeof stopped, &sl,
             "; %s stopped (unstable) at t = %.3g s (its "
             "figure by then)%s%s",
             vsph_viscous_label(f), w[f].t_unstable, holds[f] ? "" : "; ",
             holds[f] ? "" : marg[f]);
  }
  /* beside it, the exact linear decay's loss (Lamb's relation): the
   * factor from Lighthill's lost share to it at the last row */
  struct vsph_scene wsc;
  double gamma = NAN, omega = NAN, tl = w[MGF].t[w[MGF].nrow - 1];
  if (!st) st = vsph_scene_init(&wsc, &vsph_standing_wave_type, NULL);
  if (!st)
    st = vsph_references_wave_decay(wsc.u.wave.g, wsc.u.wave.k, wsc.u.wave.L,
                                    wsc.u.wave.nu, &gamma, &omega);
  if (st) return st;
  const double lamb =
      -expm1(-4.0 * wsc.u.wave.nu * wsc.u.wave.k * wsc.u.wave.k * tl) /
      -expm1(-2.0 * gamma * tl);
  snprintf(ours, sizeof ours,
           "energy lost by t_end over Lighthill's (H/dx = %zu; 1 exact, "
           "above 1 too much damping): PVWF %.3f, MGF %.3f, MEAF %.3f; over "
           "the exact linear decay's (Lamb's relation, %.1f %% below "
           "Lighthill's by %g s) MGF %.3f%s",
           WL->res[K], loss[PVWF], loss[MGF], loss[MEAF], 100 * (1 - 1 / lamb),
           tl, loss[MGF] * lamb, stopped);
  const double em = fabs(loss[MGF] - 1), ee = fabs(loss[MEAF] - 1),
               ep = fabs(loss[PVWF] - 1);
  const int meaf_fails = vsph_grade_apart(ee, em);
  const double noise = wnoise; /* the damping figure's, as above */
  const int mgf_under = vsph_grade_larger(1.0, loss[MGF], noise),
            mgf_over = vsph_grade_larger(loss[MGF], 1.0, noise);
  const int pvwf_best = vsph_grade_larger(fmin(em, ee), ep, noise);
  /* what MGF does, beyond the noise */
  char mg[112];
  if (mgf_under)
    snprintf(mg, sizeof mg, "MGF damps %.1f %% too little, as the paper says",
             100 * em);
  else if (mgf_over)
    snprintf(mg, sizeof mg,
             "MGF damps %.1f %% too much, not slightly too little", 100 * em);
  else
    snprintf(mg, sizeof mg,
             "MGF within %.1f %% of Lighthill's, inside the noise (%.3f)",
             100 * em, noise);
  if (!w[PVWF].ok)
    snprintf(verdict, sizeof verdict,
             "partly: %s; %s; PVWF's run stopped at t = %.3g s of %g s%s, so "
             "'PVWF best' is not measured at H/dx = %zu",
             meaf_fails ? "MEAF fails (its departure from 1 at least sqrt(10) "
                          "times MGF's)"
                        : "MEAF is not apart from MGF",
             mg, w[PVWF].t_unstable, WL->t_end,
             holds[PVWF] ? ""
                         : " (marginal: at the coarser rungs its stops move "
                           "with the time step or with rounding)",
             WL->res[K]);
  else if (meaf_fails && pvwf_best && mgf_under)
    snprintf(verdict, sizeof verdict,
             "reproduced on a substitute: PVWF closest, MGF slightly too "
             "little damping, MEAF apart (each beyond the noise, %.3f)",
             noise);
  else {
    struct vsph_jobs_spec rs;
    int kr;
    if ((st = vsph_report_choices_rounding(R, MGF, &rs, &kr))) return st;
    char rev[240];
    snprintf(rev, sizeof rev,
             "PVWF further from 1 than MGF beyond the noise (the paper's "
             "order reversed, at the reconstructed eps = 0.05; section 12 "
             "gives smaller steepnesses at H/dx = %zu)",
             WL->res[kr]);
    snprintf(verdict, sizeof verdict, "partly: %s; %s; %s",
             meaf_fails ? "MEAF fails" : "MEAF is not apart from MGF",
             pvwf_best ? "PVWF closest"
             : vsph_grade_larger(ep, em, noise)
                 ? rev
                 : "PVWF not the closest beyond the noise",
             mg);
  }
  if (!st)
    st = vsph_report_claim(
        R,
        "Standing wave: PVWF matches the decay best, MGF slightly "
        "under-predicts the damping, MEAF fails (VI C)",
        "PVWF best, MGF a little too little damping, MEAF wrong", ours, setup,
        verdict);
  return st;
}

/* PVWF is "quite demanding in CPU time" (IV A): its CPU time per particle
 * and step over MGF's, on the vortex patch's finest rung (rings: every form
 * runs to its end there), larger than MGF's beyond the timing noise of
 * the same runs (MEAF, whose pair term costs as MGF's, against MGF). */
static int cost_claim(struct vsph_report *R, const struct finest *fi) {
  const struct vsph_jobs_run *v = fi->run[0];
  /* CPU time, not wall time: a run's wall time moves with what ran
   * beside it (the same run's differed 4.5-fold across sittings), its CPU
   * time much less */
  double c[NFORM];
  for (int f = 0; f < NFORM; f++)
    c[f] = v[f].steps && v[f].n
               ? v[f].cpu_s / ((double)v[f].steps * (double)v[f].n)
               : (double)NAN;
  const double noise = fabs(c[MEAF] / c[MGF] - 1.0), q = c[PVWF] / c[MGF];
  char ours[VSPH_REPORT_CLAIM_BUF];
  snprintf(ours, sizeof ours,
           "CPU time per particle and step on the vortex patch (R/dx = %zu, "
           "rings): PVWF %.2f times MGF's, MEAF %.2f (the runs' "
           "timing noise); each run's load in its run.json",
           v[MGF].res, q, c[MEAF] / c[MGF]);
  return vsph_report_claim(
      R,
      "PVWF is quite demanding in CPU time: two passes and matrix "
      "operations (IV A)",
      "demanding", ours,
      "vsph's implementation (the symmetric sweep; PVWF's first pass, then "
      "an MGF-like second pass) on this machine; the paper gives no figure",
      !isfinite(q) || !isfinite(noise)
          ? "not tested: a run keeps no CPU time (run.json's cpu_s)"
      : vsph_grade_larger(q, 1.0, noise)
          ? "reproduced on a substitute: dearer than MGF beyond the timing "
            "noise (section 7 and the bench give the cost in detail)"
          : "differs: not dearer than MGF beyond the timing noise");
}

/* ------------------------------------- the paper's resolutions, archived */

/* Scene @p sc's figure of run @p r, as its claims measure it: the vortex
 * patch's largest E_k decay error against the Bessel series, the
 * stretching square's (P - P_exact)/|P_exact| at t = 0 (its E_k reference
 * is built from runs at the report's own fidelity), the wave's energy
 * lost by its last row over Lighthill's and its E_k error; @p err: the
 * error at hand, or NAN to compute it against the run's own reference;
 * @p t_end: the run's end time (a run that stopped says how far it got,
 * its figures being by its last row). */
static void scene_figure(char *buf, size_t len, int sc,
                         const struct vsph_jobs_run *r, double err,
                         double t_end) {
  char status[200];
  if (r->nrow < 2) { /* nothing to measure a decay or a loss on */
    snprintf(buf, len, "%zu row%s of energy.csv only: no figure", r->nrow,
             r->nrow == 1 ? "" : "s");
    return;
  }
  const double t1 = r->t[r->nrow - 1];
  if (r->ok)
    snprintf(status, sizeof status, "ok to t = %.4g s", t1);
  else
    snprintf(status, sizeof status,
             "**%s** at t = %.3g s; figures by its last row, t = %.3g s "
             "(%.0f %% of t_end)",
             isfinite(r->t_unstable) ? "unstable" : "stopped (no reason kept)",
             isfinite(r->t_unstable) ? r->t_unstable : t1, t1,
             100.0 * t1 / t_end);
  if (!isfinite(err) && sc != 1) err = vsph_report_runs_error(r, NULL);
  if (sc == 0) {
    snprintf(buf, len, "%s; E_k error %.2e", status, err);
  } else if (sc == 1) { /* PVWF's is exact on the square: round-off */
    const double d = vsph_report_runs_diss0(r);
    char dv[32];
    if (fabs(d) < 1e-10)
      snprintf(dv, sizeof dv, "round-off");
    else
      snprintf(dv, sizeof dv, "%+.2e", d);
    snprintf(buf, len, "%s; (P - P_exact)/\\|P_exact\\| at t = 0: %s", status,
             dv);
  } else {
    snprintf(buf, len, "%s; energy lost over Lighthill's %.3f, E_k error %.2e",
             status, vsph_report_runs_loss_ratio(r, r->nrow - 1), err);
  }
}

int vsph_report_claims_beside(struct vsph_report *R,
                              const struct vsph_jobs_run run[][NFORM],
                              const double err[][NFORM]) {
  /* the FULL plan, each run's standing in the archive (the driver's) */
  if (!R->beside_stands)
    VSPH_FAIL(VSPH_EINVAL, "the FULL plan beside the archive is not judged");
  const char *const *names = R->beside_jd.plan_name;
  const int *stands = R->beside_stands;
  const size_t n = R->beside_jd.nplan;
  int st = VSPH_OK;
  size_t held = 0, stand = 0, unjudged = 0, stale = 0, unreadable = 0;
  char *rows = NULL;
  size_t rlen = 0;
  FILE *m = open_memstream(&rows, &rlen);
  if (!m) st = VSPH_ENOMEM;
  for (int sc = 0; sc < VSPH_REPORT_NSCENES && !st; sc++)
    for (int f = 0; f < NFORM && !st; f++) {
      const struct vsph_report_ladderdef *Q =
          vsph_report_runs_ladder(&R->runs, sc, 1);
      const struct vsph_report_ladderdef *F = vsph_report_runs_full_ladder(sc);
      const struct vsph_scene_type *t = vsph_scene_find(F->scene);
      const char *dx = t ? t->length_name : "res";
      char name[128], dir[700], quick[320], full[320] = "not archived yet";
      snprintf(name, sizeof name, "%s-%s-%zu", F->scene, vsph_viscous_name(f),
               F->res[VSPH_REPORT_LADDER - 1]);
      scene_figure(quick, sizeof quick, sc, &run[sc][f], err[sc][f], Q->t_end);
      const char *judged = "–";
      snprintf(dir, sizeof dir, "%s/runs/%s", R->beside, name);
      size_t k = 0;
      while (k < n && strcmp(names[k], name)) k++;
      const int v = k < n ? stands[k] : VSPH_ARCHIVE_ABSENT;
      struct vsph_jobs_run r;
      if (v == VSPH_ARCHIVE_ABSENT && access(dir, F_OK) == 0) {
        /* there, but not whole: not read (entries.md leaves it out) */
        snprintf(full, sizeof full,
                 "an entry whose seal does not hold: not read");
        unreadable++;
      } else if (v != VSPH_ARCHIVE_ABSENT && vsph_jobs_load(dir, &r)) {
        /* whole, but not tables this build reads (said on stderr) */
        vsph_jobs_run_free(&r);
        snprintf(full, sizeof full, "its tables cannot be read (see stderr)");
        unreadable++;
      } else if (v != VSPH_ARCHIVE_ABSENT) {
        held++;
        scene_figure(full, sizeof full, sc, &r, (double)NAN, F->t_end);
        vsph_jobs_run_free(&r);
        stand += v == VSPH_ARCHIVE_STANDS;
        unjudged += v == VSPH_ARCHIVE_UNJUDGED;
        stale += v == VSPH_ARCHIVE_STALE;
        judged = v == VSPH_ARCHIVE_STANDS     ? "yes"
                 : v == VSPH_ARCHIVE_UNJUDGED ? "unjudged (entries.md says why)"
                                              : "no (entries.md says why)";
      }
      fprintf(m,
              "| %s | %s | %s/dx = %zu, t_end %g s: %s | %s/dx = %zu, "
              "t_end %g s: %s | %s |\n",
              F->scene, vsph_viscous_label(f), dx,
              Q->res[VSPH_REPORT_LADDER - 1], Q->t_end, quick, dx,
              F->res[VSPH_REPORT_LADDER - 1], F->t_end, full, judged);
    }
  if (m && fclose(m) != 0 && !st) st = VSPH_ENOMEM;
  if (!st) {
    vsph_text_set(&R->tv, "archive", "%s", R->beside);
    vsph_text_set(&R->tv, "held", "%zu", held);
    vsph_text_set(&R->tv, "stand", "%zu", stand);
    vsph_text_set(&R->tv, "unjudged", "%zu", unjudged);
    vsph_text_set(&R->tv, "stale", "%zu", stale);
    vsph_text_set(&R->tv, "unreadable", "%zu", unreadable);
    vsph_text_set(&R->tv, "total", "%d", VSPH_REPORT_NSCENES * NFORM);
    st = vsph_report_say(R, "claims.archive_head");
  }
  if (!st) {
    fputs(rows, R->md);
    fputc('\n', R->md);
  }
  free(rows);
  if (st) return st;
  return ferror(R->md) ? VSPH_EIO : VSPH_OK;
}

int vsph_report_paper_plan(struct vsph_report *R) {
  int st = vsph_report_runs_plan_ladders(&R->runs, 1);
  if (!st) st = vsph_report_speed_plan_steps(R, 2);
  if (!st) st = vsph_report_choices_plan_rounding(R);
  if (!st) st = cart_plan(R);
  if (!st) st = vsph_report_fv_plan(R);
  if (!st) {
    const struct vsph_jobs_spec ds = square_delta_spec(R);
    st = vsph_jobs_plan_run(&R->runs.jobs, &ds);
  }
  return st;
}

static void free_finest(struct finest *fi) {
  for (int sc = 0; sc < VSPH_REPORT_NSCENES; sc++)
    for (int f = 0; f < NFORM; f++) vsph_report_runs_free(&fi->run[sc][f]);
}

int vsph_report_paper_claims(struct vsph_report *R) {
  R->claim_see = "scaling";
  int st = scaling_claims(R);
  R->claim_see = "dissipation";
  if (!st) st = dissipation_claims(R);
  R->claim_see = "tensors";
  if (!st) st = theory_claims(R);
  struct finest fi;
  memset(&fi, 0, sizeof fi);
  if (!st) st = load_finest(R, &fi);
  R->claim_see = "scenes";
  if (!st) st = square_claims(R, &fi);
  R->claim_see = "convergence";
  if (!st) st = vortex_claims(R, &fi);
  R->claim_see = "scenes";
  if (!st) st = wave_claims(R, &fi);
  R->claim_see = "speed";
  if (!st) st = cost_claim(R, &fi);
  R->claim_see = NULL;
  free_finest(&fi);
  return st;
}

int vsph_report_paper_beside(struct vsph_report *R) {
  struct finest fi;
  memset(&fi, 0, sizeof fi);
  int st = load_finest(R, &fi);
  if (!st) /* (C11 adds const to arrays of arrays by cast) */
    st = vsph_report_claims_beside(R,
                                   (const struct vsph_jobs_run(*)[NFORM])fi.run,
                                   (const double(*)[NFORM])fi.err);
  free_finest(&fi);
  return st;
}
