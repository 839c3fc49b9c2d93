/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
/* vsph run: the free-surface WCSPH solver on one scene (THEORY 5-6) into a
 * folder (runs/rundir); vsph scenes: every parameter with its default. */
#include "cmd_run.h"

#include <omp.h>
#include <signal.h>
#include <stdio.h>
#include <string.h>

#include "../common/params.h"
#include "../common/status.h"
#include "../runs/jobs.h"
#include "../runs/rundir.h"
#include "../runs/shell.h"
#include "../solver/run.h"
#include "../solver/scene.h"
#include "args.h"

static const char *const CMD = "run";

static const char ABOUT[] =
    "Run the weakly compressible free-surface solver (classical RK4; with\n"
    "--set Solver:integrator=leapfrog a drift-kick-drift leapfrog; with\n"
    "--tvf 1 the transport-velocity kick-drift-kick; with --scheme contact\n"
    "contact SPH, each pair through the acoustic Riemann solution) on a\n"
    "scene (see vsph scenes). Parameters come from FILE (YAML subset:\n"
    "Solver: and Scene: sections), then --set, then the options; an\n"
    "unknown key is an error and nothing is written. Writes to DIR (default\n"
    "vsph-out/SCENE-VISC-RES):\n"
    "  energy.csv          t, Ek, Ep, Ec, P_visc, P_delta, residual, Px,\n"
    "                      Py, Lz, dEk_dt, Ek_ref, dEk_ref, Em_ref,\n"
    "                      dEm_ref (reference wave/mechanical energy and\n"
    "                      its rate), u_err, u_err_rel, v_rms (channels:\n"
    "                      velocity error against the series; cavity:\n"
    "                      RMS and largest distance from Ghia et al.\n"
    "                      over U; NaN elsewhere); one row per output,\n"
    "                      flushed\n"
    "  profile.csv         channels: t, y, u, u_ref, n per row of\n"
    "                      particles at each snapshot\n"
    "  centreline.csv      cavity: t, line, s, vel, vel_ghia at Ghia et\n"
    "                      al.'s points of both centrelines, each\n"
    "                      snapshot\n"
    "  probes.csv          with --probe-points: t, probe, x, y, z, u, v,\n"
    "                      w, p, rho, fill at each probe and energy row\n"
    "                      (the kernel interpolation of the fluid; fill\n"
    "                      about 1 inside, 0 outside, then nan)\n"
    "  snap_NNNN.vtp       particle snapshots (VTK XML PolyData, binary,\n"
    "                      zlib-compressed: velocity, density, pressure,\n"
    "                      volume, mass, smoothing_length,\n"
    "                      vorticity (2-D: the scalar\n"
    "                      vorticity_z), div_r, free_surface, id;\n"
    "                      material in two-material contact runs; each\n"
    "                      described in the file's array_descriptions)\n"
    "                      and snapshots.pvd, the time series ParaView\n"
    "                      opens (with walls_NNNN.vtp beside each: the\n"
    "                      walls, lid and ghosts, typed, as part 1)\n"
    "  used_parameters.yml every parameter, defaults filled in\n"
    "  run.json            version, scene, visc, kernel, n_particles,\n"
    "                      steps, wall_s, pairs_per_s, status (ok or\n"
    "                      unstable), unstable_time, unstable_reason, ...\n"
    "  key.txt             the seal, written last: the parameters as\n"
    "                      given, then each file's size and CRC-32\n"
    "  .vsph-folder        the marker: this folder is a vsph scene run\n"
    "  .vsph-lock          held while a run writes: a second is refused\n"
    "  checkpoint.bin      the whole state, every Solver:checkpoint_s of\n"
    "                      wall time (default 600) and on SIGTERM/SIGINT;\n"
    "                      the same command resumes from it, bitwise as if\n"
    "                      never stopped; removed when the run ends\n"
    "DIR must be new, empty or a vsph scene run's (its files are replaced);\n"
    "anything else in it is refused before anything is touched.\n"
    "A run that goes unstable stops cleanly, keeps its output and is marked\n"
    "unstable in run.json (exit status 0: stability is a result). SIGINT\n"
    "or SIGTERM ends the run after its step (run.json says interrupted)\n"
    "with exit status 128 + the signal. The bracketed defaults below are\n"
    "the Solver table's; a scene may take its own (vsph scenes lists them):\n"
    "shear and cylinders run contact SPH (Wendland C2, alpha 0.5) unless\n"
    "--visc or --scheme wcsph is given. --visc with --scheme contact is\n"
    "refused: contact SPH has no viscous form.";

int vsph_cmd_run_main(int argc, char **argv) {
  const char *out_dir = NULL;
  size_t threads = 0;
  int quiet = 0, cache = 0;
  const struct vsph_args_spec own[] = {
      {"--out", VSPH_ARGS_STRING, &out_dir, "DIR", "output folder"},
      {"--threads", VSPH_ARGS_SIZE, &threads, "T",
       "OpenMP threads, 0-1024; 0 or none: OMP_NUM_THREADS or all cores"},
      {"--params", VSPH_ARGS_PARAMS, NULL, "FILE", "parameter file"},
      {"--set", VSPH_ARGS_SET, NULL, "S:k=v",
       "one parameter, e.g. Scene:nu=1e-4 (repeatable)"},
      {"--quiet", VSPH_ARGS_FLAG, &quiet, NULL,
       "no progress; only an unstable verdict"},
      {"--cache", VSPH_ARGS_FLAG, &cache, NULL,
       "skip the run when DIR's seal holds (key.txt: version, source hash, "
       "the parameters as given, each file's size and CRC-32; written last "
       "by every run that ended) (the report's runs)"}};
  size_t n;
  const struct vsph_params_spec *spec = vsph_run_params(&n);
  const struct vsph_args_section sec = {"Solver", spec, n};
  const struct vsph_args_cmd c = {
      CMD, "SCENE [options]", ABOUT, own, sizeof own / sizeof own[0], &sec, 1,
      NULL};
  if (argc >= 2 && (!strcmp(argv[1], "--help") || !strcmp(argv[1], "-h"))) {
    vsph_args_usage(&c, stdout);
    return vsph_args_finish(CMD, 0);
  }
  if (argc < 2 || argv[1][0] == '-')
    return vsph_args_fail(CMD, "missing SCENE (see vsph scenes)");
  if (!vsph_scene_find(argv[1]))
    return vsph_args_fail(CMD, "unknown scene '%s' (see vsph scenes)", argv[1]);
  struct vsph_params *prm = vsph_params_alloc();
  if (!prm) return vsph_args_status(CMD, VSPH_ENOMEM);
  int rc = vsph_args_parse(&c, argc - 1, argv + 1, prm);
  if (rc < 0 && threads > 1024)
    rc = vsph_args_fail(CMD, "--threads must lie in 0-1024, got %zu", threads);
  if (rc >= 0) {
    vsph_params_free(prm);
    return rc;
  }
  /* the scene's own Solver defaults (vsph scenes lists them), into the
   * parameters as given, by the one function the report's jobs use */
  if (vsph_jobs_defaults(VSPH_JOBS_RUN, argv[1], prm)) {
    vsph_params_free(prm);
    return vsph_args_status(CMD, VSPH_ENOMEM);
  }
  if (threads > 0) omp_set_num_threads((int)threads);
  /* SIGINT/SIGTERM: the run stops after the current step (runs/rundir) */
  const volatile sig_atomic_t *stop = vsph_args_catch_stop();
  /* the command line as given, for run.json, quoted as a shell reads it
   * back (vsph_shell_quote) */
  char command[2048];
  size_t len = (size_t)snprintf(command, sizeof command, "vsph");
  for (int k = 0; k < argc && len + 1 < sizeof command; k++) {
    command[len++] = ' ';
    len += vsph_shell_quote(argv[k], command + len, sizeof command - len);
  }
  if (len >= sizeof command) len = sizeof command - 1;
  command[len] = '\0';
  /* until the run claims its folder nothing is written: a signal then
   * ends vsph at once, however long the set-up */
  const struct vsph_rundir_opts opts = {.dir = out_dir,
                                        .progress = quiet ? NULL : stderr,
                                        .stop = stop,
                                        .command = command,
                                        .cache = cache,
                                        .writing = vsph_args_quick_stop()};
  struct vsph_rundir_result res;
  const int st = vsph_rundir_execute(prm, argv[1], &opts, &res);
  vsph_params_free(prm);
  if (st == VSPH_EINTR) { /* the shell's convention: 128 + signal */
    fprintf(stderr,
            "vsph run: interrupted by signal %d at t = %.6g (output kept in "
            "%s, run.json says interrupted)\n",
            (int)*stop, res.t, res.dir);
    return 128 + (int)*stop;
  }
  if (st) return vsph_args_status(CMD, st);
  if (*stop) { /* the signal came after the last step, while the run's last
                  row and files were written: the run is whole, and the
                  signal still ends the command as a signal does */
    fprintf(stderr,
            "vsph run: signal %d came after the last step: the run is "
            "complete (run.json in %s says so)\n",
            (int)*stop, res.dir);
    return 128 + (int)*stop;
  }
  if (res.cached) return vsph_args_finish(CMD, 0);
  if (quiet && res.unstable)
    fprintf(stderr, "vsph run: unstable at t = %.6g: %s (output kept in %s)\n",
            res.unstable_time, res.reason, res.dir);
  return vsph_args_finish(CMD, 0);
}

static void print_table(const char *title, const struct vsph_params_spec *s,
                        size_t n) {
  printf("%s\n", title);
  for (size_t k = 0; k < n; k++) {
    char def[64];
    vsph_params_spec_default(&s[k], def, sizeof def);
    printf("  %-12s %-20s %s\n", s[k].key, def, s[k].help);
  }
}

int vsph_cmd_run_scenes(int argc, char **argv) {
  if (argc > 1 && strcmp(argv[1], "--help") && strcmp(argv[1], "-h"))
    return vsph_args_fail("scenes", "unknown option '%s'", argv[1]);
  printf("usage: vsph run SCENE [options]   (vsph run --help)\n\n");
  size_t n;
  const struct vsph_params_spec *spec = vsph_run_params(&n);
  print_table("Solver: section (all scenes)", spec, n);
  for (size_t i = 0; i < vsph_scene_count(); i++) {
    const struct vsph_scene_type *t = vsph_scene_get(i);
    char title[720];
    char sd[200], cf[96] = "";
    vsph_scene_solver_defaults_text(t, sd, sizeof sd);
    if (t->cfl > 0.0)
      snprintf(cf, sizeof cf,
               "\n  Its own Courant number (unless Solver:cfl is given): %g.",
               t->cfl);
    snprintf(title, sizeof title,
             "\n%s: %s\n  --res counts particles across %s.%s%s%s%s Scene: "
             "section",
             t->name, t->description, t->length_name,
             sd[0] ? "\n  Solver defaults of its own (unless --visc or "
                     "--scheme wcsph is given): "
                   : "",
             sd, sd[0] ? "." : "", cf);
    print_table(title, t->params, t->nparams);
  }
  return vsph_args_finish("scenes", 0);
}
