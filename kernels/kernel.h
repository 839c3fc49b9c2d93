/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
#ifndef VSPH_KERNELS_KERNEL_H
#define VSPH_KERNELS_KERNEL_H

#include <math.h>
#include <stddef.h>
#include <string.h>

#include "../common/api.h"

/** @file kernel.h
 *  @brief Smoothing kernels as runtime descriptors (THEORY.md section 1).
 *  A kernel is W(s; h) = h^-d w(q), q = s/h, w(q) = sigma_d f_d(q), with
 *  support radius kappa*h. This module owns the shapes and their
 *  normalisations only: no I/O, no particle data. */

/** A kernel shape or its derivative as a function of q = s/h. */
typedef double vsph_kernel_fn(double q);

/** The (df/dq)/q shapes, as functions of q^2, that the neighbour loops
 *  evaluate inline (vsph_kernel_dfq_eval): one per kernel and variant. */
enum vsph_kernel_dfq_id {
  VSPH_KERNEL_DFQ_GAUSSIAN = 0, /*!< -2 e^{-q^2}, q < 3 */
  VSPH_KERNEL_DFQ_CUBIC,        /*!< cubic B-spline, q < 2 */
  VSPH_KERNEL_DFQ_QUINTIC,      /*!< quintic spline, q < 3 */
  VSPH_KERNEL_DFQ_C2,           /*!< Wendland C2, 2-D and 3-D */
  VSPH_KERNEL_DFQ_C2_1D,        /*!< Wendland C2, 1-D */
  VSPH_KERNEL_DFQ_C4,           /*!< Wendland C4, 2-D and 3-D */
  VSPH_KERNEL_DFQ_C4_1D         /*!< Wendland C4, 1-D */
};

/** Kernel descriptor, looked up by name at run time (GSL gsl_rng_type
 *  pattern). Index [dim-1] selects the 1-D, 2-D or 3-D variant. */
struct vsph_kernel_type {
  const char *name;       /*!< name used on the command line */
  double kappa;           /*!< support radius in units of h */
  double sigma[3];        /*!< normalisation sigma_d for d = 1, 2, 3 */
  vsph_kernel_fn *f[3];   /*!< un-normalised shape f_d(q), 0 for q>=kappa */
  vsph_kernel_fn *df[3];  /*!< df_d/dq */
  vsph_kernel_fn *d2f[3]; /*!< d^2f_d/dq^2 (the direct Laplacian, VISC-02) */
  vsph_kernel_fn *dfq[3]; /*!< (df_d/dq)/q from q^2: the loops need W'/s */
  int dfq_id[3];          /*!< the same as a vsph_kernel_dfq_id */
  const char *reference;  /*!< source of the shape and constants */
};

extern VSPH_API const struct vsph_kernel_type vsph_gaussian_type;
extern VSPH_API const struct vsph_kernel_type vsph_cubic_type;
extern VSPH_API const struct vsph_kernel_type vsph_quintic_type;
extern VSPH_API const struct vsph_kernel_type vsph_wendland_c2_type;
extern VSPH_API const struct vsph_kernel_type vsph_wendland_c4_type;

/** @brief Number of kernels in the table. */
VSPH_API size_t vsph_kernel_count(void);

/** @brief The i-th kernel of the table (NULL when i is out of range). */
VSPH_API const struct vsph_kernel_type *vsph_kernel_get(size_t i);

/** @brief The kernel called @p name, or NULL if there is none. */
VSPH_API const struct vsph_kernel_type *vsph_kernel_find(const char *name);

/** @brief The kernel called @p name into @p out.
 *  @return VSPH_OK, or VSPH_EINVAL with a message listing the kernels. */
VSPH_API int vsph_kernel_resolve(const char *name,
                                 const struct vsph_kernel_type **out);

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

/** @brief Normalised second derivative w''(q) in dimension dim. */
static inline double vsph_kernel_d2w(const struct vsph_kernel_type *k, int dim,
                                     double q) {
  return k->sigma[dim - 1] * k->d2f[dim - 1](q);
}

/* ------------------------------------------------ inline, for the loops */

/** a b + c: one fused operation where the target has it (the polynomials
 *  below are then faster and no less accurate), else two roundings. */
#if defined(__FMA__)
#define VSPH_KERNEL_MULADD(a, b, c) fma((a), (b), (c))
#else
#define VSPH_KERNEL_MULADD(a, b, c) ((a) * (b) + (c))
#endif

/** The constants of e^{-x} = 2^{-n} e^{-r} (vsph_kernel_expneg, and
 *  solver/sweep_x86.c's lanes): 1.5 2^52, whose addition rounds to an
 *  integer; 1/ln 2; ln 2 in Cody-Waite's two parts. */
#define VSPH_KERNEL_EXPNEG_SHIFT 6755399441055744.0
#define VSPH_KERNEL_EXPNEG_LOG2E 1.4426950408889634074
#define VSPH_KERNEL_EXPNEG_LN2_HI 6.93147180369123816490e-01
#define VSPH_KERNEL_EXPNEG_LN2_LO 1.90821492927058770002e-10

/** e^{-r}'s Taylor polynomial to degree 12, coefficients (-1)^k / k!, by
 *  Estrin's scheme: pairs c_2k + c_2k+1 r, joined by r^2 (@p r2), then r^4
 *  (@p r4), then r^8 (@p r8), so the longest chain is four multiply-adds
 *  deep, not Horner's twelve. @p MULADD(a, b, c) is a b + c and @p K(v)
 *  the constant v in the caller's type (a double, or a vector's lanes):
 *  one copy of the coefficients for vsph_kernel_expneg and
 *  solver/sweep_x86.c's expneg8. @p r and its powers must be plain
 *  variables (each is named several times). */
#define VSPH_KERNEL_EXPNEG_TAYLOR(MULADD, K, r, r2, r4, r8)                   \
  MULADD(MULADD(K(1.0 / 479001600.0), r4,                                     \
                MULADD(MULADD(K(-1.0 / 39916800.0), r, K(1.0 / 3628800.0)),   \
                       r2, MULADD(K(-1.0 / 362880.0), r, K(1.0 / 40320.0)))), \
         r8,                                                                  \
         MULADD(MULADD(MULADD(K(-1.0 / 5040.0), r, K(1.0 / 720.0)), r2,       \
                       MULADD(K(-1.0 / 120.0), r, K(1.0 / 24.0))),            \
                r4,                                                           \
                MULADD(MULADD(K(-1.0 / 6.0), r, K(1.0 / 2.0)), r2,            \
                       MULADD(K(-1.0), r, K(1.0)))))

/** The identity: VSPH_KERNEL_EXPNEG_TAYLOR's @p K for doubles. */
#define VSPH_KERNEL_DOUBLE(v) (v)

/** @brief e^{-x} for 0 <= x <= 700, branch-free (so the loops can
 *  vectorise it): e^{-x} = 2^{-n} e^{-r} with n = round(x / ln 2) found
 *  by the 1.5 2^52 rounding trick, r = x - n ln 2 in Cody-Waite's two parts
 *  (|r| <= ln 2 / 2), e^{-r} by its Taylor polynomial to degree 12
 *  (remainder (ln 2/2)^13/13! = 1.7e-16) evaluated by Estrin's scheme,
 *  and 2^{-n} built from its exponent bits. Relative error at most 1e-15
 *  against libm's exp on [0, 700] (tests/check_kernel.c,
 *  test_expneg_within_1e15_of_exp; the worst found 6.3e-16 against exp,
 *  5.7e-16 against expl, with FMA or without). libm's exp is not used
 *  here: it is a call the loops cannot vectorise, and it sets errno.
 *  solver/sweep_x86.c has the same method in AVX-512 lanes (expneg8, its
 *  reduction fused, the constants and the polynomial these macros) for
 *  the Brookshaw forms' sweep (test_expneg_within_1e15_of_exp holds both
 *  to the same bound). */
static inline double vsph_kernel_expneg(double x) {
  const double shift = VSPH_KERNEL_EXPNEG_SHIFT;
  const double m = x * VSPH_KERNEL_EXPNEG_LOG2E + shift;
  const double n = m - shift; /* round(x / ln 2) */
  const double r =
      (x - n * VSPH_KERNEL_EXPNEG_LN2_HI) - n * VSPH_KERNEL_EXPNEG_LN2_LO;
  /* e^{-r} (VSPH_KERNEL_EXPNEG_TAYLOR; written out, as a loop here would
   * have to be unrolled before the loops around it vectorise); fused
   * multiply-adds where the target has them (one rounding each), else
   * multiply and add */
  const double r2 = r * r, r4 = r2 * r2, r8 = r4 * r4;
  const double p = VSPH_KERNEL_EXPNEG_TAYLOR(VSPH_KERNEL_MULADD,
                                             VSPH_KERNEL_DOUBLE, r, r2, r4, r8);
  /* 2^{-n}: the low bits of m hold n, so its exponent is 1023 - n */
  unsigned long long bits;
  memcpy(&bits, &m, sizeof bits);
  const unsigned long long e =
      (1023ull + 0x0008000000000000ull - (bits & 0x000fffffffffffffull)) << 52;
  double scale;
  memcpy(&scale, &e, sizeof scale);
  return p * scale;
}

/** @brief Renormalised 3h Gaussian: (df/dq)/q = -2 e^{-q^2} for q < 3. */
static inline double vsph_kernel_dfq_gaussian(double q2) {
  /* a bit mask rather than a branch, so the loops vectorise (outside the
   * support e may be anything: the mask clears it) */
  const double e = -2.0 * vsph_kernel_expneg(q2);
  unsigned long long bits;
  memcpy(&bits, &e, sizeof bits);
  bits &= 0ull - (unsigned long long)(q2 < 9.0);
  double r;
  memcpy(&r, &bits, sizeof r);
  return r;
}

/** @brief Cubic B-spline: (df/dq)/q. */
static inline double vsph_kernel_dfq_cubic(double q2) {
  const double q = sqrt(q2);
  if (q < 1.0) return -3.0 + 2.25 * q;
  if (q < 2.0) {
    const double t = 2.0 - q;
    return -0.75 * t * t / q;
  }
  return 0.0;
}

/** @brief Quintic spline: (df/dq)/q (q > 0 in every neighbour pair). */
static inline double vsph_kernel_dfq_quintic(double q2) {
  const double q = sqrt(q2);
  const double a = q < 3.0 ? 3.0 - q : 0.0, b = q < 2.0 ? 2.0 - q : 0.0;
  const double c = q < 1.0 ? 1.0 - q : 0.0;
  const double a4 = a * a * a * a, b4 = b * b * b * b, c4 = c * c * c * c;
  return q < 3.0 ? -5.0 * (a4 - 6.0 * b4 + 15.0 * c4) / q : 0.0;
}

/** @brief Quintic spline: f(q) = (3-q)^5 - 6 (2-q)^5 + 15 (1-q)^5, each
 *  term where positive, 0 for q >= 3 (the kernel's own f, inlined where a
 *  loop is specialised on it). */
static inline double vsph_kernel_f_quintic(double q) {
  /* selects, not branches, so that loops vectorise (each term is 0 where
   * its base is not positive: all three for q >= 3) */
  const double a = 3.0 - q, b = 2.0 - q, c = 1.0 - q;
  const double a5 = a > 0.0 ? a * a * a * a * a : 0.0;
  const double b5 = b > 0.0 ? b * b * b * b * b : 0.0;
  const double c5 = c > 0.0 ? c * c * c * c * c : 0.0;
  return a5 - 6.0 * b5 + 15.0 * c5;
}

/** @brief Cubic B-spline: f(q) = 1 - 3/2 q^2 + 3/4 q^3 (q < 1),
 *  (2 - q)^3/4 (q < 2), 0 beyond (the kernel's own f, inlined where a
 *  loop is specialised on it). */
static inline double vsph_kernel_f_cubic(double q) {
  /* selects, not branches, so that loops vectorise */
  const double t = 2.0 - q;
  const double inner = 1.0 - 1.5 * q * q + 0.75 * q * q * q;
  const double outer = q < 2.0 ? 0.25 * t * t * t : 0.0;
  return q < 1.0 ? inner : outer;
}

/** @brief Wendland C2 (2-D, 3-D): (df/dq)/q = -5 (1 - q/2)^3. */
static inline double vsph_kernel_dfq_c2(double q2) {
  const double q = sqrt(q2);
  if (q >= 2.0) return 0.0;
  const double t = 1.0 - 0.5 * q;
  return -5.0 * t * t * t;
}

/** @brief Wendland C2 (1-D): (df/dq)/q = -3 (1 - q/2)^2. */
static inline double vsph_kernel_dfq_c2_1d(double q2) {
  const double q = sqrt(q2);
  if (q >= 2.0) return 0.0;
  const double t = 1.0 - 0.5 * q;
  return -3.0 * t * t;
}

/** @brief Wendland C4 (2-D, 3-D): (df/dq)/q = -(7/3) (1 - q/2)^5 (5q + 2). */
static inline double vsph_kernel_dfq_c4(double q2) {
  const double q = sqrt(q2);
  if (q >= 2.0) return 0.0;
  const double t = 1.0 - 0.5 * q, t5 = t * t * t * t * t;
  return -7.0 / 3.0 * t5 * (5.0 * q + 2.0);
}

/** @brief Wendland C4 (1-D): (df/dq)/q = -3.5 (1 - q/2)^4 (2q + 1). */
static inline double vsph_kernel_dfq_c4_1d(double q2) {
  const double q = sqrt(q2);
  if (q >= 2.0) return 0.0;
  const double t = 1.0 - 0.5 * q, t4 = t * t * t * t;
  return -3.5 * t4 * (2.0 * q + 1.0);
}

/** @brief (df/dq)/q at q^2 = @p q2 for the shape @p id. Inlined where
 *  @p id is a constant, the switch folds away and the loop around it
 *  vectorises; the loops choose their kernel once, outside (solver/pair.h).
 */
static inline double vsph_kernel_dfq_shape(int id, double q2) {
  switch (id) {
    case VSPH_KERNEL_DFQ_GAUSSIAN:
      return vsph_kernel_dfq_gaussian(q2);
    case VSPH_KERNEL_DFQ_CUBIC:
      return vsph_kernel_dfq_cubic(q2);
    case VSPH_KERNEL_DFQ_QUINTIC:
      return vsph_kernel_dfq_quintic(q2);
    case VSPH_KERNEL_DFQ_C2:
      return vsph_kernel_dfq_c2(q2);
    case VSPH_KERNEL_DFQ_C2_1D:
      return vsph_kernel_dfq_c2_1d(q2);
    case VSPH_KERNEL_DFQ_C4:
      return vsph_kernel_dfq_c4(q2);
    default:
      return vsph_kernel_dfq_c4_1d(q2);
  }
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
