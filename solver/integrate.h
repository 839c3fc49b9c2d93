/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
#ifndef VSPH_SOLVER_INTEGRATE_H
#define VSPH_SOLVER_INTEGRATE_H

#include <signal.h>
#include <stddef.h>
#include <stdio.h>

#include "../common/api.h"
#include "equations.h"
#include "walls.h"

struct vsph_particles;

/** @file integrate.h
 *  @brief Classical fourth-order Runge-Kutta for the WCSPH system (THEORY
 *  section 5) with the time-step rule dt = min(CFL h/(c0 + max|u|),
 *  0.125 h^2/nu, 0.25 sqrt(h/max|g|)), and the stability checks that stop a
 *  run cleanly (non-finite values, particles leaving the scene's box, density
 *  outside a band). The cell list is built once per step with an edge of
 *  kappa h plus a skin covering the step's displacements, and stops on
 *  particle pairing (two particles closer than a set distance); ghosts (walls
 *  only) are regenerated per step and refreshed at every stage. Follows
 *  GSL's init / iterate / test shape. No I/O. A NULL argument is refused:
 *  VSPH_EINVAL (reported) where a status is returned, NULL from
 *  vsph_integrate_alloc (which frees the fluid it was given), NaN or 0
 *  from the sizes and steps, 1 from vsph_integrate_check. */

/** Run settings. */
struct vsph_integrate_props {
  struct vsph_equations_props eq; /*!< physics */
  struct vsph_walls walls;        /*!< walls (n = 0: none, no wall code) */
  double cfl;                     /*!< Courant number (RK4 default 1.0) */
  double dt;                      /*!< a fixed step (s) in place of the
                                       rule's, stable or not; 0: the rule */
  double rho_band;                /*!< stop when |rho/rho0 - 1| > band */
  double min_dist;                /*!< stop when two particles come closer
                                       (m): pairing, a zero-energy mode */
  double box_lo[3], box_hi[3];    /*!< stop when a particle leaves the box */
  int leapfrog;                   /*!< 1: drift-kick-drift leapfrog instead
                                       of RK4 (not with eq.tvf) */
  double xsph;                    /*!< leapfrog: XSPH's epsilon; 0: off */
};

/** Integrator state. */
struct vsph_integrate {
  struct vsph_integrate_props props; /*!< settings (a copy) */
  struct vsph_particles *p;          /*!< fluid then ghosts; owned */
  size_t n_fluid;                    /*!< fluid particles (ids 0..n-1) */
  double t;                          /*!< time (s) */
  size_t steps;                      /*!< steps taken */
  size_t interactions;               /*!< pairs gathered in the last step */
  double min_dist;                   /*!< closest pair seen in the last step */
  char reason[160];                  /*!< why the run was stopped, or "" */
  /* private below */
  struct vsph_cells *cells;
  struct vsph_viscous_ws *vws;
  struct vsph_equations_sweep *sweep; /* the symmetric sweep's buffers */
  struct vsph_walls_ghosts *gh;
  size_t *where;
  double *y0[8], *ks[8], *extra[4]; /* RK fields: r, u, rho (, e) */
  int kept; /* ks[0..] hold rates kept by particle id between steps: the
              transport velocity's a and a_b (2d fields), the leapfrog's
              drift velocity, a and d rho/dt (2d + 1 fields) */
  /** if not NULL, an RK4 step is abandoned between its stages when *stop
   *  becomes non-zero: the particles are put back as the step found them
   *  (from its start state y0) and the step returns VSPH_EINTR */
  const volatile sig_atomic_t *stop;
  size_t *order0, order0_cap, n0; /* the ids in the order a step found them */
};

/** @brief Take ownership of the fluid set @p fluid (ids 0..n-1) and set up
 *  the integrator. With walls, the set grows (vsph_particles_reserve) to
 *  hold the ghosts each step needs, counted before they are made, so the
 *  memory follows the ghosts there are rather than a worst case. The
 *  transport-velocity scheme (eq.tvf) takes wall particles (walls.solid),
 *  not ghost walls: a ghost carries no transport velocity. NULL (after
 *  reporting) on failure or bad input; @p fluid is freed in every case. */
VSPH_API struct vsph_integrate *vsph_integrate_alloc(
    const struct vsph_integrate_props *ip, struct vsph_particles *fluid);

/** @brief Free; NULL is a no-op. */
VSPH_API void vsph_integrate_free(struct vsph_integrate *s);

/** @brief Time step of THEORY section 5 for the current state; props.dt
 *  in its place where that is set. */
VSPH_API double vsph_integrate_dt(const struct vsph_integrate *s);

/** @brief The time-step rule itself (docs/theory.md section 5), for the
 *  step (vsph_integrate_dt) and the run's estimate alike:
 *  dt = min(f cfl h/(c0 + umax), g 0.125 h^2/nu, 0.25 sqrt(h/gmax)), with
 *  f = 1/4 for the split schemes (@p split 1: the transport velocity's
 *  kick-drift-kick, Adami et al.'s quarter; 2: the leapfrog), 1/2 for
 *  contact SPH, else 1; g = 1/4 for the leapfrog (its predicted mid-step
 *  velocity keeps pure diffusion stable only to dt |lambda| < 1, RK4 to
 *  about 2.8), else 1; a bound is left out where nu or gmax is 0. */
VSPH_API double vsph_integrate_dt_rule(double cfl, int split, int contact,
                                       double h, double c0, double umax,
                                       double nu, double gmax);

/** @brief One step of length @p dt: RK4; the transport velocity's
 *  kick-drift-kick (props.eq.tvf); or the drift-kick-drift leapfrog
 *  (props.leapfrog; Vukcevic et al.'s eq. 22): r += dt/2 w;
 *  evaluate at (r, u, rho); u += dt a, rho += dt drho (continuity, and
 *  evolving wall particles); w = u + xsph sum_j (m_j/rho_j) (u_j - u_i)
 *  W_ij at the mid-step positions (or w = u without XSPH); r += dt/2 w.
 *  The drift velocity w is kept by particle id for the next step's first
 *  drift [reconstructed: the paper does not say which velocity drifts]:
 *  one evaluation a step.
 *  @return VSPH_OK; VSPH_EINVAL, the set untouched, if @p dt is not a
 *  finite number >= 0 (0: the rates evaluated, nothing moved); or an error from
 * the neighbour search (e.g. VSPH_EINVAL on non-finite positions: call _check).
 */
VSPH_API int vsph_integrate_step(struct vsph_integrate *s, double dt);

/** @brief Stability test: 0 if the state is sound, 1 (reason in s->reason)
 *  otherwise (and for a NULL @p s). */
VSPH_API int vsph_integrate_check(struct vsph_integrate *s);

/** @brief Energies, momenta and the energy budget of the current state (one
 *  extra right-hand-side evaluation). */
VSPH_API int vsph_integrate_diagnostics(struct vsph_integrate *s,
                                        struct vsph_equations_energy *en,
                                        struct vsph_equations_budget *b);

/** @brief The integrator's whole state (every particle array in its
 *  current order, ghosts and wall particles included, the capacity, time,
 *  step count and the transport-velocity scheme's kept rates) packed into
 *  @p buf, or only sized when @p buf is NULL: restored by
 *  vsph_integrate_unpack into an integrator set up with the same
 *  settings, the run goes on bitwise as if never stopped. In the
 *  machine's byte order.
 *  @return the bytes packed. */
VSPH_API size_t vsph_integrate_pack(const struct vsph_integrate *s,
                                    unsigned char *buf);

/** @brief The wall particles laid beside the fluid (ids n_fluid up to
 *  n_fluid + this; 0 without solid walls): the particles beyond them are
 *  images (ghosts, periodic images). */
VSPH_API size_t vsph_integrate_wall_count(const struct vsph_integrate *s);

/** @brief vsph_integrate_pack without the rates, which every evaluation
 *  writes before anything reads them (the accelerations, d rho/dt,
 *  de/dt), and, where there are no wall particles and no transport
 *  velocity, without volume and pressure, which every evaluation then
 *  makes from the density first: in 2-D 7 doubles a particle (9 with
 *  wall particles) and its material where the whole state holds 12
 *  (vsph_run keeps the step's start so while a snapshot within the step
 *  is written).
 *  Unpacked or restored, those arrays hold NaN until the next evaluation;
 *  the next step goes on bitwise as from the whole state. */
VSPH_API size_t vsph_integrate_pack_lean(const struct vsph_integrate *s,
                                         unsigned char *buf);

/** @brief vsph_integrate_pack_lean written to @p out from its start (a
 *  fresh file, which vsph_integrate_restore_file reads from its start),
 *  then flushed: kept out of memory while a snapshot is written.
 *  @return the bytes written, 0 where a write failed. */
VSPH_API size_t vsph_integrate_pack_lean_file(const struct vsph_integrate *s,
                                              FILE *out);

/** @brief vsph_integrate_restore of the @p len bytes at the start of
 *  @p in (vsph_integrate_pack_lean_file's). @return as
 *  vsph_integrate_restore, or VSPH_EIO. */
VSPH_API int vsph_integrate_restore_file(struct vsph_integrate *s, FILE *in,
                                         size_t len);

/** @brief Restore a state packed by vsph_integrate_pack or
 *  vsph_integrate_pack_lean (@p len bytes at @p buf; *used receives those
 * read; @p used may be NULL).
 *  @return VSPH_OK, VSPH_EINVAL (a NULL argument, cut short, or not this
 * set-up's: the integrator is then unusable and must be freed), VSPH_ENOMEM. */
VSPH_API int vsph_integrate_unpack(struct vsph_integrate *s,
                                   const unsigned char *buf, size_t len,
                                   size_t *used);

/** @brief Put back a state this integrator packed itself (vsph_run's
 *  snapshot between two steps): vsph_integrate_unpack, but a capacity
 *  grown since is kept. @return as vsph_integrate_unpack. */
VSPH_API int vsph_integrate_restore(struct vsph_integrate *s,
                                    const unsigned char *buf, size_t len);

/** @brief Bytes allocated for particles, neighbour structures and
 *  integrator storage. */
VSPH_API size_t vsph_integrate_bytes(const struct vsph_integrate *s);

/** @brief The bytes an integrator for @p n_fluid particles and about
 *  @p n_ghosts ghosts (0: no walls) in @p dim dimensions will need at
 *  most, with the first-pass workspace (PVWF, B, A, VISC-0x) when @p ws is
 *  1, and with the kernel corrections' arrays too when 2, and the
 *  transport velocity's fields when @p tvf: to refuse a run before
 *  allocating it. NaN for @p dim outside 1-3. */
VSPH_API double vsph_integrate_bytes_estimate(int dim, double n_fluid,
                                              double n_ghosts, int ws, int tvf);

#endif /* VSPH_SOLVER_INTEGRATE_H */
