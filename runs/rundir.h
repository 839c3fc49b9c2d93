/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
#ifndef VSPH_IO_RUNDIR_H
#define VSPH_IO_RUNDIR_H

#include <signal.h>
#include <stddef.h>
#include <stdio.h>

struct vsph_params;

/** @file rundir.h
 *  @brief A solver run and its folder: the one path by which both
 *  `vsph run` and the report run a scene. It reads the "Solver" and "Scene"
 *  sections, refuses bad or unknown parameters before anything is written,
 *  drives solver/run and writes what it hands over: energy.csv (one row per
 *  output, flushed as written, with the reference columns of
 *  analysis/references), VTK snapshots and their PVD index,
 *  used_parameters.yml and run.json. */

/** How to run. */
struct vsph_rundir_opts {
  const char *dir; /*!< output folder; NULL: vsph-out/SCENE-VISC-RES */
  FILE *progress;  /*!< start line, a line every 2 s, closing line; NULL:
                        silence */
  /** if not NULL, the run stops after the step during which *stop became
   *  non-zero (set it from a signal handler): status "interrupted" */
  const volatile sig_atomic_t *stop;
  /** the command that asked for the run, as run.json records it; NULL:
   *  not recorded */
  const char *command;
  /** 1: a cached run: a folder whose seal (key.txt: the key of the
   *  parameters as given, vsph_rundir_key, and every file's size and
   *  CRC-32, runs/folder) holds is not run again (res->cached). Every run
   *  that ends (ok or unstable) is sealed, cached or not. */
  int cache;
  /** if not 0, the run stops as through *stop after this many steps of
   *  this process (tests of checkpoint and restart; *stop is then not
   *  consulted) */
  size_t stop_after;
  /** where that stop comes: 0 after the step and its outputs; a
   *  vsph_run_due bit: while that output is written, at the first state
   *  past stop_after steps where it is due */
  unsigned stop_in;
  /** if not NULL, set to 1 just before the folder is claimed (the first
   *  write): a caller's signal handler may end the process at once
   *  before that (vsph_args_quick_stop) */
  volatile sig_atomic_t *writing;
};

/** What one run reports back (also written to run.json). */
struct vsph_rundir_result {
  int unstable;         /*!< 1 if the run was stopped as unstable */
  int interrupted;      /*!< 1 if it was stopped through opts.stop */
  double unstable_time; /*!< when (s) */
  char reason[160];     /*!< why */
  size_t n_particles;   /*!< fluid particles */
  size_t steps;         /*!< steps taken */
  double t;             /*!< time reached (s) */
  double wall_s;        /*!< wall time of the time loop (s) */
  double cpu_s;         /*!< CPU time of the time loop, the run's threads (s) */
  double load[2][3];    /*!< load averages (1, 5, 15 min) before, after */
  double pairs;         /*!< interactions gathered over the run */
  double h, dx, c0, mu; /*!< resolution and physics used */
  char dir[512];        /*!< the folder written */
  char started[32];     /*!< UTC date and time of the start (ISO 8601) */
  size_t segments;      /*!< processes the run took: 1 + its resumptions */
  double bytes_before;  /*!< buffers' bytes in earlier processes (resumed) */
  int cached;           /*!< 1: opts.cache and the folder's key matched:
                             nothing was run (the other fields are empty) */
};

/** @brief The cache key of a run or measurement: "vsph VERSION HASH",
 *  then @p what (e.g. "scene vortex-patch"), then every parameter entry
 *  of @p prm as "Section:key=value", sorted by key. Call it before any
 *  value is read: it then holds the parameters as given (file, --set and
 *  options alike), and the defaults are fixed by the source hash. Two
 *  ways of giving the same settings give the same key.
 *  @return the key (caller frees), or NULL after reporting. */
char *vsph_rundir_key(const struct vsph_params *prm, const char *what);

/** @brief 1 if @p dir is a sealed vsph folder (a scene run or a shear
 *  test, as its marker says) whose seal holds for @p key: its key.txt
 *  holds @p key and every file's size and CRC-32 (runs/folder). */
int vsph_rundir_key_matches(const char *dir, const char *key);

/** @brief Run scene @p scene with the parameters of @p prm as @p o says,
 *  into a folder under the contract of runs/folder (claimed and locked:
 *  new, empty, or an earlier scene run's, whose files are removed, key.txt
 *  and run.json first; anything else is refused before it is touched).
 *  A folder holding a checkpoint of this very run (same sources, same
 *  parameters but Solver:checkpoint_s) resumes from it; the finished run
 *  is then bitwise the run never stopped, timings aside. A checkpoint is
 *  written every Solver:checkpoint_s of wall time and when stopped.
 *  @return VSPH_OK (a run stopped as unstable is a result, and OK);
 *  VSPH_EINVAL for bad input (one message reported, nothing written);
 *  VSPH_EINTR when stopped through o->stop (run.json says "interrupted",
 *  the checkpoint is kept, the snapshot index is closed); VSPH_EIO (a
 *  write failed: run.json says "error" if it can still be written, and
 *  never "ok"), VSPH_ENOMEM, VSPH_ELIB. */
int vsph_rundir_execute(struct vsph_params *prm, const char *scene,
                        const struct vsph_rundir_opts *o,
                        struct vsph_rundir_result *res);

#endif /* VSPH_IO_RUNDIR_H */
