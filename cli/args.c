#include "args.h"

#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../common/status.h"
#include "../kernels/kernel.h"
#include "../solver/lattice.h"

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

int vsph_args_parse(const char *cmd, int argc, char **argv,
                    const struct vsph_args_spec *specs, size_t nspecs,
                    void (*usage)(FILE *)) {
  for (int i = 1; i < argc; i++) {
    const char *a = argv[i];
    if (!strcmp(a, "--help") || !strcmp(a, "-h")) {
      usage(stdout);
      return 0;
    }
    const struct vsph_args_spec *sp = NULL;
    for (size_t k = 0; k < nspecs && !sp; k++)
      if (!strcmp(a, specs[k].name)) sp = &specs[k];
    if (!sp) return vsph_args_fail(cmd, "unknown option '%s' (see --help)", a);
    if (sp->kind == VSPH_ARGS_FLAG) {
      *(int *)sp->dst = 1;
      continue;
    }
    const char *v = vsph_args_value(cmd, argc, argv, &i);
    if (!v) return VSPH_ARGS_EXIT_USAGE;
    if (sp->kind == VSPH_ARGS_STRING)
      *(const char **)sp->dst = v;
    else if (sp->kind == VSPH_ARGS_DOUBLE) {
      if (vsph_args_double(cmd, a, v, sp->dst)) return VSPH_ARGS_EXIT_USAGE;
    } else if (vsph_args_size(cmd, a, v, sp->dst)) {
      return VSPH_ARGS_EXIT_USAGE;
    }
  }
  return -1;
}

const struct vsph_kernel_type *vsph_args_kernel(const char *cmd,
                                                const char *name) {
  const struct vsph_kernel_type *k = vsph_kernel_find(name);
  if (!k)
    vsph_args_fail(cmd,
                   "unknown kernel '%s' (gaussian, cubic, quintic, "
                   "wendland2, wendland4)",
                   name);
  return k;
}

int vsph_args_dim(const char *cmd, double dimf) {
  if (dimf != 1 && dimf != 2 && dimf != 3) {
    vsph_args_fail(cmd, "--dim must be 1, 2 or 3, got %g", dimf);
    return 0;
  }
  return (int)dimf;
}

int vsph_args_lattice(const char *cmd, const char *name, int dim,
                      double perturb, int *kind, double *amp) {
  const int perturbed = !strcmp(name, "perturbed");
  *kind = perturbed ? VSPH_LATTICE_SQUARE : vsph_lattice_find(name);
  if (*kind < 0)
    return vsph_args_fail(cmd,
                          "unknown lattice '%s' (square, hex, "
                          "perturbed)",
                          name);
  if (*kind == VSPH_LATTICE_HEX && dim != 2)
    return vsph_args_fail(cmd, "the hex lattice is 2-D only");
  if (!(perturb >= 0 && perturb < 0.5))
    return vsph_args_fail(cmd, "--perturb must lie in [0, 0.5), got %g",
                          perturb);
  *amp = perturbed ? perturb : 0.0;
  return 0;
}
