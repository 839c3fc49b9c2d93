/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
#ifndef VSPH_SOLVER_VISCOUS_H
#define VSPH_SOLVER_VISCOUS_H

#include <stddef.h>

#include "../common/api.h"
#include "../common/consts.h"
#include "../common/status.h"
#include "pair.h"

struct vsph_kernel_type;
struct vsph_particles;
struct vsph_cells;

/** @file viscous.h
 *  @brief The discrete viscous operators (div V)_i: the free-surface
 *  study's three of THEORY.md section 3 (Colagrossi et al. 2011, Eqs.
 *  4.18-4.20, 4.30: MGF, MEAF and PVWF, the renormalised two-pass form)
 *  and the ten more of docs/theory.md section 8 (Basa et al.'s models A-D,
 *  Espanol & Revenga, Zheng et al.'s VISC-01..04). Gather loops over a
 *  cell list: each particle's sum is taken by one thread in a fixed
 *  neighbour order, so the result is bitwise identical for any thread
 *  count. Each formulation is one descriptor (struct vsph_viscous_type,
 *  in its family's file of solver/forms/) holding its pair function (or,
 *  for the per-particle forms, one first pass built from pair.h's sums)
 *  and, for a family with loops of its own, those loops with the pair
 *  function inlined; the solver's right-hand side (equations.c) calls the
 *  same functions, so the operators exist once, and no code outside the
 *  descriptor table tells the forms apart. No I/O. */

/** Viscous formulation. */
enum vsph_viscous_form {
  VSPH_VISCOUS_MGF = 0, /*!< Monaghan & Gingold, Eq. (4.20) */
  VSPH_VISCOUS_MEAF,    /*!< Morris, Fox & Zhu 1997, Eq. (4.30) */
  VSPH_VISCOUS_PVWF,    /*!< principle of virtual work, Eqs. (4.18)-(4.19) */
  VSPH_VISCOUS_VI,      /*!< Violeau & Issa 2007 (Basa et al.'s model C) */
  VSPH_VISCOUS_CLEARY,  /*!< Cleary 1998 (Basa et al.'s model D), xi */
  VSPH_VISCOUS_TWOPASS, /*!< two-pass strain rate (Basa's model B; Vukcevic et
                           al. (2012)) */
  VSPH_VISCOUS_TAKEDA,  /*!< direct second derivatives (Basa's model A) */
  VSPH_VISCOUS_TAKEDA0, /*!< model A, Shepard-corrected (Basa's eq. 23) */
  VSPH_VISCOUS_ER,      /*!< Espanol & Revenga 2003, bulk viscosity zeta */
  VSPH_VISCOUS_VISC01,  /*!< Zheng et al.'s VISC-01: hybrid (Morris, eta) */
  VSPH_VISCOUS_VISC02,  /*!< VISC-02: twice-differentiated kernel */
  VSPH_VISCOUS_VISC03,  /*!< VISC-03: Schwaiger's corrected Laplacian */
  VSPH_VISCOUS_VISC04,  /*!< VISC-04: Oger's renormalised gradient */
  VSPH_VISCOUS_MEAFETA, /*!< Morris et al.'s original, with eta */
  VSPH_VISCOUS_FORM_COUNT
};

/** Every formulation's name, for the static help texts of the parameter
 *  tables (checked against the descriptor table by tests/check_viscous.c;
 *  what prints at run time comes from the table, vsph_viscous_list). */
#define VSPH_VISCOUS_NAMES                                              \
  "mgf, meaf, pvwf, vi, cleary, twopass, takeda, takeda0, er, visc01, " \
  "visc02, visc03, visc04, meafeta"

/** The free-surface study's formulations (Colagrossi et al. 2011) are the
 *  first this many (those flagged VSPH_VISCOUS_FREE_SURFACE, checked by
 *  tests/check_viscous.c); the report's free-surface ladders run these,
 *  the analysis and the internal flows run every form. */
#define VSPH_VISCOUS_PAPER_COUNT 3

/** The pair forms the kernel corrections and the transport-velocity
 *  scheme take, for static help texts (checked against the flag
 *  VSPH_VISCOUS_CORRIGIBLE by tests/check_viscous.c). */
#define VSPH_VISCOUS_CORRIGIBLE_NAMES "mgf, meaf, vi, cleary, er"

/** Cleary's calibrated coefficient (Couette flow). */
#define VSPH_VISCOUS_XI_CLEARY 4.96333

/** Basa et al.'s recalibrated coefficient (uncorrected Poiseuille,
 *  Re = 0.5, dx/h = 0.637). */
#define VSPH_VISCOUS_XI_BASA 4.24

/** The regulariser of models C and D: eta = 0.1 h (Basa et al. 2009). */
#define VSPH_VISCOUS_ETA 0.1

/** What the operators need: constant smoothing length and viscosities. */
struct vsph_viscous_props {
  enum vsph_viscous_form form;           /*!< formulation */
  int dim;                               /*!< 1, 2 or 3 */
  const struct vsph_kernel_type *kernel; /*!< smoothing kernel */
  double h;                              /*!< smoothing length (m) */
  double mu;                             /*!< dynamic viscosity (Pa s) */
  double lambda;  /*!< second viscosity (Pa s); MGF implies lambda = mu */
  double det_tol; /*!< PVWF: det(B) <= det_tol (tr B / d)^d counts as
                       singular and L falls back to the identity */
  double xi;      /*!< Cleary: K = 2 xi (default VSPH_VISCOUS_XI_CLEARY) */
  double eta;     /*!< Brookshaw forms: s^2 + (eta h)^2 (fraction of h) */
  double zeta;    /*!< Espanol-Revenga: bulk viscosity (Pa s), default 0 */
};

/** Per-particle scratch of the operators with a first pass: PVWF and
 *  model B (A_i), model A and VISC-01..04 (the force, whole from the first
 *  pass). */
struct vsph_viscous_ws {
  size_t cap;              /*!< particles it can hold */
  int dim;                 /*!< dimension */
  double *A[9];            /*!< A_i = T_i L_i, entry (a,b) in A[a*dim+b][i];
                                model A: its force density in A[0..dim-1] */
  double *dens;            /*!< PVWF, B: dissipation density -T_i:D_i;
                                A: u_i.(div V)_i */
  unsigned char *fallback; /*!< 1 where L_i fell back to the identity */
  size_t n_fallback;       /*!< how many particles fell back, last call */
  /* the kernel corrections of the right-hand side (vsph_viscous_ws_corr;
   * NULL without): per particle S = <1>, a = <grad 1>, Bonet-Lok's L */
  double *S;    /*!< sum_j V_j W_ij, j = i included */
  double *a[3]; /*!< sum_j V_j grad_i W_ij */
  double *L[9]; /*!< (sum_j V_j g0_ij (x) (r_j - r_i))^-1, row-major */
};

struct vsph_viscous_loop;

/** A formulation's first pass, if it has one (vsph_viscous_prepare). */
enum vsph_viscous_pass {
  VSPH_VISCOUS_PASS_NONE = 0, /*!< none: pair shares alone */
  VSPH_VISCOUS_PASS_STRESS,   /*!< each particle's stress A_i = T_i L_i
                                   from its velocity gradient (PVWF, B);
                                   the pair shares then take A_i + A_j:
                                   two neighbour passes */
  VSPH_VISCOUS_PASS_TAKEDA,   /*!< the whole force by direct second
                                   derivatives (Basa's model A) */
  VSPH_VISCOUS_PASS_LAPLACIAN /*!< the whole force as mu lap u by one of
                                   pair.h's Laplacians (VISC-01..04) */
};

/** Where a formulation applies and how it is built (bits of flags). */
#define VSPH_VISCOUS_FREE_SURFACE 1u /*!< the free-surface study's three */
#define VSPH_VISCOUS_CORRIGIBLE             \
  2u /*!< a sum of pair terms along grad W: \
          the kernel corrections apply */
#define VSPH_VISCOUS_RENORM                                             \
  4u                            /*!< stress pass: L = B^-1 (PVWF); else \
                                     L = I (Watkins' gradient) */
#define VSPH_VISCOUS_SHEPARD 8u /*!< Takeda pass: Shepard-corrected */
#define VSPH_VISCOUS_XI 16u     /*!< K = 2 xi (Cleary), not 2(d+2) */
#define VSPH_VISCOUS_TVF                         \
  32u /*!< runs the transport-velocity scheme    \
           (the cavity, Solver:tvf): a pair form \
           or a Laplacian, each velocity         \
           component's own (not the stress       \
           passes, whose second pass needs the   \
           wall particles' first)                */

/** The default second viscosity lambda of a formulation. */
enum vsph_viscous_lambda {
  VSPH_VISCOUS_LAMBDA_MU = 0, /*!< lambda = mu (MGF's implied value) */
  VSPH_VISCOUS_LAMBDA_STOKES, /*!< -2 mu / d: zero bulk viscosity */
  VSPH_VISCOUS_LAMBDA_STOKES3 /*!< -2 mu / 3 in any dimension, as Basa et
                                   al. and Vukcevic et al. print it */
};

/** What a formulation's dissipation density is meant to tend to as
 *  h -> 0 inside a fluid (the continuum limit analysis/dissipation.c
 *  splits its error against, THEORY.md section 4). A form's own constants
 *  can keep it off that limit, and the split then books the offset as a
 *  lattice error that does not vanish with h/dx: Cleary's K = 2 xi
 *  instead of 2(d + 2) (-24 % in 2-D), the regulariser eta of VI and
 *  MEAF-eta (about 1 %); ER's is the gradient limit in 2-D with zeta = 0
 *  (what vsph runs), not in general. For a per-particle Laplacian the
 *  truncated support at a free surface gives back part of the surface
 *  term mu (closed integral) u.du/dn that its limit lacks, so its surface
 *  part tends to a constant instead of vanishing like h/L: its
 *  consistency and surface parts are to be read together. */
enum vsph_viscous_limit {
  VSPH_VISCOUS_LIMIT_STRESS = 0, /*!< T:D = 2 mu D:D + lambda (tr D)^2,
                                      lambda the form's (a pair form along
                                      grad W, or a stress pass) */
  VSPH_VISCOUS_LIMIT_GRADIENT,   /*!< mu |grad u|^2: a pair form along the
                                      pair's velocity difference (MEAF's
                                      W:W term, Colagrossi et al. 2011,
                                      Eq. 4.31) */
  VSPH_VISCOUS_LIMIT_LAPLACIAN   /*!< -u . mu lap u: a per-particle
                                      Laplacian, whose density is
                                      u_i.(div V)_i itself */
};

/** A pair's viscous share (a descriptor's pair): the share of (div V)_i
 *  and its dissipation density from the loop's constants @p lp, pair
 *  @p pr, du = u_j - u_i (@p du), @p dux = du.x and PVWF's A_i (@p Ai).
 *  The general loop calls it through the descriptor; a family's loops
 *  inline it (solver/viscous_internal.h). */
typedef struct vsph_pair_visc vsph_viscous_pair_fn(
    const struct vsph_viscous_loop *lp, int dim, const struct vsph_pair *pr,
    struct vsph_pair_vec du, double dux, const double Ai[9]);

/** A corrigible form's pair term with the corrected gradient @p g in
 *  place of grad_i W = -F x (Basa et al.'s corrections, docs/theory.md
 *  section 10; the general loop with Solver:correction): sets the pair's
 *  share @p f of (div V)_i from V_j = @p vj, du = u_j - u_i (@p du) and
 *  @p dux = du.x, and returns its dissipation density -f.du/2. With
 *  g = -F x it is the form's uncorrected pair share. */
typedef double vsph_viscous_pair_g_fn(const struct vsph_viscous_loop *lp,
                                      int dim, const struct vsph_pair *pr,
                                      double vj, const double du[3], double dux,
                                      const double g[3], double f[3]);

/** A formulation's specialised neighbour loops (the right-hand side's
 *  gather and sweep, vsph_viscous_compute's), each with its pair function
 *  inlined: opaque here, instantiated by its family's file of
 *  solver/forms/ (solver/viscous_internal.h). */
struct vsph_viscous_loops;

/** A formulation's first pass for particle @p i (its family's, in
 *  solver/forms/): the per-particle sums of its neighbours into @p ws
 *  (PVWF's and B's stress A_i; the whole force of model A and VISC-0x in
 *  A[0..dim-1]), ws->dens[i] and ws->fallback[i]. */
typedef void vsph_viscous_first_fn(const struct vsph_viscous_props *vp,
                                   const struct vsph_pair_kernel *pk,
                                   const struct vsph_particles *p,
                                   const struct vsph_pair_ranges *rg, size_t i,
                                   struct vsph_viscous_ws *ws);

/** A viscous formulation, for the whole suite (as kernels have
 *  vsph_kernel_type): its names, where it comes from, its first pass and
 *  loop, where it applies, its parameters' defaults, and its pair
 *  function. One entry of vsph_viscous_types per vsph_viscous_form;
 *  every predicate below, the names the commands take and print, and the
 *  report's lists of forms read it. docs/theory.md, section 8, says how to
 *  add one. */
struct vsph_viscous_type {
  const char *name;   /*!< the command line's name ("mgf") */
  const char *label;  /*!< in tables and figures ("MGF") */
  const char *legend; /*!< where models of several papers meet (the channel
                           flows): with its paper's model letter ("Takeda
                           (A)"); NULL: the label */
  const char *cite;   /*!< its source and equation */
  enum vsph_viscous_pass pass;            /*!< its first pass */
  const struct vsph_viscous_loops *loops; /*!< its specialised loops,
                                               its family's (NULL: the
                                               general loop only) */
  unsigned flags;                         /*!< VSPH_VISCOUS_FREE_SURFACE, ... */
  int lap; /*!< Laplacian pass: its vsph_pair_lap_form */
  enum vsph_viscous_lambda lambda; /*!< default lambda */
  enum vsph_viscous_limit limit;   /*!< its dissipation's continuum limit */
  double eta;                 /*!< default regulariser eta (fraction of h) in
                                   s^2 + (eta h)^2 */
  const char *params;         /*!< the props it reads beyond mu, for --help */
  vsph_viscous_pair_fn *pair; /*!< its pair share; NULL where its first
                                   pass makes the whole force */
  vsph_viscous_pair_g_fn *pair_g; /*!< its corrected pair share (set
                                       exactly where flags hold
                                       VSPH_VISCOUS_CORRIGIBLE) */
  vsph_viscous_first_fn *first;   /*!< its first pass (NULL: none; set
                                       exactly where pass is not NONE) */
};

/** The table, indexed by vsph_viscous_form: each family's descriptors
 *  live in its file of solver/forms/. */
extern VSPH_API const struct vsph_viscous_type
    *const vsph_viscous_types[VSPH_VISCOUS_FORM_COUNT];

/** @brief The descriptor of @p form (NULL when out of range). */
VSPH_API const struct vsph_viscous_type *vsph_viscous_type_get(int form);

/** @brief Formulation name ("mgf", "meaf", ...; "unknown" out of range). */
VSPH_API const char *vsph_viscous_name(int form);

/** @brief The names of the forms whose flags hold every bit of @p flags
 *  (0: every form), ", "-separated, into @p buf of @p n bytes.
 *  @return @p buf. */
VSPH_API const char *vsph_viscous_list(unsigned flags, char *buf, size_t n);

/** @brief Name of a continuum limit ("stress", "gradient", "laplacian";
 *  "unknown" out of range). */
VSPH_API const char *vsph_viscous_limit_name(int limit);

/** @brief Formulation called @p name, or -1. */
VSPH_API int vsph_viscous_find(const char *name);

/** @brief The formulation called @p name into @p form.
 *  @return VSPH_OK, or VSPH_EINVAL with a message listing them. */
VSPH_API int vsph_viscous_resolve(const char *name, int *form);

/** @brief The formulation's label in tables and figures ("MGF"). */
VSPH_API const char *vsph_viscous_label(int form);

/** @brief Fill props with the defaults of THEORY.md section 3: lambda = mu
 *  for MGF, -2 mu / dim for PVWF (zero bulk viscosity), det_tol = 1e-8;
 *  and of docs/theory.md section 8: lambda = -2 mu / 3 for models A and B
 *  (the papers' Stokes factor, kept in 2-D), eta = 0.1 h for C and D,
 *  zeta = 0.
 *  @return VSPH_OK or VSPH_EINVAL (bad form, dim, h or mu). */
VSPH_API int vsph_viscous_props_init(struct vsph_viscous_props *vp, int form,
                                     const struct vsph_kernel_type *kernel,
                                     int dim, double h, double mu);

/** @brief Workspace for up to @p cap particles. NULL on failure. */
VSPH_API struct vsph_viscous_ws *vsph_viscous_ws_alloc(size_t cap, int dim);

/** @brief Give @p ws the arrays of the kernel corrections (S, a, L); a
 *  no-op when present. @return VSPH_OK or VSPH_ENOMEM (reported). */
VSPH_API int vsph_viscous_ws_corr(struct vsph_viscous_ws *ws);

/** @brief Free a workspace; NULL is a no-op. */
VSPH_API void vsph_viscous_ws_free(struct vsph_viscous_ws *ws);

/** @brief Inverse of a symmetric positive semi-definite @p dim x @p dim
 *  matrix @p b (row-major) into @p inv: PVWF's L and the renormalisation
 *  Gamma of the Laplacian forms share it. Returns 0 and leaves @p inv
 *  untouched when det <= tol (tr/d)^d (singular: the caller falls back). */
VSPH_API int vsph_viscous_invert_sym(int dim, const double *b, double *inv,
                                     double tol);

/** @brief The Laplacians of @p nf scalar fields f[c] (each of length
 *  p->n) at particle @p i by Laplacian form @p lap (vsph_pair_lap_form):
 *  the sums of vsph_pair_lap_add over i's neighbours in @p rg, Gamma =
 *  M^-1 (the identity where M is singular by @p tol, see
 *  vsph_viscous_invert_sym), vsph_pair_lap_finish. The one evaluation of
 *  the Laplacian forms: the patch test (analysis/laplacian.c) and the
 *  solver's VISC-0x formulations call it. @p eta2 is (eta h)^2. */
VSPH_API void vsph_viscous_laplacians(const struct vsph_pair_kernel *pk,
                                      const struct vsph_kernel_type *k,
                                      double h, double eta2, double tol,
                                      int lap, const struct vsph_particles *p,
                                      const struct vsph_pair_ranges *rg,
                                      size_t i, int nf,
                                      const double *const f[3], double out[3]);

/** @brief The first pass, into @p ws. PVWF: L_i, the renormalised grad u,
 *  D_i, T_i, and A_i = T_i L_i for every particle, and the count of
 *  particles whose L fell back to the identity. Model B: the same with
 *  L = I (Watkins' differenced gradient, no renormalisation). Model A:
 *  its whole force density (one pass of direct second derivatives).
 *  Other forms: no-op.
 *  @return VSPH_OK or VSPH_EINVAL (workspace too small). */
VSPH_API int vsph_viscous_prepare(const struct vsph_viscous_props *vp,
                                  const struct vsph_particles *p,
                                  const struct vsph_cells *cells,
                                  struct vsph_viscous_ws *ws);

/** @brief PVWF's (model B's) first pass for particle @p i from its sums
 *  B = sum_j V_j (-F) x (x) x and Mg = sum_j V_j (-F) du (x) x (row-major
 *  d x d, vsph_pair_pvwf_grad): L_i = B^-1 (the identity for model B or
 *  where B is singular, marked in ws->fallback), the renormalised grad u,
 *  D_i, T_i, A_i = T_i L_i and -T_i:D_i into @p ws. */
VSPH_API void vsph_viscous_pvwf_finish(const struct vsph_viscous_props *vp,
                                       struct vsph_viscous_ws *ws, size_t i,
                                       const double B[9], const double Mg[9]);

/** @brief The viscous force density (div V)_i (N/m^d) of every particle.
 *  Uses pos, vel and vol of @p p.
 *  @param vp the formulation's settings; @param p the particles.
 *  @param ws the workspace (vsph_viscous_ws_alloc).
 *  @param cells built with radius >= kappa h (or the direct path).
 *  @param out out[k][i], k < dim: component k of (div V)_i.
 *  @param dens if not NULL, the pairwise dissipation density p_i (W/m^d)
 *  with sum_i V_i p_i = sum_i V_i u_i.(div V)_i (THEORY.md section 4):
 *  MGF: (K mu / 2) sum_j V_j ((u_j-u_i).x)^2 W'/s^3;
 *  MEAF: mu sum_j V_j W'/s |u_i - u_j|^2;  PVWF: -T_i : D_i.
 *  @return VSPH_OK or VSPH_EINVAL (workspace too small, bad props). */
VSPH_API int vsph_viscous_compute(const struct vsph_viscous_props *vp,
                                  const struct vsph_particles *p,
                                  const struct vsph_cells *cells,
                                  struct vsph_viscous_ws *ws,
                                  double *const out[3], double *dens);

/** What the viscous pair term needs inside a loop, loaded once. */
struct vsph_viscous_loop {
  int form;      /*!< vsph_viscous_form */
  int dim;       /*!< dimension */
  double Kmu;    /*!< MGF, VI: K mu, K = vsph_kernel_mg_factor(dim);
                      Cleary: 2 xi mu */
  double eta2;   /*!< Brookshaw forms: (eta h)^2 (m^2), 0 for MGF */
  double two_mu; /*!< MEAF: 2 mu */
  double er_a;   /*!< Espanol-Revenga: a = zeta - mu (d+2)/d */
  double er_b;   /*!< Espanol-Revenga: b = -(d+2)(zeta + mu (d-2)/d) */
  double *A[9];  /*!< PVWF, B: A = T L of every particle (workspace);
                      A: the force density of every particle in A[0..d-1] */
  vsph_viscous_pair_fn *pair;     /*!< the form's pair share (the general
                                       loop's; NULL: none) */
  vsph_viscous_pair_g_fn *pair_g; /*!< its corrected pair share (NULL:
                                       not corrigible) */
  int nA;  /*!< entries of A_i a pair reads: d^2 for a stress pass, else 0 */
  int own; /*!< 1: the whole force is the particle's own, from A */
};

/** @brief The loop constants of @p vp; @p ws is the workspace after
 *  vsph_viscous_prepare (may be NULL for the forms without a first pass,
 *  vsph_viscous_first_pass).
 *  @return VSPH_OK, or VSPH_EINVAL where @p vp->form is out of range
 *  (@p lp is then a loop with no term: every pair and own share 0). */
static inline int vsph_viscous_loop_init(struct vsph_viscous_loop *lp,
                                         const struct vsph_viscous_props *vp,
                                         const struct vsph_viscous_ws *ws) {
  const struct vsph_viscous_loop none = {.form = -1, .dim = vp->dim};
  if (vp->form < 0 || vp->form >= VSPH_VISCOUS_FORM_COUNT) {
    *lp = none;
    return VSPH_EINVAL;
  }
  const struct vsph_viscous_type *t = vsph_viscous_types[vp->form];
  lp->form = vp->form;
  lp->dim = vp->dim;
  lp->Kmu = (t->flags & VSPH_VISCOUS_XI ? 2.0 * vp->xi
                                        : vsph_kernel_mg_factor(vp->dim)) *
            vp->mu;
  lp->eta2 = vp->eta * vp->h * vp->eta * vp->h;
  lp->two_mu = 2.0 * vp->mu;
  const double d = vp->dim;
  lp->er_a = vp->zeta - vp->mu * (d + 2.0) / d;
  lp->er_b = -(d + 2.0) * (vp->zeta + vp->mu * (d - 2.0) / d);
  for (int a = 0; a < 9; a++) lp->A[a] = ws ? ws->A[a] : NULL;
  lp->pair = t->pair;
  lp->pair_g = t->pair_g;
  lp->nA = t->pass == VSPH_VISCOUS_PASS_STRESS ? vp->dim * vp->dim : 0;
  lp->own = t->pair == NULL;
  return VSPH_OK;
}

/** @brief Whether the whole of @p form's force comes from its first pass,
 *  per particle (no pair shares): model A and the Laplacian forms
 *  VISC-01..04, mu lap u with the Laplacian of pair.h applied to each
 *  velocity component. 0 for an id out of range. */
static inline int vsph_viscous_particle_form(int form) {
  return form >= 0 && form < VSPH_VISCOUS_FORM_COUNT &&
         vsph_viscous_types[form]->pair == NULL;
}

/** @brief Whether @p form has a first pass (vsph_viscous_prepare) whose
 *  per-particle density -T:D or u.(div V) replaces the pair densities:
 *  PVWF, B and the per-particle forms. 0 for an id out of range. */
static inline int vsph_viscous_first_pass(int form) {
  return form >= 0 && form < VSPH_VISCOUS_FORM_COUNT &&
         vsph_viscous_types[form]->pass != VSPH_VISCOUS_PASS_NONE;
}

/** @brief Whether @p form is a sum of pair terms along grad_i W that the
 *  kernel corrections can correct (its descriptor's pair_g): MGF, VI,
 *  Cleary, MEAF, ER. 0 for an id out of range. */
static inline int vsph_viscous_corrigible(int form) {
  return form >= 0 && form < VSPH_VISCOUS_FORM_COUNT &&
         (vsph_viscous_types[form]->flags & VSPH_VISCOUS_CORRIGIBLE) != 0;
}

/** @brief Neighbour passes of @p form per evaluation: 2 for PVWF and
 *  model B, whose second pass differentiates their first (so their ghost
 *  layers are two supports deep), 1 for the others (model A's one pass
 *  comes before the right-hand side's but reaches one support); 0 for an
 *  id out of range. */
static inline int vsph_viscous_passes(int form) {
  if (form < 0 || form >= VSPH_VISCOUS_FORM_COUNT) return 0;
  return vsph_viscous_types[form]->pass == VSPH_VISCOUS_PASS_STRESS ? 2 : 1;
}

/** @brief Whether @p form has specialised loops of its own (its family's,
 *  solver/forms/) beside the general loop. 0 for an id out of range. */
static inline int vsph_viscous_specialised(int form) {
  return form >= 0 && form < VSPH_VISCOUS_FORM_COUNT &&
         vsph_viscous_types[form]->loops != NULL;
}

/** @brief Add the part of (div V)_i that is particle i's own, not a sum of
 *  pair shares, to @p acc: the per-particle forms' force from their first
 *  pass; nothing for the other forms. */
static inline void vsph_viscous_own(const struct vsph_viscous_loop *lp,
                                    size_t i, double acc[3]) {
  if (lp->own)
    for (int k = 0; k < lp->dim; k++) acc[k] += lp->A[k][i];
}

/** @brief PVWF's (B's) A_i of particle @p i from the workspace (nothing
 *  for the other forms). */
static inline void vsph_viscous_load_A(const struct vsph_viscous_loop *lp,
                                       size_t i, double Ai[9]) {
  for (int a = 0; a < lp->nA; a++) Ai[a] = lp->A[a][i];
}

#endif /* VSPH_SOLVER_VISCOUS_H */
