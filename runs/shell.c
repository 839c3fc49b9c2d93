/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
#include "shell.h"

#include <string.h>

size_t vsph_shell_quote(const char *s, char *out, size_t len) {
  const int safe = *s && strspn(s,
                                "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrs"
                                "tuvwxyz0123456789_./:=+-,@%") == strlen(s);
  size_t n = 0;
#define PUT(c)                     \
  do {                             \
    if (n + 1 < len) out[n] = (c); \
    n++;                           \
  } while (0)
  if (!safe) PUT('\'');
  for (; *s; s++) {
    if (!safe && *s == '\'') {
      PUT('\'');
      PUT('\\');
      PUT('\'');
    }
    PUT(*s);
  }
  if (!safe) PUT('\'');
#undef PUT
  if (len) out[n < len ? n : len - 1] = '\0';
  return n;
}
