/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
/* vsph bench: timings (reports/bench.c), never in the tests. */
#include "cmd_bench.h"

#include <stdio.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "../common/status.h"
#include "../reports/bench.h"
#include "args.h"

static const char *const CMD = "bench";

int vsph_cmd_bench_main(int argc, char **argv) {
  struct vsph_bench_props bp = {.size = 200, .solver_only = 0, .processes = 1};
  size_t busy = 0;
  const char *csv = NULL;
  const struct vsph_args_spec own[] = {
      {"--size", VSPH_ARGS_SIZE, &bp.size, "N",
       "particles across the operators' square, 10-2000 (default 200)"},
      {"--solver-only", VSPH_ARGS_FLAG, &bp.solver_only, NULL,
       "only the solver table"},
      {"--busy", VSPH_ARGS_SIZE, &busy, "K",
       "start K busy processes beside the solver table, 0-8 (default 0)"},
      {"--processes", VSPH_ARGS_SIZE, &bp.processes, "P",
       "measure the solver table in P processes one after another, 1-20 "
       "(default 1; make bench: 5): its best and the median of their bests"},
      {"--csv", VSPH_ARGS_STRING, &csv, "FILE",
       "the solver table as CSV in FILE too (a spreadsheet opens it)"},
      {"--raw", VSPH_ARGS_FLAG, &bp.raw, NULL,
       "only the solver rows, as CSV on stdout (what each of --processes "
       "prints)"}};
  const struct vsph_args_cmd c = {
      CMD,
      "[--size N] [--solver-only] [--busy K] [--processes P] [--csv FILE] "
      "[--raw]",
      "Times (1) F, G, N, M by quadrature at one depth for every kernel in\n"
      "2-D and 3-D; (2) the particle sums against the number of particles;\n"
      "(3) each viscous operator on an N x N square at h/dx = 4/3 with the\n"
      "3h Gaussian, with 1 and 2 threads. An interaction is particle i\n"
      "gathering from one neighbour j within kappa h (each unique pair\n"
      "counts twice); PVWF makes two passes, so it does two interactions\n"
      "per pair per evaluation. (4) the solver in 2-D at 42k particles\n"
      "(the size the peer, DualSPHysics, was measured at), with 1 and 2\n"
      "threads: one force evaluation (continuity, pressure, viscous) per\n"
      "formulation and with delta-SPH, and one whole RK4 step on the\n"
      "stretching square and on the standing wave (walls), and MGF with\n"
      "the cubic B-spline at h/dx 1.5699 (Basa's channels) by its own\n"
      "specialised gather beside the general loop; interactions/s\n"
      "and particle-evaluations/s per core, the peak memory per particle of\n"
      "a whole run, the load average beside each row, the peer's figures\n"
      "below; then the strong scaling (1 thread against 2) and a\n"
      "weak-scaling estimate from the memory bandwidth. The CPU's model and\n"
      "clock head the table. --busy K measures the solver table beside K\n"
      "busy processes; --processes P in P processes (a process's speed can\n"
      "differ from the next's on a shared machine).",
      own,
      sizeof own / sizeof own[0],
      NULL,
      0,
      NULL};
  const int rc = vsph_args_parse(&c, argc, argv, NULL);
  if (rc >= 0) return vsph_args_finish(CMD, rc);
  if (busy > 8) return vsph_args_fail(CMD, "--busy must be 0-8, got %zu", busy);
  if (bp.processes < 1 || bp.processes > 20)
    return vsph_args_fail(CMD, "--processes must be 1-20, got %zu",
                          bp.processes);
  if (csv && !csv[0]) return vsph_args_fail(CMD, "--csv wants a file name");
  if (bp.raw && (bp.processes > 1 || csv))
    return vsph_args_fail(CMD,
                          "--raw is one process's rows on stdout: not with "
                          "--processes or --csv");
  if (csv) { /* refused before anything is measured, nothing made */
    char dir[4096];
    struct stat sb;
    if (strlen(csv) >= sizeof dir)
      return vsph_args_fail(CMD, "--csv: a path of %zu characters is too long",
                            strlen(csv));
    snprintf(dir, sizeof dir, "%s", csv);
    char *slash = strrchr(dir, '/');
    if (slash) *(slash == dir ? slash + 1 : slash) = '\0';
    if (csv[strlen(csv) - 1] == '/' ||
        (stat(csv, &sb) == 0 && !S_ISREG(sb.st_mode)))
      return vsph_args_fail(CMD, "--csv %s is not a file", csv);
    if (access(slash ? dir : ".", F_OK) != 0)
      return vsph_args_fail(CMD, "--csv %s: its folder %s does not exist", csv,
                            slash ? dir : ".");
    if (access(slash ? dir : ".", W_OK | X_OK) != 0 ||
        (access(csv, F_OK) == 0 && access(csv, W_OK) != 0))
      return vsph_args_fail(CMD, "--csv %s is not writable", csv);
  }
  /* opened once before anything is measured (for appending: a file of the
   * user's is not cut yet): what access() cannot tell (a /proc path, a
   * full or read-only file system) is refused now, not after minutes;
   * a file made here and left unwritten is removed */
  int made = 0;
  if (csv) {
    made = access(csv, F_OK) != 0;
    FILE *f = fopen(csv, "a");
    if (!f || fclose(f) != 0)
      return vsph_args_fail(CMD, "--csv %s cannot be written", csv);
  }
  bp.csv = csv;
  bp.busy = (int)busy;
  const int st = vsph_bench_run(&bp, stdout);
  if (st && made) remove(csv);
  return st ? vsph_args_status(CMD, st) : vsph_args_finish(CMD, 0);
}
