/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
/* vsph contact: the numerical viscosity of contact SPH by Parshikov et
 * al.'s shear test (analysis/contact), or its lattice-sum prediction. */
#include "cmd_contact.h"

#include <omp.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "../analysis/contact.h"
#include "../common/consts.h"
#include "../common/params.h"
#include "../common/status.h"
#include "../io/files.h"
#include "../kernels/kernel.h"
#include "../runs/jobs.h"
#include "../runs/sheartest.h"
#include "../solver/materials.h"
#include "../solver/run.h"
#include "../solver/scene.h"
#include "args.h"

static const char *const CMD = "contact";

static const char ABOUT[] =
    "The numerical viscosity of a scheme by Parshikov et al.'s shear test\n"
    "(docs/theory.md section 12): run the shear scene (see vsph scenes),\n"
    "then fit the viscosity nu whose exact solution (Stokes' first\n"
    "problem, with the period's images) best matches the slab means of u_y\n"
    "and of the particles' displacement (the paper's control surface).\n"
    "Prints, per profile time, nu and eta/(Z D0) = nu/(c0 D0) of both fits\n"
    "and their RMS residuals; a fit that carries no information (a profile\n"
    "narrower than one slab D0, or a fit at the end of its search range) is\n"
    "printed nan, with its reason on a # line. With no option it is the\n"
    "paper's Table 1 run: lead at +-500 m/s, inviscid (Scene:viscous = 0\n"
    "unless given), contact SPH with Wendland C2 at alpha 0.5, D0 = 10 nm\n"
    "(res 80), to 4.5 ns (the shear scene's own Solver defaults, which apply\n"
    "unless --visc or --scheme wcsph is given). Parameters as for vsph run\n"
    "shear (Solver: options below, whose bracketed defaults are the\n"
    "table's; Scene: by --set). K profiles need K steps at least: fewer is\n"
    "refused. With --lattice, prints instead the lattice-sum prediction\n"
    "eta_num/(Z D0) of the acoustic solver for the Wendland C2 and cubic\n"
    "kernels, Parshikov et al.'s fit (37), and the shear factor of the contact "
    "viscous\n"
    "stress on the same lattice; its table is fixed, so any other option\n"
    "(but --threads, --quiet) is refused as having no effect.";

static int lattice_table(void) {
  const struct vsph_kernel_type *w = vsph_kernel_find("wendland2"),
                                *b = vsph_kernel_find("cubic");
  static const double alphas[] = {0.5, 0.55, 0.6, 0.75, 1.0, 1.5, 2.0};
  printf(
      "# vsph %s: eta_num/(Z D0) of the acoustic Riemann solver, lattice "
      "sum on the simple cubic lattice (h = 2 alpha D0), and Parshikov et "
      "al.'s fit "
      "(37)\n",
      VSPH_VERSION);
  printf(
      "alpha,lattice_wendland2,lattice_cubic,fit37,visc_factor_wendland2,"
      "visc_factor_cubic\n");
  for (size_t k = 0; k < sizeof alphas / sizeof alphas[0]; k++)
    printf("%g,%.5f,%.5f,%.5f,%.4f,%.4f\n", alphas[k],
           vsph_contact_lattice_coef(w, 3, alphas[k]),
           vsph_contact_lattice_coef(b, 3, alphas[k]),
           vsph_materials_eta_num_fit(alphas[k]),
           vsph_contact_lattice_visc_factor(w, 3, alphas[k]),
           vsph_contact_lattice_visc_factor(b, 3, alphas[k]));
  return vsph_args_finish(CMD, 0);
}

/* FILE's folder into @p dir ("." without one, "/" at the root); returns
 * the file's name within it. */
static const char *split_path(const char *path, char *dir, size_t len) {
  snprintf(dir, len, "%s", path);
  char *slash = strrchr(dir, '/');
  if (!slash) {
    snprintf(dir, len, ".");
    return path;
  }
  if (slash == dir)
    slash[1] = '\0';
  else
    *slash = '\0';
  return path + (slash - dir) + 1;
}

/* The profiles and both fits into FILE (atomically). */
static int write_profiles(const char *path,
                          const struct vsph_contact_shear *cs) {
  char *buf = vsph_sheartest_csv_profiles(cs);
  if (!buf) return VSPH_ENOMEM;
  char dir[1024];
  const char *name = split_path(path, dir, sizeof dir);
  const int st = vsph_files_write(dir, name, buf);
  free(buf);
  return st;
}

/* 1 if --profiles is on the line (parsed already: every option but the
 * three flags takes a value, the next word or after '='). */
static int profiles_given(int argc, char **argv) {
  for (int i = 1; i < argc; i++) {
    if (vsph_args_names(argv[i], "--profiles")) return 1;
    if (strcmp(argv[i], "--lattice") && strcmp(argv[i], "--cache") &&
        strcmp(argv[i], "--quiet") && !strchr(argv[i], '='))
      i++; /* its value */
  }
  return 0;
}

/* --lattice prints a fixed table: every option is still checked (bounds,
 * names, unknown keys, the scene), and then one that would have no effect
 * is refused rather than silently ignored. Returns -1 to go on. */
static int lattice_checks(struct vsph_params *prm, const char *csv,
                          const char *out, int cache, int profiles) {
  const char *drop = out ? "--out" : csv ? "--csv" : cache ? "--cache" : NULL;
  if (!drop && profiles) drop = "--profiles";
  if (drop)
    return vsph_args_fail(CMD,
                          "%s has no effect with --lattice, which prints its "
                          "table on standard output and runs nothing: drop %s",
                          drop, drop);
  struct vsph_run_props rp;
  struct vsph_scene sc;
  int st = vsph_run_props_init(&rp, prm);
  if (!st) st = vsph_scene_init(&sc, &vsph_shear_type, prm);
  if (st) return vsph_args_status(CMD, st);
  const char *unused = vsph_params_unused(prm);
  if (unused) {
    char hint[1024];
    vsph_params_hint(prm, unused, hint, sizeof hint);
    return vsph_args_fail(CMD, "unknown parameter '%s'%s", unused, hint);
  }
  for (size_t i = 0; i < vsph_params_count(prm); i++) {
    const char *k, *v;
    int used;
    vsph_params_entry(prm, i, &k, &v, &used);
    if (vsph_params_given(prm, k))
      return vsph_args_fail(
          CMD,
          "%s has no effect with --lattice, whose table is fixed (Wendland "
          "C2 and the cubic B-spline, alpha 0.5-2, the simple cubic "
          "lattice): drop it",
          k);
  }
  return -1;
}

/* The measurement printed (and its profiles into @p csv, if given): the
 * exit status. Frees @p prm. */
static int measure_print(struct vsph_params *prm, size_t nprof, int quiet,
                         const char *csv) {
  /* without a folder there is no checkpoint: a stop ends it, said */
  const volatile sig_atomic_t *stop = vsph_args_catch_stop();
  struct vsph_contact_shear cs = {
      .nprof = nprof,
      .progress = quiet ? NULL : vsph_sheartest_progress,
      .stop = stop};
  int st = vsph_contact_shear_measure(prm, &cs);
  vsph_params_free(prm);
  if (st == VSPH_EINTR) {
    fprintf(stderr,
            "vsph contact: stopped by signal %d; without --out DIR the test "
            "keeps no checkpoint to go on from\n",
            (int)*stop);
    return 128 + (int)*stop;
  }
  if (st) return vsph_args_status(CMD, st);
  printf(
      "# vsph %s contact: shear test, %zu particles, D0 = %g m, U0 = %g "
      "m/s, rho0 = %g, c0 = %g, %zu steps in %.1f s%s%s\n",
      VSPH_VERSION, cs.n, cs.D0, cs.U0, cs.rho0, cs.c0, cs.steps, cs.wall_s,
      cs.stable ? "" : ", UNSTABLE: ", cs.reason);
  printf("t,nu_u,eta_u_over_ZD0,rms_u,nu_dy,eta_dy_over_ZD0,rms_dy\n");
  const double zd = cs.c0 * cs.D0;
  for (size_t k = 0; k < cs.nt; k++)
    printf("%.6e,%.6e,%.5f,%.3e,%.6e,%.5f,%.3e\n", cs.t[k], cs.nu_u[k],
           cs.nu_u[k] / zd, cs.rms_u[k], cs.nu_dy[k], cs.nu_dy[k] / zd,
           cs.rms_dy[k]);
  /* a fit that is no result is nan above, and says why here */
  for (size_t k = 0; k < cs.nt; k++)
    for (int q = 0; q < 2; q++) {
      const char *why = q ? cs.na_dy[k] : cs.na_u[k];
      if (why)
        printf("# t = %.6e: the %s fit is not available (nan): %s\n", cs.t[k],
               q ? "control-surface" : "u_y", why);
    }
  if (csv && (st = write_profiles(csv, &cs))) {
    vsph_contact_shear_free(&cs);
    return vsph_args_status(CMD, st);
  }
  vsph_contact_shear_free(&cs);
  return vsph_args_finish(CMD, 0);
}

int vsph_cmd_contact_main(int argc, char **argv) {
  int lattice = 0;
  size_t nprof = 3;
  const char *csv = NULL, *out = NULL;
  int cache = 0, quiet = 0;
  size_t threads = 0;
  const struct vsph_args_spec own[] = {
      {"--lattice", VSPH_ARGS_FLAG, &lattice, NULL,
       "print the lattice-sum prediction and exit (no other option but "
       "--threads and --quiet)"},
      {"--profiles", VSPH_ARGS_SIZE, &nprof, "K",
       "profile times t_end k/K, k = 1..K (1-8; at most one per step) [3]"},
      {"--csv", VSPH_ARGS_STRING, &csv, "FILE",
       "write the profiles and both fits (t, x, u, u_fit, dy, dy_fit)"},
      {"--out", VSPH_ARGS_STRING, &out, "DIR",
       "write summary.csv (one row per profile time) and profiles.csv into "
       "DIR instead of printing (the report's shear tests)"},
      {"--cache", VSPH_ARGS_FLAG, &cache, NULL,
       "with --out: skip the measurement when DIR's seal holds (key.txt: "
       "version, source hash, the parameters as given, each file's size "
       "and CRC-32; written last in any case)"},
      {"--threads", VSPH_ARGS_SIZE, &threads, "T",
       "OpenMP threads, 0-1024; 0 or none: OMP_NUM_THREADS or all cores"},
      {"--quiet", VSPH_ARGS_FLAG, &quiet, NULL, "no progress line"},
      {"--params", VSPH_ARGS_PARAMS, NULL, "FILE", "parameter file"},
      {"--set", VSPH_ARGS_SET, NULL, "S:k=v",
       "one parameter, e.g. Scene:material=water (repeatable)"}};
  size_t n;
  const struct vsph_params_spec *spec = vsph_run_params(&n);
  const struct vsph_args_section sec = {"Solver", spec, n};
  const struct vsph_args_cmd c = {
      CMD, "[options]", ABOUT, own, sizeof own / sizeof own[0], &sec, 1, NULL};
  struct vsph_params *prm = vsph_params_alloc();
  if (!prm) return vsph_args_status(CMD, VSPH_ENOMEM);
  int rc = vsph_args_parse(&c, argc, argv, prm);
  if (rc < 0 && (nprof < 1 || nprof > 8))
    rc = vsph_args_fail(CMD, "--profiles must lie in 1-8, got %zu", nprof);
  if (rc < 0 && threads > 1024)
    rc = vsph_args_fail(CMD, "--threads must lie in 0-1024, got %zu", threads);
  if (rc < 0 && cache && !out)
    rc = vsph_args_fail(CMD, "--cache needs --out DIR");
  if (rc < 0 && out && csv)
    rc = vsph_args_fail(CMD, "--out writes profiles.csv itself: drop --csv");
  if (rc < 0 && !out && !lattice &&
      vsph_params_given(prm, "Solver:checkpoint_s"))
    rc = vsph_args_fail(CMD,
                        "--checkpoint-s needs --out DIR (the checkpoint goes "
                        "in that folder)");
  if (rc < 0 && lattice)
    rc = lattice_checks(prm, csv, out, cache, profiles_given(argc, argv));
  if (rc >= 0) {
    vsph_params_free(prm);
    return rc;
  }
  if (lattice) {
    vsph_params_free(prm);
    return lattice_table();
  }
  if (csv) { /* before the run: a folder that is not there is bad input */
    char dir[1024];
    split_path(csv, dir, sizeof dir);
    if (access(dir, W_OK) != 0) {
      vsph_params_free(prm);
      return vsph_args_fail(CMD, "--csv %s: folder '%s' is not writable", csv,
                            dir);
    }
    const int st = vsph_files_target(csv); /* never replace a device */
    if (st) {
      vsph_params_free(prm);
      return vsph_args_status(CMD, st);
    }
  }
  /* the measurement's defaults (the paper's inviscid run), into the
   * parameters as given, by the one function the report's jobs use */
  if (vsph_jobs_defaults(VSPH_JOBS_SHEAR, NULL, prm)) {
    vsph_params_free(prm);
    return vsph_args_status(CMD, VSPH_ENOMEM);
  }
  if (threads > 0) omp_set_num_threads((int)threads);
  if (out) {
    int cached;
    /* SIGINT/SIGTERM: the test stops at a checkpoint after the current
     * step, and the same command again goes on from it */
    const volatile sig_atomic_t *stop = vsph_args_catch_stop();
    const int st =
        vsph_sheartest_execute(prm, nprof, out, cache, quiet, stop, &cached);
    vsph_params_free(prm);
    if (st == VSPH_EINTR) return 128 + (int)*stop; /* the shell's rule */
    if (st) return vsph_args_status(CMD, st);
    if (!quiet)
      fprintf(stderr, "vsph contact: %s %s\n", out,
              cached ? "is cached (its seal holds): not measured again"
                     : "written");
    return vsph_args_finish(CMD, 0);
  }
  return measure_print(prm, nprof, quiet, csv);
}
