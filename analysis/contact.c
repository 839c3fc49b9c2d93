/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
#include "contact.h"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_min.h>
#include <math.h>
#include <omp.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../common/consts.h"
#include "../common/params.h"
#include "../common/status.h"
#include "../kernels/kernel.h"
#include "../solver/integrate.h"
#include "../solver/particles.h"
#include "../solver/run.h"
#include "../solver/scene.h"
#include "series.h"

/* The images of the square wave of period 2W that matter: |n| up to the
 * first whose erf terms are within 1e-17 of +-1 everywhere on (-W, W). */
static int images(double d, double W) {
  const double n = ceil(6.0 * d / (2.0 * W)) + 1.0; /* NaN: W not > 0 */
  return !(n <= 1000.0) ? 1000 : n < 1.0 ? 1 : (int)n;
}

double vsph_contact_shear_u(double x, double t, double nu, double U0,
                            double W) {
  if (isnan(nu)) return NAN; /* a fit that is not available draws nothing */
  if (!(t > 0.0) || !(nu > 0.0)) {
    const double xm = x - 2.0 * W * floor((x + W) / (2.0 * W));
    return xm > 0.0 ? U0 : xm < 0.0 ? -U0 : 0.0;
  }
  const double d = sqrt(4.0 * nu * t);
  const int N = images(d, W);
  double s = -1.0;
  for (int n = -N; n <= N; n++)
    s += erf((x - 2.0 * n * W) / d) - erf((x - 2.0 * n * W - W) / d);
  return U0 * s;
}

/* int_0^1 erf(xi/sqrt(s)) ds = sign(xi) [1 - (1 + 2 xi^2) erfc|xi| +
 * 2|xi| e^{-xi^2}/sqrt(pi)] (4 i^2erfc(xi) = (1 + 2 xi^2) erfc xi -
 * 2 xi e^{-xi^2}/sqrt(pi), Abramowitz & Stegun 7.2.5). */
static double erf_time_mean(double xi) {
  const double a = fabs(xi);
  const double g = 1.0 - (1.0 + 2.0 * a * a) * erfc(a) +
                   2.0 * a * exp(-a * a) / sqrt(VSPH_PI);
  return xi < 0.0 ? -g : g;
}

double vsph_contact_shear_dy(double x, double t, double nu, double U0,
                             double W) {
  if (isnan(nu)) return NAN;
  if (!(t > 0.0)) return 0.0;
  if (!(nu > 0.0)) return t * vsph_contact_shear_u(x, 0.0, 0.0, U0, W);
  const double d = sqrt(4.0 * nu * t);
  const int N = images(d, W);
  double s = -1.0;
  for (int n = -N; n <= N; n++)
    s += erf_time_mean((x - 2.0 * n * W) / d) -
         erf_time_mean((x - 2.0 * n * W - W) / d);
  return U0 * t * s;
}

double vsph_contact_drag_ratio(const double *px, size_t n, double rho, double S,
                               double U_drive, double *U, double *drift) {
  double u_own, drift_own;
  if (!U) U = &u_own;
  if (!drift) drift = &drift_own;
  if (n == 0 || !px) {
    *U = *drift = (double)NAN;
    return (double)NAN;
  }
  const size_t last = n - 1, tenth = last - last / 10;
  *U = px[last] / (rho * S * S);
  *drift = (px[last] - px[tenth]) / px[last];
  return U_drive / *U;
}

double vsph_contact_bimaterial_u(double x, double t, double uL, double etaL,
                                 double rhoL, double uR, double etaR,
                                 double rhoR, double *ustar) {
  const double eL = sqrt(etaL * rhoL), eR = sqrt(etaR * rhoR);
  const double us = (eL * uL + eR * uR) / (eL + eR);
  if (ustar) *ustar = us;
  if (x > 0.0) return us + (uR - us) * erf(x / sqrt(4.0 * etaR / rhoR * t));
  return us + (uL - us) * erf(-x / sqrt(4.0 * etaL / rhoL * t));
}

/* sum_j V_j |W'(r_j)| g(x_j, y_j, r_j) over the lattice of spacing 1
 * (simple cubic in 3-D, square in 2-D), h = 2 alpha: the lattice sums of
 * both predictions. */
static double lattice_sum(const struct vsph_kernel_type *k, int dim,
                          double alpha, int visc) {
  /* a kernel, 2-D or 3-D, and a support of at most 64 spacings (the
   * paper's alpha, 0.5 to 1, reaches 2 to 3) */
  if (!k || (dim != 2 && dim != 3) || !(alpha > 0.0) ||
      !(k->kappa * 2.0 * alpha <= 64.0)) {
    vsph_status_report(VSPH_EINVAL, __FILE__, __LINE__,
                       "a lattice sum needs a kernel, dim 2 or 3 and "
                       "0 < kappa 2 alpha <= 64");
    return (double)NAN;
  }
  const double h = 2.0 * alpha, H = k->kappa * h;
  const int m = (int)ceil(H);
  double s = 0.0;
  for (int a = -m; a <= m; a++)
    for (int b = -m; b <= m; b++)
      for (int c = (dim == 3 ? -m : 0); c <= (dim == 3 ? m : 0); c++) {
        const double r2 = (double)(a * a + b * b + c * c);
        if (r2 == 0.0 || r2 >= H * H) continue;
        const double r = sqrt(r2), x2 = (double)(a * a), y2 = (double)(b * b);
        const double dw = fabs(vsph_kernel_dw(k, dim, r / h)) / pow(h, dim + 1);
        s += visc ? dw / r * x2 * (1.0 + y2 / (3.0 * r2)) : x2 * (y2 / r2) * dw;
      }
  return s;
}

double vsph_contact_lattice_visc_factor(const struct vsph_kernel_type *k,
                                        int dim, double alpha) {
  return lattice_sum(k, dim, alpha, 1);
}

double vsph_contact_lattice_coef(const struct vsph_kernel_type *k, int dim,
                                 double alpha) {
  return 0.5 * lattice_sum(k, dim, alpha, 0);
}

/* The least-squares misfit of log(nu). */
struct fit {
  size_t n;
  const double *x, *v;
  int dy;
  double t, U0, W;
};

static double misfit(double lognu, void *arg) {
  const struct fit *f = arg;
  const double nu = exp(lognu);
  double s = 0.0;
  for (size_t i = 0; i < f->n; i++) {
    const double m = f->dy
                         ? vsph_contact_shear_dy(f->x[i], f->t, nu, f->U0, f->W)
                         : vsph_contact_shear_u(f->x[i], f->t, nu, f->U0, f->W);
    s += (f->v[i] - m) * (f->v[i] - m);
  }
  return s;
}

double vsph_contact_fit_nu(size_t n, const double *x, const double *v, int dy,
                           double t, double U0, double W, double lo, double hi,
                           double *rms) {
  struct fit f = {n, x, v, dy, t, U0, W};
  if (!(n > 0) || !x || !v || !(lo > 0.0) || !(hi > lo) || !(t > 0.0)) {
    vsph_status_report(VSPH_EINVAL, __FILE__, __LINE__,
                       "a viscosity fit needs data, 0 < lo < hi and t > 0");
    return NAN;
  }
  /* scan: 81 log-spaced points, then Brent about the smallest */
  enum { NS = 81 };
  const double a = log(lo), b = log(hi), step = (b - a) / (NS - 1);
  double best = INFINITY;
  int kb = 0;
  for (int k = 0; k < NS; k++) {
    const double m = misfit(a + k * step, &f);
    if (m < best) best = m, kb = k;
  }
  double lx = a + kb * step;
  if (kb > 0 && kb < NS - 1) {
    gsl_function fn = {misfit, &f};
    gsl_min_fminimizer *mz = gsl_min_fminimizer_alloc(gsl_min_fminimizer_brent);
    if (!mz) {
      vsph_status_report(VSPH_ENOMEM, __FILE__, __LINE__, "no minimiser");
      return NAN;
    }
    int st = gsl_min_fminimizer_set_with_values(
        mz, &fn, lx, best, lx - step, misfit(lx - step, &f), lx + step,
        misfit(lx + step, &f));
    for (int it = 0; !st && it < 100; it++) {
      if ((st = gsl_min_fminimizer_iterate(mz))) break;
      const double l = gsl_min_fminimizer_x_lower(mz),
                   u = gsl_min_fminimizer_x_upper(mz);
      if (gsl_min_test_interval(l, u, 1e-10, 0.0) == GSL_SUCCESS) break;
    }
    if (!st) {
      lx = gsl_min_fminimizer_x_minimum(mz);
      best = gsl_min_fminimizer_f_minimum(mz);
    }
    gsl_min_fminimizer_free(mz);
  }
  if (rms) *rms = sqrt(best / (double)n) / (dy ? U0 * t : U0);
  return exp(lx);
}

void vsph_contact_shear_free(struct vsph_contact_shear *cs) {
  if (!cs) return;
  free(cs->x);
  cs->x = NULL;
  for (int k = 0; k < 8; k++) {
    free(cs->u[k]);
    free(cs->dy[k]);
    cs->u[k] = cs->dy[k] = NULL;
  }
}

/* Slab means of u_y and of the displacement at the current state. */
static void profile(const struct vsph_run *run, const double *disp,
                    struct vsph_contact_shear *cs, size_t k, double *cnt) {
  const struct vsph_particles *p = run->integ->p;
  const size_t nb = cs->nbins;
  for (size_t b = 0; b < nb; b++) cs->u[k][b] = cs->dy[k][b] = cnt[b] = 0.0;
  for (size_t i = 0; i < p->n; i++) {
    const size_t id = p->id[i];
    if (id >= run->n_fluid) continue;
    double x = p->pos[0][i] + cs->W; /* into [0, 2W) */
    x -= 2.0 * cs->W * floor(x / (2.0 * cs->W));
    size_t b = (size_t)(x / cs->D0);
    if (b >= nb) b = nb - 1;
    cs->u[k][b] += p->vel[1][i];
    cs->dy[k][b] += disp[id];
    cnt[b] += 1.0;
  }
  for (size_t b = 0; b < nb; b++)
    if (cnt[b] > 0.0) {
      cs->u[k][b] /= cnt[b];
      cs->dy[k][b] /= cnt[b];
    }
}

int vsph_contact_defaults(struct vsph_params *prm) {
  if (!prm) VSPH_FAIL(VSPH_EINVAL, "vsph_contact_defaults: a NULL argument");
  int st = vsph_scene_solver_defaults(&vsph_shear_type, prm);
  if (!st && !vsph_params_given(prm, "Scene:viscous"))
    st = vsph_params_set(prm, "Scene:viscous", "0");
  return st;
}

/* Why the fit @p nu of a profile at @p t is no result, or NULL: narrower
 * than one slab (the profile's width sqrt(4 nu t) below D0: only the slab
 * beside the interface departs from +-U0 by more than erfc(1.5) = 3 %, so
 * one number sets the one parameter and its residual says nothing; a step
 * or two after the start, when the discrete profile is no diffusion yet:
 * there the fit came out anywhere from 0.08 to 0.12 Z D0, or 299.6 m^2/s),
 * or at the end of the fit's search range. */
static const char *no_fit(double nu, double t, double D0, double lo,
                          double hi) {
  if (!isfinite(nu)) return "the fit failed";
  if (nu <= lo * (1.0 + 1e-9) || nu >= hi * (1.0 - 1e-9))
    return "the fit reached the end of its search range";
  if (sqrt(4.0 * nu * t) < D0)
    return "the profile is narrower than one slab, sqrt(4 nu t) < D0: too "
           "early to carry information";
  return NULL;
}

/* ------------------------------------------------------ checkpoints */

/* A shear test's state: this header, then disp and prev (nf each), the
 * k profiles taken (u then dy, nb each), then the run's own state
 * (vsph_run_pack, run_len bytes). */
struct shear_ckpt {
  char magic[16];
  uint64_t k, nf, nb, nprof, run_len;
  double wall, t[8];
};
static const char SHEAR_MAGIC[16] = "vsph shear v1";

/* The state packed and handed to cs->save. */
static int shear_pack_save(const struct vsph_contact_shear *cs,
                           const struct vsph_run *run, const double *disp,
                           const double *prev, size_t k, double wall) {
  const size_t nf = run->n_fluid, nb = cs->nbins;
  const size_t run_len = vsph_run_pack(run, NULL);
  const size_t len = sizeof(struct shear_ckpt) +
                     (2 * nf + 2 * k * nb) * sizeof(double) + run_len;
  unsigned char *buf = malloc(len);
  if (!buf) VSPH_FAIL(VSPH_ENOMEM, "cannot pack the shear test's state");
  struct shear_ckpt h = {.k = k,
                         .nf = nf,
                         .nb = nb,
                         .nprof = cs->nprof,
                         .run_len = run_len,
                         .wall = wall};
  memcpy(h.magic, SHEAR_MAGIC, sizeof h.magic);
  memcpy(h.t, cs->t, sizeof h.t);
  unsigned char *at = buf;
  memcpy(at, &h, sizeof h), at += sizeof h;
  memcpy(at, disp, nf * sizeof *disp), at += nf * sizeof *disp;
  memcpy(at, prev, nf * sizeof *prev), at += nf * sizeof *prev;
  for (size_t q = 0; q < k; q++) {
    memcpy(at, cs->u[q], nb * sizeof(double)), at += nb * sizeof(double);
    memcpy(at, cs->dy[q], nb * sizeof(double)), at += nb * sizeof(double);
  }
  if (vsph_run_pack(run, at) != run_len) {
    free(buf);
    VSPH_FAIL(VSPH_EIO, "cannot read back the state kept for a snapshot");
  }
  const int st = cs->save(cs->save_ctx, buf, len);
  free(buf);
  return st;
}

/* The state cs->resume holds, restored into @p run (freshly made with the
 * same settings), the arrays, the profiles so far (*@p k) and the earlier
 * processes' wall time (*@p wall); a state of other settings or cut short
 * is refused (VSPH_EINVAL). */
static int shear_unpack(struct vsph_contact_shear *cs, struct vsph_run *run,
                        double *disp, double *prev, size_t *k, double *wall,
                        size_t nprof) {
  struct shear_ckpt h;
  const size_t nf = run->n_fluid, nb = cs->nbins;
  if (cs->resume_len < sizeof h)
    VSPH_FAIL(VSPH_EINVAL, "the shear test's checkpoint is cut short");
  memcpy(&h, cs->resume, sizeof h);
  if (memcmp(h.magic, SHEAR_MAGIC, sizeof h.magic) || h.nf != nf ||
      h.nb != nb || h.nprof != nprof || h.k > nprof ||
      cs->resume_len !=
          sizeof h + (2 * nf + 2 * h.k * nb) * sizeof(double) + h.run_len)
    VSPH_FAIL(VSPH_EINVAL, "the shear test's checkpoint is not this test's");
  const unsigned char *at = cs->resume + sizeof h;
  memcpy(disp, at, nf * sizeof *disp), at += nf * sizeof *disp;
  memcpy(prev, at, nf * sizeof *prev), at += nf * sizeof *prev;
  for (size_t q = 0; q < h.k; q++) {
    memcpy(cs->u[q], at, nb * sizeof(double)), at += nb * sizeof(double);
    memcpy(cs->dy[q], at, nb * sizeof(double)), at += nb * sizeof(double);
  }
  const int st = vsph_run_unpack(run, at, (size_t)h.run_len);
  if (st) return st;
  memcpy(cs->t, h.t, sizeof cs->t);
  *k = (size_t)h.k;
  *wall = h.wall;
  return VSPH_OK;
}

/* Each fluid particle's y displacement since the start, unwrapped
 * across the period @p Ly (a step moves a particle far less than Ly/2):
 * @p prev its last y, @p disp its sum, both by id (below @p nf). */
static void unwrap(const struct vsph_particles *p, size_t nf, double Ly,
                   double *prev, double *disp) {
  for (size_t i = 0; i < p->n; i++) {
    const size_t id = p->id[i];
    if (id >= nf) continue;
    double d = p->pos[1][i] - prev[id];
    d -= Ly * nearbyint(d / Ly);
    disp[id] += d;
    prev[id] = p->pos[1][i];
  }
}

/* The viscosity fitted to each profile of @p cs (velocity and
 * displacement), between 1e-4 and 1e4 times the scale D0 c/10; NaN where
 * the profile carries no information yet (no_fit). */
static void fit_profiles(struct vsph_contact_shear *cs) {
  const size_t nb = cs->nbins;
  const double scale = 0.1 * cs->D0 * cs->c0;
  const double lo = 1e-4 * scale, hi = 1e4 * scale;
  for (size_t q = 0; q < cs->nt; q++) {
    cs->nu_u[q] = vsph_contact_fit_nu(nb, cs->x, cs->u[q], 0, cs->t[q], cs->U0,
                                      cs->W, lo, hi, &cs->rms_u[q]);
    cs->nu_dy[q] = vsph_contact_fit_nu(nb, cs->x, cs->dy[q], 1, cs->t[q],
                                       cs->U0, cs->W, lo, hi, &cs->rms_dy[q]);
    if ((cs->na_u[q] = no_fit(cs->nu_u[q], cs->t[q], cs->D0, lo, hi)))
      cs->nu_u[q] = cs->rms_u[q] = NAN;
    if ((cs->na_dy[q] = no_fit(cs->nu_dy[q], cs->t[q], cs->D0, lo, hi)))
      cs->nu_dy[q] = cs->rms_dy[q] = NAN;
  }
}

/* @p cs emptied for the results, keeping what the caller set in it: its
 * profile count (held to 1 .. 8), its callbacks and the state to resume. */
static void shear_reset(struct vsph_contact_shear *cs) {
  const size_t nprof = cs->nprof < 1 ? 1 : cs->nprof > 8 ? 8 : cs->nprof;
  const struct vsph_contact_shear in = *cs; /* what the caller set */
  memset(cs, 0, sizeof *cs);
  cs->nprof = nprof;
  cs->progress = in.progress;
  cs->progress_ctx = in.progress_ctx;
  cs->stop = in.stop;
  cs->save = in.save;
  cs->save_ctx = in.save_ctx;
  cs->resume = in.resume;
  cs->resume_len = in.resume_len;
}

/* The shear run of @p prm laid out into *@p run (its props into @p rp) and
 * its figures into @p cs; refused before anything is laid out where a
 * parameter is unknown or the run is too short for cs->nprof profiles. */
static int shear_run_alloc(struct vsph_params *prm,
                           struct vsph_contact_shear *cs,
                           struct vsph_run_props *rp, struct vsph_run **run) {
  const size_t nprof = cs->nprof;
  struct vsph_scene sc;
  int st = vsph_run_props_init(rp, prm);
  if (!st) st = vsph_scene_init(&sc, &vsph_shear_type, prm);
  if (st) return st;
  const char *unused = vsph_params_unused(prm);
  if (unused) {
    char hint[1024];
    vsph_params_hint(prm, unused, hint, sizeof hint);
    VSPH_FAIL(VSPH_EINVAL, "unknown parameter '%s'%s", unused, hint);
  }
  rp->snapshots = 0;
  /* a profile is taken at the first step past each t_end k/K: K profiles
   * need K steps at least (a run of one step gave one profile, one step
   * old, and its "fit") */
  struct vsph_run_estimate e;
  if ((st = vsph_run_estimate(rp, &sc, &e))) return st;
  if (!(ceil(e.steps) >= (double)nprof))
    VSPH_FAIL(VSPH_EINVAL,
              "%zu profiles need %zu steps at least, and the run to t_end = "
              "%g s takes about %.3g: lengthen t_end or ask fewer profiles",
              nprof, nprof, rp->t_end > 0 ? rp->t_end : sc.t_end, e.steps);
  if ((st = vsph_run_alloc(rp, &sc, run))) return st;
  const struct vsph_scene_shear *sh = &(*run)->scene.u.shear;
  cs->n = (*run)->n_fluid;
  cs->D0 = (*run)->dx;
  cs->W = sh->W;
  cs->U0 = sh->U0;
  cs->t_end = (*run)->t_end;
  cs->rho0 = (*run)->scene.mat[0].rho0;
  cs->c0 = (*run)->scene.mat[0].c0;
  cs->nbins = 2 * rp->res;
  return VSPH_OK;
}

/* The profiles of @p cs (cs->nbins slabs at cs->nprof times, their slab
 * centres set) and the arrays by particle id (@p nf of them: @p disp
 * zeroed, @p prev) or by slab (@p cnt); VSPH_ENOMEM where one is missing
 * (the caller frees what was allocated). */
static int shear_alloc(struct vsph_contact_shear *cs, size_t nf, double **disp,
                       double **prev, double **cnt) {
  const size_t nb = cs->nbins, nprof = cs->nprof;
  *disp = calloc(nf, sizeof **disp);
  *prev = malloc(nf * sizeof **prev);
  *cnt = malloc(nb * sizeof **cnt);
  cs->x = malloc(nb * sizeof *cs->x);
  for (size_t k = 0; k < nprof; k++) {
    cs->u[k] = malloc(nb * sizeof(double));
    cs->dy[k] = malloc(nb * sizeof(double));
  }
  int ok = *disp && *prev && *cnt && cs->x;
  for (size_t k = 0; k < nprof; k++) ok = ok && cs->u[k] && cs->dy[k];
  if (!ok) {
    vsph_status_report(VSPH_ENOMEM, __FILE__, __LINE__,
                       "cannot allocate the shear test's profiles");
    return VSPH_ENOMEM;
  }
  for (size_t b = 0; b < nb; b++) cs->x[b] = -cs->W + (b + 0.5) * cs->D0;
  return VSPH_OK;
}

/* The steps of @p run until it ends or the cs->nprof profiles are taken
 * (*@p k so far), each particle's displacement followed (@p prev, @p disp)
 * and a profile taken at each profile time (@p cnt its scratch); a line
 * of progress every 5 s, a checkpoint every @p checkpoint_s of wall time
 * (0: none) and at a stop request, which ends it (VSPH_EINTR). @p wall0
 * is the earlier processes' wall time, @p t0 this one's start. */
static int shear_steps(struct vsph_contact_shear *cs, struct vsph_run *run,
                       double checkpoint_s, double *disp, double *prev,
                       double *cnt, size_t *k, double wall0, double t0) {
  const size_t nprof = cs->nprof, nf = run->n_fluid;
  const double Ly = run->scene.u.shear.Ly;
  double last = t0, last_ck = t0;
  int st;
  while (run->state == VSPH_RUN_RUNNING && *k < nprof) {
    if ((st = vsph_run_iterate(run))) return st;
    unwrap(run->integ->p, nf, Ly, prev, disp);
    const double t = vsph_run_time(run);
    if (run->state != VSPH_RUN_UNSTABLE &&
        t >= cs->t_end * (double)(*k + 1) / (double)nprof * (1.0 - 1e-12)) {
      profile(run, disp, cs, *k, cnt);
      cs->t[*k] = t;
      (*k)++;
    }
    const double now = omp_get_wtime();
    if (cs->progress && now - last > 5.0) { /* never silent for long */
      cs->progress(cs->progress_ctx, t, cs->t_end, wall0 + now - t0);
      last = now;
    }
    /* a checkpoint between two steps: at a stop, and every checkpoint_s */
    const int stopping = cs->stop && *cs->stop;
    if (cs->save && run->state == VSPH_RUN_RUNNING && *k < nprof &&
        (stopping || (checkpoint_s > 0.0 && now - last_ck >= checkpoint_s))) {
      if ((st = shear_pack_save(cs, run, disp, prev, *k, wall0 + now - t0)))
        return st;
      last_ck = now;
    }
    if (stopping && run->state == VSPH_RUN_RUNNING && *k < nprof) {
      cs->interrupted = 1;
      return VSPH_EINTR;
    }
  }
  return VSPH_OK;
}

int vsph_contact_shear_measure(struct vsph_params *prm,
                               struct vsph_contact_shear *cs) {
  if (!prm || !cs)
    VSPH_FAIL(VSPH_EINVAL, "vsph_contact_shear_measure: a NULL argument");
  shear_reset(cs);
  const size_t nprof = cs->nprof;
  struct vsph_run_props rp;
  struct vsph_run *run = NULL;
  int st = shear_run_alloc(prm, cs, &rp, &run);
  if (st) return st;
  const size_t nf = run->n_fluid;
  double *disp = NULL, *prev = NULL, *cnt = NULL;
  if ((st = shear_alloc(cs, nf, &disp, &prev, &cnt))) goto done;
  {
    const struct vsph_particles *p = run->integ->p;
    for (size_t i = 0; i < p->n; i++)
      if (p->id[i] < nf) prev[p->id[i]] = p->pos[1][i];
  }
  size_t k = 0;
  double wall0 = 0.0; /* the wall time of the processes before this one */
  if (cs->resume && (st = shear_unpack(cs, run, disp, prev, &k, &wall0, nprof)))
    goto done;
  const double t0 = omp_get_wtime();
  if ((st = shear_steps(cs, run, rp.checkpoint_s, disp, prev, cnt, &k, wall0,
                        t0)))
    goto done;
  cs->nt = k;
  cs->stable = run->state != VSPH_RUN_UNSTABLE;
  cs->t_stop = vsph_run_time(run);
  cs->steps = vsph_run_steps(run);
  snprintf(cs->reason, sizeof cs->reason, "%s", run->reason);
  cs->wall_s = wall0 + omp_get_wtime() - t0;
  fit_profiles(cs);
done:
  free(disp);
  free(prev);
  free(cnt);
  vsph_run_free(run);
  if (st) {
    const int interrupted = cs->interrupted;
    vsph_contact_shear_free(cs);
    cs->interrupted = interrupted;
  }
  return st;
}

double vsph_contact_bimaterial_fit(const double *tt, const double *x,
                                   const double *u, size_t n, double t,
                                   double U0, double nuL, double nuR, double W,
                                   double etaL, double rhoL, double etaR,
                                   double rhoR, double *rms_exact) {
  double rms_own;
  if (!rms_exact) rms_exact = &rms_own;
  if (n && (!tt || !x || !u)) return *rms_exact = (double)NAN;
  double num = 0, den = 0, e2 = 0;
  size_t m = 0;
  for (size_t i = 0; i < n; i++) {
    if (fabs(tt[i] - t) > 1e-6 * t || fabs(x[i]) > 0.5 * W) continue;
    const double side = x[i] > 0 ? U0 : -U0, nu = x[i] > 0 ? nuR : nuL;
    const double e = erf(fabs(x[i]) / sqrt(4.0 * nu * t));
    num += (1.0 - e) * (u[i] - side * e);
    den += (1.0 - e) * (1.0 - e);
    const double ex = vsph_contact_bimaterial_u(x[i], t, -U0, etaL, rhoL, U0,
                                                etaR, rhoR, NULL);
    e2 += (u[i] - ex) * (u[i] - ex);
    m++;
  }
  *rms_exact = m ? sqrt(e2 / (double)m) / U0 : (double)NAN;
  return den > 0 ? num / den / U0 : (double)NAN;
}

double vsph_contact_eta_model(double C, double rho, double c, double D0,
                              double flat, double eta, double zeta,
                              double fit) {
  return C * rho * c * D0 + flat * (eta - zeta * fit * rho * c * D0);
}

void vsph_contact_self_similar(const struct vsph_contact_shear *cs,
                               double *spread, double *lean) {
  if (!spread || !lean) return;
  *spread = *lean = (double)NAN;
  if (!cs) return;
  double lo = INFINITY, hi = -INFINITY, t0 = NAN, t1 = NAN;
  size_t good = 0;
  for (size_t q = 0; q < cs->nt && q < 8; q++) {
    if (!isfinite(cs->nu_u[q]) || !(cs->nu_u[q] > 0.0)) continue;
    lo = fmin(lo, cs->nu_u[q]);
    hi = fmax(hi, cs->nu_u[q]);
    if (!good++) t0 = cs->t[q];
    t1 = cs->t[q];
  }
  if (good < 2) return;
  *spread = 100.0 * (hi - lo) / lo;
  *lean = vsph_series_log_between(hi / lo, 1.0, t1 / t0);
}
