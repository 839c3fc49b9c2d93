#ifndef VSPH_SOLVER_EQUATIONS_H
#define VSPH_SOLVER_EQUATIONS_H

#include <stddef.h>

#include "viscous.h"

struct vsph_particles;
struct vsph_cells;

/** @file equations.h
 *  @brief The weakly compressible equations (THEORY.md section 5,
 *  Colagrossi et al. 2011 Eq. 3.13): continuity, the linear state equation
 *  p = c0^2 (rho - rho0), the PVW-compatible pressure gradient, the chosen
 *  viscous operator, optional delta-SPH density diffusion (Antuono et al.
 *  2010, simple form), and a body force; all in one gather loop. Also the
 *  energies and the energy budget. No I/O. */

/** Body force kinds: model only what a scene declares. */
enum vsph_equations_body {
  VSPH_EQUATIONS_BODY_NONE = 0, /*!< no body force, none computed */
  VSPH_EQUATIONS_BODY_RADIAL,   /*!< g = -beta^2 r (vortex patch) */
  VSPH_EQUATIONS_BODY_GRAVITY,  /*!< g = -g e_y */
  VSPH_EQUATIONS_BODY_UNIFORM,  /*!< g = f e_x, a channel's drive */
  VSPH_EQUATIONS_BODY_COUNT
};

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
};

/** Where the right-hand side goes (caller arrays of length p->n; rows of
 *  ghost particles are left untouched). */
struct vsph_equations_out {
  double *drho;        /*!< d rho/dt */
  double *acc[3];      /*!< du/dt */
  double *acc_visc[3]; /*!< optional: the viscous part (div V)/rho */
  double *drho_delta;  /*!< optional: the delta-SPH part of d rho/dt */
  size_t interactions; /*!< out: pairs (i receiving from j) within kappa h */
  double min_s2;       /*!< out: smallest squared pair distance (m^2) */
};

/** Energies and momenta of the fluid particles (per unit depth in 2-D). */
struct vsph_equations_energy {
  double Ek;   /*!< kinetic, sum m |u|^2 / 2 */
  double Ep;   /*!< potential, sum m Phi with g = -grad Phi */
  double Ec;   /*!< compressible, sum m c0^2 [ln(rho/rho0) + rho0/rho - 1] */
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
void vsph_equations_body_force(const struct vsph_equations_props *ep,
                               const double x[3], double g[3]);

/** @brief Potential Phi(x) with g = -grad Phi (J/kg). The uniform drive
 *  of a periodic channel has none that stays bounded (Phi = -f x jumps
 *  where a particle wraps): 0 there, its power -sum m f u_x is in the
 *  budget's dEp. */
double vsph_equations_potential(const struct vsph_equations_props *ep,
                                const double x[3]);

/** @brief Evaluate the right-hand side for the fluid particles: those with
 *  id < n_fluid; the others are ghosts (neighbours only). Refreshes p->p
 *  and p->vol of every particle first.
 *  @param ws viscous workspace (PVWF: for all p->n particles).
 *  @return VSPH_OK or VSPH_EINVAL. */
int vsph_equations_rhs(const struct vsph_equations_props *ep,
                       struct vsph_particles *p, size_t n_fluid,
                       const struct vsph_cells *cells,
                       struct vsph_viscous_ws *ws,
                       struct vsph_equations_out *out);

/** @brief Energies and momenta of the fluid particles (serial sums in
 *  index order). */
void vsph_equations_energy_compute(const struct vsph_equations_props *ep,
                                   const struct vsph_particles *p,
                                   size_t n_fluid,
                                   struct vsph_equations_energy *en);

/** @brief The budget from a right-hand side evaluated with acc_visc and
 *  drho_delta. */
void vsph_equations_budget_compute(const struct vsph_equations_props *ep,
                                   const struct vsph_particles *p,
                                   size_t n_fluid,
                                   const struct vsph_equations_out *out,
                                   struct vsph_equations_budget *b);

#endif /* VSPH_SOLVER_EQUATIONS_H */
