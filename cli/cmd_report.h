/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
#ifndef VSPH_CLI_CMD_REPORT_H
#define VSPH_CLI_CMD_REPORT_H
/** @file cmd_report.h @brief `vsph report` and its verbs plan, submit,
 *  assemble and archive. */
/** @brief Entry point; returns the process exit status. */
int vsph_cmd_report_main(int argc, char **argv);
#endif /* VSPH_CLI_CMD_REPORT_H */
