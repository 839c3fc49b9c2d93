/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
#ifndef VSPH_CLI_CMD_CONTACT_H
#define VSPH_CLI_CMD_CONTACT_H
/** @file cmd_contact.h @brief `vsph contact`. */
/** @brief Entry point; returns the process exit status. */
int vsph_cmd_contact_main(int argc, char **argv);
#endif /* VSPH_CLI_CMD_CONTACT_H */
