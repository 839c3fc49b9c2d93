#ifndef VSPH_CLI_ARGS_H
#define VSPH_CLI_ARGS_H

#include <stddef.h>

/** @file args.h
 *  @brief Strict command-line parsing shared by the sub-commands: every
 *  malformed or out-of-range value is one line on stderr and exit status 2.
 *  Also the CLI's error handler, which turns library reports into that one
 *  line. */

/** Exit status for bad input (the README's contract). */
#define VSPH_ARGS_EXIT_USAGE 2

/** @brief Print "vsph CMD: message" on stderr; returns VSPH_ARGS_EXIT_USAGE. */
int vsph_args_fail(const char *cmd, const char *fmt, ...);

/** @brief Parse a finite double from @p s; 0 on success, else reports
 *  "OPT: 'S' is not a number" and returns VSPH_ARGS_EXIT_USAGE. */
int vsph_args_double(const char *cmd, const char *opt, const char *s,
                     double *out);

/** @brief Parse a non-negative integer (decimal, no sign, no junk). */
int vsph_args_size(const char *cmd, const char *opt, const char *s,
                   size_t *out);

/** @brief The value after option argv[*i], advancing *i; NULL (after
 *  reporting "OPT needs a value") when there is none. */
const char *vsph_args_value(const char *cmd, int argc, char **argv, int *i);

/** @brief Install the CLI error handler: it keeps the first library message
 *  so the command can print exactly one line. */
void vsph_args_install_handler(void);

/** @brief The first library message since the last call (then cleared),
 *  or NULL. */
const char *vsph_args_last_error(void);

/** @brief Report a failed library call as one line; returns 2 for invalid
 *  input and 1 for internal failures. */
int vsph_args_status(const char *cmd, int status);

#endif /* VSPH_CLI_ARGS_H */
