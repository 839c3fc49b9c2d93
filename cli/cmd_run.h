#ifndef VSPH_CLI_CMD_RUN_H
#define VSPH_CLI_CMD_RUN_H
/** @file cmd_run.h @brief `vsph run` and `vsph scenes`. */
#include <stddef.h>

struct vsph_params;

/** What one run reports back (also written to run.json). */
struct vsph_cmd_run_result {
  int unstable;         /*!< 1 if the run was stopped as unstable */
  double unstable_time; /*!< when (s) */
  char reason[160];     /*!< why */
  size_t n_particles;   /*!< fluid particles */
  size_t steps;         /*!< steps taken */
  double t;             /*!< time reached (s) */
  double wall_s;        /*!< wall time of the time loop (s) */
  double pairs;         /*!< interactions gathered over the run */
  double h, dx, c0, mu; /*!< resolution and physics used */
};

/** @brief Run a scene from a parameter store (Solver: and Scene: keys):
 *  validate, set up, integrate, write DIR's outputs, fill @p result.
 *  quiet: 0 progress on stderr, 1 only the unstable verdict, 2 silent.
 *  @return 0, 2 after one line on stderr for bad input (nothing written),
 *  1 for an internal failure. */
int vsph_cmd_run_params(struct vsph_params *prm, const char *scene,
                        const char *out_dir, int quiet,
                        struct vsph_cmd_run_result *result);

/** @brief `vsph run SCENE ...`; returns the process exit status. */
int vsph_cmd_run_main(int argc, char **argv);
/** @brief `vsph scenes`: the scenes, their parameters and defaults. */
int vsph_cmd_run_scenes(int argc, char **argv);
#endif /* VSPH_CLI_CMD_RUN_H */
