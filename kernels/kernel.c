#include "kernel.h"

#include <string.h>

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
  for (size_t i = 0; i < vsph_kernel_count(); i++)
    if (strcmp(kernel_table[i]->name, name) == 0) return kernel_table[i];
  return NULL;
}
