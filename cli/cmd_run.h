/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
#ifndef VSPH_CLI_CMD_RUN_H
#define VSPH_CLI_CMD_RUN_H
/** @file cmd_run.h @brief `vsph run` and `vsph scenes`. */
/** @brief `vsph run SCENE ...`; returns the process exit status. */
int vsph_cmd_run_main(int argc, char **argv);
/** @brief `vsph scenes`: the scenes, their parameters and defaults. */
int vsph_cmd_run_scenes(int argc, char **argv);
#endif /* VSPH_CLI_CMD_RUN_H */
