/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
/* The pair functions (solver/pair.h) through the two codes that use them:
 * the solver's right-hand side and the analysis operators.
 *
 * 1. An O(N^2) brute-force twin written here from THEORY sections 3 and 5,
 *    independently of the library: its own distance and cut-off, its own
 *    kernel derivative (W'(s) = h^{-d-1} w'(q) from the kernel's dw, not the
 *    loops' (dw/dq)/q of q^2), its own PVWF with GSL's LU inverse (model B
 *    without it), its own model A from the Gaussian's closed-form second
 *    derivatives (not eq. 28 and w''), Espanol-Revenga with its own a, b
 *    and a non-zero bulk viscosity. The
 *    right-hand side (continuity, pressure, each viscous formulation,
 *    delta-SPH) and each operator (force and dissipation density) must
 *    match it.
 * 2. The solver's viscous acceleration times rho equals
 *    vsph_viscous_compute on the same particles, for each formulation on
 *    each scene (ghost walls included).
 * 3. The symmetric sweep (each unique pair once, equations.h) gives the
 *    per-particle gather's right-hand side to rounding on every scene, the
 *    same interactions and closest pair exactly, and the same bits on 1
 *    and 2 threads; through it the right-hand side matches the twin too. */
#include <gsl/gsl_linalg.h>
#include <gsl/gsl_randist.h>
#include <gsl/gsl_rng.h>
#include <malloc.h> /* malloc_usable_size (glibc) */
#include <math.h>
#include <omp.h>
#include <stdlib.h>
#include <string.h>

#include "../common/consts.h"
#include "../common/params.h"
#include "../kernels/kernel.h"
#include "../solver/cells.h"
#include "../solver/equations.h"
#include "../solver/equations_internal.h"
#include "../solver/integrate.h"
#include "../solver/lattice.h"
#include "../solver/particles.h"
#include "../solver/scene.h"
#include "../solver/sweep_x86.h"
#include "../solver/viscous.h"
#include "../solver/walls.h"
#include "check_suites.h"

/* High-entropy physics of the twin (GSL style): no factor can hide. */
static const double RHO0 = 1.2348, C0 = 2.385, MU = 0.0137, DELTA = 0.1;
static const double DX = 0.05, HDX = 1.3333;

/* A perturbed patch with a free surface all round, random velocities,
 * densities and volumes. */
static struct vsph_particles *random_set_in(int dim, unsigned long seed,
                                            double radius, double depth) {
  struct vsph_lattice_props lp = {.dim = dim,
                                  .kind = VSPH_LATTICE_SQUARE,
                                  .dx = DX,
                                  .perturb = 0.25,
                                  .seed = seed};
  struct vsph_particles *p = NULL;
  size_t c;
  ck_assert_int_eq(vsph_lattice_halfspace(&lp, radius, depth, &p, &c), 0);
  gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937);
  gsl_rng_set(rng, seed);
  for (size_t i = 0; i < p->n; i++) {
    p->rho[i] = RHO0 * (0.97 + 0.06 * gsl_rng_uniform(rng));
    p->m[i] = p->rho[i] * p->vol[i] * (0.9 + 0.2 * gsl_rng_uniform(rng));
    p->vol[i] = p->m[i] / p->rho[i];
    for (int k = 0; k < dim; k++) p->vel[k][i] = gsl_rng_uniform(rng) - 0.5;
  }
  gsl_rng_free(rng);
  return p;
}

static struct vsph_particles *random_set(int dim, unsigned long seed) {
  return random_set_in(dim, seed, dim == 2 ? 0.5 : 0.25, 0.11);
}

/* ------------------------------------------------------------ the twin */

/* W'(s)/s of pair (i, j), or 0 outside the support; x = r_j - r_i. */
static double twin_F(const struct vsph_kernel_type *k, int dim, double h,
                     const struct vsph_particles *p, size_t i, size_t j,
                     double x[3]) {
  double s2 = 0.0;
  for (int a = 0; a < 3; a++) {
    x[a] = a < dim ? p->pos[a][j] - p->pos[a][i] : 0.0;
    s2 += x[a] * x[a];
  }
  const double s = sqrt(s2), q = s / h;
  if (i == j || q >= k->kappa) return 0.0;
  return pow(h, -dim - 1) * vsph_kernel_dw(k, dim, q) / s;
}

/* PVWF's A_i = T_i L_i and -T_i:D_i of every particle (THEORY 3); model B
 * (renorm 0): L = I and lambda = -2 mu/3 (Basa et al.'s eq. 4). */
static void twin_pvwf(const struct vsph_viscous_props *vp,
                      const struct vsph_particles *p, double *A, double *dens,
                      int renorm) {
  const int d = vp->dim;
  const double lambda = renorm ? -2.0 * vp->mu / d : -2.0 * vp->mu / 3.0;
  for (size_t i = 0; i < p->n; i++) {
    gsl_matrix *B = gsl_matrix_calloc(d, d), *L = gsl_matrix_alloc(d, d);
    double Mg[3][3] = {{0}};
    for (size_t j = 0; j < p->n; j++) {
      double x[3];
      const double F = twin_F(vp->kernel, d, vp->h, p, i, j, x);
      if (F == 0.0) continue;
      for (int a = 0; a < d; a++)
        for (int b = 0; b < d; b++) {
          /* grad_i W = -F x */
          *gsl_matrix_ptr(B, a, b) += p->vol[j] * (-F * x[a]) * x[b];
          Mg[a][b] += p->vol[j] * (p->vel[a][j] - p->vel[a][i]) * (-F * x[b]);
        }
    }
    gsl_permutation *perm = gsl_permutation_alloc(d);
    int sign;
    gsl_linalg_LU_decomp(B, perm, &sign);
    gsl_linalg_LU_invert(B, perm, L);
    if (!renorm) gsl_matrix_set_identity(L);
    gsl_permutation_free(perm);
    double G[3][3] = {{0}}, D[3][3], T[3][3], tr = 0.0, TD = 0.0;
    for (int a = 0; a < d; a++)
      for (int b = 0; b < d; b++)
        for (int c = 0; c < d; c++)
          G[a][b] += Mg[a][c] * gsl_matrix_get(L, b, c);
    for (int a = 0; a < d; a++) tr += G[a][a];
    for (int a = 0; a < d; a++)
      for (int b = 0; b < d; b++) {
        D[a][b] = 0.5 * (G[a][b] + G[b][a]);
        T[a][b] = 2.0 * vp->mu * D[a][b] + (a == b ? lambda * tr : 0.0);
        TD += T[a][b] * D[a][b];
      }
    for (int a = 0; a < d; a++)
      for (int b = 0; b < d; b++) {
        double s = 0.0;
        for (int c = 0; c < d; c++) s += T[a][c] * gsl_matrix_get(L, c, b);
        A[(a * 3 + b) * p->n + i] = s;
      }
    dens[i] = -TD;
    gsl_matrix_free(B);
    gsl_matrix_free(L);
  }
}

/* Model A on the truncated Gaussian W = sigma h^-d (e^{-q^2} - e^{-9}),
 * q < 3 (shifted to vanish at the cut, THEORY 1): with
 * r = r_i - r_j, d_a W = -2 r_a W/h^2 and d_ab W = (4 r_a r_b/h^4 -
 * 2 delta_ab/h^2) W (the closed form, not eq. 28). The sums of Basa's
 * eq. (27) over j and i itself; shepard: the second derivatives of
 * <u>/<1> by the quotient rule (eq. 23); force mu lap u + (mu/3) grad div
 * u (eq. 6); into A[k n + i] and dens u_i.f. */
static void twin_takeda(const struct vsph_viscous_props *vp,
                        const struct vsph_particles *p, double *A, double *dens,
                        int shepard) {
  const int d = vp->dim;
  const double h = vp->h, sig = vsph_gaussian_type.sigma[d - 1] * pow(h, -d);
  for (size_t i = 0; i < p->n; i++) {
    double S0 = 0, S1[3] = {0}, S2[3][3] = {{0}};
    double U0[3] = {0}, U1[3][3] = {{0}}, U2[3][3][3] = {{{0}}};
    for (size_t j = 0; j < p->n; j++) {
      double r[3] = {0}, r2 = 0.0;
      for (int a = 0; a < d; a++) {
        r[a] = p->pos[a][i] - p->pos[a][j];
        r2 += r[a] * r[a];
      }
      if (r2 >= 9.0 * h * h) continue;
      const double E = sig * exp(-r2 / (h * h)), V = p->vol[j];
      const double W = E - sig * exp(-9.0);
      S0 += V * W;
      for (int c = 0; c < d; c++) U0[c] += V * W * p->vel[c][j];
      for (int a = 0; a < d; a++) {
        const double g = -2.0 * r[a] / (h * h) * E;
        S1[a] += V * g;
        for (int c = 0; c < d; c++) U1[c][a] += V * g * p->vel[c][j];
        for (int b = 0; b < d; b++) {
          const double g2 =
              (4.0 * r[a] * r[b] / pow(h, 4) - (a == b ? 2.0 / (h * h) : 0.0)) *
              E;
          S2[a][b] += V * g2;
          for (int c = 0; c < d; c++) U2[c][a][b] += V * g2 * p->vel[c][j];
        }
      }
    }
    double Dd[3][3][3];
    for (int c = 0; c < d; c++)
      for (int a = 0; a < d; a++)
        for (int b = 0; b < d; b++) {
          /* (U/S)_ab = U_ab/S - (U_a S_b + U_b S_a)/S^2 - U S_ab/S^2
           *            + 2 U S_a S_b/S^3 */
          Dd[c][a][b] =
              shepard ? U2[c][a][b] / S0 -
                            (U1[c][a] * S1[b] + U1[c][b] * S1[a]) / (S0 * S0) -
                            U0[c] * S2[a][b] / (S0 * S0) +
                            2.0 * U0[c] * S1[a] * S1[b] / (S0 * S0 * S0)
                      : U2[c][a][b];
        }
    double P = 0.0;
    for (int a = 0; a < d; a++) {
      double f = 0.0;
      for (int b = 0; b < d; b++)
        f += vp->mu * Dd[a][b][b] + vp->mu / 3.0 * Dd[b][a][b];
      A[a * p->n + i] = f;
      P += p->vel[a][i] * f;
    }
    dens[i] = P;
  }
}

/* Zheng et al.'s Laplacian forms (VISC-01..04, form k = 1..4) as the
 * paper writes them, on the truncated Gaussian, with r_ij = r_i - r_j,
 * grad_i W = -F x (x = r_j - r_i), u_ij = u_i - u_j, eta^2 = (0.1 h)^2
 * for the hybrid forms:
 *   VISC-01: 2 sum V u_ij r_ij.grad W/(r^2 + eta^2);
 *   VISC-02: 2/(d + 2) sum V (u_j - u_i) (W'' - W'/r), W'' and W'/r of the
 *            Gaussian in closed form;
 *   VISC-03: (d/H) (VISC-01 - 2 (Gamma g).A), B = sum V grad W (x) x,
 *            H = tr B, Gamma = B^-1, g = sum V (u_j - u_i) grad W,
 *            A = sum V grad W;
 *   VISC-04: 2 sum V u_ij r_ij.(Gamma grad W)/(r^2 + eta^2);
 * Gamma by GSL's LU inverse; force mu lap u per component into A[k n + i],
 * dens u_i.f. */
static void twin_lap(const struct vsph_viscous_props *vp,
                     const struct vsph_particles *p, double *A, double *dens,
                     int k) {
  const int d = vp->dim;
  const double h = vp->h, sig = vsph_gaussian_type.sigma[d - 1] * pow(h, -d);
  const double eta2 = k == 2 ? 0.0 : 0.01 * h * h;
  for (size_t i = 0; i < p->n; i++) {
    gsl_matrix *B = gsl_matrix_calloc(d, d), *G = gsl_matrix_alloc(d, d);
    double Av[3] = {0};
    for (size_t j = 0; j < p->n; j++) {
      double x[3];
      const double F = twin_F(vp->kernel, d, h, p, i, j, x);
      if (F == 0.0) continue;
      for (int a = 0; a < d; a++) {
        Av[a] += p->vol[j] * (-F * x[a]);
        for (int b = 0; b < d; b++)
          *gsl_matrix_ptr(B, a, b) += p->vol[j] * (-F) * x[a] * x[b];
      }
    }
    const double H = d == 2
                         ? gsl_matrix_get(B, 0, 0) + gsl_matrix_get(B, 1, 1)
                         : gsl_matrix_get(B, 0, 0) + gsl_matrix_get(B, 1, 1) +
                               gsl_matrix_get(B, 2, 2);
    gsl_permutation *perm = gsl_permutation_alloc(d);
    int sign;
    gsl_linalg_LU_decomp(B, perm, &sign);
    gsl_linalg_LU_invert(B, perm, G);
    gsl_permutation_free(perm);
    double P = 0.0;
    for (int c = 0; c < d; c++) {
      double v01 = 0.0, v02 = 0.0, v04 = 0.0, g[3] = {0};
      for (size_t j = 0; j < p->n; j++) {
        double x[3];
        const double F = twin_F(vp->kernel, d, h, p, i, j, x);
        if (F == 0.0) continue;
        double s2 = 0.0;
        for (int a = 0; a < d; a++) s2 += x[a] * x[a];
        const double V = p->vol[j], uij = p->vel[c][i] - p->vel[c][j];
        const double E = sig * exp(-s2 / (h * h));
        const double d2w = E * (4.0 * s2 / (h * h) - 2.0) / (h * h),
                     dwr = -2.0 * E / (h * h);
        double xGx = 0.0;
        for (int a = 0; a < d; a++) {
          g[a] += V * (-uij) * (-F * x[a]);
          for (int b = 0; b < d; b++)
            xGx += x[a] * gsl_matrix_get(G, a, b) * x[b];
        }
        v01 += 2.0 * V * uij * (F * s2) / (s2 + eta2); /* r_ij.grad W = F s^2 */
        v02 += 2.0 / (d + 2.0) * V * (-uij) * (d2w - dwr);
        v04 += 2.0 * V * uij * F * xGx / (s2 + eta2);
      }
      double gA = 0.0;
      for (int a = 0; a < d; a++)
        for (int b = 0; b < d; b++)
          gA += gsl_matrix_get(G, a, b) * g[b] * Av[a];
      const double lap = k == 1   ? v01
                         : k == 2 ? v02
                         : k == 3 ? d / H * (v01 - 2.0 * gA)
                                  : v04;
      A[c * p->n + i] = vp->mu * lap;
      P += p->vel[c][i] * vp->mu * lap;
    }
    dens[i] = P;
    gsl_matrix_free(B);
    gsl_matrix_free(G);
  }
}

/* Everything the twin computes, per particle. */
struct twin {
  double *drho, *acc[3], *visc[3], *ddelta, *dens;
};

static void twin_run(const struct vsph_viscous_props *vp,
                     const struct vsph_particles *p, double delta,
                     struct twin *tw) {
  const int d = vp->dim;
  const size_t n = p->n;
  double *A = calloc(9 * n, sizeof *A), *pd = calloc(n, sizeof *pd);
  const int lapf =
      vp->form >= VSPH_VISCOUS_VISC01 && vp->form <= VSPH_VISCOUS_VISC04;
  const int takeda = vp->form == VSPH_VISCOUS_TAKEDA ||
                     vp->form == VSPH_VISCOUS_TAKEDA0 || lapf;
  if (lapf) twin_lap(vp, p, A, pd, vp->form - VSPH_VISCOUS_VISC01 + 1);
  if (vp->form == VSPH_VISCOUS_PVWF || vp->form == VSPH_VISCOUS_TWOPASS)
    twin_pvwf(vp, p, A, pd, vp->form == VSPH_VISCOUS_PVWF);
  if (takeda && !lapf)
    twin_takeda(vp, p, A, pd, vp->form == VSPH_VISCOUS_TAKEDA0);
  const double K = 2.0 * (d + 2); /* THEORY 0 */
  for (size_t i = 0; i < n; i++) {
    const double pi = C0 * C0 * (p->rho[i] - RHO0);
    double cont = 0.0, dl = 0.0, ap[3] = {0}, av[3] = {0}, dens = 0.0;
    for (size_t j = 0; j < n; j++) {
      double x[3];
      const double F = twin_F(vp->kernel, d, vp->h, p, i, j, x);
      if (F == 0.0) continue;
      const double V = p->vol[j], pj = C0 * C0 * (p->rho[j] - RHO0);
      double du[3] = {0}, dux = 0.0, du2 = 0.0, s2 = 0.0, gW[3] = {0};
      for (int a = 0; a < d; a++) {
        du[a] = p->vel[a][j] - p->vel[a][i];
        dux += du[a] * x[a];
        du2 += du[a] * du[a];
        s2 += x[a] * x[a];
        gW[a] = -F * x[a]; /* grad_i W_ij */
      }
      double duW = 0.0, psiW = 0.0;
      for (int a = 0; a < d; a++) {
        duW += du[a] * gW[a];
        /* psi_ij = 2 (rho_j - rho_i) x / s^2 */
        psiW += 2.0 * (p->rho[j] - p->rho[i]) * x[a] / s2 * gW[a];
      }
      cont -= V * duW;
      dl += V * psiW;
      for (int a = 0; a < d; a++) ap[a] -= V * (pi + pj) * gW[a];
      if (vp->form == VSPH_VISCOUS_MGF) {
        for (int a = 0; a < d; a++) av[a] += K * vp->mu * V * dux / s2 * gW[a];
        dens += 0.5 * K * vp->mu * V * F * dux * dux / s2;
      } else if (vp->form == VSPH_VISCOUS_VI ||
                 vp->form == VSPH_VISCOUS_CLEARY) {
        /* Basa et al. 2009, eqs. (33)-(34) with uniform mu and the volume
         * V_j = m_j/rho_j: K = 8 (2-D; 10 in 3-D) or 2 xi, eta = 0.1 h */
        const double Kb = vp->form == VSPH_VISCOUS_VI ? K : 2.0 * 4.96333;
        const double r2 = s2 + 0.01 * vp->h * vp->h;
        for (int a = 0; a < d; a++) av[a] += Kb * vp->mu * V * dux / r2 * gW[a];
        dens += 0.5 * Kb * vp->mu * V * F * dux * dux / r2;
      } else if (vp->form == VSPH_VISCOUS_MEAF) {
        for (int a = 0; a < d; a++) av[a] += 2.0 * vp->mu * V * F * (-du[a]);
        dens += vp->mu * V * F * du2;
      } else if (vp->form == VSPH_VISCOUS_MEAFETA) {
        /* Morris et al. (1997) as printed, uniform mu: 2 mu V_j
         * (r_ij.grad_i W)/(r_ij^2 + eta^2) u_ij, r_ij = -x, u_ij = -du,
         * eta = 0.1 h; its density -f.du/2 */
        double rg = 0.0;
        for (int a = 0; a < d; a++) rg += -x[a] * gW[a];
        const double r2 = s2 + 0.01 * vp->h * vp->h;
        for (int a = 0; a < d; a++) {
          const double fa = 2.0 * vp->mu * V * rg / r2 * (-du[a]);
          av[a] += fa;
          dens -= 0.5 * fa * du[a];
        }
      } else if (vp->form == VSPH_VISCOUS_ER) {
        /* Espanol & Revenga (2003) with the number density 1/V: force
         * density sum_j V_j F_ER (a v_ij + b e (e.v_ij)), F_ER = -W'/s,
         * v_ij = u_i - u_j, e = r_ij/s (docs/theory.md section 8) */
        const double mu = vp->mu, z = vp->zeta;
        const double ea = z - mu * (d + 2.0) / d,
                     eb = -(d + 2.0) * (z + mu * (d - 2.0) / d);
        double ev = 0.0; /* e.v_ij = (-x/s).(-du) */
        for (int a = 0; a < d; a++) ev += (-x[a] / sqrt(s2)) * (-du[a]);
        for (int a = 0; a < d; a++) {
          const double fa =
              V * (-F) * (ea * (-du[a]) + eb * (-x[a] / sqrt(s2)) * ev);
          av[a] += fa;
          dens -= 0.5 * fa * du[a];
        }
      } else if (takeda) {
        /* the force comes whole from twin_takeda */
      } else {
        for (int a = 0; a < d; a++)
          for (int b = 0; b < d; b++)
            av[a] +=
                V * (A[(a * 3 + b) * n + j] + A[(a * 3 + b) * n + i]) * gW[b];
      }
    }
    const double dhc = delta * vp->h * C0;
    tw->drho[i] = p->rho[i] * cont + dhc * dl;
    tw->ddelta[i] = dhc * dl;
    for (int a = 0; a < d; a++) {
      if (takeda) av[a] = A[a * n + i];
      tw->acc[a][i] = (ap[a] + av[a]) / p->rho[i];
      tw->visc[a][i] = av[a];
    }
    const int first = vp->form == VSPH_VISCOUS_PVWF ||
                      vp->form == VSPH_VISCOUS_TWOPASS || takeda;
    tw->dens[i] = first ? pd[i] : dens;
  }
  free(A);
  free(pd);
}

static double *column(double *buf, size_t n, int k) { return buf + k * n; }

/* |a - b| <= tol max|b| over the n values. */
static void assert_close(const double *a, const double *b, size_t n, double tol,
                         const char *what) {
  double scale = 0.0, err = 0.0;
  for (size_t i = 0; i < n; i++) scale = fmax(scale, fabs(b[i]));
  for (size_t i = 0; i < n; i++) err = fmax(err, fabs(a[i] - b[i]));
  ck_assert_msg(scale > 0.0, "%s: the twin's values are all zero", what);
  ck_assert_msg(err <= tol * scale, "%s: max |library - twin| = %.3e of %.3e",
                what, err, scale);
}

/* The right-hand side and the operator against the twin, for formulation
 * form in dimension dim. Tolerance 1e-11 of the largest value: ~50-term
 * sums in another order, W' by another formula (~1e-16 each) and, for
 * PVWF, an LU inverse against cofactors (condition numbers ~10 at the
 * corners); a wrong coefficient shows at O(1e-2) or more. */
static void twin_check(int form, int dim, int sweep,
                       const struct vsph_kernel_type *kt, double delta,
                       unsigned long seed) {
  struct vsph_particles *p = random_set(dim, seed);
  const size_t n = p->n;
  struct vsph_equations_props ep = {.rho0 = RHO0, .c0 = C0, .delta = delta};
  ck_assert_int_eq(
      vsph_viscous_props_init(&ep.visc, form, kt, dim, HDX * DX, MU), 0);
  ep.visc.zeta = 0.731 * MU; /* Espanol-Revenga's b != 0 in 2-D too */
  /* the twin first, on the input order */
  double *tb = calloc(9 * n, sizeof *tb);
  struct twin tw = {column(tb, n, 0),
                    {column(tb, n, 1), column(tb, n, 2), column(tb, n, 3)},
                    {column(tb, n, 4), column(tb, n, 5), column(tb, n, 6)},
                    column(tb, n, 7),
                    column(tb, n, 8)};
  twin_run(&ep.visc, p, ep.delta, &tw);
  /* the library, on the cell order; results mapped back by id */
  struct vsph_cells *cells = vsph_cells_alloc();
  ck_assert_int_eq(vsph_cells_build(cells, p, 3.0 * ep.visc.h), 0);
  struct vsph_viscous_ws *ws = vsph_viscous_ws_alloc(n, dim);
  double *lb = calloc(18 * n, sizeof *lb);
  struct vsph_equations_out out = {
      .drho = column(lb, n, 0),
      .acc = {column(lb, n, 1), column(lb, n, 2), column(lb, n, 3)},
      .acc_visc = {column(lb, n, 4), column(lb, n, 5), column(lb, n, 6)},
      .drho_delta = column(lb, n, 7),
      .sweep = sweep ? vsph_equations_sweep_alloc() : NULL};
  ck_assert_int_eq(vsph_equations_rhs(&ep, p, n, cells, ws, &out), 0);
  vsph_equations_sweep_free(out.sweep);
  double *const f[3] = {column(lb, n, 8), column(lb, n, 9), column(lb, n, 10)};
  double *dens = column(lb, n, 11);
  ck_assert_int_eq(vsph_viscous_compute(&ep.visc, p, cells, ws, f, dens), 0);
  double *by_id = column(lb, n, 12); /* 6 columns: scratch by id */
  const double *lib[5] = {out.drho, out.drho_delta, dens, NULL, NULL};
  const double *twn[5] = {tw.drho, tw.ddelta, tw.dens, NULL, NULL};
  const char *what[5] = {"continuity + delta", "delta-SPH", "dissipation", NULL,
                         NULL};
  for (int q = 0; q < 3; q++) {
    for (size_t i = 0; i < n; i++) by_id[p->id[i]] = lib[q][i];
    if (q == 1 && delta == 0.0) /* none: exactly none */
      for (size_t i = 0; i < n; i++) ck_assert(by_id[i] == 0.0);
    else
      assert_close(by_id, twn[q], n, 1e-11, what[q]);
  }
  for (int k = 0; k < dim; k++) {
    for (size_t i = 0; i < n; i++) by_id[p->id[i]] = out.acc[k][i];
    assert_close(by_id, tw.acc[k], n, 1e-11, "acceleration");
    for (size_t i = 0; i < n; i++)
      by_id[p->id[i]] = out.acc_visc[k][i] * p->rho[i];
    assert_close(by_id, tw.visc[k], n, 1e-11, "solver's viscous term");
    for (size_t i = 0; i < n; i++) by_id[p->id[i]] = f[k][i];
    assert_close(by_id, tw.visc[k], n, 1e-11, "operator");
  }
  free(lb);
  free(tb);
  vsph_viscous_ws_free(ws);
  vsph_cells_free(cells);
  vsph_particles_free(p);
}

/* The caller's VSPH_PAIR_SIMD, a copy (NULL where unset), before a test
 * sets its own; simd_env_put_back puts it back (unset where it was) and
 * frees the copy. */
static char *simd_env_keep(void) {
  const char *was = getenv("VSPH_PAIR_SIMD");
  return was ? strdup(was) : NULL;
}

static void simd_env_put_back(char *keep) {
  if (keep)
    setenv("VSPH_PAIR_SIMD", keep, 1);
  else
    unsetenv("VSPH_PAIR_SIMD");
  free(keep);
}

/* Whether the right-hand side of @p form in @p dim (the parts on or off,
 * the symmetric sweep or the gather) with the 3h Gaussian
 * takes the Brookshaw forms' sweep by cell groups (solver/sweep_x86.c)
 * at SIMD level @p level (1 AVX2, 2 AVX-512) in this build on this CPU:
 * MGF, Violeau & Issa's or Cleary's form in 2-D by the sweep, with
 * delta-SPH or without, without the parts. Its rates are within rounding
 * of the four-lane loops', not their bits: fused multiply-adds, another
 * exponential (within 1e-15 of libm, test_expneg_within_1e15_of_exp), and
 * i's sums and j's (over a group of receivers) in eight lanes or four.
 * SIMD_ROUNDING bounds the difference as a fraction of a rate's largest entry:
 * each entry is a sum of some 50 shares, each within a few units of rounding
 * (2.2e-16) of the other loops' (about 1e-15 relative), summed in another
 * order, and where shares cancel the difference grows with the shares against
 * their sum: the largest found is 7.1e-14 of the wave's largest horizontal
 * force (1.2e-13 in make asan's -O1 build), whose pressure shares, of the size
 * of the hydrostatic gradient, cancel to a horizontal force a sixth of
 * the largest vertical one (test_sweep_scatter_simd; 3.0e-15 at most
 * elsewhere); 1e-12 leaves a factor 8, and a wrong term or factor moves
 * a rate by 1e-9 of it or more (a referee's mutant of F by 1 + 1e-9
 * fails). */
#define SIMD_ROUNDING 1e-12
/* The first pass's A = T L by the groups' kernels against the portable
 * loops', as a fraction of each entry's largest, and the kernels' B and
 * Mg against a sum pair by pair with libm's exp: no cancellation of the
 * hydrostatic kind, the largest found 1.2e-15 (A, the scatter test's
 * square and wave) and 8e-16 (test_grad_block_by_hand); 1e-14 leaves a
 * factor 8, and a kernel factor off by 1e-13 fails. */
#define GRAD_ROUNDING 1e-14
static int groups_lanes_at(int level, int form, int dim, int parts, int sweep) {
  return VSPH_SWEEP_X86_GROUPS && level >= 1 && vsph_pair_x86_simd() >= level &&
         dim == 2 && !parts && sweep &&
         (form == VSPH_VISCOUS_MGF || form == VSPH_VISCOUS_VI ||
          form == VSPH_VISCOUS_CLEARY || form == VSPH_VISCOUS_MEAF ||
          form == VSPH_VISCOUS_PVWF || form == VSPH_VISCOUS_TWOPASS);
}

/* Whether PVWF's or B's first pass (the gradient sweep) takes its sweep
 * by cell groups (vsph_sweep_x86_grad2_avx512, _avx2) at SIMD level
 * @p level in this build on this CPU: PVWF or B in 2-D by the sweep, with
 * the parts or without (the parts are the second pass's). Its sums, and
 * so A = T L and every rate after it, are within rounding of the loops',
 * not their bits, as groups_lanes_at says. */
static int grad_lanes_at(int level, int form, int dim, int sweep) {
  return VSPH_SWEEP_X86_GROUPS && level >= 1 && vsph_pair_x86_simd() >= level &&
         dim == 2 && sweep &&
         (form == VSPH_VISCOUS_PVWF || form == VSPH_VISCOUS_TWOPASS);
}

/* The same at the level the CPU allows (what a run takes) */
static int groups_lanes(int form, int dim, int parts, int sweep) {
  return groups_lanes_at(vsph_pair_x86_simd(), form, dim, parts, sweep);
}

/* The levels of the groups' sweep (1 AVX2, 2 AVX-512) that this build and
 * CPU have, by VSPH_PAIR_SIMD's names, into @p names; how many (0 to 2) */
static int groups_levels(const char *names[2]) {
  int k = 0;
  if (groups_lanes_at(1, VSPH_VISCOUS_MGF, 2, 0, 1)) names[k++] = "avx2";
  if (groups_lanes_at(2, VSPH_VISCOUS_MGF, 2, 0, 1)) names[k++] = "avx512";
  return k;
}

/* |r_j - r_i|^2 of particles @p i and @p j of set @p p, summed as the
 * loops sum it (component by component, from 0). */
static double pair_s2(const struct vsph_particles *p, size_t i, size_t j) {
  double s2 = 0.0;
  for (int a = 0; a < p->dim; a++) {
    const double x = p->pos[a][j] - p->pos[a][i];
    s2 += x * x;
  }
  return s2;
}

/* The interactions of set @p p (ids < @p nfl fluid) at smoothing length
 * @p h with the 3h Gaussian, pair by pair: each fluid receiver of a pair
 * within the support once (exact; the loops' support radius and s^2 in
 * their order). */
static size_t pair_count(const struct vsph_particles *p, size_t nfl, double h) {
  const double kap = vsph_gaussian_type.kappa, H2 = kap * h * kap * h;
  size_t count = 0;
  for (size_t i = 0; i < p->n; i++)
    for (size_t j = i + 1; j < p->n; j++) {
      const double s2 = pair_s2(p, i, j);
      if (s2 < H2) count += (p->id[i] < nfl) + (p->id[j] < nfl);
    }
  return count;
}

/* The least s^2 of a pair of set @p p within the support of the 3h
 * Gaussian at @p h of which one particle at least is fluid (id < @p nfl),
 * pair by pair (exact: the loops' s^2 in their order). */
static double pair_closest(const struct vsph_particles *p, size_t nfl,
                           double h) {
  const double kap = vsph_gaussian_type.kappa, H2 = kap * h * kap * h;
  double least = INFINITY;
  for (size_t i = 0; i < p->n; i++)
    for (size_t j = i + 1; j < p->n; j++) {
      const double s2 = pair_s2(p, i, j);
      if (s2 < H2 && (p->id[i] < nfl || p->id[j] < nfl) && s2 < least)
        least = s2;
    }
  return least;
}

/* A random set of dimension @p dim (ball of @p radius cut at @p depth),
 * its ids shuffled so that fluid and others mix. */
static struct vsph_particles *mixed_set(int dim, unsigned long seed,
                                        double radius, double depth) {
  struct vsph_particles *p = random_set_in(dim, seed, radius, depth);
  gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937);
  gsl_rng_set(rng, seed + 1);
  gsl_ran_shuffle(rng, p->id, p->n, sizeof *p->id);
  gsl_rng_free(rng);
  return p;
}

/* The right-hand side of the fluid particles alone (id < n_fluid): the
 * other particles' entries of every rate are left as they were (an
 * evolving wall's density rate is set before it and read after), and a
 * fluid particle's rates are those it has when every particle is fluid,
 * to the bit (the others are its neighbours all the same, summed in the
 * same order), and those the general finish gives it from the same sums
 * (finish_one, which the parts take: the same sums in the same order, so
 * the same bits; without the parts, 2-D sweeps finish by finish_rows2;
 * except where the sums without the parts come from the Brookshaw forms'
 * groups' sweep, groups_lanes, and the parts' from the loops it
 * replaces: then within SIMD_ROUNDING);
 * the state law's p and V every particle's, as vsph_equations_pressure
 * and m/rho make them, to the bit; and the interactions those a count
 * pair by pair gives, with half the set fluid and with one particle not
 * (the last id, at the fluid's bound). Case _i: the form (MGF, MEAF, PVWF),
 * the dimension, the sweep or the gather, delta-SPH, the parts, and the
 * body force (none, gravity, uniform) in turn. */
START_TEST(test_rhs_leaves_others) {
  static const int forms[] = {VSPH_VISCOUS_MGF, VSPH_VISCOUS_MEAF,
                              VSPH_VISCOUS_PVWF};
  static const int bodies[] = {VSPH_EQUATIONS_BODY_NONE,
                               VSPH_EQUATIONS_BODY_GRAVITY,
                               VSPH_EQUATIONS_BODY_UNIFORM};
  const int form = forms[_i % 3], dim = 2 + _i / 3 % 2, sweep = _i / 6 % 2,
            delta = _i / 12 % 2, parts = _i / 24 % 2;
  /* the ids (labels) shuffled, so that the others lie among the fluid as
   * ghosts do */
  struct vsph_particles *p =
      mixed_set(dim, 777 + (unsigned long)_i, dim == 2 ? 0.5 : 0.25, 0.11);
  const size_t n = p->n, nfl = n / 2;
  struct vsph_equations_props ep = {.rho0 = RHO0,
                                    .c0 = C0,
                                    .delta = delta ? DELTA : 0.0,
                                    .body = bodies[(_i + _i / 3) % 3],
                                    .g = 9.81,
                                    .f = 0.37};
  ck_assert_int_eq(vsph_viscous_props_init(&ep.visc, form, &vsph_gaussian_type,
                                           dim, HDX * DX, MU),
                   0);
  struct vsph_cells *cells = vsph_cells_alloc();
  ck_assert_int_eq(vsph_cells_build(cells, p, 3.0 * ep.visc.h), 0);
  struct vsph_viscous_ws *ws = vsph_viscous_ws_alloc(n, dim);
  const double mark = -7.25; /* no rate of this set takes it */
  double *buf[4];
  /* r 0: half the set fluid; 1: all; 2: half, with the parts; 3: all but
   * the particle of id n - 1 */
  const size_t nfl_r[4] = {nfl, n, nfl, n - 1};
  for (int r = 0; r < 4; r++) {
    buf[r] = malloc(8 * n * sizeof *buf[r]);
    ck_assert_ptr_nonnull(buf[r]);
    for (size_t k = 0; k < 8 * n; k++) buf[r][k] = mark;
    struct vsph_equations_out out = {
        .drho = column(buf[r], n, 0),
        .acc = {column(buf[r], n, 1), column(buf[r], n, 2),
                column(buf[r], n, 3)},
        .sweep = sweep ? vsph_equations_sweep_alloc() : NULL};
    if (parts || r == 2) {
      for (int a = 0; a < 3; a++) out.acc_visc[a] = column(buf[r], n, 4 + a);
      out.drho_delta = column(buf[r], n, 7);
    }
    ck_assert_int_eq(vsph_equations_rhs(&ep, p, nfl_r[r], cells, ws, &out), 0);
    vsph_equations_sweep_free(out.sweep);
    /* the interactions, each fluid receiver of a pair within the support
     * once, counted pair by pair here: exact */
    ck_assert_uint_eq(out.interactions, pair_count(p, nfl_r[r], ep.visc.h));
  }
  /* without the parts, the groups' sweep of a Brookshaw form in 2-D
   * where this build and CPU have it: the general finish's rates within
   * rounding of its (SIMD_ROUNDING of each rate's largest) */
  const int lanes = groups_lanes(form, dim, parts, sweep);
  double big[4] = {0, 0, 0, 0};
  for (int c = 0; c < 1 + dim; c++)
    for (size_t i = 0; i < n; i++)
      if (p->id[i] < nfl)
        big[c] = fmax(big[c], fabs(buf[2][(size_t)c * n + i]));
  size_t turns = 0; /* fluid and others alternating in index order */
  for (size_t i = 0; i < n; i++) {
    ck_assert(p->p[i] == vsph_equations_pressure(&ep, p->rho[i], 0.0));
    ck_assert(p->vol[i] == p->m[i] / p->rho[i]);
    const int fluid = p->id[i] < nfl;
    turns += i > 0 && fluid != (p->id[i - 1] < nfl);
    for (int c = 0; c < 8; c++) {
      const int rate =
          c < 1 + dim || (parts && c >= 4 && (c < 4 + dim || c == 7));
      const double v = buf[0][(size_t)c * n + i];
      if (!fluid || !rate) { /* an entry of no rate, or of another particle */
        ck_assert_msg(v == mark,
                      "case %d: entry %d of particle %zu (id %zu, "
                      "not fluid) set to %g",
                      _i, c, i, p->id[i], v);
        continue;
      }
      const double all = buf[1][(size_t)c * n + i],
                   general = buf[2][(size_t)c * n + i];
      ck_assert_msg(v != mark && v == all,
                    "case %d: entry %d of fluid particle %zu: %.17g with "
                    "half the set fluid, %.17g with all",
                    _i, c, i, v, all);
      if (c < 1 + dim)
        ck_assert_msg(
            lanes ? fabs(v - general) <= SIMD_ROUNDING * big[c] : v == general,
            "case %d: rate %d of fluid particle %zu: %.17g, by the "
            "general finish %.17g",
            _i, c, i, v, general);
    }
  }
  /* the loops meet both kinds within a strip of 64, and often */
  ck_assert_uint_gt(turns, n / 4);
  for (int r = 0; r < 4; r++) free(buf[r]);
  vsph_viscous_ws_free(ws);
  vsph_cells_free(cells);
  vsph_particles_free(p);
}
END_TEST

/* The interactions of set @p p (ids < @p nfl fluid) by the sweep, through
 * workspace @p sw, into got[0], and by a count pair by pair into got[1]
 * (each fluid receiver of a pair within the support once: exact; the
 * loops' support radius and s^2 in their order). No assertion (it may run
 * on any thread of a region): 0, or -1 where it could not evaluate. */
static int interactions_of(struct vsph_particles *p, size_t nfl,
                           struct vsph_equations_sweep *sw, size_t got[2]) {
  const int dim = p->dim;
  const size_t n = p->n;
  struct vsph_equations_props ep = {.rho0 = RHO0, .c0 = C0};
  if (vsph_viscous_props_init(&ep.visc, VSPH_VISCOUS_MGF, &vsph_gaussian_type,
                              dim, HDX * DX, MU))
    return -1;
  struct vsph_cells *cells = vsph_cells_alloc();
  struct vsph_viscous_ws *ws = vsph_viscous_ws_alloc(n, dim);
  double *buf = malloc(4 * n * sizeof *buf);
  struct vsph_equations_out out = {
      .drho = buf, .acc = {buf + n, buf + 2 * n, buf + 3 * n}, .sweep = sw};
  const int st = !cells || !ws || !buf ||
                 vsph_cells_build(cells, p, 3.0 * ep.visc.h) ||
                 vsph_equations_rhs(&ep, p, nfl, cells, ws, &out);
  free(buf);
  vsph_viscous_ws_free(ws);
  vsph_cells_free(cells);
  if (st) return -1;
  got[0] = out.interactions;
  got[1] = pair_count(p, nfl, ep.visc.h);
  return 0;
}

static void interactions_check(struct vsph_particles *p, size_t nfl,
                               struct vsph_equations_sweep *sw,
                               const char *what) {
  size_t got[2];
  ck_assert_int_eq(interactions_of(p, nfl, sw, got), 0);
  ck_assert_msg(got[0] == got[1],
                "%s, %zu of %zu fluid: %zu interactions, %zu counted", what,
                nfl, p->n, got[0], got[1]);
}

/* The interactions the sweep counts (interactions_check): a 3-D set eight
 * cells deep (the window along z clipped and whole) and a 2-D set of about
 * 5 000 particles (past VSPH_CELLS_PARALLEL: the flags of the cells whose
 * ranges hold no ghost made by the threads together), on 1 and 2 threads,
 * with half the set fluid, a fiftieth not (cells near one and near none
 * side by side) and all but the last id; one workspace throughout, its
 * flags grown from the small set to the large. */
START_TEST(test_interactions_many) {
  struct vsph_particles *set[2] = {mixed_set(3, 4142, 0.4, 0.4),
                                   mixed_set(2, 4242, 2.0, 2.0)};
  ck_assert_uint_gt(set[1]->n, 4096);
  struct vsph_equations_sweep *sw = vsph_equations_sweep_alloc();
  const int threads = omp_get_max_threads();
  for (int q = 0; q < 2; q++) {
    const size_t n = set[q]->n, nfl[3] = {n / 2, n - n / 50, n - 1};
    for (int r = 0; r < 3; r++)
      for (int t = 1; t <= 2; t++) {
        omp_set_num_threads(t);
        interactions_check(set[q], nfl[r], sw, q ? "2-D" : "3-D");
      }
    vsph_particles_free(set[q]);
  }
  omp_set_num_threads(threads);
  /* the bytes the workspace says it holds (vsph_equations_sweep_bytes)
   * against what the allocator holds for its four blocks
   * (malloc_usable_size: at least each block's size, at most a page and
   * a chunk's header more, 4096 + 16 B); its rows for two threads are
   * larger than that slack (24 KiB and more here) */
  void *const blk[4] = {sw->off, sw->buf, sw->rows, sw->flags};
  size_t held = sizeof *sw;
  for (int k = 0; k < 4; k++) held += blk[k] ? malloc_usable_size(blk[k]) : 0;
  const size_t said = vsph_equations_sweep_bytes(sw);
  ck_assert_uint_gt(sw->cap_rows * sizeof(double), 4 * (4096 + 16));
  ck_assert_uint_le(said, held);
  ck_assert_uint_ge(said + 4 * (4096 + 16), held);
  vsph_equations_sweep_free(sw);
}
END_TEST

/* The same inside a parallel region, one set per thread of two, each
 * evaluated on its own thread (a report's lanes: runs side by side in one
 * process): what each evaluates stays its own (no loop of it may be
 * shared with, or wait on, the other lane). */
START_TEST(test_interactions_in_lanes) {
  struct vsph_particles *set[2] = {mixed_set(2, 4342, 0.5, 0.5),
                                   mixed_set(2, 4343, 0.5, 0.5)};
  size_t got[2][2] = {{0, 1}, {0, 1}};
  int st[2] = {-1, -1}, lanes = 0;
#pragma omp parallel num_threads(2)
  {
#pragma omp single nowait
    lanes = omp_get_num_threads();
    omp_set_num_threads(1); /* as a report's lane: its loops on itself */
    const int t = omp_get_thread_num();
    struct vsph_equations_sweep *sw = vsph_equations_sweep_alloc();
    st[t] = sw ? interactions_of(set[t], set[t]->n - set[t]->n / 50, sw, got[t])
               : -1;
    vsph_equations_sweep_free(sw);
  }
  ck_assert_int_eq(lanes, 2);
  for (int t = 0; t < 2; t++) {
    ck_assert_int_eq(st[t], 0);
    ck_assert_msg(got[t][0] == got[t][1],
                  "lane %d: %zu interactions, %zu counted", t, got[t][0],
                  got[t][1]);
    vsph_particles_free(set[t]);
  }
}
END_TEST

START_TEST(test_rhs_matches_brute_force_twin) {
  /* the second half: the right-hand side through the symmetric sweep */
  const int sweep = _i >= 2 * VSPH_VISCOUS_FORM_COUNT;
  twin_check(_i % (2 * VSPH_VISCOUS_FORM_COUNT) / 2, 2 + _i % 2, sweep,
             &vsph_gaussian_type, DELTA, 2385 + (unsigned long)_i);
}
END_TEST

/* The same with the cubic B-spline (Basa's channels: loops of their own),
 * for the forms whose twin takes any kernel (model A's and the VISC
 * forms' twins are written for the Gaussian), without delta-SPH as those
 * runs are. */
START_TEST(test_twin_cubic) {
  static const int forms[] = {VSPH_VISCOUS_MGF,    VSPH_VISCOUS_MEAF,
                              VSPH_VISCOUS_PVWF,   VSPH_VISCOUS_VI,
                              VSPH_VISCOUS_CLEARY, VSPH_VISCOUS_TWOPASS,
                              VSPH_VISCOUS_ER};
  twin_check(forms[_i / 2], 2 + _i % 2, 0, &vsph_cubic_type, 0.0,
             4711 + (unsigned long)_i);
}
END_TEST

/* ------------------------------------------- solver against the operator */

/* Scene @p type at @p res across, formulation @p form, delta-SPH
 * @p delta (< 0: the scene's), kernel @p k at h/dx @p hdx, the
 * transport-velocity scheme when @p tvf (its background pressure
 * rho0 c0^2, as vsph run's), after three steps and a diagnostics row
 * (which builds the cells for the particles as they are): the set-up of
 * the tests that compare two loops on the same particles. Its props go
 * to @p ip. */
static struct vsph_integrate *scene_stepped_k(
    const struct vsph_scene_type *type, int form, size_t res, double delta,
    const struct vsph_kernel_type *k, double hdx, int tvf,
    struct vsph_integrate_props *ip) {
  struct vsph_scene sc;
  ck_assert_int_eq(vsph_scene_init(&sc, type, NULL), 0);
  struct vsph_particles *fluid = NULL;
  ck_assert_int_eq(sc.type->init(&sc, res, &fluid), 0);
  ck_assert_int_eq(vsph_scene_integrate_props(
                       &sc, form, k, hdx * sc.ref_length / (double)res, ip),
                   0);
  ip->cfl = 1.0;
  ip->rho_band = 0.2;
  if (delta >= 0.0) ip->eq.delta = delta;
  if (tvf) {
    ip->eq.tvf = 1;
    ip->eq.pb = ip->eq.rho0 * ip->eq.c0 * ip->eq.c0;
    ck_assert_int_eq(vsph_particles_tvf_alloc(fluid), 0);
  }
  struct vsph_integrate *s = vsph_integrate_alloc(ip, fluid);
  ck_assert_ptr_nonnull(s);
  for (int step = 0; step < 3; step++)
    ck_assert_int_eq(vsph_integrate_step(s, vsph_integrate_dt(s)), 0);
  struct vsph_equations_energy en;
  struct vsph_equations_budget b;
  ck_assert_int_eq(vsph_integrate_diagnostics(s, &en, &b), 0); /* cells */
  return s;
}

/* The same with the 3h Gaussian at h/dx 4/3, no transport velocity. */
static struct vsph_integrate *scene_stepped(const struct vsph_scene_type *type,
                                            int form, size_t res, double delta,
                                            struct vsph_integrate_props *ip) {
  return scene_stepped_k(type, form, res, delta, &vsph_gaussian_type, HDX, 0,
                         ip);
}

/* Scene sc_i, formulation form at 16 across (channels 32) after three steps
 * (ghosts generated for the wave): the right-hand side's viscous part times rho
 * equals vsph_viscous_compute on the same particles and cells to 1e-14
 * of the largest value (the same pair function in the same neighbour
 * order: only the division and multiplication by rho_i round). */
START_TEST(test_solver_equals_operator) {
  const int form = _i % VSPH_VISCOUS_FORM_COUNT;
  const int sc_i = _i / VSPH_VISCOUS_FORM_COUNT;
  struct vsph_scene sc;
  ck_assert_int_eq(vsph_scene_init(&sc, vsph_scene_get((size_t)sc_i), NULL), 0);
  ck_assert_int_eq(sc.dim, 2); /* the loop leaves out the contact scenes */
  /* a periodic channel (Couette: W/2 long) needs its period beyond PVWF's
   * two supports: 32 across there */
  const size_t res = vsph_walls_period(&sc.walls, 0) > 0.0 ? 32 : 16;
  struct vsph_integrate_props ip;
  struct vsph_integrate *s = scene_stepped(sc.type, form, res, -1.0, &ip);
  struct vsph_particles *p = s->p;
  const size_t n = p->n;
  double *buf = calloc(7 * n, sizeof *buf);
  struct vsph_equations_out out = {.drho = buf,
                                   .acc = {buf + n, buf + 2 * n},
                                   .acc_visc = {buf + 3 * n, buf + 4 * n},
                                   .drho_delta = buf + 5 * n};
  ck_assert_int_eq(
      vsph_equations_rhs(&ip.eq, p, s->n_fluid, s->cells, s->vws, &out), 0);
  struct vsph_viscous_ws *ws = vsph_viscous_ws_alloc(n, 2);
  double *f[3] = {p->acc[0], p->acc[1], NULL}; /* scratch */
  ck_assert_int_eq(vsph_viscous_compute(&ip.eq.visc, p, s->cells, ws, f, NULL),
                   0);
  double scale = 0.0, err = 0.0;
  for (size_t i = 0; i < n; i++)
    for (int k = 0; k < 2 && p->id[i] < s->n_fluid; k++)
      scale = fmax(scale, fabs(f[k][i]));
  for (size_t i = 0; i < n; i++)
    for (int k = 0; k < 2 && p->id[i] < s->n_fluid; k++)
      err = fmax(err, fabs(out.acc_visc[k][i] * p->rho[i] - f[k][i]));
  ck_assert_msg(scale > 0.0, "no viscous force");
  ck_assert_msg(err <= 1e-14 * scale,
                "%s %s: |solver - operator| = %.3e of %.3e", sc.type->name,
                vsph_viscous_name(form), err, scale);
  free(buf);
  vsph_viscous_ws_free(ws);
  vsph_integrate_free(s);
}
END_TEST

/* ------------------------------------------------- the symmetric sweep */

/* The right-hand side of s's particles with all its parts, through the
 * sweep sw (NULL: the gather) on thr threads, into buf (6 n doubles). */
static struct vsph_equations_out sweep_rhs(struct vsph_integrate *s,
                                           struct vsph_equations_sweep *sw,
                                           int thr, double *buf) {
  const size_t n = s->p->n;
  struct vsph_equations_out out = {.drho = buf,
                                   .acc = {buf + n, buf + 2 * n},
                                   .acc_visc = {buf + 3 * n, buf + 4 * n},
                                   .drho_delta = buf + 5 * n,
                                   .sweep = sw};
  omp_set_num_threads(thr);
  ck_assert_int_eq(vsph_equations_rhs(&s->props.eq, s->p, s->n_fluid, s->cells,
                                      s->vws, &out),
                   0);
  omp_set_num_threads(2);
  return out;
}

/* What two loops on the same particles must share: @p buf's second
 * block (s1, one thread) and third (s2, two threads) hold the same bits;
 * they have the reference's (first block, g) interactions and closest
 * pair; every field equals the reference's to 1e-12 of the size of its
 * terms over the fluid particles (rho0 |u|/h for the continuity sum,
 * (|p| + pb with the transport velocity)/(rho0 h) + mu |u|/(rho0 h^2)
 * for the acceleration, mu |u|/(rho0 h^2) for its viscous part: where a
 * sum cancels, its terms set the scale). @p label names the pair. */
static void assert_loops_agree(const struct vsph_integrate *s,
                               const struct vsph_integrate_props *ip,
                               const double *buf,
                               const struct vsph_equations_out *g,
                               const struct vsph_equations_out *s1,
                               const struct vsph_equations_out *s2,
                               const char *label) {
  const size_t n = s->p->n;
  ck_assert_msg(memcmp(buf + 6 * n, buf + 12 * n, 6 * n * sizeof *buf) == 0,
                "%s: 1 and 2 threads differ", label);
  ck_assert_uint_eq(s1->interactions, g->interactions);
  ck_assert_uint_eq(s2->interactions, g->interactions);
  ck_assert(s1->min_s2 == g->min_s2);
  ck_assert(g->interactions > 0);
  const char *what[6] = {"drho",       "acc x",      "acc y",
                         "acc_visc x", "acc_visc y", "drho_delta"};
  double umax = 0.0, pmax = 0.0;
  for (size_t i = 0; i < n; i++)
    if (s->p->id[i] < s->n_fluid) {
      umax = fmax(umax, hypot(s->p->vel[0][i], s->p->vel[1][i]));
      pmax = fmax(pmax, fabs(s->p->p[i]));
    }
  const double h = ip->eq.visc.h, rho0 = ip->eq.rho0;
  const double visc = ip->eq.visc.mu * umax / (rho0 * h * h);
  const double pterm = (pmax + ip->eq.pb * ip->eq.tvf) / (rho0 * h) + visc;
  const double terms[6] = {rho0 * umax / h, pterm, pterm, visc, visc, 0.0};
  for (int q = 0; q < 6; q++) {
    const double *a = buf + (size_t)q * n, *b = buf + (size_t)(6 + q) * n;
    double scale = terms[q], err = 0.0;
    for (size_t i = 0; i < n; i++) {
      if (s->p->id[i] >= s->n_fluid) continue;
      scale = fmax(scale, fabs(a[i]));
      err = fmax(err, fabs(a[i] - b[i]));
    }
    ck_assert_msg(err <= 1e-12 * scale, "%s, %s: differ by %.3e of %.3e", label,
                  what[q], err, scale);
  }
}

/* The specialised loop on 1 and 2 threads against the general loop
 * (Solver's loop_general) on the same particles, held by
 * assert_loops_agree under @p label; returns the buffer (18 n doubles:
 * general, 1 thread, 2 threads; the caller frees it). */
static double *loops_agree(struct vsph_integrate *s,
                           const struct vsph_integrate_props *ip,
                           const char *label) {
  const size_t n = s->p->n;
  double *buf = calloc(18 * n, sizeof *buf);
  const struct vsph_equations_out s1 = sweep_rhs(s, NULL, 1, buf + 6 * n),
                                  s2 = sweep_rhs(s, NULL, 2, buf + 12 * n);
  s->props.eq.loop_general = 1;
  const struct vsph_equations_out g = sweep_rhs(s, NULL, 1, buf);
  s->props.eq.loop_general = 0;
  assert_loops_agree(s, ip, buf, &g, &s1, &s2, label);
  return buf;
}

/* Scene sc_i (ghost walls where it has walls), at 16 across (channels
 * 32), formulation form, delta-SPH 0.1, after three steps: the sweep on 1
 * and 2 threads gives the same bits; interactions and the closest pair
 * equal the gather's exactly (the same pairs, classified by the same s^2:
 * (x_j - x_i)^2 = (x_i - x_j)^2 in floating point); every field equals
 * the gather's to 1e-12 of its largest fluid value (sums of ~50 terms in
 * another order: the pressure terms cancel to ~1e-3 of their size, so
 * rounding shows at ~1e-13; a share with a wrong sign or volume shows at
 * O(1)). Where a sum cancels (the steady channels: d rho/dt and the
 * transverse acceleration ~1e-9 of their terms) the scale is the size of
 * the terms: rho0 |u|/h for the continuity sum, |p|/(rho0 h) + mu |u|/
 * (rho0 h^2) for the acceleration, mu |u|/(rho0 h^2) for its viscous
 * part. */
START_TEST(test_sweep_gather_threads) {
  static const int forms[] = {VSPH_VISCOUS_MGF, VSPH_VISCOUS_MEAF,
                              VSPH_VISCOUS_PVWF, VSPH_VISCOUS_ER,
                              VSPH_VISCOUS_CLEARY};
  const int nforms = (int)(sizeof forms / sizeof forms[0]);
  /* past the scenes' cases: the stretching square at 136 across (18 496
   * particles, 36 blocks, where the block size is not the smallest) */
  const int big = _i >= (int)vsph_scene_count() * nforms;
  const int form = forms[_i % nforms], sc_i = _i / nforms;
  struct vsph_scene sc;
  ck_assert_int_eq(vsph_scene_init(&sc,
                                   big ? &vsph_stretching_square_type
                                       : vsph_scene_get((size_t)sc_i),
                                   NULL),
                   0);
  const size_t res = big                                     ? 136
                     : vsph_walls_period(&sc.walls, 0) > 0.0 ? 32
                                                             : 16;
  struct vsph_integrate_props ip;
  struct vsph_integrate *s = scene_stepped(sc.type, form, res, 0.1, &ip);
  const size_t n = s->p->n;
  double *buf = calloc(18 * n, sizeof *buf);
  struct vsph_equations_sweep *sw = vsph_equations_sweep_alloc();
  const struct vsph_equations_out g = sweep_rhs(s, NULL, 1, buf),
                                  s1 = sweep_rhs(s, sw, 1, buf + 6 * n),
                                  s2 = sweep_rhs(s, sw, 2, buf + 12 * n);
  char label[96];
  snprintf(label, sizeof label, "%s %s, sweep against gather", sc.type->name,
           vsph_viscous_name(form));
  assert_loops_agree(s, &ip, buf, &g, &s1, &s2, label);
  vsph_equations_sweep_free(sw);
  free(buf);
  vsph_integrate_free(s);
}
END_TEST

/* The shear scene in 3-D (contact SPH's test box, 4e-7 m periods: the
 * default's 3e-8 is shorter than the Gaussian's reach at 8 across; 8
 * across), formulation @p form (or contact SPH where @p contact, its
 * viscosity the scene's), after three steps. */
static struct vsph_integrate *shear3_stepped(int form, int contact) {
  struct vsph_params *prm = vsph_params_alloc();
  ck_assert_ptr_nonnull(prm);
  ck_assert_int_eq(vsph_params_set(prm, "Scene:Ly", "4e-7"), 0);
  ck_assert_int_eq(vsph_params_set(prm, "Scene:Lz", "4e-7"), 0);
  struct vsph_scene sc;
  ck_assert_int_eq(vsph_scene_init(&sc, &vsph_shear_type, prm), 0);
  vsph_params_free(prm);
  struct vsph_particles *fluid = NULL;
  ck_assert_int_eq(sc.type->init(&sc, 8, &fluid), 0);
  struct vsph_integrate_props ip;
  ck_assert_int_eq(
      vsph_scene_integrate_props(&sc, form, &vsph_gaussian_type,
                                 VSPH_CONSTS_HDX * sc.ref_length / 8.0, &ip),
      0);
  if (contact) {
    ip.eq.scheme = VSPH_EQUATIONS_CONTACT;
    ip.eq.nmat = 1;
    ip.eq.mat[0] = (struct vsph_equations_mat){
        .rho0 = ip.eq.rho0, .c0 = ip.eq.c0, .mu = ip.eq.visc.mu};
  }
  struct vsph_integrate *s = vsph_integrate_alloc(&ip, fluid);
  ck_assert_ptr_nonnull(s);
  for (int step = 0; step < 3; step++)
    ck_assert_int_eq(vsph_integrate_step(s, vsph_integrate_dt(s)), 0);
  ck_assert_int_eq(s->p->dim, 3);
  return s;
}

/* shear3_stepped, every particle's velocity then given
 * U sin(2 pi y') cos(2 pi z') more along x and U sin(2 pi x') cos(2 pi y')
 * along z (U the largest speed component, x' = (x - x_lo)/(x_hi - x_lo)
 * over the fluid's extent), so that every component of the viscous force
 * is no rounding (an evaluation's state, not a flow: the identities
 * tested hold for any). */
static struct vsph_integrate *shear3(int form, int contact) {
  struct vsph_integrate *s = shear3_stepped(form, contact);
  double lo[3] = {INFINITY, INFINITY, INFINITY},
         hi[3] = {-INFINITY, -INFINITY, -INFINITY};
  double U = 0.0;
  for (size_t i = 0; i < s->n_fluid; i++)
    for (int a = 0; a < 3; a++) {
      lo[a] = fmin(lo[a], s->p->pos[a][i]);
      hi[a] = fmax(hi[a], s->p->pos[a][i]);
      U = fmax(U, fabs(s->p->vel[a][i]));
    }
  ck_assert(U > 0.0);
  for (size_t i = 0; i < s->p->n; i++) {
    double q[3];
    for (int a = 0; a < 3; a++)
      q[a] = 2.0 * M_PI * (s->p->pos[a][i] - lo[a]) / (hi[a] - lo[a]);
    s->p->vel[2][i] = U * sin(q[0]) * cos(q[1]);
    s->p->vel[0][i] += U * sin(q[1]) * cos(q[2]);
  }
  return s;
}

/* The symmetric sweep's adds of j's shares by AVX2
 * (solver/sweep_x86.c: three fields in 2-D, four with delta-SPH or in
 * 3-D, eight in PVWF's first pass) and the groups' sweeps of the
 * Brookshaw forms in 2-D (vsph_sweep_x86_groups2_avx512, _avx2)
 * against the scalar loops: the stretching square at 24 across after three
 * steps, MGF with and without delta-SPH, PVWF, Violeau & Issa's and Cleary's
 * forms (eta not 0), the standing wave with its ghosts (ghost receivers not
 * counted), and the 3-D shear box (shear3)
 * with MGF, each with and without the dissipative parts (2 d + 2 fields,
 * the scalar loop at every level), evaluated with the portable loops
 * (VSPH_PAIR_SIMD=portable) and at each level the CPU has: every output
 * the same bits (each entry gets the same adds in the same order; the
 * candidate test gives the same chunks at every level,
 * test_candidates_simd), except the groups' sweeps', within rounding
 * (SIMD_ROUNDING, groups_lanes_at), the closest pair and the count
 * exact. A level the CPU lacks is said and left out (its groups' sweep
 * is then not tested here; nor in a build without them,
 * VSPH_SWEEP_X86_GROUPS 0). */
START_TEST(test_sweep_scatter_simd) {
  static const struct {
    int form;
    double delta;
    int dim;
    const struct vsph_scene_type *scene;
  } cases[] = {{VSPH_VISCOUS_MGF, 0.0, 2, &vsph_stretching_square_type},
               {VSPH_VISCOUS_MGF, 0.1, 2, &vsph_stretching_square_type},
               {VSPH_VISCOUS_PVWF, 0.0, 2, &vsph_stretching_square_type},
               {VSPH_VISCOUS_MGF, 0.0, 3, NULL},
               {VSPH_VISCOUS_VI, 0.0, 2, &vsph_stretching_square_type},
               {VSPH_VISCOUS_CLEARY, 0.0, 2, &vsph_stretching_square_type},
               {VSPH_VISCOUS_MGF, 0.0, 2, &vsph_standing_wave_type},
               {VSPH_VISCOUS_MEAF, 0.0, 2, &vsph_stretching_square_type},
               {VSPH_VISCOUS_MEAF, 0.1, 2, &vsph_standing_wave_type},
               {VSPH_VISCOUS_PVWF, 0.1, 2, &vsph_standing_wave_type},
               {VSPH_VISCOUS_TWOPASS, 0.0, 2, &vsph_stretching_square_type}};
  const int c = _i / 2, parts = _i % 2, dim = cases[c].dim;
  struct vsph_integrate_props ip;
  struct vsph_integrate *s = dim == 3
                                 ? shear3(cases[c].form, 0)
                                 : scene_stepped(cases[c].scene, cases[c].form,
                                                 24, cases[c].delta, &ip);
  const size_t n = s->p->n;
  const int most = vsph_pair_x86_simd();
  if (most < 2)
    fprintf(stderr,
            "test_sweep_scatter_simd: this build or CPU (or VSPH_PAIR_SIMD) "
            "allows %s only\n",
            most ? "AVX2" : "the portable loop");
  const size_t nout = (size_t)(parts ? 2 * dim + 2 : dim + 1);
  double *buf = calloc(nout * n * 3, sizeof *buf);
  struct vsph_equations_sweep *sw = vsph_equations_sweep_alloc();
  char *keep = simd_env_keep();
  static const char *const names[] = {"portable", "avx2", "avx512"};
  int st[3] = {0, 0, 0};
  double closest[3] = {0, 0, 0};
  size_t pairs[3] = {0, 0, 0};
  /* PVWF's and B's first pass: A = T L (four entries in 2-D) at each
   * level, from the workspace */
  const int stress = cases[c].form == VSPH_VISCOUS_PVWF ||
                     cases[c].form == VSPH_VISCOUS_TWOPASS;
  double *A = stress ? calloc(4 * n * 3, sizeof *A) : NULL;
  ck_assert(!stress || A);
  for (int level = 0; level <= most; level++) {
    double *const o = buf + (size_t)level * nout * n;
    struct vsph_equations_out out = {.drho = o, .sweep = sw};
    for (int a = 0; a < dim; a++) {
      out.acc[a] = o + (size_t)(1 + a) * n;
      if (parts) out.acc_visc[a] = o + (size_t)(1 + dim + a) * n;
    }
    if (parts) out.drho_delta = o + (size_t)(1 + 2 * dim) * n;
    setenv("VSPH_PAIR_SIMD", names[level], 1);
    st[level] = vsph_equations_rhs(&s->props.eq, s->p, s->n_fluid, s->cells,
                                   s->vws, &out);
    closest[level] = out.min_s2;
    pairs[level] = out.interactions;
    for (int e = 0; stress && e < 4; e++)
      memcpy(A + ((size_t)level * 4 + (size_t)e) * n, s->vws->A[e],
             n * sizeof *A);
  }
  /* the caller's environment back before any assertion (a failed one
   * leaves this test at once, and the suite runs on in this process) */
  simd_env_put_back(keep);
  for (int level = 0; level <= most; level++) {
    /* the groups' sweep at this level (the Brookshaw forms, MEAF, PVWF
     * and B; not the parts, nor 3-D), or PVWF's and B's first pass by
     * groups (the parts too) */
    const int grad = grad_lanes_at(level, cases[c].form, dim, 1);
    const int lanes =
        groups_lanes_at(level, cases[c].form, dim, parts, 1) || grad;
    if (grad) { /* A within rounding, by the groups' kernel */
      const double *const a = A + (size_t)level * 4 * n;
      for (size_t f = 0; f < 4; f++) {
        double big = 0.0;
        for (size_t e = f * n; e < (f + 1) * n; e++)
          big = fmax(big, fabs(A[e]));
        for (size_t e = f * n; e < (f + 1) * n; e++)
          ck_assert_msg(fabs(a[e] - A[e]) <= GRAD_ROUNDING * big,
                        "%s, %s: A entry %zu of particle %zu is %.17g, "
                        "portable %.17g (largest %.3g)",
                        vsph_viscous_name(cases[c].form), names[level], f,
                        e - f * n, a[e], A[e], big);
      }
      ck_assert_msg(memcmp(a, A, 4 * n * sizeof *a) != 0,
                    "%s, %s: the first pass gave the portable loops' bits",
                    vsph_viscous_name(cases[c].form), names[level]);
    }
    ck_assert_int_eq(st[level], 0);
    ck_assert_double_eq(closest[level], closest[0]); /* the closest pair */
    ck_assert_uint_eq(pairs[level], pairs[0]);       /* ghosts' not counted */
    const double *const o = buf + (size_t)level * nout * n;
    if (lanes) { /* within rounding, as said above */
      for (size_t f = 0; f < nout; f++) {
        double big = 0.0;
        for (size_t e = f * n; e < (f + 1) * n; e++)
          big = fmax(big, fabs(buf[e]));
        for (size_t e = f * n; e < (f + 1) * n; e++)
          ck_assert_msg(fabs(o[e] - buf[e]) <= SIMD_ROUNDING * big,
                        "%s 2-D, %s: entry %zu is %.17g, portable %.17g "
                        "(largest %.3g)",
                        vsph_viscous_name(cases[c].form), names[level], e, o[e],
                        buf[e], big);
      }
      /* and by the groups' kernel, not the loops: those give the portable
       * loops' bits at every level (below), the kernel sums in its own
       * order, so some entries differ in their last bits */
      ck_assert_msg(memcmp(o, buf, nout * n * sizeof *o) != 0,
                    "%s 2-D, %s: the portable loops' bits, not the groups' "
                    "sweep's",
                    vsph_viscous_name(cases[c].form), names[level]);
      continue;
    }
    for (size_t e = 0; level && e < nout * n; e++)
      ck_assert_msg(memcmp(o + e, buf + e, sizeof *o) == 0,
                    "%s %d-D (delta %g, parts %d), %s: entry %zu is %.17g, "
                    "portable %.17g",
                    vsph_viscous_name(cases[c].form), dim, cases[c].delta,
                    parts, names[level], e, o[e], buf[e]);
  }
  /* each level its own kernel: the AVX2 and AVX-512 sweeps sum in four
   * lanes and in eight, so some of these sums differ in their last bits
   * (a dispatch that took one kernel at both levels would give the same
   * bits) */
  if ((groups_lanes_at(1, cases[c].form, dim, parts, 1) &&
       groups_lanes_at(2, cases[c].form, dim, parts, 1)) ||
      grad_lanes_at(2, cases[c].form, dim, 1))
    ck_assert_msg(
        memcmp(buf + nout * n, buf + 2 * nout * n, nout * n * sizeof *buf) != 0,
        "%s: the AVX2 and AVX-512 levels gave the same bits",
        vsph_viscous_name(cases[c].form));
  if (grad_lanes_at(2, cases[c].form, dim, 1)) /* and in the first pass */
    ck_assert_msg(memcmp(A + 4 * n, A + 8 * n, 4 * n * sizeof *A) != 0,
                  "%s: the AVX2 and AVX-512 first passes gave the same bits",
                  vsph_viscous_name(cases[c].form));
  free(A);
  vsph_equations_sweep_free(sw);
  free(buf);
  vsph_integrate_free(s);
}
END_TEST

/* One and two threads give the same bits through the sweep by cell
 * groups, as through every loop of the sweep: the standing wave (its
 * ghosts too) at 48 across, in four blocks or more (six or seven; asserted: the
 * second thread then sums some of them), two RK4 steps of form _i (MGF
 * with delta-SPH, MEAF, PVWF, B) after three at the caller's level,
 * evaluated at each SIMD level this build, CPU and VSPH_PAIR_SIMD allow
 * (portable, avx2, avx512), on a team of two (asserted): every fluid
 * particle's position, velocity and density on one thread and on two,
 * bit for bit. The blocks are planned from the particle count alone and
 * each writes its own buffer, summed in block order: the threads change
 * who sums a block, not what it sums. (test_threads_bitwise, in the
 * solver suite, takes every form at 16 across, one block for most, at
 * the CPU's level.) */
START_TEST(test_groups_threads_bitwise) {
  static const int forms[] = {VSPH_VISCOUS_MGF, VSPH_VISCOUS_MEAF,
                              VSPH_VISCOUS_PVWF, VSPH_VISCOUS_TWOPASS};
  const int form = forms[_i];
  const char *names[3] = {"portable"};
  const int nl = 1 + groups_levels(names + 1);
  /* the runs made first, at the caller's level and threads (the same
   * state for both, which the comparison below would show otherwise) */
  struct vsph_integrate *s[3][2];
  for (int l = 0; l < nl; l++)
    for (int t = 0; t < 2; t++) {
      struct vsph_integrate_props ip;
      s[l][t] = scene_stepped(&vsph_standing_wave_type, form, 48,
                              form == VSPH_VISCOUS_MGF ? 0.1 : -1.0, &ip);
    }
  const int threads = omp_get_max_threads();
  char *keep = simd_env_keep();
  int st[3][2] = {{0}}, team[3][2] = {{0}};
  /* then two steps each at its level on one thread or two, with no
   * assertion until the caller's environment and threads are back */
  for (int l = 0; l < nl; l++) {
    setenv("VSPH_PAIR_SIMD", names[l], 1);
    for (int t = 0; t < 2; t++) {
      omp_set_num_threads(t + 1);
#pragma omp parallel
      {
#pragma omp single
        team[l][t] = omp_get_num_threads();
      }
      for (int k = 0; k < 2 && !st[l][t]; k++)
        st[l][t] = vsph_integrate_step(s[l][t], vsph_integrate_dt(s[l][t]));
    }
  }
  simd_env_put_back(keep);
  omp_set_num_threads(threads);
  for (int l = 0; l < nl; l++) {
    double *state[2];
    const size_t nf = s[l][0]->n_fluid;
    for (int t = 0; t < 2; t++) {
      ck_assert_int_eq(st[l][t], 0);
      ck_assert_int_eq(team[l][t], t + 1); /* two threads did run */
      ck_assert_uint_eq(s[l][t]->n_fluid, nf);
      /* several blocks: the premise */
      ck_assert_uint_ge(s[l][t]->sweep->nblk, 4);
      const struct vsph_particles *p = s[l][t]->p;
      state[t] = malloc(5 * nf * sizeof *state[t]);
      ck_assert_ptr_nonnull(state[t]);
      for (size_t i = 0; i < p->n; i++) {
        const size_t id = p->id[i];
        if (id >= nf) continue;
        state[t][id] = p->pos[0][i];
        state[t][nf + id] = p->pos[1][i];
        state[t][2 * nf + id] = p->vel[0][i];
        state[t][3 * nf + id] = p->vel[1][i];
        state[t][4 * nf + id] = p->rho[i];
      }
    }
    ck_assert_msg(memcmp(state[0], state[1], 5 * nf * sizeof(double)) == 0,
                  "%s, %s: one thread and two differ", vsph_viscous_name(form),
                  names[l]);
    free(state[0]);
    free(state[1]);
    vsph_integrate_free(s[l][0]);
    vsph_integrate_free(s[l][1]);
  }
}
END_TEST

/* @p ep for form @p form with the 3h Gaussian in 2-D at smoothing length
 * @p h, delta-SPH's @p delta (0: off), the suite's rho0, c0 and mu. */
static void gauss2_props(struct vsph_equations_props *ep, int form, double h,
                         double delta) {
  *ep = (struct vsph_equations_props){.rho0 = RHO0, .c0 = C0, .delta = delta};
  ck_assert_int_eq(
      vsph_viscous_props_init(&ep->visc, form, &vsph_gaussian_type, 2, h, MU),
      0);
}

/* The right-hand side (@p ep's form) of set
 * @p p, ids < @p nfl fluid, in @p cells: by the sweep at SIMD level
 * @p level ("portable", "avx2", "avx512": VSPH_PAIR_SIMD, the caller's
 * value put back) or, @p level NULL, by the gather; its rates into
 * @p out3 (3 n: drho, then each acceleration), its closest pair into
 * *closest and its interactions returned (SIZE_MAX where it failed). */
static size_t rhs_at(const struct vsph_equations_props *ep,
                     struct vsph_particles *p, size_t nfl,
                     const struct vsph_cells *cells, struct vsph_viscous_ws *ws,
                     const char *level, double *out3, double *closest) {
  const size_t n = p->n;
  struct vsph_equations_out out = {
      .drho = out3,
      .acc = {out3 + n, out3 + 2 * n},
      .sweep = level ? vsph_equations_sweep_alloc() : NULL};
  char *keep = simd_env_keep();
  if (level) setenv("VSPH_PAIR_SIMD", level, 1);
  const int st = vsph_equations_rhs(ep, p, nfl, cells, ws, &out);
  simd_env_put_back(keep);
  vsph_equations_sweep_free(out.sweep);
  *closest = out.min_s2;
  return st ? SIZE_MAX : out.interactions;
}

/* The closest pair between the set's one particle not fluid (id n - 1)
 * and a fluid one, 1e-3 DX apart: case 0 with the one not fluid first in
 * the cells' order (moved below a fluid particle that comes after it: a
 * receiver all of whose pairs j > i are with fluid particles), case 1
 * second (moved above one that comes before it). Each loop (the sweep at each
 * SIMD level the CPU has, and the gather) gives the closest pair that a
 * search pair by pair gives, and the interactions of a count pair by
 * pair. Before, the sweep's four-lane and portable loops left such a
 * receiver's pairs out of the closest pair, whose distance stops a run
 * (Solver:min_gap). */
START_TEST(test_closest_ghost_receiver) {
  struct vsph_particles *p = random_set(2, 9191 + (unsigned long)_i);
  const size_t n = p->n, nfl = n - 1;
  struct vsph_equations_props ep;
  gauss2_props(&ep, VSPH_VISCOUS_MGF, HDX * DX, 0.0);
  struct vsph_cells *cells = vsph_cells_alloc();
  ck_assert_int_eq(vsph_cells_build(cells, p, 3.0 * ep.visc.h), 0);
  /* a fluid particle f that the other, moved below (above) it,
   * precedes (follows) */
  int placed = 0;
  for (size_t f = n / 3; f < n && !placed; f++) {
    size_t g = 0;
    while (p->id[g] != nfl) g++;
    if (p->id[f] == nfl) continue;
    const size_t idf = p->id[f];
    p->pos[0][g] = p->pos[0][f];
    p->pos[1][g] = p->pos[1][f] + (_i ? 1e-3 : -1e-3) * DX;
    ck_assert_int_eq(vsph_cells_build(cells, p, 3.0 * ep.visc.h), 0);
    size_t ig = 0, jf = 0;
    for (size_t i = 0; i < n; i++) {
      if (p->id[i] == nfl) ig = i;
      if (p->id[i] == idf) jf = i;
    }
    placed = _i ? ig > jf : ig < jf;
  }
  ck_assert(placed);
  struct vsph_viscous_ws *ws = vsph_viscous_ws_alloc(n, 2);
  double *buf = malloc(3 * n * sizeof *buf);
  ck_assert_ptr_nonnull(buf);
  const double want = pair_closest(p, nfl, ep.visc.h);
  const size_t count = pair_count(p, nfl, ep.visc.h);
  ck_assert_double_lt(want, 2e-6 * DX * DX); /* that pair */
  static const char *const names[] = {"portable", "avx2", "avx512", NULL};
  for (int l = 0; l < 4; l++) {
    if (l > 0 && l < 3 && vsph_pair_x86_simd() < l) continue;
    double closest;
    const size_t got = rhs_at(&ep, p, nfl, cells, ws, names[l], buf, &closest);
    ck_assert_msg(got == count && closest == want,
                  "%s: %zu interactions, closest %.17g; pair by pair %zu, "
                  "%.17g",
                  names[l] ? names[l] : "gather", got, closest, count, want);
  }
  free(buf);
  vsph_viscous_ws_free(ws);
  vsph_cells_free(cells);
  vsph_particles_free(p);
}
END_TEST

/* Pairs on the support's edge, through the sweep by the portable loops
 * and by the groups' sweep of the Brookshaw forms (MGF) and of PVWF at each
 * level this build and CPU have (AVX2, AVX-512). Cases 0-2: a particle and 240
 * others on a circle of radius kappa h around it (kappa h cos t, kappa h sin t
 * from its place, so that their s^2 lie within a few units of rounding of
 * (kappa h)^2, on either side or on it), the centre in three places, so that
 * the circle's rounding differs. Case 3: two particles 0.14628 apart along x at
 * h = 0.04876 (found by a search of h and of distances near 3h): s^2 below
 * (kappa h)^2, a pair, and q^2 = s^2 / h^2 rounded to 9, so F = 0. The same
 * pairs (the interactions those of a count pair by pair, each s^2 computed as
 * the loops compute it), the same closest pair, and the rates within rounding
 * (case 3: all 0); each case with MGF, then with PVWF, whose first pass's A (by
 * the groups' kernels of the gradient sweep) is within SIMD_ROUNDING of the
 * loops' too, and 0 where theirs is. Where the CPU or build lacks the
 * groups' sweep, said and left out. */
START_TEST(test_groups_support_edge) {
  const char *levels[2];
  const int nlev = groups_levels(levels);
  if (!nlev) {
    fprintf(stderr, "test_groups_support_edge: no groups' sweep here\n");
    return;
  }
  enum { RING = 240 };
  const size_t cap = RING + 1;
  struct vsph_particles *p = vsph_particles_alloc(cap, 2);
  ck_assert_ptr_nonnull(p);
  struct vsph_cells *cells = vsph_cells_alloc();
  struct vsph_viscous_ws *ws = vsph_viscous_ws_alloc(cap, 2);
  double *buf = malloc(10 * cap * sizeof *buf), *const Ap = buf + 6 * cap;
  ck_assert_ptr_nonnull(buf);
  for (int c = 0; c < 8; c++) {
    /* MGF, then PVWF, whose first pass has the same edge */
    const int pvwf = c >= 4;
    const double h = c % 4 < 3 ? HDX * DX : 0.04876;
    struct vsph_equations_props ep;
    gauss2_props(&ep, pvwf ? VSPH_VISCOUS_PVWF : VSPH_VISCOUS_MGF, h, 0.0);
    const double R = vsph_gaussian_type.kappa * h;
    const int cc = c % 4; /* the set's case */
    const double x0 = 0.3 + 0.0137 * cc, y0 = -0.2 + 0.0291 * cc;
    const size_t n = cc < 3 ? cap : 2;
    p->n = n;
    for (size_t i = 0; i < n; i++) {
      const double t = 2.0 * M_PI * (double)i / RING + 0.01 * cc;
      p->pos[0][i] = cc == 3 ? 0.14628 * (double)i : i ? x0 + R * cos(t) : x0;
      p->pos[1][i] = cc == 3 ? 0.0 : i ? y0 + R * sin(t) : y0;
      p->vel[0][i] = 0.1 * sin(3.0 * t);
      p->vel[1][i] = 0.1 * cos(2.0 * t);
      p->rho[i] = RHO0 * (1.0 + 0.01 * sin(5.0 * t));
      p->m[i] = RHO0 * DX * DX;
      p->vol[i] = p->m[i] / p->rho[i];
      p->id[i] = i;
    }
    if (cc == 3) { /* the premise: a pair, and q^2 rounded to 9 */
      const double s2 = 0.14628 * 0.14628;
      ck_assert(s2 < R * vsph_gaussian_type.kappa * h);
      ck_assert(s2 * (1.0 / (h * h)) >= 9.0);
    }
    ck_assert_int_eq(vsph_cells_build(cells, p, 3.0 * h), 0);
    double closest[2];
    const size_t a = rhs_at(&ep, p, n, cells, ws, "portable", buf, &closest[0]);
    ck_assert_uint_eq(a, pair_count(p, n, h));
    double bigA[4] = {0, 0, 0, 0}; /* PVWF: the first pass's A, portable */
    for (int e = 0; pvwf && e < 4; e++)
      for (size_t i = 0; i < n; i++) {
        Ap[(size_t)e * n + i] = ws->A[e][i];
        bigA[e] = fmax(bigA[e], fabs(ws->A[e][i]));
      }
    for (int l = 0; l < nlev; l++) {
      const size_t b =
          rhs_at(&ep, p, n, cells, ws, levels[l], buf + 3 * n, &closest[1]);
      ck_assert_uint_eq(b, a);
      ck_assert_double_eq(closest[1], closest[0]);
      /* A within rounding, and 0 where the loops give 0 (case 3: F = 0);
       * SIMD_ROUNDING, not GRAD_ROUNDING: the centre's sums over its ring
       * of 240 cancel (du (x) x around a circle), 2.2e-14 of the largest
       * found in make asan's -O1 build, whose loops round otherwise */
      for (int e = 0; pvwf && e < 4; e++)
        for (size_t i = 0; i < n; i++) {
          const double want = Ap[(size_t)e * n + i], got = ws->A[e][i];
          ck_assert_msg(want == 0.0
                            ? got == 0.0
                            : fabs(got - want) <= SIMD_ROUNDING * bigA[e],
                        "%s, case %d, A entry %d of particle %zu: %.17g, "
                        "portable %.17g",
                        levels[l], cc, e, i, got, want);
        }
      for (size_t f = 0; f < 3; f++) {
        double big = 0.0;
        for (size_t i = 0; i < n; i++) big = fmax(big, fabs(buf[f * n + i]));
        for (size_t i = 0; i < n; i++)
          ck_assert_msg(fabs(buf[(3 + f) * n + i] - buf[f * n + i]) <=
                            SIMD_ROUNDING * big,
                        "%s, case %d, rate %zu of particle %zu: %.17g, "
                        "portable %.17g (largest %.3g)",
                        levels[l], c, f, i, buf[(3 + f) * n + i],
                        buf[f * n + i], big);
      }
    }
  }
  free(buf);
  vsph_viscous_ws_free(ws);
  vsph_cells_free(cells);
  vsph_particles_free(p);
}
END_TEST

/* A non-finite value stays where it acts: one particle's velocity set to
 * infinity, and another's density to 0 (so its volume m/rho is infinite;
 * the farthest from the first, their supports apart): every particle
 * outside both supports (s^2 >= (kappa h)^2, computed as the loops
 * compute it) keeps finite rates, by the portable loops and by the sweep
 * by cell groups (and within SIMD_ROUNDING of the portable loops'), and a
 * third particle, far from both, moved to (inf, inf) after the cells'
 * build, reaches none, by any loop; the stress forms' A that the portable
 * loops leave finite are within GRAD_ROUNDING at each level (case 0 MGF, 1
 * MEAF, whose viscous share takes the velocities' difference itself, 2 PVWF and
 * 3 B, whose first pass carries the values one support further, into A: for
 * them, outside two supports) at each level this build and CPU have, whose
 * lanes compute every candidate of a vector, those outside the support too (the
 * AVX2 sweep clears the shares and the volumes outside it by an and: without
 * it, 0 * inf). Where the CPU or build lacks the groups' sweep, said and left
 * out. */
START_TEST(test_groups_nonfinite_contained) {
  const char *names[3] = {"portable"};
  const int nl = 1 + groups_levels(names + 1);
  if (nl == 1) {
    fprintf(stderr, "test_groups_nonfinite_contained: no groups' sweep here\n");
    return;
  }
  /* a strip twice as long for the stress forms, whose two supports
   * around each infinite value leave few particles in the other */
  struct vsph_particles *p =
      _i >= 2 ? random_set_in(2, 5150, 1.0, 0.11) : random_set(2, 5150);
  const size_t n = p->n;
  struct vsph_equations_props ep;
  static const int forms[] = {VSPH_VISCOUS_MGF, VSPH_VISCOUS_MEAF,
                              VSPH_VISCOUS_PVWF, VSPH_VISCOUS_TWOPASS};
  gauss2_props(&ep, forms[_i], HDX * DX, 0.0);
  /* the stress forms' first pass carries a non-finite value one support
   * further (into A of the neighbours): two supports for them */
  const double reach = _i >= 2 ? 4.0 : 1.0;
  struct vsph_cells *cells = vsph_cells_alloc();
  ck_assert_int_eq(vsph_cells_build(cells, p, 3.0 * ep.visc.h), 0);
  const double kap = vsph_gaussian_type.kappa, h = ep.visc.h,
               H2 = kap * h * kap * h;
  const size_t bad = n / 2;
  size_t empty = 0; /* the one whose volume is infinite: the farthest */
  for (size_t k = 1; k < n; k++)
    if (pair_s2(p, bad, k) > pair_s2(p, bad, empty)) empty = k;
  ck_assert_double_gt(pair_s2(p, bad, empty), 4.0 * H2); /* apart */
  /* and one moved to x = inf after the cells' build (the walk still
   * meets it where it was): the farthest from both, it has no pair, and
   * none of its neighbours' rates may take it */
  size_t lost = 0;
  double lost_s2 = 0.0;
  for (size_t k = 0; k < n; k++) {
    const double d = fmin(pair_s2(p, bad, k), pair_s2(p, empty, k));
    if (d > lost_s2) lost = k, lost_s2 = d;
  }
  ck_assert_double_gt(lost_s2, reach * H2);
  /* both components, so that each of the AVX2 kernels' clears (of x and
   * y, of du's two components) is needed */
  p->vel[0][bad] = p->vel[1][bad] = INFINITY;
  p->rho[empty] = 0.0;
  p->pos[0][lost] = p->pos[1][lost] = INFINITY;
  struct vsph_viscous_ws *ws = vsph_viscous_ws_alloc(n, 2);
  double *buf = malloc(10 * n * sizeof *buf), *const Ap = buf + 6 * n;
  ck_assert_ptr_nonnull(buf);
  double big[3] = {0, 0, 0};     /* the portable loops' largest far rates */
  double bigA[4] = {0, 0, 0, 0}; /* the stress forms: their finite A's */
  for (int l = 0; l < nl; l++) {
    double *const o = buf + (l ? 3 * n : 0);
    double closest;
    ck_assert_uint_ne(rhs_at(&ep, p, n, cells, ws, names[l], o, &closest),
                      SIZE_MAX);
    ck_assert(isinf(p->vol[empty])); /* the premise */
    /* the stress forms' first pass: every A entry the portable loops
     * leave finite, within rounding at each level (a lane of the
     * particle's own, or a far one, that took the infinite volume or
     * velocity would make it NaN) */
    for (int e = 0; _i >= 2 && e < 4; e++)
      for (size_t k = 0; k < n; k++) {
        const double v = ws->A[e][k];
        if (!l) {
          Ap[(size_t)e * n + k] = v;
          if (isfinite(v)) bigA[e] = fmax(bigA[e], fabs(v));
          continue;
        }
        const double w = Ap[(size_t)e * n + k];
        if (isfinite(w))
          ck_assert_msg(fabs(v - w) <= GRAD_ROUNDING * bigA[e],
                        "%s: A entry %d of particle %zu is %.17g, portable "
                        "%.17g",
                        names[l], e, k, v, w);
      }
    size_t far = 0, near = 0;
    for (size_t k = 0; k < n; k++) {
      if (pair_s2(p, bad, k) < reach * H2 ||
          pair_s2(p, empty, k) < reach * H2) {
        near += !isfinite(o[k]); /* they do reach their neighbours */
        continue;
      }
      if (k == lost) continue;
      far++;
      for (size_t f = 0; f < 3; f++) {
        ck_assert_msg(isfinite(o[f * n + k]),
                      "%s: rate %zu of particle %zu, outside the supports "
                      "of the infinite ones, is %g",
                      names[l], f, k, o[f * n + k]);
        if (!l) big[f] = fmax(big[f], fabs(o[f * n + k]));
        /* and within rounding of the portable loops' (a far lane's
         * infinity that reached a sum the finish then hid, as B's in
         * L's fallback to the identity, would move it far more) */
        ck_assert_msg(
            fabs(o[f * n + k] - buf[f * n + k]) <= SIMD_ROUNDING * big[f],
            "%s: rate %zu of particle %zu, outside the supports "
            "of the infinite ones, is %.17g, portable %.17g",
            names[l], f, k, o[f * n + k], buf[f * n + k]);
      }
    }
    ck_assert_uint_gt(far, n / 2);
    ck_assert_uint_gt(near, 2);
  }
  free(buf);
  vsph_viscous_ws_free(ws);
  vsph_cells_free(cells);
  vsph_particles_free(p);
}
END_TEST

/* Crowded cells through the sweep by cell groups at each level this
 * build and CPU have (AVX2, AVX-512; form _i % 5: MGF, Violeau and Issa's,
 * Cleary's, MEAF, PVWF; delta-SPH from _i = 5 on), which takes a cell's
 * receivers eight at a time: a 2-D set (the ids shuffled, half of them
 * fluid) with 42 of its particles moved onto a 7 x 6 grid of spacing DX/10, a
 * third of a cell's edge (3h/2 = 2 DX) across, so that a cell holds more than
 * 24 of them (four groups of receivers or more) and its ranges hundreds of
 * candidates. Every rate of every fluid particle
 * within rounding of the portable loops' (SIMD_ROUNDING of the rate's
 * largest), the closest pair and the count exact, and the count that of a
 * count pair by pair, the closest pair that of a search pair by pair
 * (two particles not fluid placed closer than any other pair: left out).
 * The set lies 40 h from the origin (where the lanes past a range's end
 * meet e^{-q^2} of q^2 > 709, past the exponential's range, where it
 * gives values of no meaning: 0 or inf by AVX-512's scalef, anything
 * finite by AVX2's exponent bits) and its
 * ids not fluid run down from SIZE_MAX (2^63 and above). Where the CPU
 * or build lacks the groups' sweep, said and left out. */
START_TEST(test_groups_crowded) {
  static const int forms[] = {VSPH_VISCOUS_MGF, VSPH_VISCOUS_VI,
                              VSPH_VISCOUS_CLEARY, VSPH_VISCOUS_MEAF,
                              VSPH_VISCOUS_PVWF};
  const char *levels[2];
  const int nlev = groups_levels(levels);
  if (!nlev) {
    fprintf(stderr, "test_groups_crowded: no groups' sweep here\n");
    return;
  }
  struct vsph_particles *p = mixed_set(2, 4242 + (unsigned long)_i, 0.5, 0.11);
  const size_t n = p->n, nfl = n / 2;
  ck_assert_uint_gt(n, 4 * 42);
  for (size_t k = 0; k < 42; k++) { /* every 4th particle, into the crowd */
    p->pos[0][4 * k] = 0.013 + 0.1 * DX * (double)(k % 7);
    p->pos[1][4 * k] = -0.061 + 0.1 * DX * (double)(k / 7);
  }
  /* and the closest pair of all two others (not fluid), which the closest
   * pair with a fluid receiver leaves out */
  size_t two[2], found = 0;
  for (size_t i = 4 * 42; i < n && found < 2; i++)
    if (p->id[i] >= nfl) two[found++] = i;
  ck_assert_uint_eq(found, 2);
  p->pos[0][two[1]] = p->pos[0][two[0]] + 0.01 * DX;
  p->pos[1][two[1]] = p->pos[1][two[0]];
  /* the set 40 h from the origin along x: a masked lane past a range's
   * end loads x = 0, so its q^2 = (x_i/h)^2 > 1600 and its e^{-q^2} is
   * anything (2^{-n} from exponent bits wraps beyond q^2 ~ 709): cleared
   * or not, it must add nothing */
  for (size_t i = 0; i < n; i++) p->pos[0][i] += 40.0 * HDX * DX;
  /* the ids not fluid from SIZE_MAX down (ids are any size_t: at 2^63 and
   * above, a signed compare of 64-bit lanes would take them for fluid) */
  for (size_t i = 0; i < n; i++)
    if (p->id[i] >= nfl) p->id[i] = SIZE_MAX - (p->id[i] - nfl);
  struct vsph_equations_props ep;
  gauss2_props(&ep, forms[_i % 5], HDX * DX, _i >= 5 ? DELTA : 0.0);
  struct vsph_cells *cells = vsph_cells_alloc();
  ck_assert_int_eq(vsph_cells_build(cells, p, 3.0 * ep.visc.h), 0);
  size_t most = 0; /* the most particles in a cell */
  for (size_t c = 0; c < cells->ncells; c++)
    most = cells->count[c] > most ? cells->count[c] : most;
  ck_assert_uint_gt(most, 24); /* four groups of receivers or more */
  struct vsph_viscous_ws *ws = vsph_viscous_ws_alloc(n, 2);
  double *buf = calloc(6 * n, sizeof *buf);
  ck_assert_ptr_nonnull(buf);
  double closest[2];
  size_t pairs[2];
  pairs[0] = rhs_at(&ep, p, nfl, cells, ws, "portable", buf, &closest[0]);
  ck_assert_uint_ne(pairs[0], SIZE_MAX);
  ck_assert_uint_eq(pairs[0], pair_count(p, nfl, ep.visc.h));
  ck_assert_double_eq(closest[0], pair_closest(p, nfl, ep.visc.h));
  for (int l = 0; l < nlev; l++) {
    pairs[1] =
        rhs_at(&ep, p, nfl, cells, ws, levels[l], buf + 3 * n, &closest[1]);
    ck_assert_uint_eq(pairs[1], pairs[0]);
    ck_assert_double_eq(closest[1], closest[0]);
    for (size_t f = 0; f < 3; f++) {
      double big = 0.0;
      for (size_t i = 0; i < n; i++)
        if (p->id[i] < nfl) big = fmax(big, fabs(buf[f * n + i]));
      for (size_t i = 0; i < n; i++) {
        if (p->id[i] >= nfl) continue;
        const double a = buf[f * n + i], b = buf[(3 + f) * n + i];
        ck_assert_msg(fabs(b - a) <= SIMD_ROUNDING * big,
                      "%s, %s, rate %zu of particle %zu: %.17g, portable "
                      "%.17g (largest %.3g)",
                      vsph_viscous_name(forms[_i % 5]), levels[l], f, i, b, a,
                      big);
      }
    }
  }
  free(buf);
  vsph_viscous_ws_free(ws);
  vsph_cells_free(cells);
  vsph_particles_free(p);
}
END_TEST

/* The groups' sweeps' adds of j's shares alone, of 3 and 4 fields: the
 * AVX-512 one (vsph_sweep_x86_addj8) for 1 to 8 particles, the AVX2 one
 * (vsph_sweep_x86_addj4) for 1 to 4: each of the first nf nl entries gets
 * its one field, the same bits as a scalar add, and every entry past them
 * is left as it was, bit for bit (one of them -0, which an add of 0 would
 * turn to +0), though the lanes past nl hold shares too. A level the CPU
 * or build lacks is left out (said where both are). */
START_TEST(test_sweep_addj_by_hand) {
#if VSPH_SWEEP_X86_GROUPS /* else the functions are not built */
  const char *levels[2];
  const int nlev = groups_levels(levels);
  if (!nlev) {
    fprintf(stderr, "test_sweep_addj_by_hand: no groups' sweep here\n");
    return;
  }
  double f[4][8], q[40], want[40];
  const double *const fp[4] = {f[0], f[1], f[2], f[3]};
  for (int a = 0; a < 4; a++)
    for (int l = 0; l < 8; l++) f[a][l] = sin(0.7 + 1.3 * a + 0.41 * l);
  for (int lv = 0; lv < nlev; lv++)
    for (int nf = 3; nf <= 4; nf++) {
      const int wide = !strcmp(levels[lv], "avx512"); /* addj8, else addj4 */
      for (size_t nl = 1; nl <= (wide ? 8u : 4u); nl++) {
        const size_t used = (size_t)nf * nl;
        for (size_t e = 0; e < 40; e++) q[e] = want[e] = cos(0.9 * (double)e);
        q[used] = want[used] = -0.0;
        for (size_t l = 0; l < nl; l++)
          for (int a = 0; a < nf; a++)
            want[(size_t)nf * l + (size_t)a] += f[a][l];
        (wide ? vsph_sweep_x86_addj8 : vsph_sweep_x86_addj4)(q, nf, fp, nl);
        for (size_t e = 0; e < 40; e++)
          ck_assert_msg(memcmp(q + e, want + e, sizeof *q) == 0,
                        "%s, %d fields, %zu particles: entry %zu is %.17g, not "
                        "%.17g",
                        levels[lv], nf, nl, e, q[e], want[e]);
      }
    }
#else
  fprintf(stderr, "test_sweep_addj_by_hand: no groups' sweep in this build\n");
#endif
}
END_TEST

/* The sweep by cell groups writes within its block's buffer and nowhere
 * else (the next block's buffer follows it, and another thread may be
 * writing there): each level's kernel (vsph_sweep_x86_groups2_avx2,
 * _avx512) called directly on one block that holds every cell of a set,
 * its buffer followed by sentinels of -0 (which an add of +0 would turn
 * to +0), for eight sizes of the set (one particle fewer each time, so
 * that its last range ends at every lane of a vector): every sentinel
 * keeps its bits, the interactions are those of a count pair by pair and
 * the closest pair that of a search pair by pair; where both levels run,
 * their sums agree within SIMD_ROUNDING of each field's largest. Case
 * _i: MGF (0, 1) or MEAF (2, 3), without delta-SPH or with it (odd: four
 * fields). Where the CPU or build lacks the groups' sweep, said and left
 * out. */
START_TEST(test_groups_block_bounds) {
#if VSPH_SWEEP_X86_GROUPS /* else the kernels are not built */
  const char *levels[2];
  const int nlev = groups_levels(levels);
  if (!nlev) {
    fprintf(stderr, "test_groups_block_bounds: no groups' sweep here\n");
    return;
  }
  const int meaf = _i >= 2, delta = _i % 2, nf = delta ? 4 : 3;
  enum { SENT = 16 };
  struct vsph_particles *p = mixed_set(2, 6060 + (unsigned long)_i, 0.5, 0.11);
  const size_t n0 = p->n;
  struct vsph_equations_props ep;
  gauss2_props(&ep, meaf ? VSPH_VISCOUS_MEAF : VSPH_VISCOUS_MGF, HDX * DX,
               delta ? DELTA : 0.0);
  struct vsph_equations_ctx rc = {.ep = &ep};
  vsph_pair_kernel_init(&rc.pk, &vsph_gaussian_type, 2, ep.visc.h);
  ck_assert_int_eq(vsph_viscous_loop_init(&rc.vl, &ep.visc, NULL), 0);
  const int term =
      meaf ? VSPH_SWEEP_X86_MEAF_TERM : VSPH_SWEEP_X86_BROOKSHAW_TERM;
  struct vsph_cells *cells = vsph_cells_alloc();
  double *b[2];
  for (int l = 0; l < 2; l++) {
    b[l] = malloc(((size_t)nf * n0 + SENT) * sizeof *b[l]);
    ck_assert_ptr_nonnull(b[l]);
  }
  for (size_t k = 0; k < 8; k++) {
    p->n = n0 - k;
    const size_t n = p->n, nfl = n / 2;
    ck_assert_int_eq(vsph_cells_build(cells, p, 3.0 * ep.visc.h), 0);
    const size_t c0[2] = {0, cells->ncells}, lo = 0, hi = n;
    size_t off = 0;
    for (int l = 0; l < nlev; l++) {
      /* its own entries NaN (the kernel zeroes them first), then the
       * sentinels */
      for (size_t e = 0; e < (size_t)nf * n + SENT; e++)
        b[l][e] = e < (size_t)nf * n ? (double)NAN : -0.0;
      const struct vsph_equations_sweep sw = {
          .nblk = 1, .c0 = c0, .lo = &lo, .hi = &hi, .off = &off, .buf = b[l]};
      double closest;
      const size_t got =
          !strcmp(levels[l], "avx512")
              ? vsph_sweep_x86_groups2_avx512(&rc, p, cells, nfl, &sw, 0, delta,
                                              term, &closest)
              : vsph_sweep_x86_groups2_avx2(&rc, p, cells, nfl, &sw, 0, delta,
                                            term, &closest);
      ck_assert_uint_eq(got, pair_count(p, nfl, ep.visc.h));
      ck_assert_double_eq(closest, pair_closest(p, nfl, ep.visc.h));
      for (size_t e = (size_t)nf * n; e < (size_t)nf * n + SENT; e++)
        ck_assert_msg(b[l][e] == 0.0 && signbit(b[l][e]),
                      "%s, %zu particles, %d fields: entry %zu past the "
                      "block's buffer is %g",
                      levels[l], n, nf, e - (size_t)nf * n, b[l][e]);
    }
    for (int f = 0; nlev == 2 && f < nf; f++) {
      double big = 0.0;
      for (size_t i = 0; i < n; i++)
        big = fmax(big, fabs(b[0][(size_t)nf * i + (size_t)f]));
      for (size_t i = 0; i < n; i++) {
        const double x = b[0][(size_t)nf * i + (size_t)f],
                     y = b[1][(size_t)nf * i + (size_t)f];
        ck_assert_msg(fabs(x - y) <= SIMD_ROUNDING * big,
                      "%zu particles, field %d of particle %zu: avx2 %.17g, "
                      "avx512 %.17g",
                      n, f, i, x, y);
      }
    }
  }
  for (int l = 0; l < 2; l++) free(b[l]);
  vsph_cells_free(cells);
  vsph_particles_free(p);
#else
  fprintf(stderr, "test_groups_block_bounds: no groups' sweep in this build\n");
#endif
}
END_TEST

/* Each SIMD level runs its own kernels: on a set of one block (fewer than
 * 512 particles, half of them fluid, asserted), the right-hand side at
 * level L (VSPH_PAIR_SIMD) against level L's kernels called directly:
 * MGF's sweep, whose block buffer the workspace keeps after the
 * evaluation, against vsph_sweep_x86_groups2_avx512 (_avx2) on the same
 * particles (the pressure and volumes the evaluation left), bit for bit;
 * and PVWF's first pass, whose A the workspace keeps, against
 * vsph_sweep_x86_grad2_avx512 (_avx2) finished particle by particle by
 * vsph_viscous_pvwf_finish (one block: a particle's sums are its entries),
 * bit for bit. A dispatch that swapped the levels' kernels passes every
 * test that compares the levels' outputs with each other or with the
 * loops, and would fault on a CPU without AVX-512; this one fails. Where
 * the CPU or build lacks the kernels, said and left out. */
START_TEST(test_groups_dispatch_own_kernel) {
#if VSPH_SWEEP_X86_GROUPS /* else the kernels are not built */
  const char *levels[2];
  const int nlev = groups_levels(levels);
  if (!nlev) {
    fprintf(stderr, "test_groups_dispatch_own_kernel: no groups' sweep here\n");
    return;
  }
  struct vsph_particles *p = mixed_set(2, 4242, 0.5, 0.11);
  const size_t n = p->n, nfl = n / 2;
  ck_assert_uint_lt(n, 512); /* one block: the premise */
  struct vsph_cells *cells = vsph_cells_alloc();
  struct vsph_viscous_ws *ws = vsph_viscous_ws_alloc(n, 2),
                         *ws2 = vsph_viscous_ws_alloc(n, 2);
  double *rates = malloc(3 * n * sizeof *rates), *want = NULL;
  ck_assert(rates && ws && ws2);
  char *keep = simd_env_keep();
  int st[2][2] = {{0}};
  size_t nblk[2][2] = {{0}}, off[2][2] = {{0}};
  int same[2][2] = {{0}};
  for (int l = 0; l < nlev; l++) {
    const int wide = !strcmp(levels[l], "avx512");
    setenv("VSPH_PAIR_SIMD", levels[l], 1);
    for (int f = 0; f < 2; f++) { /* MGF's sweep, PVWF's first pass */
      struct vsph_equations_props ep;
      gauss2_props(&ep, f ? VSPH_VISCOUS_PVWF : VSPH_VISCOUS_MGF, HDX * DX,
                   0.0);
      if (vsph_cells_build(cells, p, 3.0 * ep.visc.h)) {
        st[l][f] = -1;
        continue;
      }
      struct vsph_equations_sweep *sw = vsph_equations_sweep_alloc();
      struct vsph_equations_out out = {
          .drho = rates, .acc = {rates + n, rates + 2 * n}, .sweep = sw};
      st[l][f] = vsph_equations_rhs(&ep, p, nfl, cells, ws, &out);
      nblk[l][f] = sw->nblk;
      off[l][f] = sw->off[0];
      if (!st[l][f] && sw->nblk == 1) {
        struct vsph_equations_ctx rc = {.ep = &ep};
        vsph_pair_kernel_init(&rc.pk, &vsph_gaussian_type, 2, ep.visc.h);
        if (!f) { /* MGF: the evaluation's buffer, then the kernel's */
          const size_t m = 3 * (sw->hi[0] - sw->lo[0]);
          want = realloc(want, m * sizeof *want);
          memcpy(want, sw->buf, m * sizeof *want);
          vsph_viscous_loop_init(&rc.vl, &ep.visc, NULL);
          double closest;
          (wide ? vsph_sweep_x86_groups2_avx512 : vsph_sweep_x86_groups2_avx2)(
              &rc, p, cells, nfl, sw, 0, 0, VSPH_SWEEP_X86_BROOKSHAW_TERM,
              &closest);
          same[l][f] = memcmp(want, sw->buf, m * sizeof *want) == 0;
        } else { /* PVWF: the kernel's sums finished, against ws's A */
          double *const b = sw->buf;
          (wide ? vsph_sweep_x86_grad2_avx512 : vsph_sweep_x86_grad2_avx2)(
              &rc.pk, p, cells, sw, 0);
          for (size_t i = 0; i < n; i++)
            vsph_viscous_pvwf_finish(&ep.visc, ws2, i, b + 8 * i,
                                     b + 8 * i + 4);
          same[l][f] = 1;
          for (int e = 0; e < 4; e++)
            for (size_t i = 0; i < n; i++)
              same[l][f] &= ws2->A[e][i] == ws->A[e][i];
        }
      }
      vsph_equations_sweep_free(sw);
    }
  }
  simd_env_put_back(keep);
  for (int l = 0; l < nlev; l++)
    for (int f = 0; f < 2; f++) {
      ck_assert_int_eq(st[l][f], 0);
      ck_assert_uint_eq(nblk[l][f], 1);
      ck_assert_uint_eq(off[l][f], 0);
      ck_assert_msg(same[l][f],
                    "%s: the evaluation at level %s is not that level's "
                    "kernel's",
                    f ? "PVWF's first pass" : "MGF's sweep", levels[l]);
    }
  free(want);
  free(rates);
  vsph_viscous_ws_free(ws2);
  vsph_viscous_ws_free(ws);
  vsph_cells_free(cells);
  vsph_particles_free(p);
#else
  fprintf(stderr,
          "test_groups_dispatch_own_kernel: no groups' sweep in this build\n");
#endif
}
END_TEST

/* PVWF's and B's first pass by cell groups alone
 * (vsph_sweep_x86_grad2_avx512, _avx2): each level's kernel called
 * directly on one block that holds every cell of a set 40 h from the
 * origin (so that a lane past a range's end, which loads 0, lies far
 * outside the support: q^2 in the thousands, far past the exponential's
 * range 0-700, where its value means nothing; the lane must add nothing),
 * its buffer followed by sentinels of -0 (which an add of +0 would turn
 * to +0), for eight sizes of the set (one particle fewer each time, so
 * that its last range ends at every lane of a vector). Each particle's
 * eight fields are B = sum_j V_j (-F) x (x) x and Mg = sum_j V_j (-F)
 * du (x) x over every j != i within the support, ghosts or not (THEORY
 * 3), summed here pair by pair with the twin's F (vsph_kernel_dw and
 * libm's exp, not the kernels' route): within GRAD_ROUNDING of each
 * field's largest (the kernels' exponential is within 1e-15 of libm's,
 * test_expneg_within_1e15_of_exp; some 50 shares an entry, summed in
 * another order); every sentinel keeps its bits. A velocity field of
 * both components (the random set's) so that each of Mg's entries has
 * its own value: a transposed or swapped field fails. Where the CPU or
 * build lacks the kernels, said and left out. */
START_TEST(test_grad_block_by_hand) {
#if VSPH_SWEEP_X86_GROUPS /* else the kernels are not built */
  const char *levels[2];
  const int nlev = groups_levels(levels);
  if (!nlev) {
    fprintf(stderr, "test_grad_block_by_hand: no groups' sweep here\n");
    return;
  }
  enum { SENT = 16 };
  struct vsph_particles *p = mixed_set(2, 7070, 0.5, 0.11);
  const double h = HDX * DX;
  const size_t n0 = p->n;
  for (size_t i = 0; i < n0; i++)
    for (int a = 0; a < 2; a++) p->pos[a][i] += 40.0 * h;
  struct vsph_pair_kernel pk;
  vsph_pair_kernel_init(&pk, &vsph_gaussian_type, 2, h);
  struct vsph_cells *cells = vsph_cells_alloc();
  double *b = malloc((8 * n0 + SENT) * sizeof *b),
         *want = malloc(8 * n0 * sizeof *want);
  ck_assert(b && want);
  for (size_t k = 0; k < 8; k++) {
    p->n = n0 - k;
    const size_t n = p->n;
    ck_assert_int_eq(vsph_cells_build(cells, p, 3.0 * h), 0);
    for (size_t e = 0; e < 8 * n; e++) want[e] = 0.0;
    for (size_t i = 0; i < n; i++)
      for (size_t j = 0; j < n; j++) {
        double x[3];
        const double G = -twin_F(&vsph_gaussian_type, 2, h, p, i, j, x);
        if (G == 0.0) continue; /* i itself, or outside the support */
        const double w = p->vol[j] * G, du[2] = {p->vel[0][j] - p->vel[0][i],
                                                 p->vel[1][j] - p->vel[1][i]};
        for (int a = 0; a < 2; a++)
          for (int c = 0; c < 2; c++) {
            want[8 * i + (size_t)(2 * a + c)] += w * x[a] * x[c];
            want[8 * i + (size_t)(4 + 2 * a + c)] += w * du[a] * x[c];
          }
      }
    double big[8] = {0};
    for (size_t i = 0; i < n; i++)
      for (int f = 0; f < 8; f++)
        big[f] = fmax(big[f], fabs(want[8 * i + (size_t)f]));
    const size_t c0[2] = {0, cells->ncells}, lo = 0, hi = n;
    size_t off = 0;
    for (int l = 0; l < nlev; l++) {
      /* its own entries NaN (the kernel zeroes them first), then the
       * sentinels */
      for (size_t e = 0; e < 8 * n + SENT; e++)
        b[e] = e < 8 * n ? (double)NAN : -0.0;
      const struct vsph_equations_sweep sw = {
          .nblk = 1, .c0 = c0, .lo = &lo, .hi = &hi, .off = &off, .buf = b};
      (!strcmp(levels[l], "avx512")
           ? vsph_sweep_x86_grad2_avx512
           : vsph_sweep_x86_grad2_avx2)(&pk, p, cells, &sw, 0);
      for (size_t e = 0; e < 8 * n; e++)
        ck_assert_msg(fabs(b[e] - want[e]) <= GRAD_ROUNDING * big[e % 8],
                      "%s, %zu particles: field %zu of particle %zu is "
                      "%.17g, pair by pair %.17g",
                      levels[l], n, e % 8, e / 8, b[e], want[e]);
      for (size_t e = 8 * n; e < 8 * n + SENT; e++)
        ck_assert_msg(b[e] == 0.0 && signbit(b[e]),
                      "%s, %zu particles: entry %zu past the block's buffer "
                      "is %g",
                      levels[l], n, e - 8 * n, b[e]);
    }
  }
  free(b);
  free(want);
  vsph_cells_free(cells);
  vsph_particles_free(p);
#else
  fprintf(stderr, "test_grad_block_by_hand: no groups' sweep in this build\n");
#endif
}
END_TEST

/* The lanes' adds alone (vsph_sweep_x86_add_avx2 for 3 and 4 fields,
 * vsph_sweep_x86_add8_avx2 with a factor) on made-up shares against the
 * scalar loop, for every chunk size 0-13 (whole blocks of four and every
 * tail), receivers in a shuffled order with one left out: every entry the
 * same bits, and the one left out untouched. Where the CPU has no AVX2,
 * said and left out. */
START_TEST(test_sweep_lanes_by_hand) {
  if (vsph_pair_x86_simd() < 1) {
    fprintf(stderr, "test_sweep_lanes_by_hand: no AVX2 here\n");
    return;
  }
  enum { NJ = 16, S = VSPH_PAIR_CHUNK_MAX };
  static double js[8 * S], a[NJ * 8], b[NJ * 8];
  for (int f = 0; f < 8; f++)
    for (int k = 0; k < S; k++)
      js[f * S + k] = sin(1.0 + 3.7 * f + 0.61 * k) * pow(10.0, f % 3 - 1);
  const size_t lo = 5;
  size_t jj[NJ];
  for (size_t k = 0; k < NJ; k++) jj[k] = lo + (7 * k + 3) % NJ; /* distinct */
  for (int nf = 3; nf <= 8; nf++) {
    if (nf > 4 && nf < 8) continue;
    for (size_t m = 0; m <= 13; m++) {
      for (size_t e = 0; e < NJ * 8; e++) a[e] = b[e] = cos(0.3 * (double)e);
      const double v = 0.7312;
      if (nf == 8)
        vsph_sweep_x86_add8_avx2(a, lo, jj, m, js, S, v);
      else
        vsph_sweep_x86_add_avx2(a, lo, nf, jj, m, js, S);
      for (size_t k = 0; k < m; k++) /* the scalar loops of the sweeps */
        for (int f = 0; f < nf; f++)
          b[(jj[k] - lo) * (size_t)nf + (size_t)f] +=
              nf == 8 ? v * js[(size_t)f * S + k] : js[(size_t)f * S + k];
      ck_assert_msg(memcmp(a, b, sizeof a) == 0, "%d fields, %zu pairs", nf, m);
    }
  }
}
END_TEST

/* The candidate test by AVX-512 and by AVX2 (solver/pair_x86.c) against
 * the portable loop on the same particles (a perturbed patch in 2-D and
 * in 3-D, 3h Gaussian and quintic supports, every particle as receiver, all
 * neighbours and the upper half j > i): chunk by chunk the same
 * neighbours in the same order, the same r_j - r_i, s^2, F and V_j F, to
 * the bit (each computes x = r_j - r_i and s^2 = (x0 x0 + x1 x1) + x2 x2
 * with the same operations). A level the CPU lacks is said and left out. */
/* One walk of each particle of @p p over @p rg (NULL: its own cell's
 * ranges in @p cells), the portable loop against level @p level, every
 * chunk's fields the same bits; returns the pairs and the fullest chunk. */
static size_t walks_agree(const struct vsph_particles *p,
                          const struct vsph_cells *cells,
                          const struct vsph_pair_ranges *all,
                          const struct vsph_pair_kernel *pk0, int level,
                          size_t *fullest) {
  struct vsph_pair_kernel pk[2] = {*pk0, *pk0};
  pk[0].simd = level;
  pk[1].simd = 0;
  const int dim = pk0->dim;
  static struct vsph_pair_chunk b[2];
  size_t pairs = 0;
  const size_t ncell = all ? 1 : cells->ncells;
  for (size_t cell = 0; cell < ncell; cell++) {
    struct vsph_pair_ranges rg;
    if (all)
      rg = *all;
    else
      vsph_pair_ranges_cell(&rg, cells, cell);
    const size_t i0 = all ? 0 : cells->start[cell],
                 i1 = all ? p->n : cells->start[cell] + cells->count[cell];
    for (size_t i = i0; i < i1; i++)
      for (int upper = 0; upper < 2; upper++) {
        struct vsph_pair_iter it[2];
        for (int w = 0; w < 2; w++) {
          if (upper)
            vsph_pair_begin_upper(&it[w], &pk[w], p, &rg, i);
          else
            vsph_pair_begin(&it[w], &pk[w], p, &rg, i);
        }
        for (;;) {
          const size_t m0 = vsph_pair_gather(&it[0], dim, pk[0].dfq_id, &b[0]),
                       m1 = vsph_pair_gather(&it[1], dim, pk[1].dfq_id, &b[1]);
          ck_assert_msg(m0 == m1, "level %d: %zu neighbours, portable %zu",
                        level, m0, m1);
          if (!m0) break;
          pairs += m0;
          *fullest = m0 > *fullest ? m0 : *fullest;
          ck_assert(!memcmp(b[0].j, b[1].j, m0 * sizeof b[0].j[0]));
          for (int a = 0; a < dim; a++)
            ck_assert(!memcmp(b[0].x[a], b[1].x[a], m0 * sizeof(double)));
          ck_assert_msg(!memcmp(b[0].s2, b[1].s2, m0 * sizeof(double)),
                        "level %d: s^2 differs", level);
          ck_assert(!memcmp(b[0].F, b[1].F, m0 * sizeof(double)));
          ck_assert(!memcmp(b[0].VF, b[1].VF, m0 * sizeof(double)));
        }
      }
  }
  return pairs;
}

/* The walks of each cell's particles made together at level @p level
 * (vsph_pair_cell_begin, vsph_pair_begin_upper_in, vsph_pair_next_chunk)
 * against each particle's own upper walk by the portable loop: chunk by
 * chunk the same fields, to the bit. Counts the walks that took the
 * joint walk's chunk (*joint), those that went on alone after it, their
 * first chunk full (*alone), and of those the ones that went on inside a
 * row (*midrow). */
static void cells_agree(const struct vsph_particles *p,
                        const struct vsph_cells *cells,
                        const struct vsph_pair_kernel *pk0, int level,
                        size_t *joint, size_t *alone, size_t *midrow) {
  struct vsph_pair_kernel pk[2] = {*pk0, *pk0};
  pk[0].simd = level;
  pk[1].simd = 0;
  const int dim = pk0->dim;
  static struct vsph_pair_chunk own, b1;
  static struct vsph_pair_cell pc;
  for (size_t cell = 0; cell < cells->ncells; cell++) {
    struct vsph_pair_ranges rg;
    vsph_pair_ranges_cell(&rg, cells, cell);
    const size_t s0 = cells->start[cell], cnt = cells->count[cell];
    vsph_pair_cell_begin(&pc, &pk[0], s0, cnt, dim);
    for (size_t i = s0; i < s0 + cnt; i++) {
      struct vsph_pair_iter it[2];
      vsph_pair_begin_upper_in(&it[0], &pk[0], p, &rg, &pc, i);
      vsph_pair_begin_upper(&it[1], &pk[1], p, &rg, i);
      *joint += it[0].ready != NULL;
      *alone += it[0].ready && it[0].ready_r != SIZE_MAX;
      *midrow += it[0].ready && it[0].ready_r != SIZE_MAX &&
                 it[0].ready_j < rg.hi[it[0].ready_r];
      for (;;) {
        const struct vsph_pair_chunk *b0;
        const size_t m0 =
            vsph_pair_next_chunk(&it[0], dim, pk[0].dfq_id, 1, &own, &b0);
        const size_t m1 =
            vsph_pair_gather_as(&it[1], dim, pk[1].dfq_id, 1, &b1);
        ck_assert_msg(m0 == m1,
                      "level %d, particle %zu: %zu neighbours, "
                      "portable %zu",
                      level, i, m0, m1);
        if (!m0) break;
        ck_assert(!memcmp(b0->j, b1.j, m0 * sizeof b1.j[0]));
        for (int a = 0; a < dim; a++)
          ck_assert(!memcmp(b0->x[a], b1.x[a], m0 * sizeof(double)));
        ck_assert(!memcmp(b0->s2, b1.s2, m0 * sizeof(double)));
        ck_assert(!memcmp(b0->F, b1.F, m0 * sizeof(double)));
        ck_assert(!memcmp(b0->VF, b1.VF, m0 * sizeof(double)));
      }
    }
  }
}

/* A walk whose first chunk fills before it ends (cells_agree): in 2-D,
 * three particles in one cell (edge 0.5) and, in the next cell of the
 * row, 10 particles beyond their support (3h = 0.6), then a cluster in a
 * 1/8-cell box within it. Case 0, 130 in the cluster: each of the three
 * has more than 128 candidates ahead in its row, and its chunk is full
 * at the end of its second block of 64, not at the first nor after 96 (a
 * block of 32 would end it there): the joint walk's chunk ends inside
 * the row. Case 1, 65 in the cluster and 5 neighbours in the row above:
 * the chunk (65-67 neighbours) is full only at its row's end, inside its
 * second block, and the walk goes on alone into the next row (a walk
 * that checked only whole blocks would run on into it: 70-72). Either
 * way the walk goes on alone from there (as do the walks of the
 * cluster's own cell, eight at a time); at each level the CPU has, the
 * same chunks as the portable walk's. */
START_TEST(test_joint_walk_resumes) {
  const size_t nc = _i ? 65 : 130, na = _i ? 5 : 0, n = 13 + nc + na + 2;
  struct vsph_particles *p = vsph_particles_alloc(n, 2);
  ck_assert_ptr_nonnull(p);
  p->n = n;
  for (size_t i = 0; i < n; i++) {
    if (i < 3) { /* the three */
      p->pos[0][i] = 0.1 + 0.1 * (double)i;
      p->pos[1][i] = 0.25;
    } else if (i < 13) { /* beyond their support */
      p->pos[0][i] = 0.95;
      p->pos[1][i] = 0.05 + 0.04 * (double)(i - 3);
    } else if (i < 13 + nc) { /* the cluster */
      p->pos[0][i] = 0.55 + 0.005 * (double)((i - 13) % 10);
      p->pos[1][i] = 0.225 + 0.005 * (double)((i - 13) / 10);
    } else { /* the row above */
      p->pos[0][i] = 0.2 + 0.02 * (double)(i - 13 - nc);
      p->pos[1][i] = 0.6;
    }
    p->id[i] = i;
    p->rho[i] = RHO0;
    p->vol[i] = 1e-3;
    p->m[i] = RHO0 * 1e-3;
  }
  /* the grid's corners (0, 0.05) and (2.4, 1.45), out of reach */
  p->pos[0][n - 2] = 0.0;
  p->pos[1][n - 2] = 1.45;
  p->pos[0][n - 1] = 2.4;
  p->pos[1][n - 1] = 1.45;
  struct vsph_cells *cells = vsph_cells_alloc();
  ck_assert_int_eq(vsph_cells_build(cells, p, 1.0), 0); /* edge 0.5 */
  struct vsph_pair_kernel pk;
  vsph_pair_kernel_init(&pk, &vsph_gaussian_type, 2, 0.2); /* 3h = 0.6 */
  for (int level = 1; level <= pk.simd; level++) {
    size_t joint = 0, alone = 0, midrow = 0;
    cells_agree(p, cells, &pk, level, &joint, &alone, &midrow);
    if (_i) /* the three go on at their row's end */
      ck_assert_uint_ge(alone - midrow, 3);
    else
      ck_assert_uint_ge(midrow, 3); /* the three, and the cluster's own */
  }
  vsph_cells_free(cells);
  vsph_particles_free(p);
}
END_TEST

/* The joint walk's guards, receivers 8-11 of a random 2-D set: where
 * their "cell" spans two touching ranges (0-10, 10-40) they walk alone,
 * and so does a receiver begun out of turn (8 and 9 after 10 and 11 made
 * their group, the ranges one, 0-40): at each level the CPU has, each
 * gets the portable walk's chunks. */
START_TEST(test_joint_walk_guards) {
  struct vsph_particles *p = random_set(2, 5);
  struct vsph_pair_kernel pk;
  vsph_pair_kernel_init(&pk, &vsph_gaussian_type, 2, HDX * DX * 3.0);
  const struct vsph_pair_ranges two = {.n = 2, .lo = {0, 10}, .hi = {10, 40}},
                                one = {.n = 1, .lo = {0}, .hi = {40}};
  static struct vsph_pair_cell pc;
  static struct vsph_pair_chunk own, b1;
  const size_t order[2][4] = {{8, 9, 10, 11}, {10, 8, 9, 11}};
  for (int level = 1; level <= pk.simd; level++)
    for (int c = 0; c < 2; c++) {
      const struct vsph_pair_ranges *rg = c ? &one : &two;
      struct vsph_pair_kernel pl = pk, p0 = pk;
      pl.simd = level;
      p0.simd = 0;
      vsph_pair_cell_begin(&pc, &pl, 8, 4, 2);
      size_t pairs = 0;
      for (int t = 0; t < 4; t++) {
        struct vsph_pair_iter it, i1;
        vsph_pair_begin_upper_in(&it, &pl, p, rg, &pc, order[c][t]);
        vsph_pair_begin_upper(&i1, &p0, p, rg, order[c][t]);
        for (;;) {
          const struct vsph_pair_chunk *b0;
          const size_t m0 = vsph_pair_next_chunk(&it, 2, pk.dfq_id, 1, &own,
                                                 &b0),
                       m1 = vsph_pair_gather_as(&i1, 2, pk.dfq_id, 1, &b1);
          ck_assert_uint_eq(m0, m1);
          if (!m0) break;
          pairs += m0;
          ck_assert(!memcmp(b0->j, b1.j, m0 * sizeof b1.j[0]));
          ck_assert(!memcmp(b0->s2, b1.s2, m0 * sizeof(double)));
        }
      }
      ck_assert_uint_gt(pairs, 40); /* a support of many neighbours */
    }
  vsph_particles_free(p);
}
END_TEST

START_TEST(test_candidates_simd) {
  const int dim = 2 + _i / 2;
  struct vsph_particles *p = random_set(dim, 11 + (unsigned long)_i);
  const struct vsph_kernel_type *k =
      _i % 2 ? &vsph_quintic_type : &vsph_gaussian_type;
  const double h = HDX * DX;
  struct vsph_cells *cells = vsph_cells_alloc();
  ck_assert_int_eq(vsph_cells_build(cells, p, k->kappa * h), 0);
  struct vsph_pair_kernel pk;
  vsph_pair_kernel_init(&pk, k, dim, h);
  const int most = pk.simd;
  if (most < 2)
    fprintf(stderr,
            "test_candidates_simd: this build or CPU (or VSPH_PAIR_SIMD) "
            "allows %s only\n",
            most ? "AVX2" : "the portable loop");
  for (int level = 1; level <= most; level++) {
    size_t fullest = 0;
    /* about 3 pi (kappa h/dx)^2 / 2 pairs a particle in 2-D, more in
     * 3-D, the two walks (fewer at the free surfaces all round) */
    ck_assert_uint_gt(walks_agree(p, cells, NULL, &pk, level, &fullest),
                      20 * p->n);
    /* every particle a neighbour of every other (one range over the set,
     * a support wider than the patch): the chunks fill to their last
     * entry, where the whole-vector stores end */
    struct vsph_pair_kernel wide;
    vsph_pair_kernel_init(&wide, k, dim, 100.0 * h);
    struct vsph_pair_ranges all;
    vsph_pair_ranges_all(&all, p->n);
    fullest = 0;
    (void)walks_agree(p, NULL, &all, &wide, level, &fullest);
    ck_assert_uint_eq(fullest, VSPH_PAIR_CHUNK_MAX);
    /* an empty range first, and one candidate */
    struct vsph_pair_ranges odd = {.n = 3, .lo = {0, 5, 7}, .hi = {0, 6, 7}};
    (void)walks_agree(p, NULL, &odd, &wide, level, &fullest);
    /* the cells' joint walks: most walks take one (cells of about
     * 2^dim particles); in 3-D (about 130 neighbours j > i) or with the
     * wider support (3h in 2-D: 20 cells' worth of candidates above,
     * fewer neighbours) some are left to walk alone */
    size_t joint = 0, alone = 0, midrow = 0;
    cells_agree(p, cells, &pk, level, &joint, &alone, &midrow);
    ck_assert_uint_gt(joint, p->n / 4);
    if (dim == 3) ck_assert_uint_gt(alone, 0);
    /* 3-D: a cluster of 200 particles in a 1/10-cell box; the rows
     * through it hold more than a block (64 candidates), so the walks of
     * the sparse cells beside it fill their first chunk inside a row */
    if (dim == 3) {
      struct vsph_particles *q = random_set(dim, 11 + (unsigned long)_i);
      for (size_t c = 0; c < 200; c++)
        for (int a = 0; a < dim; a++)
          q->pos[a][(c * 7) % q->n] =
              q->pos[a][q->n / 2] +
              0.1 * cells->edge * (double)((c * (size_t)(a + 3)) % 17) / 17.0;
      struct vsph_cells *qc = vsph_cells_alloc();
      ck_assert_int_eq(vsph_cells_build(qc, q, k->kappa * h), 0);
      joint = alone = midrow = 0;
      cells_agree(q, qc, &pk, level, &joint, &alone, &midrow);
      ck_assert_uint_gt(midrow, 0);
      vsph_cells_free(qc);
      vsph_particles_free(q);
    }
  }
  vsph_cells_free(cells);
  vsph_particles_free(p);
}
END_TEST

/* The specialised gathers of the transport-velocity cavity (2-D quintic
 * spline, h = dx, after Adami et al.), of the channels (2-D cubic
 * B-spline, h/dx 1.5699, after Basa et al.) and a family's gather for any
 * other shape (the Wendland kernels), case by case: on 1 and 2
 * threads they give the same bits; against the general loop on the same
 * particles (Solver's loop_general) the same interactions and closest
 * pair, and each field to 1e-12 of the size of its terms (the same pair
 * functions, sums in another order; the scales as in
 * test_sweep_gather_threads). The cavity's Adami walls (summation
 * density, wall pressure and velocity) with the quintic inlined equal the
 * general kernel's to 1e-13 (sums of ~30 terms in another order). */
START_TEST(test_gather_shapes) {
  static const struct {
    const struct vsph_scene_type *type;
    const struct vsph_kernel_type *k;
    double hdx;
    int tvf, form;
  } cases[] = {
      {&vsph_cavity_type, &vsph_quintic_type, 1.0, 1, VSPH_VISCOUS_MGF},
      {&vsph_cavity_type, &vsph_quintic_type, 1.0, 1, VSPH_VISCOUS_MEAF},
      {&vsph_cavity_type, &vsph_quintic_type, 1.0, 1, VSPH_VISCOUS_ER},
      {&vsph_cavity_type, &vsph_quintic_type, 1.0, 1, VSPH_VISCOUS_VI},
      {&vsph_channel_poiseuille_type, &vsph_cubic_type, 1.5699, 0,
       VSPH_VISCOUS_MGF},
      {&vsph_channel_poiseuille_type, &vsph_cubic_type, 1.5699, 0,
       VSPH_VISCOUS_MEAF},
      {&vsph_channel_poiseuille_type, &vsph_cubic_type, 1.5699, 0,
       VSPH_VISCOUS_PVWF},
      {&vsph_channel_poiseuille_type, &vsph_cubic_type, 1.5699, 0,
       VSPH_VISCOUS_ER},
      {&vsph_channel_couette_type, &vsph_cubic_type, 1.5699, 0,
       VSPH_VISCOUS_CLEARY},
      {&vsph_channel_couette_type, &vsph_cubic_type, 1.5699, 0,
       VSPH_VISCOUS_TWOPASS},
      /* a family's loop for any other shape (Wendland kernels) */
      {&vsph_standing_wave_type, &vsph_wendland_c2_type, 1.5699, 0,
       VSPH_VISCOUS_MGF},
      {&vsph_channel_poiseuille_type, &vsph_wendland_c4_type, 1.5699, 0,
       VSPH_VISCOUS_ER}};
  const int c = _i;
  struct vsph_integrate_props ip;
  struct vsph_integrate *s =
      scene_stepped_k(cases[c].type, cases[c].form, cases[c].tvf ? 16 : 32, 0.0,
                      cases[c].k, cases[c].hdx, cases[c].tvf, &ip);
  const char *name = cases[c].type->name;
  const char *form = vsph_viscous_name(cases[c].form);
  const size_t n = s->p->n;
  char label[96];
  snprintf(label, sizeof label, "%s %s, specialised against general", name,
           form);
  double *buf = loops_agree(s, &ip, label);
  if (cases[c].tvf) { /* the Adami walls, general then inlined */
    struct vsph_particles *p = s->p;
    const size_t cols = 5;
    double *w = calloc(2 * cols * n, sizeof *w);
    for (int pass = 0; pass < 2; pass++) {
      s->props.eq.loop_general = !pass;
      ck_assert_int_eq(vsph_equations_walls_adami(&s->props.eq, &s->props.walls,
                                                  p, s->n_fluid, s->cells),
                       0);
      double *o = w + (size_t)pass * cols * n;
      memcpy(o, p->rho, n * sizeof *o);
      memcpy(o + n, p->p, n * sizeof *o);
      memcpy(o + 2 * n, p->vol, n * sizeof *o);
      memcpy(o + 3 * n, p->vel[0], n * sizeof *o);
      memcpy(o + 4 * n, p->vel[1], n * sizeof *o);
    }
    s->props.eq.loop_general = 0;
    static const char *const col[5] = {"rho", "p", "vol", "u", "v"};
    double rho_max = 0.0;
    for (size_t i = 0; i < n; i++) rho_max = fmax(rho_max, fabs(w[i]));
    for (size_t q = 0; q < cols; q++) {
      double scale = 0.0, err = 0.0;
      for (size_t i = 0; i < n; i++) {
        scale = fmax(scale, fabs(w[q * n + i]));
        err = fmax(err, fabs(w[q * n + i] - w[(cols + q) * n + i]));
      }
      /* the fluid's p is the state law's c0^2 (rho - rho0) of a summed
       * density that agrees to 1e-13 of rho (the row above), and the
       * walls' p is made from the fluid's: its bound is c0^2 times that,
       * not a share of p itself, which is small beside the ulps of rho it
       * is the difference of (a build of 8 lanes sums rho in another
       * order and shows it: 4.4e-14 of p's largest, 2.4e-2) */
      if (q == 1)
        scale = fmax(scale, s->props.eq.c0 * s->props.eq.c0 * rho_max);
      ck_assert_msg(scale > 0.0 && err <= 1e-13 * scale,
                    "walls %s: |inlined - general| %.3e of %.3e", col[q], err,
                    scale);
    }
    free(w);
  }
  free(buf);
  vsph_integrate_free(s);
}
END_TEST

/* Contact SPH's specialised loops of the 3h Gaussian (2-D: the bench's
 * stretching square, contact SPH with the scene's viscosity, and
 * inviscid), as test_gather_shapes: 1 and 2 threads the same bits, and
 * against the general loop (Solver's loop_general) the same interactions
 * and closest pair and each field to 1e-12 of its terms' size. */
START_TEST(test_contact_shapes) {
  struct vsph_integrate_props ip;
  struct vsph_integrate *s =
      scene_stepped_k(&vsph_stretching_square_type, VSPH_VISCOUS_MEAF, 24, 0.0,
                      &vsph_gaussian_type, VSPH_CONSTS_HDX, 0, &ip);
  s->props.eq.scheme = VSPH_EQUATIONS_CONTACT;
  s->props.eq.nmat = 1;
  s->props.eq.mat[0] = (struct vsph_equations_mat){
      .rho0 = ip.eq.rho0, .c0 = ip.eq.c0, .mu = _i ? 0.0 : ip.eq.visc.mu};
  ip.eq.visc.mu = s->props.eq.mat[0].mu; /* the scales */
  double *buf = loops_agree(s, &ip,
                            _i ? "contact SPH, inviscid, Gaussian 2-D"
                               : "contact SPH, viscous, Gaussian 2-D");
  free(buf);
  vsph_integrate_free(s);
}
END_TEST

/* Contact SPH's dissipative parts hold the physical viscosity as the
 * force does (the 3h Gaussian; 2-D: the stretching square at 24 across
 * after three steps; 3-D: the shear box, shear3, with its z velocity): the
 * viscous traction g enters the acceleration as sum (f + g)/rho and its
 * dissipative part as sum (fd + g)/rho, f and fd not depending on the
 * viscosity, so between the scene's viscosity and none, acc_visc changes
 * by what acc changes, particle by particle and component by component,
 * to rounding: two sums of ~50 terms in another order, the terms up to
 * about L/h = 20 times the sums they cancel to, so ~50 x 1.1e-16 x 20 =
 * 1e-13 of the largest acceleration; 1e-12 allowed. In each component the
 * change is no rounding (over 1e-6 of the largest). A traction left out
 * of either sum, or of one component, changes one and not the other. */
START_TEST(test_contact_parts_viscous) {
  struct vsph_integrate_props ip;
  struct vsph_integrate *s =
      _i ? shear3(VSPH_VISCOUS_MEAF, 1)
         : scene_stepped_k(&vsph_stretching_square_type, VSPH_VISCOUS_MEAF, 24,
                           0.0, &vsph_gaussian_type, VSPH_CONSTS_HDX, 0, &ip);
  if (!_i) {
    s->props.eq.scheme = VSPH_EQUATIONS_CONTACT;
    s->props.eq.nmat = 1;
    s->props.eq.mat[0] = (struct vsph_equations_mat){
        .rho0 = ip.eq.rho0, .c0 = ip.eq.c0, .mu = ip.eq.visc.mu};
  }
  const int dim = s->p->dim;
  /* in the 3-D box the acoustic solver's velocity term, rho0 c0 du/h,
   * outweighs the scene's viscous one by about 1e16 (its 1e-7 m scale):
   * a viscosity of rho0 c0 h there makes the two alike */
  const double mu =
      _i ? s->props.eq.mat[0].rho0 * s->props.eq.mat[0].c0 * s->props.eq.visc.h
         : s->props.eq.mat[0].mu;
  ck_assert(mu > 0.0);
  const size_t n = s->p->n, nout = (size_t)(2 * dim + 2);
  double *buf = calloc(2 * nout * n, sizeof *buf);
  for (int v = 0; v < 2; v++) { /* the scene's viscosity, then none */
    s->props.eq.mat[0].mu = v ? 0.0 : mu;
    double *const o = buf + (size_t)v * nout * n;
    struct vsph_equations_out out = {
        .drho = o, .drho_delta = o + (2 * (size_t)dim + 1) * n};
    for (int a = 0; a < dim; a++) {
      out.acc[a] = o + (size_t)(1 + a) * n;
      out.acc_visc[a] = o + (size_t)(1 + dim + a) * n;
    }
    ck_assert_int_eq(vsph_equations_rhs(&s->props.eq, s->p, s->n_fluid,
                                        s->cells, s->vws, &out),
                     0);
  }
  double big = 0.0, dv[3] = {0, 0, 0}, err = 0.0;
  const double *const o = buf, *const z = buf + nout * n;
  for (int a = 0; a < dim; a++)
    for (size_t i = 0; i < n; i++) {
      if (s->p->id[i] >= s->n_fluid) continue;
      const size_t ea = (1 + (size_t)a) * n + i,
                   ev = (1 + (size_t)dim + (size_t)a) * n + i;
      const double dacc = o[ea] - z[ea], dvis = o[ev] - z[ev];
      big = fmax(big, fmax(fabs(o[ea]), fabs(o[ev])));
      dv[a] = fmax(dv[a], fabs(dacc));
      err = fmax(err, fabs(dvis - dacc));
    }
  for (int a = 0; a < dim; a++)
    ck_assert_msg(dv[a] > 1e-6 * big,
                  "%d-D: the viscosity changes acc %d by %.3e of %.3e", dim, a,
                  dv[a], big);
  ck_assert_msg(err <= 1e-12 * big,
                "%d-D: acc_visc's change differs from acc's by %.3e of %.3e",
                dim, err, big);
  free(buf);
  vsph_integrate_free(s);
}
END_TEST

/* The 3-D Gaussian loop of contact SPH (the shear scene, 8 across,
 * contact SPH with its viscosity, after three steps): 1 and 2 threads the
 * same bits, and the general loop's interactions and each field to 1e-12
 * of the field's largest (the same pair functions; here the same order
 * too, so in practice the same bits). */
static void contact3(struct vsph_integrate *s, int thr, double *buf,
                     size_t *nint) {
  const size_t n = s->p->n;
  struct vsph_equations_out out = {.drho = buf,
                                   .acc = {buf + n, buf + 2 * n, buf + 3 * n}};
  omp_set_num_threads(thr);
  ck_assert_int_eq(vsph_equations_rhs(&s->props.eq, s->p, s->n_fluid, s->cells,
                                      s->vws, &out),
                   0);
  omp_set_num_threads(2);
  *nint = out.interactions;
}

START_TEST(test_contact_shapes_3d) {
  struct vsph_integrate *s = shear3_stepped(VSPH_VISCOUS_MEAF, 1);
  const size_t n = s->p->n;
  double *buf = calloc(12 * n, sizeof *buf);
  size_t n1, n2, ng;
  contact3(s, 1, buf + 4 * n, &n1);
  contact3(s, 2, buf + 8 * n, &n2);
  s->props.eq.loop_general = 1;
  contact3(s, 1, buf, &ng);
  s->props.eq.loop_general = 0;
  ck_assert(memcmp(buf + 4 * n, buf + 8 * n, 4 * n * sizeof *buf) == 0);
  ck_assert(ng > 0 && n1 == ng && n2 == ng);
  for (int q = 0; q < 4; q++) {
    double big = 0.0, err = 0.0;
    for (size_t i = 0; i < n; i++) {
      if (s->p->id[i] >= s->n_fluid) continue;
      big = fmax(big, fabs(buf[q * n + i]));
      err = fmax(err, fabs(buf[q * n + i] - buf[(4 + q) * n + i]));
    }
    ck_assert_msg(big > 0.0 && err <= 1e-12 * big, "field %d: %.3e of %.3e", q,
                  err, big);
  }
  free(buf);
  vsph_integrate_free(s);
}
END_TEST

/* XSPH's drift velocity (vsph_equations_xsph) on a random set, 2-D and
 * 3-D, against an O(N^2) sum written here, w_i = u_i + eps sum_j
 * (m_j/rho_j) (u_j - u_i) W(|r_j - r_i|) over every other particle within
 * the support: 1e-12 of max |u| (~60 terms of mixed sign); and a uniform
 * velocity drifts as it is, to rounding. */
START_TEST(test_xsph_sum) {
  const int dim = 2 + _i;
  struct vsph_particles *p = random_set(dim, 77 + (unsigned long)_i);
  struct vsph_equations_props ep = {.rho0 = RHO0, .c0 = C0};
  const double h = HDX * DX, eps = 0.3;
  ck_assert_int_eq(vsph_viscous_props_init(&ep.visc, VSPH_VISCOUS_MGF,
                                           &vsph_cubic_type, dim, h, MU),
                   0);
  struct vsph_cells *cells = vsph_cells_alloc();
  ck_assert_int_eq(vsph_cells_build(cells, p, 2.0 * h), 0);
  double *w[3] = {NULL, NULL, NULL};
  for (int k = 0; k < dim; k++) w[k] = calloc(p->n, sizeof(double));
  vsph_equations_xsph(&ep, p, p->n, cells, eps, w);
  size_t busy = 0;
  for (size_t i = 0; i < p->n; i++) {
    double s[3] = {0, 0, 0};
    size_t nb = 0;
    for (size_t j = 0; j < p->n; j++) {
      if (j == i) continue;
      double r2 = 0.0;
      for (int k = 0; k < dim; k++)
        r2 += (p->pos[k][j] - p->pos[k][i]) * (p->pos[k][j] - p->pos[k][i]);
      const double q = sqrt(r2) / h;
      if (!(q < 2.0)) continue;
      nb++;
      const double W = vsph_kernel_w(&vsph_cubic_type, dim, q) / pow(h, dim);
      for (int k = 0; k < dim; k++)
        s[k] += p->m[j] / p->rho[j] * (p->vel[k][j] - p->vel[k][i]) * W;
    }
    busy += nb > 10;
    for (int k = 0; k < dim; k++)
      ck_assert_double_eq_tol(w[k][i], p->vel[k][i] + eps * s[k], 1e-12);
  }
  ck_assert_uint_gt(busy, p->n / 2); /* most have full neighbourhoods */
  for (size_t i = 0; i < p->n; i++)
    for (int k = 0; k < dim; k++) p->vel[k][i] = 0.25 * (k + 1);
  vsph_equations_xsph(&ep, p, p->n, cells, eps, w);
  for (size_t i = 0; i < p->n; i++)
    for (int k = 0; k < dim; k++)
      ck_assert_double_eq_tol(w[k][i], 0.25 * (k + 1), 1e-15);
  for (int k = 0; k < dim; k++) free(w[k]);
  vsph_cells_free(cells);
  vsph_particles_free(p);
}
END_TEST

/* ------------------------------------ state equations and the reduction */

/* The right-hand side of a random set (free surface, no ghosts) with the
 * state equation eos, pressure reduction reduce, no viscosity and no
 * delta-SPH; p->acc holds the acceleration, p->de the gas's energy rate. */
static void rhs_eos(struct vsph_particles *p, int eos, int reduce,
                    struct vsph_equations_props *ep) {
  *ep = (struct vsph_equations_props){
      .rho0 = RHO0, .c0 = C0, .eos = eos, .reduce = reduce};
  ck_assert_int_eq(
      vsph_viscous_props_init(&ep->visc, VSPH_VISCOUS_MGF, &vsph_gaussian_type,
                              p->dim, HDX * DX, 0.0),
      0);
  struct vsph_cells *cells = vsph_cells_alloc();
  ck_assert_int_eq(vsph_cells_build(cells, p, 3.0 * ep->visc.h), 0);
  struct vsph_equations_out out = {.drho = p->drho, .de = p->de};
  for (int k = 0; k < p->dim; k++) out.acc[k] = p->acc[k];
  ck_assert_int_eq(vsph_equations_rhs(ep, p, p->n, cells, NULL, &out), 0);
  vsph_cells_free(cells);
}

/* Tait's law (Basa's eq. 13), the gas law and the isothermal law (p =
 * c0^2 rho, Morris et al.'s) against their closed forms,
 * and the energies: on a random set without viscosity or delta-SPH the
 * pressure terms exchange kinetic and compressible energy only, so
 * dEk/dt + dEc/dt = 0 to rounding (1e-12 of sum |m u.a|: ~1e3 terms of
 * mixed sign). For Tait and the isothermal law dEc uses e'(rho) = p/rho^2
 * of Ec's closed form
 * (checked by a centred difference of Ec in rho, 1e-7: step 1e-5, error
 * O(step^2)); for the gas, dEc = sum m de/dt of the energy equation. */
START_TEST(test_state_equations) {
  static const int EOS[3] = {VSPH_EQUATIONS_EOS_TAIT, VSPH_EQUATIONS_EOS_GAS,
                             VSPH_EQUATIONS_EOS_ISOTHERMAL};
  const int eos = EOS[_i];
  struct vsph_particles *p = random_set(2, 515);
  const double e0 = C0 * C0 / (1.4 * 0.4); /* p0/((gamma-1) rho0) */
  ck_assert_int_eq(vsph_particles_energy_alloc(p), 0);
  for (size_t i = 0; i < p->n; i++)
    p->e[i] = e0 * (0.95 + 0.1 * (double)(i % 7) / 7.0);
  struct vsph_equations_props ep;
  rhs_eos(p, eos, 0, &ep);
  for (size_t i = 0; i < p->n; i += 17) {
    const double r = p->rho[i] / RHO0;
    const double want = eos == VSPH_EQUATIONS_EOS_TAIT
                            ? RHO0 * C0 * C0 / 7.0 * (pow(r, 7.0) - 1.0)
                        : eos == VSPH_EQUATIONS_EOS_GAS
                            ? 0.4 * p->rho[i] * p->e[i]
                            : C0 * C0 * p->rho[i];
    ck_assert_double_eq_tol(p->p[i], want, 1e-14 * fabs(RHO0 * C0 * C0));
  }
  ck_assert_double_eq_tol(vsph_equations_gas_e0(&ep), e0, 1e-14 * e0);
  struct vsph_equations_out out = {.drho = p->drho, .de = p->de};
  for (int k = 0; k < 2; k++) out.acc[k] = p->acc[k];
  struct vsph_equations_budget b;
  vsph_equations_budget_compute(&ep, p, p->n, &out, &b);
  double scale = 0.0;
  for (size_t i = 0; i < p->n; i++)
    scale += p->m[i] * (fabs(p->vel[0][i] * p->acc[0][i]) +
                        fabs(p->vel[1][i] * p->acc[1][i]));
  ck_assert_double_gt(fabs(b.dEk), 1e-3 * scale);
  ck_assert_double_le(fabs(b.dEk + b.dEc), 1e-12 * scale);
  if (eos != VSPH_EQUATIONS_EOS_GAS) { /* e'(rho) of Ec = p/rho^2 */
    struct vsph_particles *q = vsph_particles_alloc(1, 2);
    q->n = 1;
    q->m[0] = 1.0;
    q->id[0] = 0;
    const double rho = 1.013 * RHO0, dr = 1e-5 * RHO0;
    struct vsph_equations_energy ea, eb;
    q->rho[0] = rho + dr;
    vsph_equations_energy_compute(&ep, q, 1, &ea);
    q->rho[0] = rho - dr;
    vsph_equations_energy_compute(&ep, q, 1, &eb);
    const double pr = eos == VSPH_EQUATIONS_EOS_TAIT
                          ? RHO0 * C0 * C0 / 7.0 * (pow(1.013, 7.0) - 1.0)
                          : C0 * C0 * rho;
    ck_assert_double_eq_tol((ea.Ec - eb.Ec) / (2 * dr), pr / (rho * rho),
                            1e-7 * pr / (rho * rho));
    vsph_particles_free(q);
  }
  vsph_particles_free(p);
}
END_TEST

/* Basa et al.'s pressure reduction (eq. 20, our form (9) analogue
 * p_i + p_j - 2 pbar_i): against an O(N^2) twin with its own neighbour
 * mean (i counted, Basa's "neighbours of a include a"), to 1e-11 as the
 * twin above; and a uniform pressure on the disordered set then gives no
 * force at all (the digest's [D] property), to rounding, while without the
 * reduction it gives sum_j V_j 2 p grad W != 0. */
START_TEST(test_pressure_reduction) {
  struct vsph_particles *p = random_set(2, 616);
  const size_t n = p->n;
  struct vsph_equations_props ep;
  rhs_eos(p, VSPH_EQUATIONS_EOS_LINEAR, 1, &ep);
  double scale = 0.0, err = 0.0;
  for (size_t i = 0; i < n; i++) {
    double pn = 0.0, cnt = 1.0, a[2] = {0, 0};
    for (size_t j = 0; j < n; j++) {
      double x[3];
      if (twin_F(ep.visc.kernel, 2, ep.visc.h, p, i, j, x) == 0.0) continue;
      pn += C0 * C0 * (p->rho[j] - RHO0);
      cnt += 1.0;
    }
    const double pi = C0 * C0 * (p->rho[i] - RHO0), pbar = (pi + pn) / cnt;
    for (size_t j = 0; j < n; j++) {
      double x[3];
      const double F = twin_F(ep.visc.kernel, 2, ep.visc.h, p, i, j, x);
      if (F == 0.0) continue;
      const double pj = C0 * C0 * (p->rho[j] - RHO0);
      for (int k = 0; k < 2; k++) /* -(1/rho_i) V_j (..) grad_i W */
        a[k] += p->vol[j] * (pi + pj - 2.0 * pbar) * F * x[k] / p->rho[i];
    }
    for (int k = 0; k < 2; k++) {
      scale = fmax(scale, fabs(a[k]));
      err = fmax(err, fabs(p->acc[k][i] - a[k]));
    }
  }
  ck_assert_double_gt(scale, 0.0);
  ck_assert_double_le(err, 1e-11 * scale);
  for (size_t i = 0; i < n; i++) p->rho[i] = 1.01 * RHO0; /* uniform p */
  double with = 0.0, without = 0.0;
  rhs_eos(p, VSPH_EQUATIONS_EOS_LINEAR, 1, &ep);
  for (size_t i = 0; i < n; i++) with = fmax(with, fabs(p->acc[0][i]));
  rhs_eos(p, VSPH_EQUATIONS_EOS_LINEAR, 0, &ep);
  for (size_t i = 0; i < n; i++) without = fmax(without, fabs(p->acc[0][i]));
  ck_assert_double_gt(without, 0.0);
  ck_assert_double_le(with, 1e-12 * without);
  vsph_particles_free(p);
}
END_TEST

/* ------------------------------------------ Basa et al.'s corrections */

/* The right-hand side of @p p with correction @p corr, formulation
 * @p form, the linear law, no delta-SPH; acc and drho into p. */
static void rhs_corr(struct vsph_particles *p, int form, int corr,
                     struct vsph_equations_props *ep) {
  const int general = ep->loop_general;
  *ep = (struct vsph_equations_props){
      .rho0 = RHO0, .c0 = C0, .corr = corr, .loop_general = general};
  ck_assert_int_eq(vsph_viscous_props_init(&ep->visc, form, &vsph_gaussian_type,
                                           p->dim, HDX * DX, MU),
                   0);
  ep->visc.zeta = 0.731 * MU;
  struct vsph_cells *cells = vsph_cells_alloc();
  ck_assert_int_eq(vsph_cells_build(cells, p, 3.0 * ep->visc.h), 0);
  struct vsph_viscous_ws *ws = vsph_viscous_ws_alloc(p->n, p->dim);
  ck_assert_int_eq(vsph_viscous_ws_corr(ws), 0);
  struct vsph_equations_out out = {.drho = p->drho};
  for (int k = 0; k < p->dim; k++) out.acc[k] = p->acc[k];
  ck_assert_int_eq(vsph_equations_rhs(ep, p, p->n, cells, ws, &out), 0);
  vsph_viscous_ws_free(ws);
  vsph_cells_free(cells);
}

/* Exactness on the perturbed patch with its free surface (Basa et al.
 * section 4; the digest's [R] on the full Shepard gradient): with either
 * correction a uniform pressure gives no force at all (sum_j V_j g_ij = 0,
 * i's own term included), and with Bonet-Lok's the continuity sum of a
 * linear velocity u = B x is -rho tr B at every particle, the surface ones
 * too. Tolerance 1e-11 of the uncorrected values (sums of ~50 terms of
 * size 1/h to rounding; the uncorrected error is O(1) at the surface). */
START_TEST(test_corr_exact) {
  const int dim = 2 + _i;
  struct vsph_particles *p = random_set(dim, 777 + (unsigned long)_i);
  const double B[3][3] = {{0.3, -1.1, 0.4}, {0.7, 0.5, -0.2}, {0.1, 0.9, -0.6}};
  double trB = 0.0;
  for (int a = 0; a < dim; a++) trB += B[a][a];
  for (size_t i = 0; i < p->n; i++) {
    p->rho[i] = 1.01 * RHO0; /* uniform pressure */
    p->vol[i] = p->m[i] / p->rho[i];
    for (int a = 0; a < dim; a++) {
      p->vel[a][i] = 0.0;
      for (int b = 0; b < dim; b++) p->vel[a][i] += B[a][b] * p->pos[b][i];
    }
  }
  struct vsph_equations_props ep = {.loop_general = 0};
  double ref_a = 0.0, ref_d = 0.0; /* the uncorrected errors' scale */
  for (int corr = 0; corr < VSPH_PAIR_CORR_COUNT; corr++) {
    rhs_corr(p, VSPH_VISCOUS_MGF, corr, &ep);
    double ed = 0.0; /* continuity against -rho div u */
    for (size_t i = 0; i < p->n; i++)
      ed = fmax(ed, fabs(p->drho[i] + p->rho[i] * trB));
    if (corr == VSPH_PAIR_CORR_NONE)
      ref_d = ed;
    else if (corr == VSPH_PAIR_CORR_BONETLOK)
      ck_assert_msg(ed <= 1e-11 * ref_d, "Bonet-Lok div u: %.3e of %.3e", ed,
                    ref_d);
  }
  ck_assert_double_gt(ref_d, 1e-3 * fabs(RHO0 * trB));
  /* uniform pressure, no velocity: the pressure force alone */
  for (size_t i = 0; i < p->n; i++)
    for (int a = 0; a < dim; a++) p->vel[a][i] = 0.0;
  for (int corr = 0; corr < VSPH_PAIR_CORR_COUNT; corr++) {
    rhs_corr(p, VSPH_VISCOUS_MEAF, corr, &ep);
    double ea = 0.0;
    for (size_t i = 0; i < p->n; i++)
      for (int a = 0; a < dim; a++) ea = fmax(ea, fabs(p->acc[a][i]));
    if (corr == VSPH_PAIR_CORR_NONE)
      ref_a = ea;
    else
      ck_assert_msg(ea <= 1e-11 * ref_a,
                    "correction %d, uniform p: %.3e of %.3e", corr, ea, ref_a);
  }
  ck_assert_double_gt(ref_a, 0.0);
  vsph_particles_free(p);
}
END_TEST

/* The corrected right-hand side against an O(N^2) twin written from Basa
 * et al.'s eqs. (21)-(26) (the full Shepard gradient, M with r_j - r_i,
 * GSL's LU inverse), for MGF, MEAF and Espanol-Revenga with each
 * correction, by the form's family's loop and by the general loop:
 * continuity and acceleration to 1e-11 of the largest value, as the twin
 * above. */
START_TEST(test_corr_twin) {
  static const int forms[3] = {VSPH_VISCOUS_MGF, VSPH_VISCOUS_MEAF,
                               VSPH_VISCOUS_ER};
  const int form = forms[_i % 3], corr = 1 + _i / 3, dim = 2;
  struct vsph_particles *p = random_set(dim, 4040 + (unsigned long)_i);
  const size_t n = p->n;
  double *tw = calloc(3 * n, sizeof *tw); /* drho, acc x, acc y, by id */
  /* the twin, on the input order */
  const double h = HDX * DX, sig = vsph_gaussian_type.sigma[1] / (h * h);
  const double e9 = exp(-9.0);
  for (size_t i = 0; i < n; i++) {
    double S = 0.0, a[2] = {0, 0};
    for (size_t j = 0; j < n; j++) {
      double x[3];
      const double F = twin_F(&vsph_gaussian_type, dim, h, p, i, j, x);
      const double s2 = x[0] * x[0] + x[1] * x[1];
      if (j != i && F == 0.0) continue;
      S += p->vol[j] * sig * (exp(-s2 / (h * h)) - e9);
      for (int k = 0; k < 2; k++) a[k] += p->vol[j] * (-F * x[k]);
    }
    /* g0_ij = grad W/S - W a/S^2, for every j within reach and j = i */
    gsl_matrix *M = gsl_matrix_calloc(2, 2), *L = gsl_matrix_alloc(2, 2);
    for (size_t j = 0; j < n; j++) {
      double x[3];
      const double F = twin_F(&vsph_gaussian_type, dim, h, p, i, j, x);
      if (F == 0.0) continue;
      const double W = sig * (exp(-(x[0] * x[0] + x[1] * x[1]) / (h * h)) - e9);
      for (int k = 0; k < 2; k++)
        for (int l = 0; l < 2; l++)
          *gsl_matrix_ptr(M, k, l) +=
              p->vol[j] * (-F * x[k] / S - W * a[k] / (S * S)) * x[l];
    }
    if (corr == VSPH_PAIR_CORR_BONETLOK) {
      gsl_permutation *perm = gsl_permutation_alloc(2);
      int sign;
      gsl_linalg_LU_decomp(M, perm, &sign);
      gsl_linalg_LU_invert(M, perm, L);
      gsl_permutation_free(perm);
    } else {
      gsl_matrix_set_identity(L);
    }
    const double pi = C0 * C0 * (p->rho[i] - RHO0), mu = MU;
    double cont = 0.0, acc[2] = {0, 0};
    for (size_t j = 0; j < n; j++) {
      double x[3];
      const double F = twin_F(&vsph_gaussian_type, dim, h, p, i, j, x);
      if (j != i && F == 0.0) continue;
      const double s2 = x[0] * x[0] + x[1] * x[1];
      const double W = sig * (exp(-s2 / (h * h)) - e9);
      double g0[2], g[2];
      for (int k = 0; k < 2; k++) g0[k] = -F * x[k] / S - W * a[k] / (S * S);
      for (int k = 0; k < 2; k++)
        g[k] =
            gsl_matrix_get(L, k, 0) * g0[0] + gsl_matrix_get(L, k, 1) * g0[1];
      const double V = p->vol[j], pj = C0 * C0 * (p->rho[j] - RHO0);
      for (int k = 0; k < 2; k++) acc[k] -= V * (pi + pj) * g[k] / p->rho[i];
      if (j == i) continue; /* the differenced terms have no own term */
      double du[2], dux = 0.0, xg = 0.0;
      for (int k = 0; k < 2; k++) {
        du[k] = p->vel[k][j] - p->vel[k][i];
        dux += du[k] * x[k];
        xg += x[k] * g[k];
      }
      cont -= V * (du[0] * g[0] + du[1] * g[1]);
      for (int k = 0; k < 2; k++) {
        double fv;
        if (form == VSPH_VISCOUS_MGF) /* K mu V (du.x)/s^2 g, K = 8 */
          fv = 8.0 * mu * V * dux / s2 * g[k];
        else if (form == VSPH_VISCOUS_MEAF) /* 2 mu V (x.g)/s^2 du */
          fv = 2.0 * mu * V * xg / s2 * du[k];
        else { /* -V (x.g)/s^2 (a du + b (du.x) x/s^2), 2-D */
          const double z = 0.731 * mu, ea = z - 2.0 * mu, eb = -4.0 * z;
          fv = -V * xg / s2 * (ea * du[k] + eb * dux * x[k] / s2);
        }
        acc[k] += fv / p->rho[i];
      }
    }
    tw[i] = p->rho[i] * cont;
    tw[n + i] = acc[0];
    tw[2 * n + i] = acc[1];
    gsl_matrix_free(M);
    gsl_matrix_free(L);
  }
  double *lib = calloc(3 * n, sizeof *lib);
  /* the form's family's loop, then the general one (its pair_g through
   * the descriptor) */
  for (int general = 0; general < 2; general++) {
    struct vsph_equations_props ep = {.loop_general = general};
    rhs_corr(p, form, corr, &ep); /* reorders p */
    for (size_t i = 0; i < n; i++) {
      lib[p->id[i]] = p->drho[i];
      lib[n + p->id[i]] = p->acc[0][i];
      lib[2 * n + p->id[i]] = p->acc[1][i];
    }
    assert_close(lib, tw, n, 1e-11, "corrected continuity");
    assert_close(lib + n, tw + n, n, 1e-11, "corrected acceleration x");
    assert_close(lib + 2 * n, tw + 2 * n, n, 1e-11, "corrected acceleration y");
  }
  free(lib);
  free(tw);
  vsph_particles_free(p);
}
END_TEST

Suite *vsph_pair_suite(void) {
  Suite *s = suite_create("pair");
  TCase *tc = tcase_create("twin");
  tcase_set_timeout(tc, 60);
  tcase_add_loop_test(tc, test_rhs_matches_brute_force_twin, 0,
                      4 * VSPH_VISCOUS_FORM_COUNT);
  tcase_add_loop_test(tc, test_twin_cubic, 0, 14);
  /* the scenes before the shear layer: it (3-D, a periodic depth below
   * these kernels' reach at 16 across) and the cylinders (two materials)
   * are contact SPH's, checked in tests/check_contact.c */
  size_t nwc = 0;
  while (vsph_scene_get(nwc) && vsph_scene_get(nwc) != &vsph_shear_type) nwc++;
  tcase_add_loop_test(tc, test_solver_equals_operator, 0,
                      (int)nwc * VSPH_VISCOUS_FORM_COUNT);
  suite_add_tcase(s, tc);
  return s;
}

/* solver/equations.c: the right-hand side's sweep and gather loops, the
 * state equations, XSPH, the pressure reduction and the corrections. */
Suite *vsph_equations_suite(void) {
  Suite *s = suite_create("equations");
  TCase *tc = tcase_create("rhs");
  tcase_set_timeout(tc, 60);
  tcase_add_loop_test(tc, test_rhs_leaves_others, 0, 48);
  tcase_add_test(tc, test_interactions_many);
  tcase_add_test(tc, test_interactions_in_lanes);
  size_t nwc = 0;
  while (vsph_scene_get(nwc) && vsph_scene_get(nwc) != &vsph_shear_type) nwc++;
  tcase_add_loop_test(tc, test_candidates_simd, 0, 4);
  tcase_add_loop_test(tc, test_joint_walk_resumes, 0, 2);
  tcase_add_test(tc, test_joint_walk_guards);
  tcase_add_loop_test(tc, test_sweep_scatter_simd, 0, 22);
  tcase_add_loop_test(tc, test_groups_threads_bitwise, 0, 4);
  tcase_add_loop_test(tc, test_groups_crowded, 0, 10);
  tcase_add_test(tc, test_groups_support_edge);
  tcase_add_loop_test(tc, test_groups_nonfinite_contained, 0, 4);
  tcase_add_loop_test(tc, test_closest_ghost_receiver, 0, 2);
  tcase_add_test(tc, test_sweep_addj_by_hand);
  tcase_add_loop_test(tc, test_groups_block_bounds, 0, 4);
  tcase_add_test(tc, test_grad_block_by_hand);
  tcase_add_test(tc, test_groups_dispatch_own_kernel);
  tcase_add_test(tc, test_sweep_lanes_by_hand);
  tcase_add_loop_test(tc, test_sweep_gather_threads, 0, (int)nwc * 5);
  tcase_add_loop_test(tc, test_sweep_gather_threads,
                      (int)vsph_scene_count() * 5,
                      (int)vsph_scene_count() * 5 + 1);
  tcase_add_loop_test(tc, test_contact_shapes, 0, 2);
  tcase_add_test(tc, test_contact_shapes_3d);
  tcase_add_loop_test(tc, test_contact_parts_viscous, 0, 2);
  tcase_add_loop_test(tc, test_gather_shapes, 0, 12);
  tcase_add_loop_test(tc, test_state_equations, 0, 3);
  tcase_add_loop_test(tc, test_xsph_sum, 0, 2);
  tcase_add_test(tc, test_pressure_reduction);
  tcase_add_loop_test(tc, test_corr_exact, 0, 2);
  tcase_add_loop_test(tc, test_corr_twin, 0, 6);
  suite_add_tcase(s, tc);
  return s;
}
