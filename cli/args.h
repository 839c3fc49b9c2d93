/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
#ifndef VSPH_CLI_ARGS_H
#define VSPH_CLI_ARGS_H

#include <signal.h>
#include <stddef.h>
#include <stdio.h>

struct vsph_params;
struct vsph_params_spec;

/** @file args.h
 *  @brief Command-line parsing shared by the sub-commands. A sub-command
 *  declares its own options (flags, files) and the parameter sections of
 *  the modules it calls; every key of those sections becomes an option
 *  --key (underscores written as dashes), so defaults, bounds and help come
 *  from the modules' tables and are never restated here. Every malformed or
 *  out-of-range value is one line on stderr and exit status 2. Also the
 *  CLI's error handler, which turns library reports into that one line. */

/** Exit status for bad input (the README's contract). */
#define VSPH_ARGS_EXIT_USAGE 2

/** Kinds of a sub-command's own options. */
enum vsph_args_kind {
  VSPH_ARGS_FLAG = 0, /*!< no value: sets an int to 1 */
  VSPH_ARGS_STRING,   /*!< a string (const char *) */
  VSPH_ARGS_SIZE,     /*!< a non-negative decimal integer (size_t) */
  VSPH_ARGS_SET,      /*!< "Section:key=value" into the parameter store */
  VSPH_ARGS_PARAMS    /*!< a parameter file read into the store */
};

/** One option of a sub-command's own. */
struct vsph_args_spec {
  const char *name;         /*!< with the leading dashes */
  enum vsph_args_kind kind; /*!< value kind */
  void *dst;                /*!< int, const char * or size_t; NULL for SET,
                                 PARAMS */
  const char *value;        /*!< the value's name in the help, or NULL */
  const char *help;         /*!< one line */
};

/** A module's parameter section offered as options. */
struct vsph_args_section {
  const char *section;                 /*!< "Tensors", "Solver", ... */
  const struct vsph_params_spec *spec; /*!< its table */
  size_t n;                            /*!< its length */
};

/** A sub-command. */
struct vsph_args_cmd {
  const char *name;     /*!< "tensors" */
  const char *synopsis; /*!< what follows "usage: vsph NAME" */
  const char *about;    /*!< a paragraph on what it does and writes */
  const struct vsph_args_spec *own;         /*!< its own options */
  size_t nown;                              /*!< their number */
  const struct vsph_args_section *sections; /*!< module sections */
  size_t nsections;                         /*!< their number */
  const char *const *required; /*!< keys that must be given, or NULL */
};

/** @brief 1 if word @p arg of a command line names option @p opt: "--opt"
 *  or "--opt=value". */
int vsph_args_names(const char *arg, const char *opt);

/** @brief Print "vsph CMD: message" on stderr; returns
 *  VSPH_ARGS_EXIT_USAGE. */
int vsph_args_fail(const char *cmd, const char *fmt, ...);

/** @brief The usage of @p c: synopsis, about, then every option with its
 *  default and meaning (from the module tables). */
void vsph_args_usage(const struct vsph_args_cmd *c, FILE *f);

/** @brief Parse argv[1..] for @p c into @p prm and the own options' dsts.
 *  Parameter files come first, then --set, then the section options,
 *  whatever their order on the line; "--help"/"-h" prints the usage.
 *  @return -1 to go on, 0 after --help, VSPH_ARGS_EXIT_USAGE on bad input
 *  (one line already printed). */
int vsph_args_parse(const struct vsph_args_cmd *c, int argc, char **argv,
                    struct vsph_params *prm);

/** @brief Install the CLI error handler: it keeps the first library message
 *  so the command can print exactly one line. */
void vsph_args_install_handler(void);

/** @brief Catch SIGINT and SIGTERM: the signal's number is stored in the
 *  flag returned, which the long commands pass on as their stop request
 *  (the run ends after its current step; exit status 128 + signal). */
const volatile sig_atomic_t *vsph_args_catch_stop(void);

/** @brief From now on, until the flag returned is set to 1 (by the code
 *  that starts writing, e.g. runs/rundir when it claims its folder), a
 *  SIGINT or SIGTERM ends the process at once with 128 + signal and one
 *  line on stderr: nothing has been written, so there is nothing to keep,
 *  and a long set-up need not be waited for. Call after
 *  vsph_args_catch_stop. */
volatile sig_atomic_t *vsph_args_quick_stop(void);

/** @brief After @p seconds of wall time (> 0), raise the stop flag of
 *  vsph_args_catch_stop as a signal would, with SIGALRM's number: a time
 *  budget, spent. It never ends the process at once (a budget is not an
 *  interruption). @return 0, or -1 when the timer cannot be set. */
int vsph_args_stop_after(double seconds);

/** @brief Report a failed library call as one line (the first library
 *  message since the last report, else the status's name); returns 2 for
 *  invalid input and 1 for internal failures. */
int vsph_args_status(const char *cmd, int status);

/** @brief The same, the line headed by @p what (an option's name, say:
 *  "--from-archive: ..."; NULL: none), so a message from deep in the
 *  library says which input it is about. */
int vsph_args_status_about(const char *cmd, const char *what, int status);

/** @brief Flush stdout and report a failed write (exit status 1) unless
 *  @p rc already says a failure (reported then). Every sub-command ends
 *  through it. @return @p rc, or 1 if stdout failed. */
int vsph_args_finish(const char *cmd, int rc);

/** @brief Print @p obj (a cJSON object; freed) to stdout and end the
 *  command through vsph_args_finish: the --json ending of the analysis
 *  commands. @return 0, or the status of a failed print or write. */
int vsph_args_json(const char *cmd, void *obj);

/** An analysis command (tensors, scaling, dissipation, laplacian): its
 *  options are --json and one module's parameter section; it computes one
 *  result and prints it as a table or as JSON. The four hooks work on the
 *  command's own state @p work (its props and result). */
struct vsph_args_analysis {
  const char *name;      /*!< "tensors" */
  const char *synopsis;  /*!< what follows "usage: vsph NAME" */
  const char *about;     /*!< a paragraph on what it does */
  const char *json_keys; /*!< the help line of --json */
  const char *section;   /*!< the module's parameter section */
  /** the section's table (its length in *n) */
  const struct vsph_params_spec *(*params)(size_t *n);
  /** the props from the parsed settings (a status) */
  int (*init)(void *work, struct vsph_params *prm);
  /** the computation (a status) */
  int (*compute)(void *work);
  /** the result as a cJSON object, or NULL when it cannot be built */
  void *(*json)(const void *work);
  /** the table on stdout (0, or a status reported already: 1 or 2) */
  int (*print)(const void *work);
};

/** @brief The whole body of an analysis command: parse, init, compute,
 *  then the table or (--json) the JSON, ended through vsph_args_finish.
 *  @return the exit status. */
int vsph_args_analysis_main(const struct vsph_args_analysis *a, void *work,
                            int argc, char **argv);

#endif /* VSPH_CLI_ARGS_H */
