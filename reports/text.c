/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
#include "text.h"

#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#include "../common/status.h"

void vsph_text_clear(struct vsph_text_vars *tv) { tv->n = 0; }

int vsph_text_set(struct vsph_text_vars *tv, const char *key, const char *fmt,
                  ...) {
  size_t k = 0;
  while (k < tv->n && strcmp(tv->key[k], key)) k++;
  if (k == VSPH_TEXT_MAXVARS)
    VSPH_FAIL(VSPH_EINVAL, "more than %d template values", VSPH_TEXT_MAXVARS);
  if (k == tv->n) {
    snprintf(tv->key[k], sizeof tv->key[k], "%s", key);
    tv->n++;
  }
  va_list ap;
  va_start(ap, fmt);
  const int w = vsnprintf(tv->val[k], sizeof tv->val[k], fmt, ap);
  va_end(ap);
  tv->cut[k] = w < 0 || (size_t)w >= sizeof tv->val[k];
  if (tv->cut[k])
    VSPH_FAIL(VSPH_EINVAL, "the value of {{%s}} is longer than %zu characters",
              key, sizeof tv->val[k] - 1);
  return VSPH_OK;
}

const char *vsph_text_get(const char *name) {
  for (unsigned long b = 0; b < vsph_text_nblocks; b++)
    if (!strcmp(vsph_text_blocks[b].name, name))
      return vsph_text_blocks[b].text;
  return NULL;
}

int vsph_text_write(FILE *out, const char *name,
                    const struct vsph_text_vars *tv) {
  const char *c = vsph_text_get(name);
  if (!c) VSPH_FAIL(VSPH_EINVAL, "no prose block '%s' in reports/text", name);
  for (;;) {
    const char *open = strstr(c, "{{");
    if (!open) break;
    const char *close = strstr(open + 2, "}}");
    if (!close) break;
    fwrite(c, 1, (size_t)(open - c), out);
    const size_t len = (size_t)(close - open - 2);
    size_t k = 0;
    while (tv && k < tv->n &&
           !(strlen(tv->key[k]) == len && !strncmp(tv->key[k], open + 2, len)))
      k++;
    if (!tv || k == tv->n)
      VSPH_FAIL(VSPH_EINVAL,
                "prose block '%s' uses {{%.*s}}, which has no "
                "value",
                name, (int)len, open + 2);
    if (tv->cut[k])
      VSPH_FAIL(VSPH_EINVAL,
                "prose block '%s': the value of {{%s}} was cut short", name,
                tv->key[k]);
    fputs(tv->val[k], out);
    c = close + 2;
  }
  fputs(c, out);
  return VSPH_OK;
}

int vsph_text_format(char *buf, size_t len, const char *name,
                     const struct vsph_text_vars *tv) {
  if (len == 0) return VSPH_EINVAL;
  buf[0] = '\0';
  FILE *f = fmemopen(buf, len, "w");
  if (!f) VSPH_FAIL(VSPH_ENOMEM, "cannot format prose block '%s'", name);
  const int st = vsph_text_write(f, name, tv);
  fclose(f);
  buf[len - 1] = '\0';
  size_t n = strlen(buf);
  while (n > 0 && (buf[n - 1] == '\n' || buf[n - 1] == ' ')) buf[--n] = '\0';
  return st;
}
