/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
#ifndef VSPH_CLI_CMD_DISSIPATION_H
#define VSPH_CLI_CMD_DISSIPATION_H
/** @file cmd_dissipation.h @brief `vsph dissipation`. */
/** @brief Entry point; returns the process exit status. */
int vsph_cmd_dissipation_main(int argc, char **argv);
#endif /* VSPH_CLI_CMD_DISSIPATION_H */
