/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
#ifndef VSPH_SOLVER_FORMS_FORMS_H
#define VSPH_SOLVER_FORMS_FORMS_H

/* The viscous formulations' descriptors, one family per file of
 * solver/forms/ (its pair terms in FAMILY.h; its descriptors, their pair
 * functions and, for a family with loops of its own, its specialised
 * loops (VSPH_VISCOUS_LOOPS) in FAMILY.c), gathered into
 * vsph_viscous_types by solver/viscous.c. Within solver/ only. */

#include "../pair.h"
#include "../viscous.h"
#include "../viscous_internal.h"

/* The dissipation density -f.du/2 of a corrected pair share @p f
 * (a vsph_viscous_pair_g_fn's return), du = u_j - u_i. */
static inline double vsph_forms_dens_g(int dim, const double f[3],
                                       const double du[3]) {
  double fdu = 0.0;
  for (int k = 0; k < dim; k++) fdu += f[k] * du[k];
  return -0.5 * fdu;
}

extern const struct vsph_viscous_type vsph_brookshaw_mgf;
extern const struct vsph_viscous_type vsph_brookshaw_vi;
extern const struct vsph_viscous_type vsph_brookshaw_cleary;
extern const struct vsph_viscous_type vsph_morris_meaf;
extern const struct vsph_viscous_type vsph_morris_meafeta;
extern const struct vsph_viscous_type vsph_stress_pvwf;
extern const struct vsph_viscous_type vsph_stress_twopass;
extern const struct vsph_viscous_type vsph_takeda_a;
extern const struct vsph_viscous_type vsph_takeda_a0;
extern const struct vsph_viscous_type vsph_er_er;
extern const struct vsph_viscous_type vsph_zheng_visc01;
extern const struct vsph_viscous_type vsph_zheng_visc02;
extern const struct vsph_viscous_type vsph_zheng_visc03;
extern const struct vsph_viscous_type vsph_zheng_visc04;

#endif /* VSPH_SOLVER_FORMS_FORMS_H */
