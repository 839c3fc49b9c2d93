#ifndef VSPH_CLI_ARGS_H
#define VSPH_CLI_ARGS_H

#include <stddef.h>
#include <stdio.h>

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

/** Kinds of option value. */
enum vsph_args_kind {
  VSPH_ARGS_FLAG = 0, /*!< no value: sets an int to 1 */
  VSPH_ARGS_STRING,   /*!< a string (const char *) */
  VSPH_ARGS_DOUBLE,   /*!< a finite double */
  VSPH_ARGS_SIZE      /*!< a non-negative integer (size_t) */
};

/** One option of a sub-command: "--name" and where its value goes. */
struct vsph_args_spec {
  const char *name;         /*!< with the leading dashes */
  enum vsph_args_kind kind; /*!< value kind */
  void *dst;                /*!< int, const char *, double or size_t */
};

/** @brief Parse argv[1..] against @p specs (table-driven, so every command
 *  rejects the same way). "--help"/"-h" prints @p usage to stdout.
 *  @return -1 to go on, 0 after --help, VSPH_ARGS_EXIT_USAGE on bad input
 *  (one line already printed). */
int vsph_args_parse(const char *cmd, int argc, char **argv,
                    const struct vsph_args_spec *specs, size_t nspecs,
                    void (*usage)(FILE *));

struct vsph_kernel_type;

/** @brief Kernel called @p name, or NULL after "unknown kernel" (exit 2). */
const struct vsph_kernel_type *vsph_args_kernel(const char *cmd,
                                                const char *name);

/** @brief Dimension from a parsed double: 1, 2 or 3, else reports and
 *  returns 0. */
int vsph_args_dim(const char *cmd, double dimf);

/** @brief Resolve --lattice square|hex|perturbed and --perturb A into a
 *  vsph_lattice_kind and an amplitude (0 unless perturbed); checks hex is
 *  2-D and 0 <= A < 0.5. @return 0 or VSPH_ARGS_EXIT_USAGE. */
int vsph_args_lattice(const char *cmd, const char *name, int dim,
                      double perturb, int *kind, double *amp);

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
