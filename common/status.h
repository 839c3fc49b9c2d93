/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
#ifndef VSPH_COMMON_STATUS_H
#define VSPH_COMMON_STATUS_H

#include "api.h"

/** @file status.h
 *  @brief Status codes and the replaceable error handler (the GSL model,
 *  without abort). Library code reports through vsph_status_report and
 *  returns the code; only cli/ decides to stop. */

#include <stdarg.h>

/** Status codes returned by every fallible vsph function. */
enum vsph_status {
  VSPH_OK = 0,  /*!< success */
  VSPH_EINVAL,  /*!< bad argument or parameter value */
  VSPH_ENOMEM,  /*!< allocation failed */
  VSPH_EIO,     /*!< file could not be read or written */
  VSPH_ENOCONV, /*!< iteration hit its limit without meeting tolerance */
  VSPH_ELIB,    /*!< failure reported by GSL or FFTW */
  VSPH_EINTR,   /*!< stopped on request (a signal): output kept, marked */
  VSPH_EFAIL,   /*!< a run it depends on failed or went unstable */
  VSPH_EBUG,    /*!< vsph's own parts disagree: a bug, never bad input */
  VSPH_STATUS_COUNT
};

/** Signature of an error handler: status, source file, line, message. */
typedef void vsph_status_handler_fn(int status, const char *file, int line,
                                    const char *msg);

/** @brief Human-readable name of a status code ("invalid argument", ...). */
VSPH_API const char *vsph_status_str(int status);

/** @brief Format a message and pass it to the current handler.
 *  @note The default handler writes "file:line: message" to stderr. */
VSPH_API void vsph_status_report(int status, const char *file, int line,
                                 const char *fmt, ...);

/** @brief Install a handler (NULL restores the default); returns the old one.
 *  @note Process-global: set it before any OpenMP region starts. */
VSPH_API vsph_status_handler_fn *vsph_status_set_handler(
    vsph_status_handler_fn *fn);

/** Report, then return the code from the current function. */
#define VSPH_FAIL(s, ...)                                     \
  do {                                                        \
    vsph_status_report((s), __FILE__, __LINE__, __VA_ARGS__); \
    return (s);                                               \
  } while (0)

/** Internal invariant check, compiled out with -DNDEBUG (FFTW's A()). */
#ifdef NDEBUG
#define VSPH_ASSERT(expr) ((void)0)
#else
#define VSPH_ASSERT(expr)                                         \
  do {                                                            \
    if (!(expr))                                                  \
      vsph_status_report(VSPH_EINVAL, __FILE__, __LINE__,         \
                         "internal invariant failed: %s", #expr); \
  } while (0)
#endif

#endif /* VSPH_COMMON_STATUS_H */
