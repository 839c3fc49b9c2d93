#ifndef VSPH_KERNELS_KERNEL_H
#define VSPH_KERNELS_KERNEL_H

#include <math.h>
#include <stddef.h>

/** @file kernel.h
 *  @brief Smoothing kernels as runtime descriptors (THEORY.md section 1).
 *  A kernel is W(s; h) = h^-d w(q), q = s/h, w(q) = sigma_d f_d(q), with
 *  support radius kappa*h. This module owns the shapes and their
 *  normalisations only: no I/O, no particle data. */

/** A kernel shape or its derivative as a function of q = s/h. */
typedef double vsph_kernel_fn(double q);

/** Kernel descriptor, looked up by name at run time (GSL gsl_rng_type
 *  pattern). Index [dim-1] selects the 1-D, 2-D or 3-D variant. */
struct vsph_kernel_type {
  const char *name;       /*!< name used on the command line */
  double kappa;           /*!< support radius in units of h */
  double sigma[3];        /*!< normalisation sigma_d for d = 1, 2, 3 */
  vsph_kernel_fn *f[3];   /*!< un-normalised shape f_d(q), 0 for q>=kappa */
  vsph_kernel_fn *df[3];  /*!< df_d/dq */
  vsph_kernel_fn *dfq[3]; /*!< (df_d/dq)/q from q^2: the loops need W'/s */
  const char *reference;  /*!< source of the shape and constants */
};

extern const struct vsph_kernel_type vsph_gaussian_type;
extern const struct vsph_kernel_type vsph_cubic_type;
extern const struct vsph_kernel_type vsph_quintic_type;
extern const struct vsph_kernel_type vsph_wendland_c2_type;
extern const struct vsph_kernel_type vsph_wendland_c4_type;

/** @brief Number of kernels in the table. */
size_t vsph_kernel_count(void);

/** @brief The i-th kernel of the table (NULL when i is out of range). */
const struct vsph_kernel_type *vsph_kernel_get(size_t i);

/** @brief The kernel called @p name, or NULL if there is none. */
const struct vsph_kernel_type *vsph_kernel_find(const char *name);

/** @brief The kernel called @p name into @p out.
 *  @return VSPH_OK, or VSPH_EINVAL with a message listing the kernels. */
int vsph_kernel_resolve(const char *name, const struct vsph_kernel_type **out);

/** @brief Normalised kernel w(q) in dimension dim (dimensionless). */
static inline double vsph_kernel_w(const struct vsph_kernel_type *k, int dim,
                                   double q) {
  return k->sigma[dim - 1] * k->f[dim - 1](q);
}

/** @brief Normalised derivative w'(q) = dw/dq in dimension dim. */
static inline double vsph_kernel_dw(const struct vsph_kernel_type *k, int dim,
                                    double q) {
  return k->sigma[dim - 1] * k->df[dim - 1](q);
}

/** @brief The Monaghan-Gingold factor K = 2(d + 2) of THEORY section 0:
 *  6, 8, 10 in 1, 2, 3 dimensions. It scales MGF (Eq. 4.20) and the
 *  moments F and G; this is its one definition. */
static inline double vsph_kernel_mg_factor(int dim) { return 2.0 * (dim + 2); }

/** @brief The prefactor of W'(s)/s: W'(s)/s = sigma_d h^{-d-2} (df/dq)/q,
 *  so every loop evaluates W'/s as this times dfq(s^2/h^2), without a
 *  square root (h in m; result in m^{-d-2}). */
static inline double vsph_kernel_dwq_factor(const struct vsph_kernel_type *k,
                                            int dim, double h) {
  return k->sigma[dim - 1] * pow(h, -(dim + 2));
}

#endif /* VSPH_KERNELS_KERNEL_H */
