/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
#ifndef VSPH_RUNS_SHELL_H
#define VSPH_RUNS_SHELL_H

#include <stddef.h>

/** @file shell.h
 *  @brief A string as a POSIX shell reads it back: the one quoting rule of
 *  every command line vsph writes (run.json's command, the report's plan,
 *  its Slurm scripts). */

/** @brief @p s for a POSIX shell into @p out (at most @p len bytes with
 *  the NUL): as it is when every character is safe
 *  (`A-Za-z0-9_./:=+-,@%`), else in single quotes, a quote inside written
 *  '\''; the empty string as ''.
 *  @return the length the whole quoted string needs (as snprintf: a
 *  result >= @p len means it was cut). */
size_t vsph_shell_quote(const char *s, char *out, size_t len);

#endif /* VSPH_RUNS_SHELL_H */
