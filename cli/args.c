#include "args.h"

#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../common/status.h"

int vsph_args_fail(const char *cmd, const char *fmt, ...) {
  va_list ap;
  va_start(ap, fmt);
  fprintf(stderr, "vsph %s: ", cmd);
  vfprintf(stderr, fmt, ap);
  fputc('\n', stderr);
  va_end(ap);
  return VSPH_ARGS_EXIT_USAGE;
}

int vsph_args_double(const char *cmd, const char *opt, const char *s,
                     double *out) {
  char *end;
  errno = 0;
  const double v = strtod(s, &end);
  if (end == s || *end != '\0' || errno == ERANGE || !isfinite(v))
    return vsph_args_fail(cmd, "%s: '%s' is not a finite number", opt, s);
  *out = v;
  return 0;
}

int vsph_args_size(const char *cmd, const char *opt, const char *s,
                   size_t *out) {
  char *end;
  errno = 0;
  if (s[0] < '0' || s[0] > '9')
    return vsph_args_fail(cmd, "%s: '%s' is not a non-negative integer", opt,
                          s);
  const unsigned long long v = strtoull(s, &end, 10);
  if (*end != '\0' || errno == ERANGE)
    return vsph_args_fail(cmd, "%s: '%s' is not a non-negative integer", opt,
                          s);
  *out = (size_t)v;
  return 0;
}

const char *vsph_args_value(const char *cmd, int argc, char **argv, int *i) {
  if (*i + 1 >= argc) {
    vsph_args_fail(cmd, "%s needs a value", argv[*i]);
    return NULL;
  }
  return argv[++*i];
}

/* The CLI keeps the first message of a failing call chain, so a command
 * prints one line however deep the failure was reported. */
static char last_msg[1024];

static void cli_handler(int status, const char *file, int line,
                        const char *msg) {
  (void)status;
  (void)file;
  (void)line;
  if (last_msg[0] == '\0') snprintf(last_msg, sizeof last_msg, "%s", msg);
}

void vsph_args_install_handler(void) { vsph_status_set_handler(cli_handler); }

const char *vsph_args_last_error(void) {
  static char copy[1024];
  if (last_msg[0] == '\0') return NULL;
  snprintf(copy, sizeof copy, "%s", last_msg);
  last_msg[0] = '\0';
  return copy;
}

int vsph_args_status(const char *cmd, int status) {
  const char *msg = vsph_args_last_error();
  fprintf(stderr, "vsph %s: %s\n", cmd, msg ? msg : vsph_status_str(status));
  return status == VSPH_EINVAL ? VSPH_ARGS_EXIT_USAGE : 1;
}
