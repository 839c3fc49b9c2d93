#ifndef VSPH_IO_RUNDIR_H
#define VSPH_IO_RUNDIR_H

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

/** What one run reports back (also written to run.json). */
struct vsph_rundir_result {
  int unstable;         /*!< 1 if the run was stopped as unstable */
  double unstable_time; /*!< when (s) */
  char reason[160];     /*!< why */
  size_t n_particles;   /*!< fluid particles */
  size_t steps;         /*!< steps taken */
  double t;             /*!< time reached (s) */
  double wall_s;        /*!< wall time of the time loop (s) */
  double pairs;         /*!< interactions gathered over the run */
  double h, dx, c0, mu; /*!< resolution and physics used */
  char dir[512];        /*!< the folder written */
};

/** @brief Run scene @p scene with the parameters of @p prm into @p dir
 *  (NULL: runs/SCENE-VISC-RES).
 *  @param progress where to print the start line, a progress line every
 *  2 s and the closing line; NULL for silence.
 *  @return VSPH_OK (a run stopped as unstable is a result, and OK),
 *  VSPH_EINVAL for bad input (one message reported, nothing written),
 *  VSPH_EIO, VSPH_ENOMEM, VSPH_ELIB. */
int vsph_rundir_execute(struct vsph_params *prm, const char *scene,
                        const char *dir, FILE *progress,
                        struct vsph_rundir_result *res);

#endif /* VSPH_IO_RUNDIR_H */
