/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
#ifndef VSPH_CLI_CMD_BENCH_H
#define VSPH_CLI_CMD_BENCH_H
/** @file cmd_bench.h @brief `vsph bench`: timings (never in the tests). */
/** @brief Entry point; returns the process exit status. */
int vsph_cmd_bench_main(int argc, char **argv);
#endif /* VSPH_CLI_CMD_BENCH_H */
