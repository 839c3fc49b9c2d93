/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
#ifndef VSPH_SOLVER_RUN_H
#define VSPH_SOLVER_RUN_H

#include <stddef.h>
#include <stdio.h>

#include "../common/api.h"
#include "../common/params.h"
#include "equations.h"
#include "scene.h"

struct vsph_integrate;
struct vsph_kernel_type;
struct vsph_params_spec;

/** @file run.h
 *  @brief The simulation driver in GSL's alloc / iterate / free shape: it
 *  lays out a scene, advances it step by step with the integrator, stops it
 *  as unstable when the stability checks fail, and tells the caller when an
 *  energy row or a snapshot is due. It owns the "Solver" parameter section.
 *  No file I/O: the caller (runs/rundir) writes what it is handed.
 *
 *  @code
 *  vsph_run_alloc(&rp, &scene, &run);
 *  for (;;) {
 *    if (run->due & VSPH_RUN_ROW) { vsph_run_row(run, &row); ... }
 *    if (run->due & VSPH_RUN_SNAPSHOT) { ... run->integ->p ... }
 *    if (run->state != VSPH_RUN_RUNNING) break;
 *    vsph_run_iterate(run);
 *  }
 *  vsph_run_free(run);
 *  @endcode */

/** Outputs due at the current state (bits of vsph_run::due). */
enum vsph_run_due {
  VSPH_RUN_ROW = 1u,     /*!< an energy row (vsph_run_row) */
  VSPH_RUN_SNAPSHOT = 2u /*!< a particle snapshot */
};

/** Where the run stands. */
enum vsph_run_state {
  VSPH_RUN_RUNNING = 0, /*!< more steps to take */
  VSPH_RUN_DONE,        /*!< reached t_end */
  VSPH_RUN_UNSTABLE     /*!< stopped by a stability check: a result */
};

/** The "Solver" section (defaults and bounds in run.c's table). */
/** The most probes a run takes (Solver:probe_points): each reads every
 *  fluid particle at each output row. */
#define VSPH_RUN_PROBES_MAX 100

struct vsph_run_props {
  double xi;           /*!< Cleary's coefficient */
  double zeta;         /*!< Espanol-Revenga: zeta / mu */
  size_t res;          /*!< particles across the reference length */
  double hdx;          /*!< h/dx */
  double t_end;        /*!< end time (s); 0: the scene's */
  double cfl;          /*!< Courant number of RK4 */
  double dt;           /*!< a fixed time step (s); 0: the rule's */
  double delta;        /*!< delta-SPH coefficient; 0: off */
  double relax;        /*!< relaxed start: time (s) the particles settle at
                            rest, damped, before the scene's velocity is
                            given them; 0: start on the lattice */
  double rho_band;     /*!< unstable when |rho/rho0 - 1| exceeds it */
  double min_gap;      /*!< unstable when two particles come closer (dx) */
  size_t outputs;      /*!< energy rows over the run */
  size_t snapshots;    /*!< snapshots over the run; 0: none */
  double perturb;      /*!< random shift of the initial lattice (dx) */
  size_t seed;         /*!< seed of that shift (mt19937) */
  size_t max_steps;    /*!< refuse a run estimated to need more steps; stop
                            one that reaches it */
  double max_memory;   /*!< refuse a run estimated to need more (GiB) */
  double checkpoint_s; /*!< wall time between checkpoints (s); 0: only on
                            a signal (runs/rundir writes them) */
  double p0;           /*!< gas law: reference pressure (Pa); 0: from c0 */
  size_t reduce;       /*!< 1: Basa et al.'s local pressure reduction */
  size_t tvf;          /*!< 1: the transport-velocity scheme */
  double pb;           /*!< its background pressure (Pa); 0: rho0 c0^2 */
  double xsph;         /*!< XSPH's epsilon (leapfrog only); 0: off */
  double alpha;        /*!< contact: h = 2 alpha dx (0: from hdx) */
  double zeta_num;     /*!< contact: fraction of eta_num removed */
  double
      eta_num; /*!< contact: eta_num/(Z D0); 0: Parshikov et al.'s eq. (37) */
  size_t probe_points; /*!< probes evenly on the segment from (x0, y0) to
                            (x1, y1), both ends included; 1: the point
                            (x0, y0); 0: none (runs/rundir's probes.csv) */
  double probe_x0, probe_y0, probe_x1, probe_y1; /*!< the segment (m) */
  double probe_z;                                /*!< its z in 3-D (m) */
  /* the settings given by name (Solver:visc, kernel, eos, correction,
   * scheme, density, integrator), each held once, as what the name
   * resolves to (vsph_run_props_init); their names: vsph_viscous_name,
   * ktype->name, vsph_equations_eos_name, ..._corr_name, ..._scheme_name */
  int form;                             /*!< visc: vsph_viscous_form */
  const struct vsph_kernel_type *ktype; /*!< kernel: the kernel */
  int eos_kind;                         /*!< eos: vsph_equations_eos */
  int corr;                             /*!< correction: vsph_pair_corr */
  int scheme_kind;                      /*!< scheme: vsph_equations_scheme */
  int summation;                        /*!< density: 1 summation, 0
                                             continuity */
  int leapfrog;                         /*!< integrator: 1 leapfrog, 0 rk4 */
  int probe_z_given;                    /*!< 1: Solver:probe_z was given */
};

/** A run in progress. Fields are read-only for the caller. */
struct vsph_run {
  struct vsph_run_props props;  /*!< settings (a copy) */
  struct vsph_scene scene;      /*!< the scene (a copy) */
  struct vsph_integrate *integ; /*!< integrator: particles, time, steps */
  size_t n_fluid;               /*!< fluid particles */
  double h, dx, t_end;          /*!< resolution and end time */
  unsigned due;                 /*!< vsph_run_due bits at this state */
  int state;                    /*!< vsph_run_state */
  double t_unstable;            /*!< when it was stopped (s) */
  char reason[160];             /*!< why, or "" */
  double pairs;                 /*!< interactions gathered so far */
  int evaluated; /*!< 1: evaluated since its last step (an energy row, or
                      a snapshot's own time): the integrator's particles
                      are sorted by its cell list for this state and its
                      rates are free until the next step (a snapshot's
                      diagnostics use both); set by the run, not by its
                      caller */
  /* private: the output schedule */
  double out_dt, snap_dt, next_out, next_snap;
  /* private: at a snapshot's own time within a step (vsph_run_iterate),
   * the state it was reached from, packed, and that time */
  unsigned char *side;
  FILE *side_file; /* or there (an unlinked scratch file) */
  size_t side_len;
  double side_t;
};

/** One energy row: energies, momenta and the budget of the current
 *  state. */
struct vsph_run_row {
  double t;                        /*!< time (s) */
  struct vsph_equations_energy en; /*!< energies and momenta */
  struct vsph_equations_budget b;  /*!< power terms and residual */
};

/** @brief What the run's pairs compute, for names and metadata: the
 *  viscous formulation (Solver:visc), or "contact" for contact SPH. */
static inline const char *vsph_run_method(const struct vsph_run_props *rp) {
  return rp->scheme_kind == VSPH_EQUATIONS_CONTACT
             ? "contact"
             : vsph_viscous_name(rp->form);
}

/** @brief The "Solver" parameter table (@p n receives its length): its
 *  keys, defaults, bounds and help, for help texts and parameter files.
 *  Its offsets are those of vsph_run_props_init's own reading (the names
 *  it resolves are not kept in struct vsph_run_props): read a section with
 *  vsph_run_props_init; vsph_params_load refuses this table for a
 *  struct vsph_run_props. */
VSPH_API const struct vsph_params_spec *vsph_run_params(size_t *n);

/** @brief Read the "Solver" section of @p prm (NULL: defaults) into
 *  @p rp, check it and resolve the names it gives (formulation, kernel,
 *  state equation, correction, scheme, density, integrator). The
 *  scene's own Solver defaults (its CFL, contact SPH's settings) are not
 *  applied here: for a run of a scene, vsph_run_props_for_scene.
 *  @return VSPH_OK or VSPH_EINVAL (the message names the parameter). */
VSPH_API int vsph_run_props_init(struct vsph_run_props *rp,
                                 struct vsph_params *prm);

struct vsph_scene_type;

/** @brief The "Solver" section for a run of scene @p type: the scene's
 *  own Solver defaults given to @p prm where it sets none
 *  (vsph_scene_solver_defaults: its CFL; contact SPH for the shear and
 *  cylinder scenes), then read as vsph_run_props_init reads it. What
 *  `vsph run` and the report's runs do; applying it twice changes
 *  nothing. @return VSPH_OK, or VSPH_EINVAL (a NULL @p rp, @p type or
 *  @p prm; a bad setting, named). */
VSPH_API int vsph_run_props_for_scene(struct vsph_run_props *rp,
                                      const struct vsph_scene_type *type,
                                      struct vsph_params *prm);

/** What a run will cost, estimated before anything is allocated. */
struct vsph_run_estimate {
  double particles;  /*!< fluid particles */
  double bytes;      /*!< memory at most (ghosts and buffers included) */
  double steps;      /*!< steps to the end time at t = 0's time step */
  double neighbours; /*!< particles within each one's reach (every pass) */
};

/** @brief The estimate of a run of @p sc with @p rp (the figures
 *  vsph_run_alloc checks against Solver:max_memory and max_steps), for a
 *  scheduler: its order and resource requests.
 *  @return VSPH_OK, or VSPH_EINVAL when the run would be refused (the
 *  message says why). */
VSPH_API int vsph_run_estimate(const struct vsph_run_props *rp,
                               const struct vsph_scene *sc,
                               struct vsph_run_estimate *e);

/** @brief Lay out @p sc at rp->res particles across, perturb it if asked,
 *  and set up the integrator. Due at once: a row and (if any) a snapshot.
 *  @return VSPH_OK, VSPH_EINVAL, VSPH_ENOMEM, VSPH_ELIB. */
VSPH_API int vsph_run_alloc(const struct vsph_run_props *rp,
                            const struct vsph_scene *sc, struct vsph_run **out);

/** @brief Free; NULL is a no-op. */
VSPH_API void vsph_run_free(struct vsph_run *r);

/** @brief One step (dt of THEORY 5, cut to land on t_end), then the
 *  stability checks; updates state and due. A run stopped as unstable is
 *  not an error. Snapshots fall at multiples of t_end / snapshots: where
 *  one falls strictly within the coming step, this call instead takes a
 *  step of its own from the current state to that time and stops there
 *  with VSPH_RUN_SNAPSHOT due; the next call puts the state back as it
 *  was and takes the step itself, so the run's path (its energy rows,
 *  its end) is bitwise that of a run without snapshots.
 *  A snapshot that falls on a step's end with no energy row there is
 *  likewise shown aside (evaluated, at its round time) and put back.
 *  @return VSPH_OK; VSPH_EINTR when r->integ->stop asked for a stop
 *  within the step (the run is then at the step's start: as before the
 *  call, or, where the call began at a snapshot's own time, the state
 *  that snapshot was reached from); or an internal failure (VSPH_ENOMEM,
 *  ...). */
VSPH_API int vsph_run_iterate(struct vsph_run *r);

/** @brief The energy row of the current state (one extra right-hand side).
 *  @return VSPH_OK or an internal failure. */
VSPH_API int vsph_run_row(struct vsph_run *r, struct vsph_run_row *row);

/** @brief The run's whole state (the driver's schedule and counters and
 *  the integrator's state) packed into @p buf, or only
 *  sized when @p buf is NULL. Between two vsph_run_iterate calls a run
 *  restored from it by vsph_run_unpack goes on bitwise as if never
 *  stopped. @return the bytes packed; 0 where the state kept in a
 *  scratch file for a snapshot cannot be read back. */
VSPH_API size_t vsph_run_pack(const struct vsph_run *r, unsigned char *buf);

/** @brief Restore a state packed by vsph_run_pack into @p r, freshly made
 *  by vsph_run_alloc with the same settings (@p len bytes at @p buf).
 *  Due after it is what was due when it was packed: a driver clears each
 *  bit of vsph_run::due as it writes that output, so that a state packed
 *  before its outputs were all written has the rest written on restore.
 *  @return VSPH_OK; VSPH_EINVAL when it is cut short or not this run's (r
 *  must then be freed); VSPH_ENOMEM. */
VSPH_API int vsph_run_unpack(struct vsph_run *r, const unsigned char *buf,
                             size_t len);

/** @brief Time reached (s). */
VSPH_API double vsph_run_time(const struct vsph_run *r);

/** @brief Steps taken. */
VSPH_API size_t vsph_run_steps(const struct vsph_run *r);

/** @brief Bytes allocated for particles, neighbours and the integrator
 *  (not the transient copy a snapshot within a step keeps). */
VSPH_API size_t vsph_run_bytes(const struct vsph_run *r);

/** @brief PVWF particles whose L fell back to the identity in the last
 *  evaluation (0 for the other forms). */
VSPH_API size_t vsph_run_fallbacks(const struct vsph_run *r);

#endif /* VSPH_SOLVER_RUN_H */
