/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
/* vsph: viscous SPH at a free surface. Dispatches the sub-commands. */
#include <gsl/gsl_errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "../common/consts.h"
#include "../common/sysinfo.h"
#include "args.h"
#include "cmd_bench.h"
#include "cmd_contact.h"
#include "cmd_dissipation.h"
#include "cmd_laplacian.h"
#include "cmd_report.h"
#include "cmd_run.h"
#include "cmd_scaling.h"
#include "cmd_tensors.h"

struct command {
  const char *name;
  int (*fn)(int, char **);
  const char *what;
};

static const struct command commands[] = {
    {"tensors", vsph_cmd_tensors_main,
     "kernel moment tensors F, G, N, M by quadrature or particle sums"},
    {"scaling", vsph_cmd_scaling_main,
     "1/h truncation-error scaling at the surface; interior convergence"},
    {"dissipation", vsph_cmd_dissipation_main,
     "dissipation integral of a formulation on a disc or square"},
    {"laplacian", vsph_cmd_laplacian_main,
     "Laplacian patch test of the forms VISC-01..04 (Zheng et al. 2018)"},
    {"run", vsph_cmd_run_main, "run the free-surface WCSPH solver on a scene"},
    {"contact", vsph_cmd_contact_main,
     "numerical viscosity of a scheme by Parshikov et al.'s shear test"},
    {"scenes", vsph_cmd_run_scenes,
     "list the scenes, their parameters and defaults"},
    {"report", vsph_cmd_report_main,
     "the main job: every part of the report into reports/out"},
    {"bench", vsph_cmd_bench_main,
     "timings: quadrature, particle sums, operators, solver"},
};

static void usage(FILE *f) {
  fprintf(f,
          "usage: vsph COMMAND [options]   (vsph COMMAND --help for each)\n"
          "vsph %s: consistency of viscous SPH formulations at a free "
          "surface\n(Colagrossi et al., Phys. Rev. E 84, 026705, 2011).\n\n"
          "commands:\n",
          VSPH_VERSION);
  for (size_t i = 0; i < sizeof commands / sizeof commands[0]; i++)
    fprintf(f, "  %-12s %s\n", commands[i].name, commands[i].what);
}

/* OpenMP threads that wait at a barrier spin for a short while, then
 * sleep. libgomp's default spins about 3 ms: beside other busy processes a
 * spinning thread takes the core its partner needs (a small run took 16.5 s
 * with 2 threads against 3.5 s with 1). Sleeping at once (passive) costs a
 * wake-up at every barrier instead (the same small run, quiet: 2.3 s on 2
 * threads against 1.4 s spinning). GOMP_SPINCOUNT=1000 keeps both: 1.5 s
 * quiet, 4.2 s loaded; large runs are the same under all three (docs/speed.md,
 * Speed). libgomp reads these once, when it loads, so vsph sets it and
 * starts itself again; a policy the environment gives (OMP_WAIT_POLICY or
 * GOMP_SPINCOUNT) is kept. */
static int set_wait_policy(void) {
  if (getenv("OMP_WAIT_POLICY") || getenv("GOMP_SPINCOUNT")) return 0;
  return setenv("GOMP_SPINCOUNT", "1000", 1) == 0;
}

/* The installed program runs on any x86-64: bin/vsph is built for the
 * baseline (make install with the default ARCH on a CPU with AVX2 and FMA,
 * scripts/install), and where the CPU has x86-64-v3 it starts the
 * install's copy built for it, PREFIX/libexec/vsph/x86-64-v3/vsph, found
 * beside bin/ (the same sources; results agree to rounding, as the
 * library's two copies do). VSPH_BASELINE set in the environment (to
 * anything) keeps the baseline copy. A copy built for x86-64-v3 or wider never
 * looks, so there is no loop. Sets @p path and returns 1 where that copy is to
 * run, with this program's own path in @p self (4096 bytes). */
static int faster_copy(char *path, size_t len, char *self) {
#if defined(__x86_64__) && !defined(__AVX2__) && defined(__GNUC__)
  if (getenv("VSPH_BASELINE")) return 0;
  __builtin_cpu_init();
#if defined(__clang__) || __GNUC__ < 12 /* no ISA levels: its features */
  if (!(__builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma") &&
        __builtin_cpu_supports("bmi") && __builtin_cpu_supports("bmi2")))
    return 0;
#else
  if (!__builtin_cpu_supports("x86-64-v3")) return 0;
#endif
  const ssize_t k = readlink("/proc/self/exe", self, 4095);
  if (k <= 0) return 0;
  self[k] = '\0';
  const char *slash = strrchr(self, '/');
  if (!slash) return 0;
  const int m = snprintf(path, len, "%.*s/../libexec/vsph/x86-64-v3/vsph",
                         (int)(slash - self), self);
  return m > 0 && (size_t)m < len && access(path, X_OK) == 0;
#else
  (void)path;
  (void)len;
  (void)self;
  return 0;
#endif
}

/* Start the copy for this CPU or start again under the wait policy,
 * whichever applies; if the start fails, vsph runs on as it is. */
static void start(char **argv) {
  char path[4200], self[4096];
  const int faster = faster_copy(path, sizeof path, self);
  const int policy = set_wait_policy();
  if (faster) {
    /* the copy's children and scripts name this program (VSPH_EXE, read
     * by vsph report), which chooses the copy wherever they run */
    setenv("VSPH_EXE", self, 1);
    execv(path, argv);
  }
  if (policy) execv("/proc/self/exe", argv);
}

int main(int argc, char **argv) {
  start(argv);
  /* STYLE B4: GSL reports through return codes; set before any thread. */
  gsl_set_error_handler_off();
  vsph_args_install_handler();
  if (argc < 2) return vsph_args_fail("", "missing COMMAND (see vsph --help)");
  if (!strcmp(argv[1], "--help") || !strcmp(argv[1], "-h") ||
      !strcmp(argv[1], "help")) {
    usage(stdout);
    return vsph_args_finish("--help", 0);
  }
  if (!strcmp(argv[1], "--version")) {
    printf("vsph %s (built for %s)\n", VSPH_VERSION, vsph_sysinfo_build_isa());
    return vsph_args_finish("--version", 0);
  }
  /* every command's output is flushed and checked before the exit status */
  for (size_t i = 0; i < sizeof commands / sizeof commands[0]; i++)
    if (!strcmp(argv[1], commands[i].name))
      return vsph_args_finish(commands[i].name,
                              commands[i].fn(argc - 1, argv + 1));
  /* the name echoed through the one message path: escaped and capped */
  return vsph_args_fail("", "unknown command '%s' (see vsph --help)", argv[1]);
}
