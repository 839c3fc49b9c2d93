/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
#ifndef VSPH_SOLVER_MATERIALS_H
#define VSPH_SOLVER_MATERIALS_H

#include "../common/api.h"

/** @file materials.h
 *  @brief Table 1 of Parshikov, Medin, Rublev & Dyachkov (2023 or later) as
 * data: each material's reference density and sound speed (the linear state
 *  equation p = c0^2 (rho - rho0), their eq. 4), its handbook viscosity
 *  and the numerical viscosity they measured for contact SPH at
 *  alpha = 0.5, D0 = 10 nm, with the Wendland C2 and the cubic B-spline
 *  kernels (docs/theory.md section 12). No I/O. */

/** One row of the table. */
struct vsph_material {
  const char *name;  /*!< lower case, as on the command line */
  const char *label; /*!< as in the paper's table */
  double rho0;       /*!< reference density (kg/m^3) */
  double c0;         /*!< sound speed (m/s) */
  double eta;        /*!< handbook viscosity (Pa s); NaN where the table
                          gives none; paraffin: 80 mPa s, the upper end of
                          its 25-80 (the drag test implies it) */
  double eta_num_w;  /*!< measured numerical viscosity, Wendland C2 (Pa s) */
  double eta_num_b;  /*!< the same, cubic B-spline (Pa s) */
};

/** The diameter of the table's particles, D0 = 10 nm (m). */
#define VSPH_MATERIALS_D0 10e-9

/** @brief Parshikov et al.'s fit of the numerical viscosity of contact SPH, eq.
 * (37) (Wendland C2, the shear test): eta_num/(Z D0) = 0.47142 alpha - 0.14629
 *  for alpha <= 0.55, 0.18093 alpha + 0.01347 above. */
static inline double vsph_materials_eta_num_fit(double alpha) {
  return alpha <= 0.55 ? 0.47142 * alpha - 0.14629 : 0.18093 * alpha + 0.01347;
}

/** @brief F/(eta U) of Stokes flow through a periodic row of cylinders of
 *  diameter d at period S, U the mean velocity, as Parshikov et al.'s eq. (39)
 * after Thilo, Meyer & Kasper (a Miyagi-type series in w = pi d/(2S)): 8 pi a0,
 * a0 = [1 - 2 ln(2w) + 2w^2/3 - w^4/9 + 8w^6/135 - 53w^8/1350 + 1112w^10/42525
 * - 241643w^12/13395375 + 18776w^14/1488375]^-1; so that C_D = 16 pi a0/Re. */
VSPH_API double vsph_materials_drag_row(double d_over_S);

/** @brief The same for the square array, Sangani & Acrivos (1982):
 *  4 pi/(-ln(c)/2 - 0.738 + c - 0.887 c^2 + 2.038 c^3), c = pi d^2/(4S^2)
 *  the solid fraction. */
VSPH_API double vsph_materials_drag_square(double d_over_S);

/** @brief Number of rows (20). */
VSPH_API int vsph_materials_count(void);

/** @brief Row @p i, or NULL. */
VSPH_API const struct vsph_material *vsph_materials_get(int i);

/** @brief The row called @p name into @p out.
 *  @return VSPH_OK, or VSPH_EINVAL (a NULL argument, or a message listing
 *  the names). */
VSPH_API int vsph_materials_resolve(const char *name,
                                    const struct vsph_material **out);

#endif /* VSPH_SOLVER_MATERIALS_H */
