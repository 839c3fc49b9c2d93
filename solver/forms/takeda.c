/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
/* The descriptors of Takeda-type direct second derivatives, model A and A[0]
 * (their first pass makes the whole force) (solver/viscous.h's struct
 * vsph_viscous_type; their pair terms in takeda.h). */
#include "forms.h"

const struct vsph_viscous_type vsph_takeda_a = {
    .name = "takeda",
    .label = "A",
    .cite =
        "direct second derivatives, Takeda et al. 1994 (Basa et "
        "al. 2009, model A, eqs. 27-28)",
    .pass = VSPH_VISCOUS_PASS_TAKEDA,
    .family = VSPH_VISCOUS_FAMILY_NONE,
    .flags = 0,
    .lap = -1,
    .lambda = VSPH_VISCOUS_LAMBDA_STOKES3,
    .limit = VSPH_VISCOUS_LIMIT_LAPLACIAN,
    .eta = 0.0,
    .params = "",
    .pair = NULL};

const struct vsph_viscous_type vsph_takeda_a0 = {
    .name = "takeda0",
    .label = "A[0]",
    .cite = "model A, Shepard-corrected (Basa et al. 2009, eq. 23)",
    .pass = VSPH_VISCOUS_PASS_TAKEDA,
    .family = VSPH_VISCOUS_FAMILY_NONE,
    .flags = VSPH_VISCOUS_SHEPARD,
    .lap = -1,
    .lambda = VSPH_VISCOUS_LAMBDA_STOKES3,
    .limit = VSPH_VISCOUS_LIMIT_LAPLACIAN,
    .eta = 0.0,
    .params = "",
    .pair = NULL};
