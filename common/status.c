/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
#include "status.h"

#include <stdio.h>

static const char *const vsph_status_names[] = {
    [VSPH_OK] = "success",
    [VSPH_EINVAL] = "invalid argument",
    [VSPH_ENOMEM] = "out of memory",
    [VSPH_EIO] = "input/output error",
    [VSPH_ENOCONV] = "no convergence",
    [VSPH_ELIB] = "numerical library failure",
    [VSPH_EINTR] = "interrupted",
    [VSPH_EFAIL] = "a run it depends on failed",
    [VSPH_EBUG] = "internal inconsistency (a bug)",
};
_Static_assert(sizeof vsph_status_names / sizeof vsph_status_names[0] ==
                   VSPH_STATUS_COUNT,
               "status name table out of sync");

static void default_handler(int status, const char *file, int line,
                            const char *msg) {
  (void)status;
  fprintf(stderr, "%s:%d: %s\n", file, line, msg);
}

/* The one process-global mutable pointer allowed by STYLE B13. */
static vsph_status_handler_fn *current_handler = default_handler;

const char *vsph_status_str(int status) {
  if (status < 0 || status >= VSPH_STATUS_COUNT) return "unknown status";
  return vsph_status_names[status];
}

void vsph_status_report(int status, const char *file, int line, const char *fmt,
                        ...) {
  char msg[1024];
  va_list ap;
  va_start(ap, fmt);
  vsnprintf(msg, sizeof msg, fmt, ap);
  va_end(ap);
  current_handler(status, file, line, msg);
}

vsph_status_handler_fn *vsph_status_set_handler(vsph_status_handler_fn *fn) {
  vsph_status_handler_fn *old = current_handler;
  current_handler = fn ? fn : default_handler;
  return old;
}
