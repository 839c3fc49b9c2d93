/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
#include "kernel.h"

#include <stdio.h>
#include <string.h>

#include "../common/status.h"

/* One table backs lookup by name and the loop tests (FFTW convention). */
static const struct vsph_kernel_type *const kernel_table[] = {
    &vsph_gaussian_type,    &vsph_cubic_type,       &vsph_quintic_type,
    &vsph_wendland_c2_type, &vsph_wendland_c4_type,
};

size_t vsph_kernel_count(void) {
  return sizeof kernel_table / sizeof kernel_table[0];
}

const struct vsph_kernel_type *vsph_kernel_get(size_t i) {
  return i < vsph_kernel_count() ? kernel_table[i] : NULL;
}

const struct vsph_kernel_type *vsph_kernel_find(const char *name) {
  if (!name) return NULL;
  for (size_t i = 0; i < vsph_kernel_count(); i++)
    if (strcmp(kernel_table[i]->name, name) == 0) return kernel_table[i];
  return NULL;
}

int vsph_kernel_resolve(const char *name, const struct vsph_kernel_type **out) {
  if (!name || !out)
    VSPH_FAIL(VSPH_EINVAL, "vsph_kernel_resolve: a NULL argument");
  *out = vsph_kernel_find(name);
  if (*out) return VSPH_OK;
  char list[256] = "";
  size_t len = 0;
  for (size_t i = 0; i < vsph_kernel_count() && len < sizeof list; i++)
    len += (size_t)snprintf(list + len, sizeof list - len, "%s%s",
                            i ? ", " : "", kernel_table[i]->name);
  VSPH_FAIL(VSPH_EINVAL, "unknown kernel '%s' (%s)", name, list);
}
