/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
#ifndef VSPH_SOLVER_EQUATIONS_H
#define VSPH_SOLVER_EQUATIONS_H

#include <math.h>
#include <stddef.h>

#include "../common/api.h"
#include "viscous.h"

struct vsph_particles;
struct vsph_cells;

/** @file equations.h
 *  @brief The weakly compressible equations (THEORY.md section 5,
 *  Colagrossi et al. 2011 Eq. 3.13): continuity, a state equation (linear
 *  p = c0^2 (rho - rho0) by default; Tait's, or the ideal gas with its
 *  energy equation, docs/theory.md section 10), the PVW-compatible
 *  pressure gradient (optionally with Basa et al.'s local pressure
 *  reduction), the chosen viscous operator, optional delta-SPH density
 *  diffusion (Antuono et al. 2010, simple form), and a body force; all in
 *  one gather loop. Also the energies and the energy budget. No I/O. */

/** Body force kinds: model only what a scene declares. */
enum vsph_equations_body {
  VSPH_EQUATIONS_BODY_NONE = 0, /*!< no body force, none computed */
  VSPH_EQUATIONS_BODY_RADIAL,   /*!< g = -beta^2 r (vortex patch) */
  VSPH_EQUATIONS_BODY_GRAVITY,  /*!< g = -g e_y */
  VSPH_EQUATIONS_BODY_UNIFORM,  /*!< g = f e_x, a channel's drive */
  VSPH_EQUATIONS_BODY_COUNT
};

/** State equations: model only what a run asks for (the gas law alone
 *  carries an energy equation). */
enum vsph_equations_eos {
  VSPH_EQUATIONS_EOS_LINEAR = 0, /*!< p = c0^2 (rho - rho0) (THEORY 5) */
  VSPH_EQUATIONS_EOS_TAIT,       /*!< p = rho0 c0^2/gamma ((rho/rho0)^gamma
                                      - 1), gamma = 7 (Basa's eq. 13) */
  VSPH_EQUATIONS_EOS_GAS,        /*!< p = (gamma - 1) rho e, e by the
                                      energy equation (Basa's eqs. 12, 14) */
  VSPH_EQUATIONS_EOS_ISOTHERMAL, /*!< p = c0^2 rho, the absolute pressure
                                      (Morris et al. 1997; Vukcevic et
                                      al.'s eq. 20) */
  VSPH_EQUATIONS_EOS_COUNT
};

/** The schemes: the weakly compressible SPH of THEORY 5 with a viscous
 *  operator, or contact (Godunov-type) SPH, whose pairs interact through
 *  the acoustic Riemann solution (Parshikov et al., Parshikov et al. eqs. 5-9;
 *  docs/theory.md section 12). Chosen once per evaluation, outside the
 *  pair loop. */
enum vsph_equations_scheme {
  VSPH_EQUATIONS_WCSPH = 0, /*!< continuity, p_i + p_j, the viscous form */
  VSPH_EQUATIONS_CONTACT,   /*!< 2 P*, 2 (U* - U_i^R), contact viscosity */
  VSPH_EQUATIONS_SCHEME_COUNT
};

/** Materials a contact run may hold (a per-particle index, p->mat). */
#define VSPH_EQUATIONS_MAT_MAX 2

/** One material of a contact run: its linear state equation, its
 *  physical viscosity and the numerical viscosity the correcting tensor
 *  removes a fraction zeta_num of (Parshikov et al. section 4). */
struct vsph_equations_mat {
  double rho0;    /*!< reference density (kg/m^d) */
  double c0;      /*!< sound speed (m/s); Z = rho c0 */
  double mu;      /*!< physical viscosity (Pa s) */
  double eta_num; /*!< numerical viscosity (Pa s), Parshikov et al. eq. (37) */
  int fixed;      /*!< 1: a rigid body held in place (a cylinder): its
                       particles get no acceleration and no body force,
                       their density follows the strain rate; mu = 0 and
                       eta_num = 0, so the fluid sticks to them through the
                       Riemann solution alone, uncorrected (Parshikov et al.'s ball)
                   */
};

/** Tait's exponent (Batchelor; Basa et al.'s eq. 13). */
#define VSPH_EQUATIONS_TAIT_GAMMA 7.0
/** The ideal gas's ratio of specific heats: Basa et al. give none; 1.4,
 *  air's, is **[reconstructed]** (docs/theory.md section 10). */
#define VSPH_EQUATIONS_GAS_GAMMA 1.4

/** Physics of one run. */
struct vsph_equations_props {
  struct vsph_viscous_props visc; /*!< kernel, h, dim, mu, formulation */
  double rho0;                    /*!< reference density (kg/m^d) */
  double c0;                      /*!< sound speed (m/s) */
  double delta;                   /*!< delta-SPH coefficient; 0 = off */
  int body;                       /*!< vsph_equations_body */
  double beta;                    /*!< radial force rate (1/s) */
  double g;                       /*!< gravity (m/s^2) */
  double f;                       /*!< uniform drive along x (m/s^2) */
  int eos;                        /*!< vsph_equations_eos */
  int reduce;                     /*!< 1: Basa's pressure reduction (eq. 20):
                                       p_i - pbar_i and p_j - pbar_i in the
                                       pressure gradient, pbar_i the plain
                                       mean over i's neighbours and i */
  int corr;                       /*!< vsph_pair_corr: Basa's kernel
                                       corrections of every grad W in
                                       continuity, pressure and the viscous
                                       term (corrigible forms; the workspace
                                       needs vsph_viscous_ws_corr) */
  int solid;                      /*!< 1: fixed wall particles; their state
                                       and the fluid's pressure are set by
                                       vsph_equations_walls_adami, not by
                                       the right-hand side */
  int tvf;                        /*!< 1: the transport-velocity scheme
                                       (Adami, Hu & Adams 2013): summation
                                       density, the A term, and the
                                       background acceleration in bacc */
  double pb;                      /*!< its background pressure (Pa) */
  int summation;                  /*!< 1: the fluid's density by summation,
                                       rho_i = sum_j m_j W_ij over fluid and
                                       ghosts or wall particles, before each
                                       evaluation (the integrator leaves it
                                       alone); tvf implies it */
  int scheme;                     /*!< vsph_equations_scheme */
  double zeta_num;                /*!< contact: the fraction of the
                                       numerical viscosity removed, zeta */
  int nmat;                       /*!< contact: materials (>= 1) */
  struct vsph_equations_mat mat[VSPH_EQUATIONS_MAT_MAX]; /*!< contact */
  int loop_general; /*!< 1: every shape of the gather and of the Adami
                         walls through the general loop, no specialised
                         copy (the tests' reference for those copies) */
};

/** @brief The pair viscosity of contact SPH, Parshikov et al. eqs. (30)-(32):
 *  eta_eff = eta_i eta_j (1 + sqrt(nu_i/nu_j))/(eta_i + eta_j
 *  sqrt(nu_i/nu_j)), nu = eta/rho0 at the reference densities
 *  ([reconstructed]); eta for identical materials, 0 if either is 0. */
static inline double vsph_equations_eta_eff(double eta_i, double rho_i,
                                            double eta_j, double rho_j) {
  if (!(eta_i > 0.0) || !(eta_j > 0.0)) return 0.0;
  const double r = sqrt((eta_i / rho_i) / (eta_j / rho_j));
  return eta_i * eta_j * (1.0 + r) / (eta_i + eta_j * r);
}

/** @brief Material @p m's reference density (ep->rho0 outside contact
 *  runs). */
static inline double vsph_equations_rho0(const struct vsph_equations_props *ep,
                                         int m) {
  return ep->nmat > m ? ep->mat[m].rho0 : ep->rho0;
}

/** @brief Material @p m's sound speed (ep->c0 outside contact runs). */
static inline double vsph_equations_c0(const struct vsph_equations_props *ep,
                                       int m) {
  return ep->nmat > m ? ep->mat[m].c0 : ep->c0;
}

/** @brief The state equation called @p name ("linear", "tait", "gas")
 *  into @p eos. @return VSPH_OK, or VSPH_EINVAL with a message listing
 *  them. */
VSPH_API int vsph_equations_eos_resolve(const char *name, int *eos);

/** @brief The scheme called @p name ("wcsph", "contact") into @p scheme.
 *  @return VSPH_OK, or VSPH_EINVAL with a message listing them. */
VSPH_API int vsph_equations_scheme_resolve(const char *name, int *scheme);

/** @brief The kernel correction called @p name ("none", "shepard",
 *  "bonetlok"; vsph_pair_corr) into @p corr. @return VSPH_OK, or
 *  VSPH_EINVAL with a message listing them. */
VSPH_API int vsph_equations_corr_resolve(const char *name, int *corr);

/** @brief The names of a state equation, a scheme and a kernel
 *  correction (the words their _resolve functions read), "unknown" for a
 *  value out of range. */
VSPH_API const char *vsph_equations_eos_name(int eos);
VSPH_API const char *vsph_equations_scheme_name(int scheme);
VSPH_API const char *vsph_equations_corr_name(int corr);

/** @brief The pressure of density @p rho and specific internal energy
 *  @p e (used by the gas law only) under the run's state equation. For
 *  the gas, c0^2 = gamma p0/rho0 at the reference state. */
static inline double vsph_equations_pressure(
    const struct vsph_equations_props *ep, double rho, double e) {
  switch (ep->eos) {
    case VSPH_EQUATIONS_EOS_TAIT: {
      const double g = VSPH_EQUATIONS_TAIT_GAMMA;
      return ep->rho0 * ep->c0 * ep->c0 / g * (pow(rho / ep->rho0, g) - 1.0);
    }
    case VSPH_EQUATIONS_EOS_GAS:
      return (VSPH_EQUATIONS_GAS_GAMMA - 1.0) * rho * e;
    case VSPH_EQUATIONS_EOS_ISOTHERMAL:
      return ep->c0 * ep->c0 * rho;
    default:
      return ep->c0 * ep->c0 * (rho - ep->rho0);
  }
}

/** @brief The gas law's specific internal energy at the reference state,
 *  e0 = p0/((gamma - 1) rho0) with p0 = rho0 c0^2/gamma (so that the
 *  sound speed there is c0). */
static inline double vsph_equations_gas_e0(
    const struct vsph_equations_props *ep) {
  const double g = VSPH_EQUATIONS_GAS_GAMMA;
  return ep->c0 * ep->c0 / (g * (g - 1.0));
}

/** Where the right-hand side goes (caller arrays of length p->n; rows of
 *  ghost particles are left untouched). */
struct vsph_equations_out {
  double *drho;        /*!< d rho/dt */
  double *acc[3];      /*!< du/dt */
  double *acc_visc[3]; /*!< optional: the viscous part (div V)/rho */
  double *drho_delta;  /*!< optional: the delta-SPH part of d rho/dt */
  double *de;          /*!< the gas law only: de/dt (energy equation) */
  size_t interactions; /*!< out: pairs (i receiving from j) within kappa h */
  double min_s2;       /*!< out: smallest squared pair distance (m^2) */
  struct vsph_equations_sweep *sweep; /*!< optional: the symmetric sweep's
                                           workspace (see below); NULL:
                                           every loop gathers per particle */
};

/** The symmetric sweep's workspace (opaque). With it, the specialised
 *  loops (2-D and 3-D, the 3h Gaussian, MGF and its Brookshaw kin, MEAF,
 *  Espanol-Revenga, PVWF's second pass; no correction, reduction or
 *  transport velocity) visit each unique pair (i < j) once per
 *  evaluation: its geometry, kernel and pair terms are computed once, i's
 *  share summed at once and j's added to a buffer of the pair's block (a
 *  fixed run of cells, the same for any thread count); each particle's
 *  result is then its block buffers summed in block order. 1 and 2
 *  threads give bitwise-identical results; the per-particle gather agrees
 *  to rounding. */
struct vsph_equations_sweep;

/** @brief An empty sweep workspace (it grows as the evaluations need);
 *  NULL when out of memory. */
VSPH_API struct vsph_equations_sweep *vsph_equations_sweep_alloc(void);

/** @brief Free a sweep workspace; NULL is a no-op. */
VSPH_API void vsph_equations_sweep_free(struct vsph_equations_sweep *sw);

/** @brief The bytes the sweep workspace holds now. */
VSPH_API size_t
vsph_equations_sweep_bytes(const struct vsph_equations_sweep *sw);

/** Energies and momenta of the fluid particles (per unit depth in 2-D). */
struct vsph_equations_energy {
  double Ek;   /*!< kinetic, sum m |u|^2 / 2 */
  double Ep;   /*!< potential, sum m Phi with g = -grad Phi */
  double Ec;   /*!< compressible: linear law sum m c0^2 [ln(rho/rho0) +
                    rho0/rho - 1]; Tait's sum m int_rho0^rho p/r^2 dr; the
                    gas sum m (e - e0) */
  double P[3]; /*!< linear momentum */
  double Lz;   /*!< angular momentum about the origin, z component */
};

/** Power terms of the budget d(Ek + Ep + Ec)/dt = P_visc + P_delta. */
struct vsph_equations_budget {
  double dEk, dEp, dEc; /*!< time derivatives from the right-hand side */
  double P_visc;        /*!< sum m u . (div V)/rho = sum V u . (div V) */
  double P_delta;       /*!< sum m p/rho^2 (d rho/dt)_delta */
  double residual;      /*!< dEk + dEp + dEc - P_visc - P_delta */
};

/** @brief Body force at x (m/s^2). */
VSPH_API void vsph_equations_body_force(const struct vsph_equations_props *ep,
                                        const double x[3], double g[3]);

/** @brief Potential Phi(x) with g = -grad Phi (J/kg). The uniform drive
 *  of a periodic channel has none that stays bounded (Phi = -f x jumps
 *  where a particle wraps): 0 there, its power -sum m f u_x is in the
 *  budget's dEp. */
VSPH_API double vsph_equations_potential(const struct vsph_equations_props *ep,
                                         const double x[3]);

struct vsph_walls;
struct vsph_cells;

/** @brief Fixed wall particles' state, Adami, Hu & Adams (2012), before
 *  each evaluation (ep->solid; the linear law): with ep->tvf the fluid's
 *  density by summation, rho_i = sum_j m_j W_ij over fluid and wall
 *  particles (i included); then every fluid particle's p and V = m/rho;
 *  then each wall particle w (id >= n_fluid) takes the Shepard average
 *  of its fluid neighbours, p_w = sum_f p_f W_wf / sum_f W_wf (no body
 *  force or wall acceleration: the scenes that use it have none), the
 *  density of p_w under the linear law, and the velocity
 *  2 u_prescribed - (Shepard average of u_f) (no slip; the transport
 *  velocity equal to it, so its A term vanishes). A wall particle without
 *  fluid neighbours keeps p = 0 and the prescribed velocity.
 *  @return VSPH_OK or VSPH_EINVAL (not the linear law). */
VSPH_API int vsph_equations_walls_adami(const struct vsph_equations_props *ep,
                                        const struct vsph_walls *w,
                                        struct vsph_particles *p,
                                        size_t n_fluid,
                                        const struct vsph_cells *cells);

/** @brief Evolving wall particles' state (ep->solid = VSPH_WALLS_EVOLVING;
 *  Basa, Quinlan & Lastiwka 2009, cavity: "density and pressure evolve by
 *  continuity and the state equation"), before each evaluation: every wall
 *  particle's p by the run's law from its density (which the integrator
 *  advances) and V = m/rho; the fluid's density by summation over fluid
 *  and wall particles (ep->summation) or its integrated one, its p and V;
 *  then each wall particle's continuity rate in p->drho from its fluid
 *  neighbours, the particle at rest (it does not move; the lid's sliding
 *  enters only the viscous term), rho_w sum_f V_f F u_f.x
 *  [reconstructed: fluid neighbours only, and at rest, so that the lid's
 *  corner particles are not drained by the sliding they only stand for].
 *  The velocities are vsph_walls_solid_extrapolate's.
 *  @return VSPH_OK or VSPH_EINVAL (the gas law). */
VSPH_API int vsph_equations_walls_evolving(
    const struct vsph_equations_props *ep, struct vsph_particles *p,
    size_t n_fluid, const struct vsph_cells *cells);

/** @brief XSPH's drift velocity (Monaghan 1989, in Vukcevic et al.'s
 *  eq. 21 form) of every fluid particle i (id < n_fluid):
 *  w_i = u_i + eps sum_j (m_j/rho_j) (u_j - u_i) W_ij over its neighbours
 *  within the support (ghosts and wall particles included, i itself not),
 *  into w[k][i] by index; positions and velocities as they are. */
VSPH_API void vsph_equations_xsph(const struct vsph_equations_props *ep,
                                  const struct vsph_particles *p,
                                  size_t n_fluid,
                                  const struct vsph_cells *cells, double eps,
                                  double *const w[3]);

/** @brief The fluid particles' density by summation (ep->summation, ghost
 *  walls or none): rho_i = sum_j m_j W_ij over every particle within
 *  reach, i itself and the ghosts included (their masses are their
 *  sources'), then p_i (with e = 0: the right-hand side recomputes it) and
 *  V_i = m_i/rho_i; the fluid sweep of vsph_equations_walls_adami.
 *  Positions as they are; the ghosts' own density is left to
 *  vsph_walls_update. */
VSPH_API void vsph_equations_density_sum(const struct vsph_equations_props *ep,
                                         struct vsph_particles *p,
                                         size_t n_fluid,
                                         const struct vsph_cells *cells);

/** @brief Evaluate the right-hand side for the fluid particles: those with
 *  id < n_fluid; the others are ghosts (neighbours only). Refreshes p->p
 *  and p->vol of every particle first (with ep->solid: the state
 *  vsph_equations_walls_adami set is taken as it is). With ep->tvf, adds
 *  the transport-velocity scheme's A term, (1/rho_i) sum_j V_j (A_i + A_j)
 *  . grad_i W_ij with A = rho u (x) (tvel - u), to the acceleration and
 *  sets bacc_i = -(2 pb/rho_i) sum_j V_j grad_i W_ij, the background
 *  pressure's push that the transport velocity carries.
 *  @param ep the equations' settings.
 *  @param p the particles (fluid and ghosts).
 *  @param n_fluid the fluid particles' ids are below it.
 *  @param cells the cell list of @p p (radius >= kappa h).
 *  @param ws viscous workspace (PVWF: for all p->n particles).
 *  @param out receives the rates, by index.
 *  @return VSPH_OK or VSPH_EINVAL. */
VSPH_API int vsph_equations_rhs(const struct vsph_equations_props *ep,
                                struct vsph_particles *p, size_t n_fluid,
                                const struct vsph_cells *cells,
                                struct vsph_viscous_ws *ws,
                                struct vsph_equations_out *out);

/** @brief Energies and momenta of the fluid particles (serial sums in
 *  index order). */
VSPH_API void vsph_equations_energy_compute(
    const struct vsph_equations_props *ep, const struct vsph_particles *p,
    size_t n_fluid, struct vsph_equations_energy *en);

/** @brief The budget from a right-hand side evaluated with acc_visc and
 *  drho_delta. */
VSPH_API void vsph_equations_budget_compute(
    const struct vsph_equations_props *ep, const struct vsph_particles *p,
    size_t n_fluid, const struct vsph_equations_out *out,
    struct vsph_equations_budget *b);

#endif /* VSPH_SOLVER_EQUATIONS_H */
