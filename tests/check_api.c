/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
/* The library's public face against bad arguments: every function the
 * public headers export (VSPH_API), called once with every pointer NULL
 * and every number zero, and once with the numbers out of range (NaN,
 * SIZE_MAX, -1), each call in a child process: none may crash (a NULL
 * dereference, an abort); each refuses with a status, returns its
 * sentinel, or does nothing. A second test holds the table to the headers,
 * so a function added to the public face without its calls here fails. */
#include <check.h>
#include <ctype.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

#include "../analysis/dissipation.h"
#include "../analysis/fields.h"
#include "../analysis/moments.h"
#include "../analysis/references.h"
#include "../analysis/scaling.h"
#include "../common/params.h"
#include "../common/status.h"
#include "../kernels/kernel.h"
#include "../solver/cells.h"
#include "../solver/equations.h"
#include "../solver/lattice.h"
#include "../solver/particles.h"
#include "../solver/run.h"
#include "../solver/scene.h"
#include "../solver/viscous.h"
#include "../solver/walls.h"
#include "check_suites.h"

struct api_call {
  const char *name;
  void (*call)(void);
};

static void call_vsph_params_alloc_0(void) { (void)vsph_params_alloc(); }

static void call_vsph_params_alloc_1(void) { (void)vsph_params_alloc(); }

static void call_vsph_params_free_0(void) { vsph_params_free(NULL); }

static void call_vsph_params_free_1(void) { vsph_params_free(NULL); }

static void call_vsph_params_read_0(void) {
  (void)vsph_params_read(NULL, NULL);
}

static void call_vsph_params_read_1(void) {
  (void)vsph_params_read(NULL, NULL);
}

static void call_vsph_params_read_string_0(void) {
  (void)vsph_params_read_string(NULL, NULL, 0, NULL);
}

static void call_vsph_params_read_string_1(void) {
  (void)vsph_params_read_string(NULL, NULL, SIZE_MAX, NULL);
}

static void call_vsph_params_set_0(void) {
  (void)vsph_params_set(NULL, NULL, NULL);
}

static void call_vsph_params_set_1(void) {
  (void)vsph_params_set(NULL, NULL, NULL);
}

static void call_vsph_params_assign_0(void) {
  (void)vsph_params_assign(NULL, NULL);
}

static void call_vsph_params_assign_1(void) {
  (void)vsph_params_assign(NULL, NULL);
}

static void call_vsph_params_get_double_0(void) {
  (void)vsph_params_get_double(NULL, NULL, NULL);
}

static void call_vsph_params_get_double_1(void) {
  (void)vsph_params_get_double(NULL, NULL, NULL);
}

static void call_vsph_params_get_double_or_0(void) {
  (void)vsph_params_get_double_or(NULL, NULL, 0.0, NULL);
}

static void call_vsph_params_get_double_or_1(void) {
  (void)vsph_params_get_double_or(NULL, NULL, NAN, NULL);
}

static void call_vsph_params_get_string_or_0(void) {
  (void)vsph_params_get_string_or(NULL, NULL, NULL, NULL);
}

static void call_vsph_params_get_string_or_1(void) {
  (void)vsph_params_get_string_or(NULL, NULL, NULL, NULL);
}

static void call_vsph_params_unused_0(void) { (void)vsph_params_unused(NULL); }

static void call_vsph_params_unused_1(void) { (void)vsph_params_unused(NULL); }

static void call_vsph_params_nearest_0(void) {
  (void)vsph_params_nearest(NULL, NULL, 0);
}

static void call_vsph_params_nearest_1(void) {
  (void)vsph_params_nearest("x", NULL, SIZE_MAX);
}

static void call_vsph_params_hint_0(void) {
  vsph_params_hint(NULL, NULL, NULL, 0);
}

static void call_vsph_params_hint_1(void) {
  char b[8];
  vsph_params_hint(NULL, "x", b, SIZE_MAX);
}

static void call_vsph_params_given_0(void) {
  (void)vsph_params_given(NULL, NULL);
}

static void call_vsph_params_given_1(void) {
  (void)vsph_params_given(NULL, NULL);
}

static void call_vsph_params_count_0(void) { (void)vsph_params_count(NULL); }

static void call_vsph_params_count_1(void) { (void)vsph_params_count(NULL); }

static void call_vsph_params_entry_0(void) {
  vsph_params_entry(NULL, 0, NULL, NULL, NULL);
}

static void call_vsph_params_entry_1(void) {
  vsph_params_entry(NULL, SIZE_MAX, NULL, NULL, NULL);
}

static void call_vsph_params_load_0(void) {
  (void)vsph_params_load(NULL, NULL, NULL, 0, NULL);
}

static void call_vsph_params_load_1(void) {
  (void)vsph_params_load(NULL, NULL, NULL, SIZE_MAX, NULL);
}

static void call_vsph_params_spec_find_0(void) {
  (void)vsph_params_spec_find(NULL, 0, NULL);
}

static void call_vsph_params_spec_find_1(void) {
  (void)vsph_params_spec_find(NULL, SIZE_MAX, NULL);
}

static void call_vsph_params_spec_default_0(void) {
  vsph_params_spec_default(NULL, NULL, 0);
}

static void call_vsph_params_spec_default_1(void) {
  vsph_params_spec_default(NULL, NULL, SIZE_MAX);
}

static void call_vsph_params_parse_number_0(void) {
  (void)vsph_params_parse_number(NULL, NULL);
}

static void call_vsph_params_parse_number_1(void) {
  (void)vsph_params_parse_number(NULL, NULL);
}

static void call_vsph_status_str_0(void) { (void)vsph_status_str(0); }

static void call_vsph_status_str_1(void) { (void)vsph_status_str(-1); }

static void call_vsph_kernel_count_0(void) { (void)vsph_kernel_count(); }

static void call_vsph_kernel_count_1(void) { (void)vsph_kernel_count(); }

static void call_vsph_kernel_get_0(void) { (void)vsph_kernel_get(0); }

static void call_vsph_kernel_get_1(void) { (void)vsph_kernel_get(SIZE_MAX); }

static void call_vsph_kernel_find_0(void) { (void)vsph_kernel_find(NULL); }

static void call_vsph_kernel_find_1(void) { (void)vsph_kernel_find(NULL); }

static void call_vsph_kernel_resolve_0(void) {
  (void)vsph_kernel_resolve(NULL, NULL);
}

static void call_vsph_kernel_resolve_1(void) {
  (void)vsph_kernel_resolve(NULL, NULL);
}

static void call_vsph_cells_alloc_0(void) { (void)vsph_cells_alloc(); }

static void call_vsph_cells_alloc_1(void) { (void)vsph_cells_alloc(); }

static void call_vsph_cells_free_0(void) { vsph_cells_free(NULL); }

static void call_vsph_cells_free_1(void) { vsph_cells_free(NULL); }

static void call_vsph_cells_build_0(void) {
  (void)vsph_cells_build(NULL, NULL, 0.0);
}

static void call_vsph_cells_build_1(void) {
  (void)vsph_cells_build(NULL, NULL, NAN);
}

static void call_vsph_cells_build_direct_0(void) {
  (void)vsph_cells_build_direct(NULL, NULL);
}

static void call_vsph_cells_build_direct_1(void) {
  (void)vsph_cells_build_direct(NULL, NULL);
}

static void call_vsph_cells_ranges_0(void) {
  (void)vsph_cells_ranges(NULL, 0, NULL, NULL);
}

static void call_vsph_cells_ranges_1(void) {
  (void)vsph_cells_ranges(NULL, SIZE_MAX, NULL, NULL);
}

static void call_vsph_equations_eos_resolve_0(void) {
  (void)vsph_equations_eos_resolve(NULL, NULL);
}

static void call_vsph_equations_eos_resolve_1(void) {
  (void)vsph_equations_eos_resolve(NULL, NULL);
}

static void call_vsph_equations_scheme_resolve_0(void) {
  (void)vsph_equations_scheme_resolve(NULL, NULL);
}

static void call_vsph_equations_scheme_resolve_1(void) {
  (void)vsph_equations_scheme_resolve(NULL, NULL);
}

static void call_vsph_equations_corr_resolve_0(void) {
  (void)vsph_equations_corr_resolve(NULL, NULL);
}

static void call_vsph_equations_corr_resolve_1(void) {
  (void)vsph_equations_corr_resolve(NULL, NULL);
}

static void call_vsph_equations_sweep_alloc_0(void) {
  (void)vsph_equations_sweep_alloc();
}

static void call_vsph_equations_sweep_alloc_1(void) {
  (void)vsph_equations_sweep_alloc();
}

static void call_vsph_equations_sweep_free_0(void) {
  vsph_equations_sweep_free(NULL);
}

static void call_vsph_equations_sweep_free_1(void) {
  vsph_equations_sweep_free(NULL);
}

static void call_vsph_equations_sweep_bytes_0(void) {
  (void)vsph_equations_sweep_bytes(NULL);
}

static void call_vsph_equations_sweep_bytes_1(void) {
  (void)vsph_equations_sweep_bytes(NULL);
}

static void call_vsph_equations_body_force_0(void) {
  vsph_equations_body_force(NULL, NULL, NULL);
}

static void call_vsph_equations_body_force_1(void) {
  vsph_equations_body_force(NULL, NULL, NULL);
}

static void call_vsph_equations_potential_0(void) {
  (void)vsph_equations_potential(NULL, NULL);
}

static void call_vsph_equations_potential_1(void) {
  (void)vsph_equations_potential(NULL, NULL);
}

static void call_vsph_equations_walls_adami_0(void) {
  (void)vsph_equations_walls_adami(NULL, NULL, NULL, 0, NULL);
}

static void call_vsph_equations_walls_adami_1(void) {
  (void)vsph_equations_walls_adami(NULL, NULL, NULL, SIZE_MAX, NULL);
}

static void call_vsph_equations_walls_evolving_0(void) {
  (void)vsph_equations_walls_evolving(NULL, NULL, 0, NULL);
}

static void call_vsph_equations_walls_evolving_1(void) {
  (void)vsph_equations_walls_evolving(NULL, NULL, SIZE_MAX, NULL);
}

static void call_vsph_equations_xsph_0(void) {
  vsph_equations_xsph(NULL, NULL, 0, NULL, 0.0, NULL);
}

static void call_vsph_equations_xsph_1(void) {
  vsph_equations_xsph(NULL, NULL, SIZE_MAX, NULL, NAN, NULL);
}

static void call_vsph_equations_density_sum_0(void) {
  vsph_equations_density_sum(NULL, NULL, 0, NULL);
}

static void call_vsph_equations_density_sum_1(void) {
  vsph_equations_density_sum(NULL, NULL, SIZE_MAX, NULL);
}

static void call_vsph_equations_rhs_0(void) {
  (void)vsph_equations_rhs(NULL, NULL, 0, NULL, NULL, NULL);
}

static void call_vsph_equations_rhs_1(void) {
  (void)vsph_equations_rhs(NULL, NULL, SIZE_MAX, NULL, NULL, NULL);
}

static void call_vsph_equations_energy_compute_0(void) {
  vsph_equations_energy_compute(NULL, NULL, 0, NULL);
}

static void call_vsph_equations_energy_compute_1(void) {
  vsph_equations_energy_compute(NULL, NULL, SIZE_MAX, NULL);
}

static void call_vsph_equations_budget_compute_0(void) {
  vsph_equations_budget_compute(NULL, NULL, 0, NULL, NULL);
}

static void call_vsph_equations_budget_compute_1(void) {
  vsph_equations_budget_compute(NULL, NULL, SIZE_MAX, NULL, NULL);
}

static void call_vsph_lattice_name_0(void) { (void)vsph_lattice_name(0); }

static void call_vsph_lattice_name_1(void) { (void)vsph_lattice_name(-1); }

static void call_vsph_lattice_label_0(void) {
  (void)vsph_lattice_label(0, 0.0);
}

static void call_vsph_lattice_label_1(void) {
  (void)vsph_lattice_label(-1, NAN);
}

static void call_vsph_lattice_find_0(void) { (void)vsph_lattice_find(NULL); }

static void call_vsph_lattice_find_1(void) { (void)vsph_lattice_find(NULL); }

static void call_vsph_lattice_resolve_0(void) {
  (void)vsph_lattice_resolve(NULL, 0, 0.0, NULL, NULL);
}

static void call_vsph_lattice_resolve_1(void) {
  (void)vsph_lattice_resolve(NULL, -1, NAN, NULL, NULL);
}

static void call_vsph_lattice_halfspace_0(void) {
  (void)vsph_lattice_halfspace(NULL, 0.0, 0.0, NULL, NULL);
}

static void call_vsph_lattice_halfspace_1(void) {
  (void)vsph_lattice_halfspace(NULL, NAN, NAN, NULL, NULL);
}

static void call_vsph_lattice_perturb_0(void) {
  (void)vsph_lattice_perturb(NULL, 0.0, 0, 0);
}

static void call_vsph_lattice_perturb_1(void) {
  (void)vsph_lattice_perturb(NULL, NAN, 0, SIZE_MAX);
}

static void call_vsph_lattice_square_0(void) {
  (void)vsph_lattice_square(NULL, 0.0, 0, NULL);
}

static void call_vsph_lattice_square_1(void) {
  (void)vsph_lattice_square(NULL, NAN, SIZE_MAX, NULL);
}

static void call_vsph_lattice_disc_0(void) {
  (void)vsph_lattice_disc(NULL, 0.0, 0, NULL);
}

static void call_vsph_lattice_disc_1(void) {
  (void)vsph_lattice_disc(NULL, NAN, SIZE_MAX, NULL);
}

static void call_vsph_lattice_disc_cartesian_0(void) {
  (void)vsph_lattice_disc_cartesian(NULL, 0.0, 0, NULL);
}

static void call_vsph_lattice_disc_cartesian_1(void) {
  (void)vsph_lattice_disc_cartesian(NULL, NAN, SIZE_MAX, NULL);
}

static void call_vsph_particles_alloc_0(void) {
  (void)vsph_particles_alloc(0, 0);
}

static void call_vsph_particles_alloc_1(void) {
  (void)vsph_particles_alloc(SIZE_MAX, -1);
}

static void call_vsph_particles_reserve_0(void) {
  (void)vsph_particles_reserve(NULL, 0);
}

static void call_vsph_particles_reserve_1(void) {
  (void)vsph_particles_reserve(NULL, SIZE_MAX);
}

static void call_vsph_particles_energy_alloc_0(void) {
  (void)vsph_particles_energy_alloc(NULL);
}

static void call_vsph_particles_energy_alloc_1(void) {
  (void)vsph_particles_energy_alloc(NULL);
}

static void call_vsph_particles_tvf_alloc_0(void) {
  (void)vsph_particles_tvf_alloc(NULL);
}

static void call_vsph_particles_tvf_alloc_1(void) {
  (void)vsph_particles_tvf_alloc(NULL);
}

static void call_vsph_particles_mat_alloc_0(void) {
  (void)vsph_particles_mat_alloc(NULL);
}

static void call_vsph_particles_mat_alloc_1(void) {
  (void)vsph_particles_mat_alloc(NULL);
}

static void call_vsph_particles_free_0(void) { vsph_particles_free(NULL); }

static void call_vsph_particles_free_1(void) { vsph_particles_free(NULL); }

static void call_vsph_particles_refresh_vol_0(void) {
  vsph_particles_refresh_vol(NULL);
}

static void call_vsph_particles_refresh_vol_1(void) {
  vsph_particles_refresh_vol(NULL);
}

static void call_vsph_particles_permute_0(void) {
  vsph_particles_permute(NULL, NULL, NULL, NULL);
}

static void call_vsph_particles_permute_1(void) {
  vsph_particles_permute(NULL, NULL, NULL, NULL);
}

static void call_vsph_run_params_0(void) { (void)vsph_run_params(NULL); }

static void call_vsph_run_params_1(void) { (void)vsph_run_params(NULL); }

static void call_vsph_run_props_init_0(void) {
  (void)vsph_run_props_init(NULL, NULL);
}

static void call_vsph_run_props_init_1(void) {
  (void)vsph_run_props_init(NULL, NULL);
}

static void call_vsph_run_estimate_0(void) {
  (void)vsph_run_estimate(NULL, NULL, NULL);
}

static void call_vsph_run_estimate_1(void) {
  (void)vsph_run_estimate(NULL, NULL, NULL);
}

static void call_vsph_run_alloc_0(void) {
  (void)vsph_run_alloc(NULL, NULL, NULL);
}

static void call_vsph_run_alloc_1(void) {
  (void)vsph_run_alloc(NULL, NULL, NULL);
}

static void call_vsph_run_free_0(void) { vsph_run_free(NULL); }

static void call_vsph_run_free_1(void) { vsph_run_free(NULL); }

static void call_vsph_run_iterate_0(void) { (void)vsph_run_iterate(NULL); }

static void call_vsph_run_iterate_1(void) { (void)vsph_run_iterate(NULL); }

static void call_vsph_run_row_0(void) { (void)vsph_run_row(NULL, NULL); }

static void call_vsph_run_row_1(void) { (void)vsph_run_row(NULL, NULL); }

static void call_vsph_run_pack_0(void) { (void)vsph_run_pack(NULL, NULL); }

static void call_vsph_run_pack_1(void) { (void)vsph_run_pack(NULL, NULL); }

static void call_vsph_run_unpack_0(void) {
  (void)vsph_run_unpack(NULL, NULL, 0);
}

static void call_vsph_run_unpack_1(void) {
  (void)vsph_run_unpack(NULL, NULL, SIZE_MAX);
}

static void call_vsph_run_time_0(void) { (void)vsph_run_time(NULL); }

static void call_vsph_run_time_1(void) { (void)vsph_run_time(NULL); }

static void call_vsph_run_steps_0(void) { (void)vsph_run_steps(NULL); }

static void call_vsph_run_steps_1(void) { (void)vsph_run_steps(NULL); }

static void call_vsph_run_bytes_0(void) { (void)vsph_run_bytes(NULL); }

static void call_vsph_run_bytes_1(void) { (void)vsph_run_bytes(NULL); }

static void call_vsph_run_fallbacks_0(void) { (void)vsph_run_fallbacks(NULL); }

static void call_vsph_run_fallbacks_1(void) { (void)vsph_run_fallbacks(NULL); }

static void call_vsph_scene_is_channel_0(void) {
  (void)vsph_scene_is_channel(NULL);
}

static void call_vsph_scene_is_channel_1(void) {
  (void)vsph_scene_is_channel(NULL);
}

static void call_vsph_scene_has_profile_0(void) {
  (void)vsph_scene_has_profile(NULL);
}

static void call_vsph_scene_has_profile_1(void) {
  (void)vsph_scene_has_profile(NULL);
}

static void call_vsph_scene_count_0(void) { (void)vsph_scene_count(); }

static void call_vsph_scene_count_1(void) { (void)vsph_scene_count(); }

static void call_vsph_scene_get_0(void) { (void)vsph_scene_get(0); }

static void call_vsph_scene_get_1(void) { (void)vsph_scene_get(SIZE_MAX); }

static void call_vsph_scene_find_0(void) { (void)vsph_scene_find(NULL); }

static void call_vsph_scene_find_1(void) { (void)vsph_scene_find(NULL); }

static void call_vsph_scene_solver_defaults_0(void) {
  (void)vsph_scene_solver_defaults(NULL, NULL);
}

static void call_vsph_scene_solver_defaults_1(void) {
  (void)vsph_scene_solver_defaults(NULL, NULL);
}

static void call_vsph_scene_solver_defaults_text_0(void) {
  vsph_scene_solver_defaults_text(NULL, NULL, 0);
}

static void call_vsph_scene_solver_defaults_text_1(void) {
  vsph_scene_solver_defaults_text(NULL, NULL, SIZE_MAX);
}

static void call_vsph_scene_init_0(void) {
  (void)vsph_scene_init(NULL, NULL, NULL);
}

static void call_vsph_scene_init_1(void) {
  (void)vsph_scene_init(NULL, NULL, NULL);
}

static void call_vsph_scene_sound_speed_0(void) {
  (void)vsph_scene_sound_speed(NULL, 0.0);
}

static void call_vsph_scene_sound_speed_1(void) {
  (void)vsph_scene_sound_speed(NULL, NAN);
}

static void call_vsph_scene_integrate_props_0(void) {
  (void)vsph_scene_integrate_props(NULL, 0, NULL, 0.0, NULL);
}

static void call_vsph_scene_integrate_props_1(void) {
  (void)vsph_scene_integrate_props(NULL, -1, NULL, NAN, NULL);
}

static void call_vsph_scene_set_pressure_0(void) {
  vsph_scene_set_pressure(NULL, NULL, 0, 0.0);
}

static void call_vsph_scene_set_pressure_1(void) {
  vsph_scene_set_pressure(NULL, NULL, SIZE_MAX, NAN);
}

static void call_vsph_scene_rectangle_0(void) {
  (void)vsph_scene_rectangle(NULL, 0, 0, 0.0, 0.0, NULL);
}

static void call_vsph_scene_rectangle_1(void) {
  (void)vsph_scene_rectangle(NULL, SIZE_MAX, SIZE_MAX, NAN, NAN, NULL);
}

static void call_vsph_standing_wave_velocity_0(void) {
  vsph_standing_wave_velocity(NULL, 0.0, 0.0, NULL);
}

static void call_vsph_standing_wave_velocity_1(void) {
  vsph_standing_wave_velocity(NULL, NAN, NAN, NULL);
}

static void call_vsph_vortex_patch_omega_0(void) {
  (void)vsph_vortex_patch_omega(0.0, 0.0, 0.0, 0.0, 0.0);
}

static void call_vsph_vortex_patch_omega_1(void) {
  (void)vsph_vortex_patch_omega(NAN, NAN, NAN, NAN, NAN);
}

static void call_vsph_viscous_type_get_0(void) {
  (void)vsph_viscous_type_get(0);
}

static void call_vsph_viscous_type_get_1(void) {
  (void)vsph_viscous_type_get(-1);
}

static void call_vsph_viscous_name_0(void) { (void)vsph_viscous_name(0); }

static void call_vsph_viscous_name_1(void) { (void)vsph_viscous_name(-1); }

static void call_vsph_viscous_list_0(void) {
  (void)vsph_viscous_list(0, NULL, 0);
}

static void call_vsph_viscous_list_1(void) {
  (void)vsph_viscous_list(0, NULL, SIZE_MAX);
}

static void call_vsph_viscous_limit_name_0(void) {
  (void)vsph_viscous_limit_name(0);
}

static void call_vsph_viscous_limit_name_1(void) {
  (void)vsph_viscous_limit_name(-1);
}

static void call_vsph_viscous_find_0(void) { (void)vsph_viscous_find(NULL); }

static void call_vsph_viscous_find_1(void) { (void)vsph_viscous_find(NULL); }

static void call_vsph_viscous_resolve_0(void) {
  (void)vsph_viscous_resolve(NULL, NULL);
}

static void call_vsph_viscous_resolve_1(void) {
  (void)vsph_viscous_resolve(NULL, NULL);
}

static void call_vsph_viscous_label_0(void) { (void)vsph_viscous_label(0); }

static void call_vsph_viscous_label_1(void) { (void)vsph_viscous_label(-1); }

static void call_vsph_viscous_props_init_0(void) {
  (void)vsph_viscous_props_init(NULL, 0, NULL, 0, 0.0, 0.0);
}

static void call_vsph_viscous_props_init_1(void) {
  (void)vsph_viscous_props_init(NULL, -1, NULL, -1, NAN, NAN);
}

static void call_vsph_viscous_ws_alloc_0(void) {
  (void)vsph_viscous_ws_alloc(0, 0);
}

static void call_vsph_viscous_ws_alloc_1(void) {
  (void)vsph_viscous_ws_alloc(SIZE_MAX, -1);
}

static void call_vsph_viscous_ws_corr_0(void) {
  (void)vsph_viscous_ws_corr(NULL);
}

static void call_vsph_viscous_ws_corr_1(void) {
  (void)vsph_viscous_ws_corr(NULL);
}

static void call_vsph_viscous_ws_free_0(void) { vsph_viscous_ws_free(NULL); }

static void call_vsph_viscous_ws_free_1(void) { vsph_viscous_ws_free(NULL); }

static void call_vsph_viscous_invert_sym_0(void) {
  (void)vsph_viscous_invert_sym(0, NULL, NULL, 0.0);
}

static void call_vsph_viscous_invert_sym_1(void) {
  (void)vsph_viscous_invert_sym(-1, NULL, NULL, NAN);
}

static void call_vsph_viscous_laplacians_0(void) {
  vsph_viscous_laplacians(NULL, NULL, 0.0, 0.0, 0.0, 0, NULL, NULL, 0, 0, NULL,
                          NULL);
}

static void call_vsph_viscous_laplacians_1(void) {
  vsph_viscous_laplacians(NULL, NULL, NAN, NAN, NAN, -1, NULL, NULL, SIZE_MAX,
                          -1, NULL, NULL);
}

static void call_vsph_viscous_prepare_0(void) {
  (void)vsph_viscous_prepare(NULL, NULL, NULL, NULL);
}

static void call_vsph_viscous_prepare_1(void) {
  (void)vsph_viscous_prepare(NULL, NULL, NULL, NULL);
}

static void call_vsph_viscous_pvwf_finish_0(void) {
  vsph_viscous_pvwf_finish(NULL, NULL, 0, NULL, NULL);
}

static void call_vsph_viscous_pvwf_finish_1(void) {
  vsph_viscous_pvwf_finish(NULL, NULL, SIZE_MAX, NULL, NULL);
}

static void call_vsph_viscous_compute_0(void) {
  (void)vsph_viscous_compute(NULL, NULL, NULL, NULL, NULL, NULL);
}

static void call_vsph_viscous_compute_1(void) {
  (void)vsph_viscous_compute(NULL, NULL, NULL, NULL, NULL, NULL);
}

static void call_vsph_walls_solid_name_0(void) {
  (void)vsph_walls_solid_name(0);
}

static void call_vsph_walls_solid_name_1(void) {
  (void)vsph_walls_solid_name(-1);
}

static void call_vsph_walls_solid_resolve_0(void) {
  (void)vsph_walls_solid_resolve(NULL, NULL);
}

static void call_vsph_walls_solid_resolve_1(void) {
  (void)vsph_walls_solid_resolve(NULL, NULL);
}

static void call_vsph_walls_velocity_name_0(void) {
  (void)vsph_walls_velocity_name(0);
}

static void call_vsph_walls_velocity_name_1(void) {
  (void)vsph_walls_velocity_name(-1);
}

static void call_vsph_walls_velocity_resolve_0(void) {
  (void)vsph_walls_velocity_resolve(NULL, NULL);
}

static void call_vsph_walls_velocity_resolve_1(void) {
  (void)vsph_walls_velocity_resolve(NULL, NULL);
}

static void call_vsph_walls_add_periodic_0(void) {
  (void)vsph_walls_add_periodic(NULL, 0, 0.0, 0.0);
}

static void call_vsph_walls_add_periodic_1(void) {
  (void)vsph_walls_add_periodic(NULL, -1, NAN, NAN);
}

static void call_vsph_walls_period_0(void) { (void)vsph_walls_period(NULL, 0); }

static void call_vsph_walls_period_1(void) {
  (void)vsph_walls_period(NULL, -1);
}

static void call_vsph_walls_wrap_0(void) { vsph_walls_wrap(NULL, NULL, 0); }

static void call_vsph_walls_wrap_1(void) {
  vsph_walls_wrap(NULL, NULL, SIZE_MAX);
}

static void call_vsph_walls_ghosts_alloc_0(void) {
  (void)vsph_walls_ghosts_alloc(NULL, 0);
}

static void call_vsph_walls_ghosts_alloc_1(void) {
  (void)vsph_walls_ghosts_alloc(NULL, SIZE_MAX);
}

static void call_vsph_walls_ghosts_free_0(void) {
  vsph_walls_ghosts_free(NULL);
}

static void call_vsph_walls_ghosts_free_1(void) {
  vsph_walls_ghosts_free(NULL);
}

static void call_vsph_walls_count_0(void) {
  (void)vsph_walls_count(NULL, NULL, 0, 0.0);
}

static void call_vsph_walls_count_1(void) {
  (void)vsph_walls_count(NULL, NULL, SIZE_MAX, NAN);
}

static void call_vsph_walls_generate_0(void) {
  (void)vsph_walls_generate(NULL, NULL, 0, 0.0, NULL);
}

static void call_vsph_walls_generate_1(void) {
  (void)vsph_walls_generate(NULL, NULL, SIZE_MAX, NAN, NULL);
}

static void call_vsph_walls_update_0(void) {
  vsph_walls_update(NULL, NULL, 0, NULL, NULL);
}

static void call_vsph_walls_update_1(void) {
  vsph_walls_update(NULL, NULL, SIZE_MAX, NULL, NULL);
}

static void call_vsph_walls_solid_count_0(void) {
  (void)vsph_walls_solid_count(NULL, 0, 0.0, 0.0);
}

static void call_vsph_walls_solid_count_1(void) {
  (void)vsph_walls_solid_count(NULL, -1, NAN, NAN);
}

static void call_vsph_walls_solid_generate_0(void) {
  (void)vsph_walls_solid_generate(NULL, NULL, 0, 0.0, 0.0);
}

static void call_vsph_walls_solid_generate_1(void) {
  (void)vsph_walls_solid_generate(NULL, NULL, SIZE_MAX, NAN, NAN);
}

static void call_vsph_walls_solid_velocity_0(void) {
  vsph_walls_solid_velocity(NULL, 0, NULL, NULL);
}

static void call_vsph_walls_solid_velocity_1(void) {
  vsph_walls_solid_velocity(NULL, -1, NULL, NULL);
}

static void call_vsph_walls_solid_extrapolate_0(void) {
  vsph_walls_solid_extrapolate(NULL, NULL, 0, NULL);
}

static void call_vsph_walls_solid_extrapolate_1(void) {
  vsph_walls_solid_extrapolate(NULL, NULL, SIZE_MAX, NULL);
}

static void call_vsph_dissipation_shape_name_0(void) {
  (void)vsph_dissipation_shape_name(0);
}

static void call_vsph_dissipation_shape_name_1(void) {
  (void)vsph_dissipation_shape_name(-1);
}

static void call_vsph_dissipation_shape_find_0(void) {
  (void)vsph_dissipation_shape_find(NULL);
}

static void call_vsph_dissipation_shape_find_1(void) {
  (void)vsph_dissipation_shape_find(NULL);
}

static void call_vsph_dissipation_params_0(void) {
  (void)vsph_dissipation_params(NULL);
}

static void call_vsph_dissipation_params_1(void) {
  (void)vsph_dissipation_params(NULL);
}

static void call_vsph_dissipation_props_init_0(void) {
  (void)vsph_dissipation_props_init(NULL, NULL);
}

static void call_vsph_dissipation_props_init_1(void) {
  (void)vsph_dissipation_props_init(NULL, NULL);
}

static void call_vsph_dissipation_exact_0(void) {
  (void)vsph_dissipation_exact(NULL, NULL, NULL);
}

static void call_vsph_dissipation_exact_1(void) {
  (void)vsph_dissipation_exact(NULL, NULL, NULL);
}

static void call_vsph_dissipation_compute_0(void) {
  (void)vsph_dissipation_compute(NULL, NULL);
}

static void call_vsph_dissipation_compute_1(void) {
  (void)vsph_dissipation_compute(NULL, NULL);
}

static void call_vsph_dissipation_particles_0(void) {
  (void)vsph_dissipation_particles(NULL, NULL, NULL);
}

static void call_vsph_dissipation_particles_1(void) {
  (void)vsph_dissipation_particles(NULL, NULL, NULL);
}

static void call_vsph_fields_name_0(void) { (void)vsph_fields_name(0); }

static void call_vsph_fields_name_1(void) { (void)vsph_fields_name(-1); }

static void call_vsph_fields_find_0(void) { (void)vsph_fields_find(NULL); }

static void call_vsph_fields_find_1(void) { (void)vsph_fields_find(NULL); }

static void call_vsph_fields_props_init_0(void) {
  (void)vsph_fields_props_init(NULL, 0, 0);
}

static void call_vsph_fields_props_init_1(void) {
  (void)vsph_fields_props_init(NULL, -1, -1);
}

static void call_vsph_fields_eval_0(void) {
  vsph_fields_eval(NULL, NULL, NULL, NULL);
}

static void call_vsph_fields_eval_1(void) {
  vsph_fields_eval(NULL, NULL, NULL, NULL);
}

static void call_vsph_fields_second_0(void) {
  vsph_fields_second(NULL, NULL, NULL, NULL);
}

static void call_vsph_fields_second_1(void) {
  vsph_fields_second(NULL, NULL, NULL, NULL);
}

static void call_vsph_moments_quadrature_0(void) {
  (void)vsph_moments_quadrature(NULL, 0, 0.0, 0.0, NULL, NULL, NULL);
}

static void call_vsph_moments_quadrature_1(void) {
  (void)vsph_moments_quadrature(NULL, -1, NAN, NAN, NULL, NULL, NULL);
}

static void call_vsph_moments_constants_0(void) {
  (void)vsph_moments_constants(NULL, 0, 0.0, NULL, NULL, NULL);
}

static void call_vsph_moments_constants_1(void) {
  (void)vsph_moments_constants(NULL, -1, NAN, NULL, NULL, NULL);
}

static void call_vsph_moments_theory_0(void) {
  vsph_moments_theory(0, 0, 0.0, 0.0, NULL);
}

static void call_vsph_moments_theory_1(void) {
  vsph_moments_theory(-1, -1, NAN, NAN, NULL);
}

static void call_vsph_moments_sum_0(void) {
  (void)vsph_moments_sum(NULL, NULL, 0, 0.0, NULL);
}

static void call_vsph_moments_sum_1(void) {
  (void)vsph_moments_sum(NULL, NULL, SIZE_MAX, NAN, NULL);
}

static void call_vsph_moments_gap_0(void) {
  vsph_moments_gap(NULL, NULL, NULL);
}

static void call_vsph_moments_gap_1(void) {
  vsph_moments_gap(NULL, NULL, NULL);
}

static void call_vsph_moments_params_0(void) {
  (void)vsph_moments_params(NULL);
}

static void call_vsph_moments_params_1(void) {
  (void)vsph_moments_params(NULL);
}

static void call_vsph_moments_props_init_0(void) {
  (void)vsph_moments_props_init(NULL, NULL);
}

static void call_vsph_moments_props_init_1(void) {
  (void)vsph_moments_props_init(NULL, NULL);
}

static void call_vsph_moments_compute_0(void) {
  (void)vsph_moments_compute(NULL, NULL);
}

static void call_vsph_moments_compute_1(void) {
  (void)vsph_moments_compute(NULL, NULL);
}

static void call_vsph_references_vortex_alloc_0(void) {
  (void)vsph_references_vortex_alloc(0.0, 0.0, 0.0, 0.0, 0.0, 0);
}

static void call_vsph_references_vortex_alloc_1(void) {
  (void)vsph_references_vortex_alloc(NAN, NAN, NAN, NAN, NAN, SIZE_MAX);
}

static void call_vsph_references_vortex_free_0(void) {
  vsph_references_vortex_free(NULL);
}

static void call_vsph_references_vortex_free_1(void) {
  vsph_references_vortex_free(NULL);
}

static void call_vsph_references_vortex_initial_0(void) {
  (void)vsph_references_vortex_initial(NULL, 0.0);
}

static void call_vsph_references_vortex_initial_1(void) {
  (void)vsph_references_vortex_initial(NULL, NAN);
}

static void call_vsph_references_vortex_eval_0(void) {
  vsph_references_vortex_eval(NULL, 0.0, 0.0, NULL, NULL);
}

static void call_vsph_references_vortex_eval_1(void) {
  vsph_references_vortex_eval(NULL, NAN, NAN, NULL, NULL);
}

static void call_vsph_references_vortex_energy_0(void) {
  (void)vsph_references_vortex_energy(NULL, 0.0, 0.0, NULL, NULL);
}

static void call_vsph_references_vortex_energy_1(void) {
  (void)vsph_references_vortex_energy(NULL, NAN, NAN, NULL, NULL);
}

static void call_vsph_references_vortex_energy_series_0(void) {
  vsph_references_vortex_energy_series(NULL, 0.0, 0.0, NULL, NULL);
}

static void call_vsph_references_vortex_energy_series_1(void) {
  vsph_references_vortex_energy_series(NULL, NAN, NAN, NULL, NULL);
}

static void call_vsph_references_poiseuille_0(void) {
  (void)vsph_references_poiseuille(0.0, 0.0, 0.0, 0.0, 0.0, NULL);
}

static void call_vsph_references_poiseuille_1(void) {
  (void)vsph_references_poiseuille(NAN, NAN, NAN, NAN, NAN, NULL);
}

static void call_vsph_references_couette_0(void) {
  (void)vsph_references_couette(0.0, 0.0, 0.0, 0.0, 0.0, NULL);
}

static void call_vsph_references_couette_1(void) {
  (void)vsph_references_couette(NAN, NAN, NAN, NAN, NAN, NULL);
}

static void call_vsph_references_channel_0(void) {
  (void)vsph_references_channel(NULL, 0.0, 0.0, NULL);
}

static void call_vsph_references_channel_1(void) {
  (void)vsph_references_channel(NULL, NAN, NAN, NULL);
}

static void call_vsph_references_profile_error_0(void) {
  vsph_references_profile_error(NULL, NULL, 0, 0.0, NULL);
}

static void call_vsph_references_profile_error_1(void) {
  vsph_references_profile_error(NULL, NULL, SIZE_MAX, NAN, NULL);
}

static void call_vsph_references_profile_bins_0(void) {
  (void)vsph_references_profile_bins(NULL, NULL, 0, 0.0, 0, NULL, NULL, NULL,
                                     NULL);
}

static void call_vsph_references_profile_bins_1(void) {
  (void)vsph_references_profile_bins(NULL, NULL, SIZE_MAX, NAN, SIZE_MAX, NULL,
                                     NULL, NULL, NULL);
}

static void call_vsph_references_profile_zigzag_0(void) {
  vsph_references_profile_zigzag(NULL, NULL, NULL, 0, 0.0, NULL);
}

static void call_vsph_references_profile_zigzag_1(void) {
  vsph_references_profile_zigzag(NULL, NULL, NULL, SIZE_MAX, NAN, NULL);
}

static void call_vsph_references_ghia_0(void) {
  (void)vsph_references_ghia(0.0, NULL);
}

static void call_vsph_references_ghia_1(void) {
  (void)vsph_references_ghia(NAN, NULL);
}

static void call_vsph_references_shepard_0(void) {
  vsph_references_shepard(NULL, 0, NULL, 0.0, NULL, NULL);
}

static void call_vsph_references_shepard_1(void) {
  vsph_references_shepard(NULL, SIZE_MAX, NULL, NAN, NULL, NULL);
}

static void call_vsph_references_cavity_point_0(void) {
  (void)vsph_references_cavity_point(NULL, NULL, 0, 0, NULL, 0, NULL, 0.0, NULL,
                                     NULL);
}

static void call_vsph_references_cavity_point_1(void) {
  (void)vsph_references_cavity_point(NULL, NULL, -1, SIZE_MAX, NULL, SIZE_MAX,
                                     NULL, NAN, NULL, NULL);
}

static void call_vsph_references_cavity_error_0(void) {
  vsph_references_cavity_error(NULL, NULL, 0, NULL, 0.0, NULL);
}

static void call_vsph_references_cavity_error_1(void) {
  vsph_references_cavity_error(NULL, NULL, SIZE_MAX, NULL, NAN, NULL);
}

static void call_vsph_references_cavity_umin_0(void) {
  (void)vsph_references_cavity_umin(NULL, NULL, 0, 0, 0.0, NULL, NULL, 0);
}

static void call_vsph_references_cavity_umin_1(void) {
  (void)vsph_references_cavity_umin(NULL, NULL, SIZE_MAX, SIZE_MAX, NAN, NULL,
                                    NULL, SIZE_MAX);
}

static void call_vsph_references_wave_decay_0(void) {
  (void)vsph_references_wave_decay(0.0, 0.0, 0.0, 0.0, NULL, NULL);
}

static void call_vsph_references_wave_decay_1(void) {
  (void)vsph_references_wave_decay(NAN, NAN, NAN, NAN, NULL, NULL);
}

static void call_vsph_references_lighthill_0(void) {
  (void)vsph_references_lighthill(NULL, 0.0, 0.0);
}

static void call_vsph_references_lighthill_1(void) {
  (void)vsph_references_lighthill(NULL, NAN, NAN);
}

static void call_vsph_references_scene_alloc_0(void) {
  (void)vsph_references_scene_alloc(NULL);
}

static void call_vsph_references_scene_alloc_1(void) {
  (void)vsph_references_scene_alloc(NULL);
}

static void call_vsph_references_scene_free_0(void) {
  vsph_references_scene_free(NULL);
}

static void call_vsph_references_scene_free_1(void) {
  vsph_references_scene_free(NULL);
}

static void call_vsph_references_scene_eval_0(void) {
  (void)vsph_references_scene_eval(NULL, 0.0, NULL, NULL);
}

static void call_vsph_references_scene_eval_1(void) {
  (void)vsph_references_scene_eval(NULL, NAN, NULL, NULL);
}

static void call_vsph_references_scene_mech_0(void) {
  (void)vsph_references_scene_mech(NULL, 0.0, NULL, NULL);
}

static void call_vsph_references_scene_mech_1(void) {
  (void)vsph_references_scene_mech(NULL, NAN, NULL, NULL);
}

static void call_vsph_scaling_params_0(void) {
  (void)vsph_scaling_params(NULL);
}

static void call_vsph_scaling_params_1(void) {
  (void)vsph_scaling_params(NULL);
}

static void call_vsph_scaling_props_init_0(void) {
  (void)vsph_scaling_props_init(NULL, NULL);
}

static void call_vsph_scaling_props_init_1(void) {
  (void)vsph_scaling_props_init(NULL, NULL);
}

static void call_vsph_scaling_slope_0(void) {
  (void)vsph_scaling_slope(NULL, NULL, 0);
}

static void call_vsph_scaling_slope_1(void) {
  (void)vsph_scaling_slope(NULL, NULL, SIZE_MAX);
}

static void call_vsph_scaling_hdx_ladder_0(void) {
  (void)vsph_scaling_hdx_ladder(NULL);
}

static void call_vsph_scaling_hdx_ladder_1(void) {
  (void)vsph_scaling_hdx_ladder(NULL);
}

static void call_vsph_scaling_surface_0(void) {
  (void)vsph_scaling_surface(NULL, NULL);
}

static void call_vsph_scaling_surface_1(void) {
  (void)vsph_scaling_surface(NULL, NULL);
}

static void call_vsph_scaling_interior_0(void) {
  (void)vsph_scaling_interior(NULL, NULL, 0, NULL);
}

static void call_vsph_scaling_interior_1(void) {
  (void)vsph_scaling_interior(NULL, NULL, SIZE_MAX, NULL);
}

static void call_vsph_scaling_axis_0(void) {
  (void)vsph_scaling_axis(NULL, 0, NULL, NULL, NULL);
}

static void call_vsph_scaling_axis_1(void) {
  (void)vsph_scaling_axis(NULL, SIZE_MAX, NULL, NULL, NULL);
}

static const struct api_call CALLS[] = {
    {"vsph_params_alloc", call_vsph_params_alloc_0},
    {"vsph_params_alloc", call_vsph_params_alloc_1},
    {"vsph_params_free", call_vsph_params_free_0},
    {"vsph_params_free", call_vsph_params_free_1},
    {"vsph_params_read", call_vsph_params_read_0},
    {"vsph_params_read", call_vsph_params_read_1},
    {"vsph_params_read_string", call_vsph_params_read_string_0},
    {"vsph_params_read_string", call_vsph_params_read_string_1},
    {"vsph_params_set", call_vsph_params_set_0},
    {"vsph_params_set", call_vsph_params_set_1},
    {"vsph_params_assign", call_vsph_params_assign_0},
    {"vsph_params_assign", call_vsph_params_assign_1},
    {"vsph_params_get_double", call_vsph_params_get_double_0},
    {"vsph_params_get_double", call_vsph_params_get_double_1},
    {"vsph_params_get_double_or", call_vsph_params_get_double_or_0},
    {"vsph_params_get_double_or", call_vsph_params_get_double_or_1},
    {"vsph_params_get_string_or", call_vsph_params_get_string_or_0},
    {"vsph_params_get_string_or", call_vsph_params_get_string_or_1},
    {"vsph_params_nearest", call_vsph_params_nearest_0},
    {"vsph_params_nearest", call_vsph_params_nearest_1},
    {"vsph_params_hint", call_vsph_params_hint_0},
    {"vsph_params_hint", call_vsph_params_hint_1},
    {"vsph_params_unused", call_vsph_params_unused_0},
    {"vsph_params_unused", call_vsph_params_unused_1},
    {"vsph_params_given", call_vsph_params_given_0},
    {"vsph_params_given", call_vsph_params_given_1},
    {"vsph_params_count", call_vsph_params_count_0},
    {"vsph_params_count", call_vsph_params_count_1},
    {"vsph_params_entry", call_vsph_params_entry_0},
    {"vsph_params_entry", call_vsph_params_entry_1},
    {"vsph_params_load", call_vsph_params_load_0},
    {"vsph_params_load", call_vsph_params_load_1},
    {"vsph_params_spec_find", call_vsph_params_spec_find_0},
    {"vsph_params_spec_find", call_vsph_params_spec_find_1},
    {"vsph_params_spec_default", call_vsph_params_spec_default_0},
    {"vsph_params_spec_default", call_vsph_params_spec_default_1},
    {"vsph_params_parse_number", call_vsph_params_parse_number_0},
    {"vsph_params_parse_number", call_vsph_params_parse_number_1},
    {"vsph_status_str", call_vsph_status_str_0},
    {"vsph_status_str", call_vsph_status_str_1},
    {"vsph_kernel_count", call_vsph_kernel_count_0},
    {"vsph_kernel_count", call_vsph_kernel_count_1},
    {"vsph_kernel_get", call_vsph_kernel_get_0},
    {"vsph_kernel_get", call_vsph_kernel_get_1},
    {"vsph_kernel_find", call_vsph_kernel_find_0},
    {"vsph_kernel_find", call_vsph_kernel_find_1},
    {"vsph_kernel_resolve", call_vsph_kernel_resolve_0},
    {"vsph_kernel_resolve", call_vsph_kernel_resolve_1},
    {"vsph_cells_alloc", call_vsph_cells_alloc_0},
    {"vsph_cells_alloc", call_vsph_cells_alloc_1},
    {"vsph_cells_free", call_vsph_cells_free_0},
    {"vsph_cells_free", call_vsph_cells_free_1},
    {"vsph_cells_build", call_vsph_cells_build_0},
    {"vsph_cells_build", call_vsph_cells_build_1},
    {"vsph_cells_build_direct", call_vsph_cells_build_direct_0},
    {"vsph_cells_build_direct", call_vsph_cells_build_direct_1},
    {"vsph_cells_ranges", call_vsph_cells_ranges_0},
    {"vsph_cells_ranges", call_vsph_cells_ranges_1},
    {"vsph_equations_eos_resolve", call_vsph_equations_eos_resolve_0},
    {"vsph_equations_eos_resolve", call_vsph_equations_eos_resolve_1},
    {"vsph_equations_scheme_resolve", call_vsph_equations_scheme_resolve_0},
    {"vsph_equations_scheme_resolve", call_vsph_equations_scheme_resolve_1},
    {"vsph_equations_corr_resolve", call_vsph_equations_corr_resolve_0},
    {"vsph_equations_corr_resolve", call_vsph_equations_corr_resolve_1},
    {"vsph_equations_sweep_alloc", call_vsph_equations_sweep_alloc_0},
    {"vsph_equations_sweep_alloc", call_vsph_equations_sweep_alloc_1},
    {"vsph_equations_sweep_free", call_vsph_equations_sweep_free_0},
    {"vsph_equations_sweep_free", call_vsph_equations_sweep_free_1},
    {"vsph_equations_sweep_bytes", call_vsph_equations_sweep_bytes_0},
    {"vsph_equations_sweep_bytes", call_vsph_equations_sweep_bytes_1},
    {"vsph_equations_body_force", call_vsph_equations_body_force_0},
    {"vsph_equations_body_force", call_vsph_equations_body_force_1},
    {"vsph_equations_potential", call_vsph_equations_potential_0},
    {"vsph_equations_potential", call_vsph_equations_potential_1},
    {"vsph_equations_walls_adami", call_vsph_equations_walls_adami_0},
    {"vsph_equations_walls_adami", call_vsph_equations_walls_adami_1},
    {"vsph_equations_walls_evolving", call_vsph_equations_walls_evolving_0},
    {"vsph_equations_walls_evolving", call_vsph_equations_walls_evolving_1},
    {"vsph_equations_xsph", call_vsph_equations_xsph_0},
    {"vsph_equations_xsph", call_vsph_equations_xsph_1},
    {"vsph_equations_density_sum", call_vsph_equations_density_sum_0},
    {"vsph_equations_density_sum", call_vsph_equations_density_sum_1},
    {"vsph_equations_rhs", call_vsph_equations_rhs_0},
    {"vsph_equations_rhs", call_vsph_equations_rhs_1},
    {"vsph_equations_energy_compute", call_vsph_equations_energy_compute_0},
    {"vsph_equations_energy_compute", call_vsph_equations_energy_compute_1},
    {"vsph_equations_budget_compute", call_vsph_equations_budget_compute_0},
    {"vsph_equations_budget_compute", call_vsph_equations_budget_compute_1},
    {"vsph_lattice_name", call_vsph_lattice_name_0},
    {"vsph_lattice_name", call_vsph_lattice_name_1},
    {"vsph_lattice_label", call_vsph_lattice_label_0},
    {"vsph_lattice_label", call_vsph_lattice_label_1},
    {"vsph_lattice_find", call_vsph_lattice_find_0},
    {"vsph_lattice_find", call_vsph_lattice_find_1},
    {"vsph_lattice_resolve", call_vsph_lattice_resolve_0},
    {"vsph_lattice_resolve", call_vsph_lattice_resolve_1},
    {"vsph_lattice_halfspace", call_vsph_lattice_halfspace_0},
    {"vsph_lattice_halfspace", call_vsph_lattice_halfspace_1},
    {"vsph_lattice_perturb", call_vsph_lattice_perturb_0},
    {"vsph_lattice_perturb", call_vsph_lattice_perturb_1},
    {"vsph_lattice_square", call_vsph_lattice_square_0},
    {"vsph_lattice_square", call_vsph_lattice_square_1},
    {"vsph_lattice_disc", call_vsph_lattice_disc_0},
    {"vsph_lattice_disc", call_vsph_lattice_disc_1},
    {"vsph_lattice_disc_cartesian", call_vsph_lattice_disc_cartesian_0},
    {"vsph_lattice_disc_cartesian", call_vsph_lattice_disc_cartesian_1},
    {"vsph_particles_alloc", call_vsph_particles_alloc_0},
    {"vsph_particles_alloc", call_vsph_particles_alloc_1},
    {"vsph_particles_reserve", call_vsph_particles_reserve_0},
    {"vsph_particles_reserve", call_vsph_particles_reserve_1},
    {"vsph_particles_energy_alloc", call_vsph_particles_energy_alloc_0},
    {"vsph_particles_energy_alloc", call_vsph_particles_energy_alloc_1},
    {"vsph_particles_tvf_alloc", call_vsph_particles_tvf_alloc_0},
    {"vsph_particles_tvf_alloc", call_vsph_particles_tvf_alloc_1},
    {"vsph_particles_mat_alloc", call_vsph_particles_mat_alloc_0},
    {"vsph_particles_mat_alloc", call_vsph_particles_mat_alloc_1},
    {"vsph_particles_free", call_vsph_particles_free_0},
    {"vsph_particles_free", call_vsph_particles_free_1},
    {"vsph_particles_refresh_vol", call_vsph_particles_refresh_vol_0},
    {"vsph_particles_refresh_vol", call_vsph_particles_refresh_vol_1},
    {"vsph_particles_permute", call_vsph_particles_permute_0},
    {"vsph_particles_permute", call_vsph_particles_permute_1},
    {"vsph_run_params", call_vsph_run_params_0},
    {"vsph_run_params", call_vsph_run_params_1},
    {"vsph_run_props_init", call_vsph_run_props_init_0},
    {"vsph_run_props_init", call_vsph_run_props_init_1},
    {"vsph_run_estimate", call_vsph_run_estimate_0},
    {"vsph_run_estimate", call_vsph_run_estimate_1},
    {"vsph_run_alloc", call_vsph_run_alloc_0},
    {"vsph_run_alloc", call_vsph_run_alloc_1},
    {"vsph_run_free", call_vsph_run_free_0},
    {"vsph_run_free", call_vsph_run_free_1},
    {"vsph_run_iterate", call_vsph_run_iterate_0},
    {"vsph_run_iterate", call_vsph_run_iterate_1},
    {"vsph_run_row", call_vsph_run_row_0},
    {"vsph_run_row", call_vsph_run_row_1},
    {"vsph_run_pack", call_vsph_run_pack_0},
    {"vsph_run_pack", call_vsph_run_pack_1},
    {"vsph_run_unpack", call_vsph_run_unpack_0},
    {"vsph_run_unpack", call_vsph_run_unpack_1},
    {"vsph_run_time", call_vsph_run_time_0},
    {"vsph_run_time", call_vsph_run_time_1},
    {"vsph_run_steps", call_vsph_run_steps_0},
    {"vsph_run_steps", call_vsph_run_steps_1},
    {"vsph_run_bytes", call_vsph_run_bytes_0},
    {"vsph_run_bytes", call_vsph_run_bytes_1},
    {"vsph_run_fallbacks", call_vsph_run_fallbacks_0},
    {"vsph_run_fallbacks", call_vsph_run_fallbacks_1},
    {"vsph_scene_is_channel", call_vsph_scene_is_channel_0},
    {"vsph_scene_is_channel", call_vsph_scene_is_channel_1},
    {"vsph_scene_has_profile", call_vsph_scene_has_profile_0},
    {"vsph_scene_has_profile", call_vsph_scene_has_profile_1},
    {"vsph_scene_count", call_vsph_scene_count_0},
    {"vsph_scene_count", call_vsph_scene_count_1},
    {"vsph_scene_get", call_vsph_scene_get_0},
    {"vsph_scene_get", call_vsph_scene_get_1},
    {"vsph_scene_find", call_vsph_scene_find_0},
    {"vsph_scene_find", call_vsph_scene_find_1},
    {"vsph_scene_solver_defaults", call_vsph_scene_solver_defaults_0},
    {"vsph_scene_solver_defaults", call_vsph_scene_solver_defaults_1},
    {"vsph_scene_solver_defaults_text", call_vsph_scene_solver_defaults_text_0},
    {"vsph_scene_solver_defaults_text", call_vsph_scene_solver_defaults_text_1},
    {"vsph_scene_init", call_vsph_scene_init_0},
    {"vsph_scene_init", call_vsph_scene_init_1},
    {"vsph_scene_sound_speed", call_vsph_scene_sound_speed_0},
    {"vsph_scene_sound_speed", call_vsph_scene_sound_speed_1},
    {"vsph_scene_integrate_props", call_vsph_scene_integrate_props_0},
    {"vsph_scene_integrate_props", call_vsph_scene_integrate_props_1},
    {"vsph_scene_set_pressure", call_vsph_scene_set_pressure_0},
    {"vsph_scene_set_pressure", call_vsph_scene_set_pressure_1},
    {"vsph_scene_rectangle", call_vsph_scene_rectangle_0},
    {"vsph_scene_rectangle", call_vsph_scene_rectangle_1},
    {"vsph_standing_wave_velocity", call_vsph_standing_wave_velocity_0},
    {"vsph_standing_wave_velocity", call_vsph_standing_wave_velocity_1},
    {"vsph_vortex_patch_omega", call_vsph_vortex_patch_omega_0},
    {"vsph_vortex_patch_omega", call_vsph_vortex_patch_omega_1},
    {"vsph_viscous_type_get", call_vsph_viscous_type_get_0},
    {"vsph_viscous_type_get", call_vsph_viscous_type_get_1},
    {"vsph_viscous_name", call_vsph_viscous_name_0},
    {"vsph_viscous_name", call_vsph_viscous_name_1},
    {"vsph_viscous_list", call_vsph_viscous_list_0},
    {"vsph_viscous_list", call_vsph_viscous_list_1},
    {"vsph_viscous_limit_name", call_vsph_viscous_limit_name_0},
    {"vsph_viscous_limit_name", call_vsph_viscous_limit_name_1},
    {"vsph_viscous_find", call_vsph_viscous_find_0},
    {"vsph_viscous_find", call_vsph_viscous_find_1},
    {"vsph_viscous_resolve", call_vsph_viscous_resolve_0},
    {"vsph_viscous_resolve", call_vsph_viscous_resolve_1},
    {"vsph_viscous_label", call_vsph_viscous_label_0},
    {"vsph_viscous_label", call_vsph_viscous_label_1},
    {"vsph_viscous_props_init", call_vsph_viscous_props_init_0},
    {"vsph_viscous_props_init", call_vsph_viscous_props_init_1},
    {"vsph_viscous_ws_alloc", call_vsph_viscous_ws_alloc_0},
    {"vsph_viscous_ws_alloc", call_vsph_viscous_ws_alloc_1},
    {"vsph_viscous_ws_corr", call_vsph_viscous_ws_corr_0},
    {"vsph_viscous_ws_corr", call_vsph_viscous_ws_corr_1},
    {"vsph_viscous_ws_free", call_vsph_viscous_ws_free_0},
    {"vsph_viscous_ws_free", call_vsph_viscous_ws_free_1},
    {"vsph_viscous_invert_sym", call_vsph_viscous_invert_sym_0},
    {"vsph_viscous_invert_sym", call_vsph_viscous_invert_sym_1},
    {"vsph_viscous_laplacians", call_vsph_viscous_laplacians_0},
    {"vsph_viscous_laplacians", call_vsph_viscous_laplacians_1},
    {"vsph_viscous_prepare", call_vsph_viscous_prepare_0},
    {"vsph_viscous_prepare", call_vsph_viscous_prepare_1},
    {"vsph_viscous_pvwf_finish", call_vsph_viscous_pvwf_finish_0},
    {"vsph_viscous_pvwf_finish", call_vsph_viscous_pvwf_finish_1},
    {"vsph_viscous_compute", call_vsph_viscous_compute_0},
    {"vsph_viscous_compute", call_vsph_viscous_compute_1},
    {"vsph_walls_solid_name", call_vsph_walls_solid_name_0},
    {"vsph_walls_solid_name", call_vsph_walls_solid_name_1},
    {"vsph_walls_solid_resolve", call_vsph_walls_solid_resolve_0},
    {"vsph_walls_solid_resolve", call_vsph_walls_solid_resolve_1},
    {"vsph_walls_velocity_name", call_vsph_walls_velocity_name_0},
    {"vsph_walls_velocity_name", call_vsph_walls_velocity_name_1},
    {"vsph_walls_velocity_resolve", call_vsph_walls_velocity_resolve_0},
    {"vsph_walls_velocity_resolve", call_vsph_walls_velocity_resolve_1},
    {"vsph_walls_add_periodic", call_vsph_walls_add_periodic_0},
    {"vsph_walls_add_periodic", call_vsph_walls_add_periodic_1},
    {"vsph_walls_period", call_vsph_walls_period_0},
    {"vsph_walls_period", call_vsph_walls_period_1},
    {"vsph_walls_wrap", call_vsph_walls_wrap_0},
    {"vsph_walls_wrap", call_vsph_walls_wrap_1},
    {"vsph_walls_ghosts_alloc", call_vsph_walls_ghosts_alloc_0},
    {"vsph_walls_ghosts_alloc", call_vsph_walls_ghosts_alloc_1},
    {"vsph_walls_ghosts_free", call_vsph_walls_ghosts_free_0},
    {"vsph_walls_ghosts_free", call_vsph_walls_ghosts_free_1},
    {"vsph_walls_count", call_vsph_walls_count_0},
    {"vsph_walls_count", call_vsph_walls_count_1},
    {"vsph_walls_generate", call_vsph_walls_generate_0},
    {"vsph_walls_generate", call_vsph_walls_generate_1},
    {"vsph_walls_update", call_vsph_walls_update_0},
    {"vsph_walls_update", call_vsph_walls_update_1},
    {"vsph_walls_solid_count", call_vsph_walls_solid_count_0},
    {"vsph_walls_solid_count", call_vsph_walls_solid_count_1},
    {"vsph_walls_solid_generate", call_vsph_walls_solid_generate_0},
    {"vsph_walls_solid_generate", call_vsph_walls_solid_generate_1},
    {"vsph_walls_solid_velocity", call_vsph_walls_solid_velocity_0},
    {"vsph_walls_solid_velocity", call_vsph_walls_solid_velocity_1},
    {"vsph_walls_solid_extrapolate", call_vsph_walls_solid_extrapolate_0},
    {"vsph_walls_solid_extrapolate", call_vsph_walls_solid_extrapolate_1},
    {"vsph_dissipation_shape_name", call_vsph_dissipation_shape_name_0},
    {"vsph_dissipation_shape_name", call_vsph_dissipation_shape_name_1},
    {"vsph_dissipation_shape_find", call_vsph_dissipation_shape_find_0},
    {"vsph_dissipation_shape_find", call_vsph_dissipation_shape_find_1},
    {"vsph_dissipation_params", call_vsph_dissipation_params_0},
    {"vsph_dissipation_params", call_vsph_dissipation_params_1},
    {"vsph_dissipation_props_init", call_vsph_dissipation_props_init_0},
    {"vsph_dissipation_props_init", call_vsph_dissipation_props_init_1},
    {"vsph_dissipation_exact", call_vsph_dissipation_exact_0},
    {"vsph_dissipation_exact", call_vsph_dissipation_exact_1},
    {"vsph_dissipation_compute", call_vsph_dissipation_compute_0},
    {"vsph_dissipation_compute", call_vsph_dissipation_compute_1},
    {"vsph_dissipation_particles", call_vsph_dissipation_particles_0},
    {"vsph_dissipation_particles", call_vsph_dissipation_particles_1},
    {"vsph_fields_name", call_vsph_fields_name_0},
    {"vsph_fields_name", call_vsph_fields_name_1},
    {"vsph_fields_find", call_vsph_fields_find_0},
    {"vsph_fields_find", call_vsph_fields_find_1},
    {"vsph_fields_props_init", call_vsph_fields_props_init_0},
    {"vsph_fields_props_init", call_vsph_fields_props_init_1},
    {"vsph_fields_eval", call_vsph_fields_eval_0},
    {"vsph_fields_eval", call_vsph_fields_eval_1},
    {"vsph_fields_second", call_vsph_fields_second_0},
    {"vsph_fields_second", call_vsph_fields_second_1},
    {"vsph_moments_quadrature", call_vsph_moments_quadrature_0},
    {"vsph_moments_quadrature", call_vsph_moments_quadrature_1},
    {"vsph_moments_constants", call_vsph_moments_constants_0},
    {"vsph_moments_constants", call_vsph_moments_constants_1},
    {"vsph_moments_theory", call_vsph_moments_theory_0},
    {"vsph_moments_theory", call_vsph_moments_theory_1},
    {"vsph_moments_sum", call_vsph_moments_sum_0},
    {"vsph_moments_sum", call_vsph_moments_sum_1},
    {"vsph_moments_gap", call_vsph_moments_gap_0},
    {"vsph_moments_gap", call_vsph_moments_gap_1},
    {"vsph_moments_params", call_vsph_moments_params_0},
    {"vsph_moments_params", call_vsph_moments_params_1},
    {"vsph_moments_props_init", call_vsph_moments_props_init_0},
    {"vsph_moments_props_init", call_vsph_moments_props_init_1},
    {"vsph_moments_compute", call_vsph_moments_compute_0},
    {"vsph_moments_compute", call_vsph_moments_compute_1},
    {"vsph_references_vortex_alloc", call_vsph_references_vortex_alloc_0},
    {"vsph_references_vortex_alloc", call_vsph_references_vortex_alloc_1},
    {"vsph_references_vortex_free", call_vsph_references_vortex_free_0},
    {"vsph_references_vortex_free", call_vsph_references_vortex_free_1},
    {"vsph_references_vortex_initial", call_vsph_references_vortex_initial_0},
    {"vsph_references_vortex_initial", call_vsph_references_vortex_initial_1},
    {"vsph_references_vortex_eval", call_vsph_references_vortex_eval_0},
    {"vsph_references_vortex_eval", call_vsph_references_vortex_eval_1},
    {"vsph_references_vortex_energy", call_vsph_references_vortex_energy_0},
    {"vsph_references_vortex_energy", call_vsph_references_vortex_energy_1},
    {"vsph_references_vortex_energy_series",
     call_vsph_references_vortex_energy_series_0},
    {"vsph_references_vortex_energy_series",
     call_vsph_references_vortex_energy_series_1},
    {"vsph_references_poiseuille", call_vsph_references_poiseuille_0},
    {"vsph_references_poiseuille", call_vsph_references_poiseuille_1},
    {"vsph_references_couette", call_vsph_references_couette_0},
    {"vsph_references_couette", call_vsph_references_couette_1},
    {"vsph_references_channel", call_vsph_references_channel_0},
    {"vsph_references_channel", call_vsph_references_channel_1},
    {"vsph_references_profile_error", call_vsph_references_profile_error_0},
    {"vsph_references_profile_error", call_vsph_references_profile_error_1},
    {"vsph_references_profile_bins", call_vsph_references_profile_bins_0},
    {"vsph_references_profile_bins", call_vsph_references_profile_bins_1},
    {"vsph_references_profile_zigzag", call_vsph_references_profile_zigzag_0},
    {"vsph_references_profile_zigzag", call_vsph_references_profile_zigzag_1},
    {"vsph_references_ghia", call_vsph_references_ghia_0},
    {"vsph_references_ghia", call_vsph_references_ghia_1},
    {"vsph_references_shepard", call_vsph_references_shepard_0},
    {"vsph_references_shepard", call_vsph_references_shepard_1},
    {"vsph_references_cavity_point", call_vsph_references_cavity_point_0},
    {"vsph_references_cavity_point", call_vsph_references_cavity_point_1},
    {"vsph_references_cavity_error", call_vsph_references_cavity_error_0},
    {"vsph_references_cavity_error", call_vsph_references_cavity_error_1},
    {"vsph_references_cavity_umin", call_vsph_references_cavity_umin_0},
    {"vsph_references_cavity_umin", call_vsph_references_cavity_umin_1},
    {"vsph_references_wave_decay", call_vsph_references_wave_decay_0},
    {"vsph_references_wave_decay", call_vsph_references_wave_decay_1},
    {"vsph_references_lighthill", call_vsph_references_lighthill_0},
    {"vsph_references_lighthill", call_vsph_references_lighthill_1},
    {"vsph_references_scene_alloc", call_vsph_references_scene_alloc_0},
    {"vsph_references_scene_alloc", call_vsph_references_scene_alloc_1},
    {"vsph_references_scene_free", call_vsph_references_scene_free_0},
    {"vsph_references_scene_free", call_vsph_references_scene_free_1},
    {"vsph_references_scene_eval", call_vsph_references_scene_eval_0},
    {"vsph_references_scene_eval", call_vsph_references_scene_eval_1},
    {"vsph_references_scene_mech", call_vsph_references_scene_mech_0},
    {"vsph_references_scene_mech", call_vsph_references_scene_mech_1},
    {"vsph_scaling_params", call_vsph_scaling_params_0},
    {"vsph_scaling_params", call_vsph_scaling_params_1},
    {"vsph_scaling_props_init", call_vsph_scaling_props_init_0},
    {"vsph_scaling_props_init", call_vsph_scaling_props_init_1},
    {"vsph_scaling_slope", call_vsph_scaling_slope_0},
    {"vsph_scaling_slope", call_vsph_scaling_slope_1},
    {"vsph_scaling_hdx_ladder", call_vsph_scaling_hdx_ladder_0},
    {"vsph_scaling_hdx_ladder", call_vsph_scaling_hdx_ladder_1},
    {"vsph_scaling_surface", call_vsph_scaling_surface_0},
    {"vsph_scaling_surface", call_vsph_scaling_surface_1},
    {"vsph_scaling_interior", call_vsph_scaling_interior_0},
    {"vsph_scaling_interior", call_vsph_scaling_interior_1},
    {"vsph_scaling_axis", call_vsph_scaling_axis_0},
    {"vsph_scaling_axis", call_vsph_scaling_axis_1},
};

#define NCALLS (sizeof CALLS / sizeof CALLS[0])

/* Call k in a child (its messages to /dev/null): 1 when it returned, 0
 * when it died by a signal (the signal in *sig). */
static int survives(size_t k, int *sig) {
  fflush(NULL);
  const pid_t pid = fork();
  ck_assert_int_ge(pid, 0);
  if (pid == 0) {
    if (!freopen("/dev/null", "w", stderr)) _exit(3);
    CALLS[k].call();
    _exit(0);
  }
  int status = 0;
  ck_assert_int_eq(waitpid(pid, &status, 0), pid);
  *sig = WIFSIGNALED(status) ? WTERMSIG(status) : 0;
  return WIFEXITED(status) && WEXITSTATUS(status) == 0;
}

START_TEST(test_null_and_out_of_range) {
  char bad[3000] = "";
  size_t m = 0, nbad = 0;
  for (size_t k = 0; k < NCALLS; k++) {
    int sig = 0;
    if (!survives(k, &sig)) {
      nbad++;
      fprintf(stderr, "check_api: %s crashed (signal %d)\n", CALLS[k].name,
              sig);
      if (m < sizeof bad - 80)
        m += (size_t)snprintf(bad + m, sizeof bad - m, " %s (signal %d)",
                              CALLS[k].name, sig);
    }
  }
  ck_assert_msg(nbad == 0, "%zu of %zu calls crashed:%s", nbad, (size_t)NCALLS,
                bad);
}
END_TEST

/* Every function a public header marks VSPH_API has its calls above
 * (vsph_status_report, variadic, and vsph_status_set_handler, which sets
 * the process's handler, are the two left out by name). */
START_TEST(test_every_entry_called) {
  static const char *const HDR[] = {
      "common/params.h",    "common/status.h",    "kernels/kernel.h",
      "solver/cells.h",     "solver/equations.h", "solver/lattice.h",
      "solver/particles.h", "solver/run.h",       "solver/scene.h",
      "solver/viscous.h",   "solver/walls.h",     "analysis/dissipation.h",
      "analysis/fields.h",  "analysis/moments.h", "analysis/references.h",
      "analysis/scaling.h"};
  size_t n = 0;
  for (size_t h = 0; h < sizeof HDR / sizeof HDR[0]; h++) {
    FILE *f = fopen(HDR[h], "r"); /* the tests run in the source tree */
    ck_assert_msg(f != NULL, "%s", HDR[h]);
    char text[1 << 16];
    const size_t len = fread(text, 1, sizeof text - 1, f);
    fclose(f);
    text[len] = '\0';
    for (const char *s = strstr(text, "VSPH_API"); s;
         s = strstr(s + 8, "VSPH_API")) {
      const char *paren = strchr(s, '('), *semi = strpbrk(s, ";{");
      if (!paren || (semi && semi < paren)) continue; /* a table */
      const char *e = paren;
      while (e > s && (e[-1] == ' ' || e[-1] == '\n')) e--;
      const char *b = e;
      while (b > s && (isalnum((unsigned char)b[-1]) || b[-1] == '_')) b--;
      char name[96];
      snprintf(name, sizeof name, "%.*s", (int)(e - b), b);
      if (!strcmp(name, "vsph_status_report") ||
          !strcmp(name, "vsph_status_set_handler"))
        continue;
      size_t k = 0;
      while (k < NCALLS && strcmp(CALLS[k].name, name)) k++;
      ck_assert_msg(k < NCALLS, "%s (%s) has no calls in tests/check_api.c",
                    name, HDR[h]);
      n++;
    }
  }
  ck_assert_uint_gt(n, 150);
}
END_TEST

/* The formulation ids a caller may pass to the public functions and
 * static inline helpers of solver/viscous.h (and to the right-hand side
 * through its props): -1, VSPH_VISCOUS_FORM_COUNT and 1000000 are each
 * refused with their documented value, never read past the descriptor
 * table (vsph_viscous_passes(1000000) read vsph_viscous_types[1000000]). */
START_TEST(test_form_ids_out_of_range) {
  vsph_test_silence();
  const int bad[3] = {-1, VSPH_VISCOUS_FORM_COUNT, 1000000};
  struct vsph_particles *p = vsph_particles_alloc(4, 2);
  ck_assert_ptr_nonnull(p);
  p->n = 1;
  p->m[0] = p->rho[0] = 1.0;
  struct vsph_cells *cells = vsph_cells_alloc();
  ck_assert_int_eq(vsph_cells_build_direct(cells, p), 0);
  struct vsph_viscous_ws *ws = vsph_viscous_ws_alloc(4, 2);
  for (int b = 0; b < 3; b++) {
    const int f = bad[b];
    ck_assert_int_eq(vsph_viscous_passes(f), 0);
    ck_assert_int_eq(vsph_viscous_particle_form(f), 0);
    ck_assert_int_eq(vsph_viscous_first_pass(f), 0);
    ck_assert_int_eq(vsph_viscous_corrigible(f), 0);
    ck_assert_int_eq(vsph_viscous_specialised(f), 0);
    ck_assert_ptr_null(vsph_viscous_type_get(f));
    ck_assert_str_eq(vsph_viscous_name(f), "unknown");
    ck_assert_str_eq(vsph_viscous_label(f), "?");
    ck_assert_str_eq(vsph_viscous_limit_name(f), "unknown");
    struct vsph_viscous_props vp;
    ck_assert_int_eq(
        vsph_viscous_props_init(&vp, f, &vsph_gaussian_type, 2, 0.1, 1.0),
        VSPH_EINVAL);
    ck_assert_int_eq(
        vsph_viscous_props_init(&vp, 0, &vsph_gaussian_type, 2, 0.1, 1.0),
        VSPH_OK);
    vp.form = f;
    /* a loop with no term: every share and its own part nothing */
    struct vsph_viscous_loop lp;
    ck_assert_int_eq(vsph_viscous_loop_init(&lp, &vp, ws), VSPH_EINVAL);
    ck_assert(lp.pair == NULL);
    ck_assert(lp.pair_g == NULL);
    ck_assert_int_eq(lp.nA + lp.own, 0);
    double acc[3] = {0.25, 0.5, 0.75}, Ai[9] = {0};
    vsph_viscous_own(&lp, 0, acc);
    vsph_viscous_load_A(&lp, 0, Ai);
    ck_assert(acc[0] == 0.25 && acc[1] == 0.5 && Ai[0] == 0.0);
    /* the functions taking props refuse it */
    double *out[3] = {p->acc[0], p->acc[1], NULL};
    ck_assert_int_eq(vsph_viscous_prepare(&vp, p, cells, ws), VSPH_EINVAL);
    ck_assert_int_eq(vsph_viscous_compute(&vp, p, cells, ws, out, NULL),
                     VSPH_EINVAL);
    const double B[9] = {1, 0, 0, 1}, Mg[9] = {0};
    ws->dens[0] = 0.125;
    vsph_viscous_pvwf_finish(&vp, ws, 0, B, Mg); /* a no-op */
    ck_assert(ws->dens[0] == 0.125);
    struct vsph_equations_props ep = {.visc = vp, .rho0 = 1.0, .c0 = 1.0};
    struct vsph_equations_out eo = {.drho = p->drho,
                                    .acc = {p->acc[0], p->acc[1]}};
    p->rho[0] = 1.5; /* refused before the state equation writes p */
    p->p[0] = 0.0;
    ck_assert_int_eq(vsph_equations_rhs(&ep, p, 1, cells, ws, &eo),
                     VSPH_EINVAL);
    ck_assert(p->p[0] == 0.0);
    p->rho[0] = 1.0;
  }
  vsph_viscous_ws_free(ws);
  vsph_cells_free(cells);
  vsph_particles_free(p);
}
END_TEST

Suite *vsph_api_suite(void) {
  Suite *s = suite_create("api");
  TCase *tc = tcase_create("bad arguments");
  tcase_set_timeout(tc, 120);
  tcase_add_test(tc, test_null_and_out_of_range);
  tcase_add_test(tc, test_every_entry_called);
  tcase_add_test(tc, test_form_ids_out_of_range);
  suite_add_tcase(s, tc);
  return s;
}
