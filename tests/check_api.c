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
#include <limits.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

#include "../analysis/contact.h"
#include "../analysis/dissipation.h"
#include "../analysis/fields.h"
#include "../analysis/laplacian.h"
#include "../analysis/moments.h"
#include "../analysis/references.h"
#include "../analysis/scaling.h"
#include "../analysis/series.h"
#include "../common/params.h"
#include "../common/status.h"
#include "../common/sysinfo.h"
#include "../io/csv.h"
#include "../io/files.h"
#include "../io/json.h"
#include "../io/plot.h"
#include "../io/vtk.h"
#include "../kernels/kernel.h"
#include "../solver/cells.h"
#include "../solver/diagnostics.h"
#include "../solver/equations.h"
#include "../solver/integrate.h"
#include "../solver/lattice.h"
#include "../solver/materials.h"
#include "../solver/pair.h"
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
  (void)vsph_params_load(NULL, NULL, NULL, 0, NULL, 0);
}

static void call_vsph_params_load_1(void) {
  (void)vsph_params_load(NULL, NULL, NULL, SIZE_MAX, NULL, SIZE_MAX);
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

static void call_vsph_equations_eos_name_0(void) {
  (void)vsph_equations_eos_name(-1);
}

static void call_vsph_equations_eos_name_1(void) {
  (void)vsph_equations_eos_name(INT_MAX);
}

static void call_vsph_equations_scheme_name_0(void) {
  (void)vsph_equations_scheme_name(-1);
}

static void call_vsph_equations_scheme_name_1(void) {
  (void)vsph_equations_scheme_name(INT_MAX);
}

static void call_vsph_equations_corr_name_0(void) {
  (void)vsph_equations_corr_name(-1);
}

static void call_vsph_equations_corr_name_1(void) {
  (void)vsph_equations_corr_name(INT_MAX);
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

static void call_vsph_files_open_0(void) { (void)vsph_files_open(NULL, NULL); }

static void call_vsph_files_open_1(void) { (void)vsph_files_open(NULL, NULL); }

static void call_vsph_files_close_0(void) {
  (void)vsph_files_close(NULL, NULL, NULL);
}

static void call_vsph_files_close_1(void) {
  (void)vsph_files_close(NULL, NULL, NULL);
}

static void call_vsph_files_discard_0(void) {
  vsph_files_discard(NULL, NULL, NULL);
}

static void call_vsph_files_discard_1(void) {
  vsph_files_discard(NULL, NULL, NULL);
}

static void call_vsph_files_write_0(void) {
  (void)vsph_files_write(NULL, NULL, NULL);
}

static void call_vsph_files_write_1(void) {
  (void)vsph_files_write(NULL, NULL, NULL);
}

static void call_vsph_files_mkdir_0(void) { (void)vsph_files_mkdir(NULL); }

static void call_vsph_files_mkdir_1(void) { (void)vsph_files_mkdir(NULL); }

static void call_vsph_files_target_0(void) { (void)vsph_files_target(NULL); }

static void call_vsph_files_target_1(void) { (void)vsph_files_target(NULL); }

static void call_vsph_files_reopen_0(void) {
  (void)vsph_files_reopen(NULL, NULL, 0);
}

static void call_vsph_files_reopen_1(void) {
  (void)vsph_files_reopen(NULL, NULL, -1);
}

static void call_vsph_files_slurp_0(void) {
  (void)vsph_files_slurp(NULL, NULL);
}

static void call_vsph_files_slurp_1(void) {
  (void)vsph_files_slurp(NULL, NULL);
}

static void call_vsph_csv_open_0(void) {
  (void)vsph_csv_open(NULL, NULL, NULL);
}

static void call_vsph_csv_open_1(void) {
  (void)vsph_csv_open(NULL, NULL, NULL);
}

static void call_vsph_csv_close_0(void) {
  (void)vsph_csv_close(NULL, NULL, NULL);
}

static void call_vsph_csv_close_1(void) {
  (void)vsph_csv_close(NULL, NULL, NULL);
}

static void call_vsph_csv_read_0(void) { (void)vsph_csv_read(NULL); }

static void call_vsph_csv_read_1(void) { (void)vsph_csv_read(NULL); }

static void call_vsph_csv_free_0(void) { vsph_csv_free(NULL); }

static void call_vsph_csv_free_1(void) { vsph_csv_free(NULL); }

static void call_vsph_csv_column_0(void) { (void)vsph_csv_column(NULL, NULL); }

static void call_vsph_csv_column_1(void) { (void)vsph_csv_column(NULL, NULL); }

static void call_vsph_csv_column_number_0(void) {
  (void)vsph_csv_column_number(NULL, NULL);
}

static void call_vsph_csv_column_number_1(void) {
  (void)vsph_csv_column_number(NULL, NULL);
}

static void call_vsph_json_array_0(void) { (void)vsph_json_array(NULL, 0); }

static void call_vsph_json_array_1(void) {
  (void)vsph_json_array(NULL, SIZE_MAX);
}

static void call_vsph_json_number_0(void) { vsph_json_number(NULL, NULL, 0.0); }

static void call_vsph_json_number_1(void) { vsph_json_number(NULL, NULL, NAN); }

static void call_vsph_json_load_0(void) { vsph_json_load(NULL, NULL, NULL); }

static void call_vsph_json_load_1(void) { vsph_json_load(NULL, NULL, NULL); }

static void call_vsph_json_moments_0(void) { vsph_json_moments(NULL, NULL); }

static void call_vsph_json_moments_1(void) { vsph_json_moments(NULL, NULL); }

static void call_vsph_json_print_0(void) { (void)vsph_json_print(NULL); }

static void call_vsph_json_print_1(void) { (void)vsph_json_print(NULL); }

static void call_vsph_json_text_0(void) { (void)vsph_json_text(NULL); }

static void call_vsph_json_text_1(void) { (void)vsph_json_text(NULL); }

static void call_vsph_json_write_0(void) {
  (void)vsph_json_write(NULL, NULL, NULL);
}

static void call_vsph_json_write_1(void) {
  (void)vsph_json_write(NULL, NULL, NULL);
}

static void call_vsph_json_read_0(void) { (void)vsph_json_read(NULL); }

static void call_vsph_json_read_1(void) { (void)vsph_json_read(NULL); }

static void call_vsph_json_get_number_0(void) {
  (void)vsph_json_get_number(NULL, NULL, 0.0);
}

static void call_vsph_json_get_number_1(void) {
  (void)vsph_json_get_number(NULL, NULL, NAN);
}

static void call_vsph_json_tensors_0(void) {
  (void)vsph_json_tensors(NULL, NULL);
}

static void call_vsph_json_tensors_1(void) {
  (void)vsph_json_tensors(NULL, NULL);
}

static void call_vsph_json_scaling_0(void) {
  (void)vsph_json_scaling(NULL, NULL, 0.0, 0.0);
}

static void call_vsph_json_scaling_1(void) {
  (void)vsph_json_scaling(NULL, NULL, NAN, NAN);
}

static void call_vsph_json_dissipation_0(void) {
  (void)vsph_json_dissipation(NULL, NULL);
}

static void call_vsph_json_dissipation_1(void) {
  (void)vsph_json_dissipation(NULL, NULL);
}

static void call_vsph_json_laplacian_0(void) {
  (void)vsph_json_laplacian(NULL, NULL);
}

static void call_vsph_json_laplacian_1(void) {
  (void)vsph_json_laplacian(NULL, NULL);
}

static void call_vsph_plot_colour_0(void) { (void)vsph_plot_colour(0); }

static void call_vsph_plot_colour_1(void) { (void)vsph_plot_colour(SIZE_MAX); }

static void call_vsph_plot_point_0(void) { (void)vsph_plot_point(0); }

static void call_vsph_plot_point_1(void) { (void)vsph_plot_point(SIZE_MAX); }

static void call_vsph_plot_plain_0(void) { vsph_plot_plain(NULL, 0, NULL); }

static void call_vsph_plot_plain_1(void) {
  vsph_plot_plain(NULL, SIZE_MAX, NULL);
}

static void call_vsph_plot_init_0(void) {
  vsph_plot_init(NULL, NULL, NULL, NULL, NULL, NULL);
}

static void call_vsph_plot_init_1(void) {
  vsph_plot_init(NULL, NULL, NULL, NULL, NULL, NULL);
}

static void call_vsph_plot_add_0(void) {
  (void)vsph_plot_add(NULL, NULL, NULL, NULL, NULL);
}

static void call_vsph_plot_add_1(void) {
  (void)vsph_plot_add(NULL, NULL, NULL, NULL, NULL);
}

static void call_vsph_plot_add_unkeyed_0(void) {
  (void)vsph_plot_add_unkeyed(NULL, NULL, NULL, NULL, NULL);
}

static void call_vsph_plot_add_unkeyed_1(void) {
  struct vsph_plot pl;
  memset(&pl, 0, sizeof pl);
  (void)vsph_plot_add_unkeyed(&pl, "f.csv", "1:2", NULL, "lines");
}

static void call_vsph_plot_write_0(void) { (void)vsph_plot_write(NULL); }

static void call_vsph_plot_write_1(void) { (void)vsph_plot_write(NULL); }

static void call_vsph_plot_particles_0(void) {
  (void)vsph_plot_particles(NULL, NULL, NULL, NULL, 0, 0, NULL, 0, NULL, NULL);
}

static void call_vsph_plot_particles_1(void) {
  (void)vsph_plot_particles(NULL, NULL, NULL, NULL, SIZE_MAX, -1, NULL, -1,
                            NULL, NULL);
}

static void call_vsph_vtk_write_0(void) {
  (void)vsph_vtk_write(NULL, NULL, NULL, 0, 0.0, NULL, NULL);
}

static void call_vsph_vtk_write_1(void) {
  (void)vsph_vtk_write(NULL, NULL, NULL, SIZE_MAX, NAN, NULL, NULL);
}

static void call_vsph_vtk_write_mapped_0(void) {
  (void)vsph_vtk_write_mapped(NULL, NULL, NULL, 0, NULL, 0.0, NULL, NULL);
}

static void call_vsph_vtk_write_mapped_1(void) {
  (void)vsph_vtk_write_mapped(NULL, NULL, NULL, SIZE_MAX, NULL, NAN, NULL,
                              NULL);
}

static void call_vsph_vtk_read_0(void) { (void)vsph_vtk_read(NULL, NULL); }

static void call_vsph_vtk_read_1(void) { (void)vsph_vtk_read(NULL, NULL); }

static void call_vsph_vtk_write_frame_0(void) {
  (void)vsph_vtk_write_frame(NULL, NULL, NULL, 0, 0);
}

static void call_vsph_vtk_write_frame_1(void) {
  (void)vsph_vtk_write_frame(NULL, NULL, NULL, -1, UINT_MAX);
}

static void call_vsph_vtk_snapshot_free_0(void) {
  vsph_vtk_snapshot_free(NULL);
}

static void call_vsph_vtk_snapshot_free_1(void) {
  vsph_vtk_snapshot_free(NULL);
}

static void call_vsph_vtk_pvd_open_0(void) {
  (void)vsph_vtk_pvd_open(NULL, NULL);
}

static void call_vsph_vtk_pvd_open_1(void) {
  (void)vsph_vtk_pvd_open(NULL, NULL);
}

static void call_vsph_vtk_pvd_reopen_0(void) {
  (void)vsph_vtk_pvd_reopen(NULL, NULL, 0);
}

static void call_vsph_vtk_pvd_reopen_1(void) {
  (void)vsph_vtk_pvd_reopen(NULL, NULL, -1);
}

static void call_vsph_vtk_pvd_add_0(void) {
  (void)vsph_vtk_pvd_add(NULL, 0.0, NULL);
}

static void call_vsph_vtk_pvd_add_1(void) {
  (void)vsph_vtk_pvd_add(NULL, NAN, NULL);
}

static void call_vsph_vtk_pvd_add_part_0(void) {
  (void)vsph_vtk_pvd_add_part(NULL, 0.0, 0, NULL);
}

static void call_vsph_vtk_pvd_add_part_1(void) {
  (void)vsph_vtk_pvd_add_part(NULL, NAN, -1, NULL);
}

static void call_vsph_vtk_write_walls_0(void) {
  (void)vsph_vtk_write_walls(NULL, NULL, NULL, 0, 0, 0.0, 0.0);
}

static void call_vsph_vtk_write_walls_1(void) {
  (void)vsph_vtk_write_walls(NULL, NULL, NULL, SIZE_MAX, SIZE_MAX, NAN, NAN);
}

static void call_vsph_vtk_pvd_close_0(void) { (void)vsph_vtk_pvd_close(NULL); }

static void call_vsph_vtk_pvd_close_1(void) { (void)vsph_vtk_pvd_close(NULL); }

static void call_vsph_pair_x86_simd_0(void) { (void)vsph_pair_x86_simd(); }

static void call_vsph_pair_x86_simd_1(void) { (void)vsph_pair_x86_simd(); }

static void call_vsph_series_interp_0(void) {
  (void)vsph_series_interp(NULL, NULL, 0, 0.0);
}

static void call_vsph_series_interp_1(void) {
  (void)vsph_series_interp(NULL, NULL, SIZE_MAX, NAN);
}

static void call_vsph_series_extrapolate_0(void) {
  (void)vsph_series_extrapolate(NULL, NULL);
}

static void call_vsph_series_extrapolate_1(void) {
  (void)vsph_series_extrapolate(NULL, NULL);
}

static void call_vsph_series_decay_error_0(void) {
  (void)vsph_series_decay_error(NULL, NULL, 0);
}

static void call_vsph_series_decay_error_1(void) {
  (void)vsph_series_decay_error(NULL, NULL, SIZE_MAX);
}

static void call_vsph_series_decay_error_table_0(void) {
  (void)vsph_series_decay_error_table(NULL, NULL, 0, NULL, NULL, 0);
}

static void call_vsph_series_decay_error_table_1(void) {
  (void)vsph_series_decay_error_table(NULL, NULL, SIZE_MAX, NULL, NULL,
                                      SIZE_MAX);
}

static void call_vsph_series_onset_0(void) {
  (void)vsph_series_onset(NULL, NULL, 0, NULL, NULL, 0, 0.0);
}

static void call_vsph_series_onset_1(void) {
  (void)vsph_series_onset(NULL, NULL, SIZE_MAX, NULL, NULL, SIZE_MAX, NAN);
}

static void call_vsph_series_integral_0(void) {
  (void)vsph_series_integral(NULL, NULL, 0);
}

static void call_vsph_series_integral_1(void) {
  (void)vsph_series_integral(NULL, NULL, SIZE_MAX);
}

static void call_vsph_series_loss_ratio_0(void) {
  (void)vsph_series_loss_ratio(0.0, 0.0, 0.0, 0.0);
}

static void call_vsph_series_loss_ratio_1(void) {
  (void)vsph_series_loss_ratio(NAN, NAN, NAN, NAN);
}

static void call_vsph_series_first_reach_0(void) {
  (void)vsph_series_first_reach(NULL, NULL, 0, 0.0, 0.0, 0.0);
}

static void call_vsph_series_first_reach_1(void) {
  (void)vsph_series_first_reach(NULL, NULL, SIZE_MAX, NAN, NAN, NAN);
}

static void call_vsph_series_failure_0(void) {
  (void)vsph_series_failure(NULL, NULL, 0, 0.0, 0.0, 0.0, 0.0, NULL);
}

static void call_vsph_series_failure_1(void) {
  (void)vsph_series_failure(NULL, NULL, SIZE_MAX, NAN, NAN, NAN, NAN, NULL);
}

static void call_vsph_series_tail_mean_0(void) {
  (void)vsph_series_tail_mean(NULL, NULL, 0, 0.0);
}

static void call_vsph_series_tail_mean_1(void) {
  (void)vsph_series_tail_mean(NULL, NULL, SIZE_MAX, NAN);
}

static void call_vsph_series_tail_range_0(void) {
  (void)vsph_series_tail_range(NULL, NULL, 0, 0.0);
}

static void call_vsph_series_tail_range_1(void) {
  (void)vsph_series_tail_range(NULL, NULL, SIZE_MAX, NAN);
}

static void call_vsph_series_plateau_0(void) {
  vsph_series_plateau(NULL, NULL, NULL, NULL, 0, 0.0, 0.0, 0.0, NULL, 0, NULL,
                      NULL);
}

static void call_vsph_series_plateau_1(void) {
  vsph_series_plateau(NULL, NULL, NULL, NULL, SIZE_MAX, NAN, NAN, NAN, NULL,
                      SIZE_MAX, NULL, NULL);
}

static void call_vsph_series_cfl_pick_0(void) {
  (void)vsph_series_cfl_pick(NULL, NULL, 0, 0, 0.0);
}

static void call_vsph_series_cfl_pick_1(void) {
  (void)vsph_series_cfl_pick(NULL, NULL, SIZE_MAX, -1, NAN);
}

static void call_vsph_series_interp_cubic_0(void) {
  (void)vsph_series_interp_cubic(NULL, NULL, 0, 0.0);
}

static void call_vsph_series_interp_cubic_1(void) {
  (void)vsph_series_interp_cubic(NULL, NULL, SIZE_MAX, NAN);
}

static void call_vsph_run_props_for_scene_0(void) {
  (void)vsph_run_props_for_scene(NULL, NULL, NULL);
}

static void call_vsph_run_props_for_scene_1(void) {
  struct vsph_run_props rp;
  (void)vsph_run_props_for_scene(&rp, NULL, NULL);
}

static void call_vsph_contact_self_similar_0(void) {
  vsph_contact_self_similar(NULL, NULL, NULL);
}

static void call_vsph_contact_self_similar_1(void) {
  double a, b;
  vsph_contact_self_similar(NULL, &a, &b);
}

static void call_vsph_series_ratio_history_0(void) {
  (void)vsph_series_ratio_history(NULL, NULL, 0, NULL, NULL, 0, 0.0, 0.0, 0.0,
                                  NULL);
}

static void call_vsph_series_ratio_history_1(void) {
  (void)vsph_series_ratio_history(NULL, NULL, SIZE_MAX, NULL, NULL, SIZE_MAX,
                                  NAN, NAN, NAN, NULL);
}

static void call_vsph_series_log_between_0(void) {
  (void)vsph_series_log_between(0.0, 0.0, 0.0);
}

static void call_vsph_series_log_between_1(void) {
  (void)vsph_series_log_between(NAN, -1.0, NAN);
}

static void call_vsph_references_cavity_rms_0(void) {
  (void)vsph_references_cavity_rms(NULL, NULL, 0, 0, 0.0, 0.0, NULL, NULL, 0);
}

static void call_vsph_references_cavity_rms_1(void) {
  (void)vsph_references_cavity_rms(NULL, NULL, 34, 17, 1000.0, NAN, NULL, NULL,
                                   SIZE_MAX);
}

static void call_vsph_references_ghia_rest_0(void) {
  (void)vsph_references_ghia_rest(0.0);
}

static void call_vsph_references_ghia_rest_1(void) {
  (void)vsph_references_ghia_rest(NAN);
}

static void call_vsph_series_order_0(void) {
  (void)vsph_series_order(0.0, 0.0, 0.0, 0.0);
}

static void call_vsph_series_order_1(void) {
  (void)vsph_series_order(NAN, NAN, NAN, NAN);
}

static void call_vsph_series_selfconv_0(void) {
  (void)vsph_series_selfconv(NULL, 0, NULL);
}

static void call_vsph_series_selfconv_1(void) {
  (void)vsph_series_selfconv(NULL, SIZE_MAX, NULL);
}

static void call_vsph_series_slope_where_0(void) {
  (void)vsph_series_slope_where(NULL, NULL, NULL, 0, NULL);
}

static void call_vsph_series_slope_where_1(void) {
  (void)vsph_series_slope_where(NULL, NULL, NULL, SIZE_MAX, NULL);
}

static void call_vsph_contact_shear_u_0(void) {
  (void)vsph_contact_shear_u(0.0, 0.0, 0.0, 0.0, 0.0);
}

static void call_vsph_contact_shear_u_1(void) {
  (void)vsph_contact_shear_u(NAN, NAN, NAN, NAN, NAN);
}

static void call_vsph_contact_shear_dy_0(void) {
  (void)vsph_contact_shear_dy(0.0, 0.0, 0.0, 0.0, 0.0);
}

static void call_vsph_contact_shear_dy_1(void) {
  (void)vsph_contact_shear_dy(NAN, NAN, NAN, NAN, NAN);
}

static void call_vsph_contact_eta_model_0(void) {
  (void)vsph_contact_eta_model(0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0);
}

static void call_vsph_contact_eta_model_1(void) {
  (void)vsph_contact_eta_model(NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN);
}

static void call_vsph_contact_bimaterial_fit_0(void) {
  (void)vsph_contact_bimaterial_fit(NULL, NULL, NULL, 0, 0.0, 0.0, 0.0, 0.0,
                                    0.0, 0.0, 0.0, 0.0, 0.0, NULL);
}

static void call_vsph_contact_bimaterial_fit_1(void) {
  (void)vsph_contact_bimaterial_fit(NULL, NULL, NULL, SIZE_MAX, NAN, NAN, NAN,
                                    NAN, NAN, NAN, NAN, NAN, NAN, NULL);
}

static void call_vsph_contact_drag_ratio_0(void) {
  (void)vsph_contact_drag_ratio(NULL, 0, 0.0, 0.0, 0.0, NULL, NULL);
}

static void call_vsph_contact_drag_ratio_1(void) {
  (void)vsph_contact_drag_ratio(NULL, SIZE_MAX, NAN, NAN, NAN, NULL, NULL);
}

static void call_vsph_contact_bimaterial_u_0(void) {
  (void)vsph_contact_bimaterial_u(0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, NULL);
}

static void call_vsph_contact_bimaterial_u_1(void) {
  (void)vsph_contact_bimaterial_u(NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NULL);
}

static void call_vsph_contact_lattice_coef_0(void) {
  (void)vsph_contact_lattice_coef(NULL, 0, 0.0);
}

static void call_vsph_contact_lattice_coef_1(void) {
  (void)vsph_contact_lattice_coef(NULL, -1, NAN);
}

static void call_vsph_contact_lattice_visc_factor_0(void) {
  (void)vsph_contact_lattice_visc_factor(NULL, 0, 0.0);
}

static void call_vsph_contact_lattice_visc_factor_1(void) {
  (void)vsph_contact_lattice_visc_factor(NULL, -1, NAN);
}

static void call_vsph_contact_fit_nu_0(void) {
  (void)vsph_contact_fit_nu(0, NULL, NULL, 0, 0.0, 0.0, 0.0, 0.0, 0.0, NULL);
}

static void call_vsph_contact_fit_nu_1(void) {
  (void)vsph_contact_fit_nu(SIZE_MAX, NULL, NULL, -1, NAN, NAN, NAN, NAN, NAN,
                            NULL);
}

static void call_vsph_contact_defaults_0(void) {
  (void)vsph_contact_defaults(NULL);
}

static void call_vsph_contact_defaults_1(void) {
  (void)vsph_contact_defaults(NULL);
}

static void call_vsph_contact_shear_measure_0(void) {
  (void)vsph_contact_shear_measure(NULL, NULL);
}

static void call_vsph_contact_shear_measure_1(void) {
  (void)vsph_contact_shear_measure(NULL, NULL);
}

static void call_vsph_contact_shear_free_0(void) {
  vsph_contact_shear_free(NULL);
}

static void call_vsph_contact_shear_free_1(void) {
  vsph_contact_shear_free(NULL);
}

static void call_vsph_laplacian_form_name_0(void) {
  (void)vsph_laplacian_form_name(0);
}

static void call_vsph_laplacian_form_name_1(void) {
  (void)vsph_laplacian_form_name(-1);
}

static void call_vsph_laplacian_form_find_0(void) {
  (void)vsph_laplacian_form_find(NULL);
}

static void call_vsph_laplacian_form_find_1(void) {
  (void)vsph_laplacian_form_find(NULL);
}

static void call_vsph_laplacian_field_name_0(void) {
  (void)vsph_laplacian_field_name(0);
}

static void call_vsph_laplacian_field_name_1(void) {
  (void)vsph_laplacian_field_name(-1);
}

static void call_vsph_laplacian_params_0(void) {
  (void)vsph_laplacian_params(NULL);
}

static void call_vsph_laplacian_params_1(void) {
  (void)vsph_laplacian_params(NULL);
}

static void call_vsph_laplacian_props_init_0(void) {
  (void)vsph_laplacian_props_init(NULL, NULL);
}

static void call_vsph_laplacian_props_init_1(void) {
  (void)vsph_laplacian_props_init(NULL, NULL);
}

static void call_vsph_laplacian_patch_0(void) {
  (void)vsph_laplacian_patch(NULL, NULL);
}

static void call_vsph_laplacian_patch_1(void) {
  (void)vsph_laplacian_patch(NULL, NULL);
}

static void call_vsph_integrate_alloc_0(void) {
  (void)vsph_integrate_alloc(NULL, NULL);
}

static void call_vsph_integrate_alloc_1(void) {
  (void)vsph_integrate_alloc(NULL, NULL);
}

static void call_vsph_integrate_free_0(void) { vsph_integrate_free(NULL); }

static void call_vsph_integrate_free_1(void) { vsph_integrate_free(NULL); }

static void call_vsph_integrate_dt_0(void) { (void)vsph_integrate_dt(NULL); }

static void call_vsph_integrate_dt_1(void) { (void)vsph_integrate_dt(NULL); }

static void call_vsph_integrate_dt_rule_0(void) {
  (void)vsph_integrate_dt_rule(0.0, 0, 0, 0.0, 0.0, 0.0, 0.0, 0.0);
}

static void call_vsph_integrate_dt_rule_1(void) {
  (void)vsph_integrate_dt_rule(NAN, -1, -1, NAN, NAN, NAN, NAN, NAN);
}

static void call_vsph_integrate_step_0(void) {
  (void)vsph_integrate_step(NULL, 0.0);
}

static void call_vsph_integrate_step_1(void) {
  (void)vsph_integrate_step(NULL, NAN);
}

static void call_vsph_integrate_check_0(void) {
  (void)vsph_integrate_check(NULL);
}

static void call_vsph_integrate_check_1(void) {
  (void)vsph_integrate_check(NULL);
}

static void call_vsph_integrate_diagnostics_0(void) {
  (void)vsph_integrate_diagnostics(NULL, NULL, NULL);
}

static void call_vsph_integrate_diagnostics_1(void) {
  (void)vsph_integrate_diagnostics(NULL, NULL, NULL);
}

static void call_vsph_integrate_pack_0(void) {
  (void)vsph_integrate_pack(NULL, NULL);
}

static void call_vsph_integrate_pack_1(void) {
  (void)vsph_integrate_pack(NULL, NULL);
}

static void call_vsph_integrate_wall_count_0(void) {
  (void)vsph_integrate_wall_count(NULL);
}

static void call_vsph_integrate_wall_count_1(void) {
  (void)vsph_integrate_wall_count(NULL);
}

static void call_vsph_integrate_pack_lean_0(void) {
  (void)vsph_integrate_pack_lean(NULL, NULL);
}

static void call_vsph_integrate_pack_lean_1(void) {
  (void)vsph_integrate_pack_lean(NULL, NULL);
}

static void call_vsph_integrate_pack_lean_file_0(void) {
  (void)vsph_integrate_pack_lean_file(NULL, NULL);
}

static void call_vsph_integrate_pack_lean_file_1(void) {
  (void)vsph_integrate_pack_lean_file(NULL, NULL);
}

static void call_vsph_integrate_restore_file_0(void) {
  (void)vsph_integrate_restore_file(NULL, NULL, 0);
}

static void call_vsph_integrate_restore_file_1(void) {
  (void)vsph_integrate_restore_file(NULL, NULL, SIZE_MAX);
}

static void call_vsph_integrate_unpack_0(void) {
  (void)vsph_integrate_unpack(NULL, NULL, 0, NULL);
}

static void call_vsph_integrate_unpack_1(void) {
  (void)vsph_integrate_unpack(NULL, NULL, SIZE_MAX, NULL);
}

static void call_vsph_integrate_restore_0(void) {
  (void)vsph_integrate_restore(NULL, NULL, 0);
}

static void call_vsph_integrate_restore_1(void) {
  (void)vsph_integrate_restore(NULL, NULL, SIZE_MAX);
}

static void call_vsph_integrate_bytes_0(void) {
  (void)vsph_integrate_bytes(NULL);
}

static void call_vsph_integrate_bytes_1(void) {
  (void)vsph_integrate_bytes(NULL);
}

static void call_vsph_integrate_bytes_estimate_0(void) {
  (void)vsph_integrate_bytes_estimate(0, 0.0, 0.0, 0, 0);
}

static void call_vsph_integrate_bytes_estimate_1(void) {
  (void)vsph_integrate_bytes_estimate(-1, NAN, NAN, -1, -1);
}

static void call_vsph_materials_drag_row_0(void) {
  (void)vsph_materials_drag_row(0.0);
}

static void call_vsph_materials_drag_row_1(void) {
  (void)vsph_materials_drag_row(NAN);
}

static void call_vsph_materials_drag_square_0(void) {
  (void)vsph_materials_drag_square(0.0);
}

static void call_vsph_materials_drag_square_1(void) {
  (void)vsph_materials_drag_square(NAN);
}

static void call_vsph_materials_count_0(void) { (void)vsph_materials_count(); }

static void call_vsph_materials_count_1(void) { (void)vsph_materials_count(); }

static void call_vsph_materials_get_0(void) { (void)vsph_materials_get(0); }

static void call_vsph_materials_get_1(void) { (void)vsph_materials_get(-1); }

static void call_vsph_materials_resolve_0(void) {
  (void)vsph_materials_resolve(NULL, NULL);
}

static void call_vsph_materials_resolve_1(void) {
  (void)vsph_materials_resolve(NULL, NULL);
}

static void call_vsph_diagnostics_surface_threshold_0(void) {
  (void)vsph_diagnostics_surface_threshold(0);
}

static void call_vsph_diagnostics_surface_threshold_1(void) {
  (void)vsph_diagnostics_surface_threshold(-1);
}

static void call_vsph_diagnostics_compute_0(void) {
  (void)vsph_diagnostics_compute(NULL, 0, NULL, 0.0, NULL, NULL);
}

static void call_vsph_diagnostics_compute_1(void) {
  (void)vsph_diagnostics_compute(NULL, SIZE_MAX, NULL, NAN, NULL, NULL);
}

static void call_vsph_diagnostics_compute_cells_0(void) {
  (void)vsph_diagnostics_compute_cells(NULL, 0, NULL, NULL, 0.0, NULL, NULL,
                                       NULL);
}

static void call_vsph_diagnostics_compute_cells_1(void) {
  (void)vsph_diagnostics_compute_cells(NULL, SIZE_MAX, NULL, NULL, NAN, NULL,
                                       NULL, NULL);
}

static void call_vsph_diagnostics_probe_0(void) {
  (void)vsph_diagnostics_probe(NULL, 0, NULL, 0.0, NULL, NULL, NULL);
}

static void call_vsph_diagnostics_probe_1(void) {
  (void)vsph_diagnostics_probe(NULL, SIZE_MAX, NULL, NAN, NULL, NULL, NULL);
}

static void call_vsph_diagnostics_free_0(void) { vsph_diagnostics_free(NULL); }

static void call_vsph_diagnostics_free_1(void) { vsph_diagnostics_free(NULL); }

static void call_vsph_sysinfo_load_0(void) { vsph_sysinfo_load(NULL); }

static void call_vsph_sysinfo_load_1(void) { vsph_sysinfo_load(NULL); }

static void call_vsph_sysinfo_cpu_s_0(void) { (void)vsph_sysinfo_cpu_s(); }

static void call_vsph_sysinfo_cpu_s_1(void) { (void)vsph_sysinfo_cpu_s(); }

static void call_vsph_sysinfo_thread_cpu_s_0(void) {
  (void)vsph_sysinfo_thread_cpu_s();
}

static void call_vsph_sysinfo_thread_cpu_s_1(void) {
  (void)vsph_sysinfo_thread_cpu_s();
}

static void call_vsph_sysinfo_wait_policy_0(void) {
  (void)vsph_sysinfo_wait_policy(NULL, 0);
}

static void call_vsph_sysinfo_wait_policy_1(void) {
  (void)vsph_sysinfo_wait_policy(NULL, SIZE_MAX);
}

static void call_vsph_sysinfo_build_isa_0(void) {
  (void)vsph_sysinfo_build_isa();
}

static void call_vsph_sysinfo_build_isa_1(void) {
  (void)vsph_sysinfo_build_isa();
}

static void call_vsph_sysinfo_peak_rss_0(void) {
  (void)vsph_sysinfo_peak_rss();
}

static void call_vsph_sysinfo_peak_rss_1(void) {
  (void)vsph_sysinfo_peak_rss();
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
    {"vsph_equations_eos_name", call_vsph_equations_eos_name_0},
    {"vsph_equations_eos_name", call_vsph_equations_eos_name_1},
    {"vsph_equations_scheme_name", call_vsph_equations_scheme_name_0},
    {"vsph_equations_scheme_name", call_vsph_equations_scheme_name_1},
    {"vsph_equations_corr_name", call_vsph_equations_corr_name_0},
    {"vsph_equations_corr_name", call_vsph_equations_corr_name_1},
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
    {"vsph_files_open", call_vsph_files_open_0},
    {"vsph_files_open", call_vsph_files_open_1},
    {"vsph_files_close", call_vsph_files_close_0},
    {"vsph_files_close", call_vsph_files_close_1},
    {"vsph_files_discard", call_vsph_files_discard_0},
    {"vsph_files_discard", call_vsph_files_discard_1},
    {"vsph_files_write", call_vsph_files_write_0},
    {"vsph_files_write", call_vsph_files_write_1},
    {"vsph_files_mkdir", call_vsph_files_mkdir_0},
    {"vsph_files_mkdir", call_vsph_files_mkdir_1},
    {"vsph_files_target", call_vsph_files_target_0},
    {"vsph_files_target", call_vsph_files_target_1},
    {"vsph_files_reopen", call_vsph_files_reopen_0},
    {"vsph_files_reopen", call_vsph_files_reopen_1},
    {"vsph_files_slurp", call_vsph_files_slurp_0},
    {"vsph_files_slurp", call_vsph_files_slurp_1},
    {"vsph_csv_open", call_vsph_csv_open_0},
    {"vsph_csv_open", call_vsph_csv_open_1},
    {"vsph_csv_close", call_vsph_csv_close_0},
    {"vsph_csv_close", call_vsph_csv_close_1},
    {"vsph_csv_read", call_vsph_csv_read_0},
    {"vsph_csv_read", call_vsph_csv_read_1},
    {"vsph_csv_free", call_vsph_csv_free_0},
    {"vsph_csv_free", call_vsph_csv_free_1},
    {"vsph_csv_column", call_vsph_csv_column_0},
    {"vsph_csv_column", call_vsph_csv_column_1},
    {"vsph_csv_column_number", call_vsph_csv_column_number_0},
    {"vsph_csv_column_number", call_vsph_csv_column_number_1},
    {"vsph_json_array", call_vsph_json_array_0},
    {"vsph_json_array", call_vsph_json_array_1},
    {"vsph_json_number", call_vsph_json_number_0},
    {"vsph_json_number", call_vsph_json_number_1},
    {"vsph_json_load", call_vsph_json_load_0},
    {"vsph_json_load", call_vsph_json_load_1},
    {"vsph_json_moments", call_vsph_json_moments_0},
    {"vsph_json_moments", call_vsph_json_moments_1},
    {"vsph_json_print", call_vsph_json_print_0},
    {"vsph_json_print", call_vsph_json_print_1},
    {"vsph_json_text", call_vsph_json_text_0},
    {"vsph_json_text", call_vsph_json_text_1},
    {"vsph_json_write", call_vsph_json_write_0},
    {"vsph_json_write", call_vsph_json_write_1},
    {"vsph_json_read", call_vsph_json_read_0},
    {"vsph_json_read", call_vsph_json_read_1},
    {"vsph_json_get_number", call_vsph_json_get_number_0},
    {"vsph_json_get_number", call_vsph_json_get_number_1},
    {"vsph_json_tensors", call_vsph_json_tensors_0},
    {"vsph_json_tensors", call_vsph_json_tensors_1},
    {"vsph_json_scaling", call_vsph_json_scaling_0},
    {"vsph_json_scaling", call_vsph_json_scaling_1},
    {"vsph_json_dissipation", call_vsph_json_dissipation_0},
    {"vsph_json_dissipation", call_vsph_json_dissipation_1},
    {"vsph_json_laplacian", call_vsph_json_laplacian_0},
    {"vsph_json_laplacian", call_vsph_json_laplacian_1},
    {"vsph_plot_colour", call_vsph_plot_colour_0},
    {"vsph_plot_colour", call_vsph_plot_colour_1},
    {"vsph_plot_point", call_vsph_plot_point_0},
    {"vsph_plot_point", call_vsph_plot_point_1},
    {"vsph_plot_plain", call_vsph_plot_plain_0},
    {"vsph_plot_plain", call_vsph_plot_plain_1},
    {"vsph_plot_init", call_vsph_plot_init_0},
    {"vsph_plot_init", call_vsph_plot_init_1},
    {"vsph_plot_add", call_vsph_plot_add_0},
    {"vsph_plot_add", call_vsph_plot_add_1},
    {"vsph_plot_add_unkeyed", call_vsph_plot_add_unkeyed_0},
    {"vsph_plot_add_unkeyed", call_vsph_plot_add_unkeyed_1},
    {"vsph_plot_write", call_vsph_plot_write_0},
    {"vsph_plot_write", call_vsph_plot_write_1},
    {"vsph_plot_particles", call_vsph_plot_particles_0},
    {"vsph_plot_particles", call_vsph_plot_particles_1},
    {"vsph_vtk_write", call_vsph_vtk_write_0},
    {"vsph_vtk_write", call_vsph_vtk_write_1},
    {"vsph_vtk_write_mapped", call_vsph_vtk_write_mapped_0},
    {"vsph_vtk_write_mapped", call_vsph_vtk_write_mapped_1},
    {"vsph_vtk_read", call_vsph_vtk_read_0},
    {"vsph_vtk_read", call_vsph_vtk_read_1},
    {"vsph_vtk_write_frame", call_vsph_vtk_write_frame_0},
    {"vsph_vtk_write_frame", call_vsph_vtk_write_frame_1},
    {"vsph_vtk_snapshot_free", call_vsph_vtk_snapshot_free_0},
    {"vsph_vtk_snapshot_free", call_vsph_vtk_snapshot_free_1},
    {"vsph_vtk_pvd_open", call_vsph_vtk_pvd_open_0},
    {"vsph_vtk_pvd_open", call_vsph_vtk_pvd_open_1},
    {"vsph_vtk_pvd_reopen", call_vsph_vtk_pvd_reopen_0},
    {"vsph_vtk_pvd_reopen", call_vsph_vtk_pvd_reopen_1},
    {"vsph_vtk_pvd_add", call_vsph_vtk_pvd_add_0},
    {"vsph_vtk_pvd_add", call_vsph_vtk_pvd_add_1},
    {"vsph_vtk_pvd_add_part", call_vsph_vtk_pvd_add_part_0},
    {"vsph_vtk_pvd_add_part", call_vsph_vtk_pvd_add_part_1},
    {"vsph_vtk_write_walls", call_vsph_vtk_write_walls_0},
    {"vsph_vtk_write_walls", call_vsph_vtk_write_walls_1},
    {"vsph_vtk_pvd_close", call_vsph_vtk_pvd_close_0},
    {"vsph_vtk_pvd_close", call_vsph_vtk_pvd_close_1},
    {"vsph_pair_x86_simd", call_vsph_pair_x86_simd_0},
    {"vsph_pair_x86_simd", call_vsph_pair_x86_simd_1},
    {"vsph_series_interp", call_vsph_series_interp_0},
    {"vsph_series_interp", call_vsph_series_interp_1},
    {"vsph_series_extrapolate", call_vsph_series_extrapolate_0},
    {"vsph_series_extrapolate", call_vsph_series_extrapolate_1},
    {"vsph_series_decay_error", call_vsph_series_decay_error_0},
    {"vsph_series_decay_error", call_vsph_series_decay_error_1},
    {"vsph_series_decay_error_table", call_vsph_series_decay_error_table_0},
    {"vsph_series_decay_error_table", call_vsph_series_decay_error_table_1},
    {"vsph_series_onset", call_vsph_series_onset_0},
    {"vsph_series_onset", call_vsph_series_onset_1},
    {"vsph_series_integral", call_vsph_series_integral_0},
    {"vsph_series_integral", call_vsph_series_integral_1},
    {"vsph_series_loss_ratio", call_vsph_series_loss_ratio_0},
    {"vsph_series_loss_ratio", call_vsph_series_loss_ratio_1},
    {"vsph_series_first_reach", call_vsph_series_first_reach_0},
    {"vsph_series_first_reach", call_vsph_series_first_reach_1},
    {"vsph_series_failure", call_vsph_series_failure_0},
    {"vsph_series_failure", call_vsph_series_failure_1},
    {"vsph_series_tail_mean", call_vsph_series_tail_mean_0},
    {"vsph_series_tail_mean", call_vsph_series_tail_mean_1},
    {"vsph_series_tail_range", call_vsph_series_tail_range_0},
    {"vsph_series_tail_range", call_vsph_series_tail_range_1},
    {"vsph_series_plateau", call_vsph_series_plateau_0},
    {"vsph_series_plateau", call_vsph_series_plateau_1},
    {"vsph_series_cfl_pick", call_vsph_series_cfl_pick_0},
    {"vsph_series_cfl_pick", call_vsph_series_cfl_pick_1},
    {"vsph_series_interp_cubic", call_vsph_series_interp_cubic_0},
    {"vsph_series_interp_cubic", call_vsph_series_interp_cubic_1},
    {"vsph_run_props_for_scene", call_vsph_run_props_for_scene_0},
    {"vsph_run_props_for_scene", call_vsph_run_props_for_scene_1},
    {"vsph_contact_self_similar", call_vsph_contact_self_similar_0},
    {"vsph_contact_self_similar", call_vsph_contact_self_similar_1},
    {"vsph_series_ratio_history", call_vsph_series_ratio_history_0},
    {"vsph_series_ratio_history", call_vsph_series_ratio_history_1},
    {"vsph_series_log_between", call_vsph_series_log_between_0},
    {"vsph_series_log_between", call_vsph_series_log_between_1},
    {"vsph_references_cavity_rms", call_vsph_references_cavity_rms_0},
    {"vsph_references_cavity_rms", call_vsph_references_cavity_rms_1},
    {"vsph_references_ghia_rest", call_vsph_references_ghia_rest_0},
    {"vsph_references_ghia_rest", call_vsph_references_ghia_rest_1},
    {"vsph_series_order", call_vsph_series_order_0},
    {"vsph_series_order", call_vsph_series_order_1},
    {"vsph_series_selfconv", call_vsph_series_selfconv_0},
    {"vsph_series_selfconv", call_vsph_series_selfconv_1},
    {"vsph_series_slope_where", call_vsph_series_slope_where_0},
    {"vsph_series_slope_where", call_vsph_series_slope_where_1},
    {"vsph_contact_shear_u", call_vsph_contact_shear_u_0},
    {"vsph_contact_shear_u", call_vsph_contact_shear_u_1},
    {"vsph_contact_shear_dy", call_vsph_contact_shear_dy_0},
    {"vsph_contact_shear_dy", call_vsph_contact_shear_dy_1},
    {"vsph_contact_eta_model", call_vsph_contact_eta_model_0},
    {"vsph_contact_eta_model", call_vsph_contact_eta_model_1},
    {"vsph_contact_bimaterial_fit", call_vsph_contact_bimaterial_fit_0},
    {"vsph_contact_bimaterial_fit", call_vsph_contact_bimaterial_fit_1},
    {"vsph_contact_drag_ratio", call_vsph_contact_drag_ratio_0},
    {"vsph_contact_drag_ratio", call_vsph_contact_drag_ratio_1},
    {"vsph_contact_bimaterial_u", call_vsph_contact_bimaterial_u_0},
    {"vsph_contact_bimaterial_u", call_vsph_contact_bimaterial_u_1},
    {"vsph_contact_lattice_coef", call_vsph_contact_lattice_coef_0},
    {"vsph_contact_lattice_coef", call_vsph_contact_lattice_coef_1},
    {"vsph_contact_lattice_visc_factor",
     call_vsph_contact_lattice_visc_factor_0},
    {"vsph_contact_lattice_visc_factor",
     call_vsph_contact_lattice_visc_factor_1},
    {"vsph_contact_fit_nu", call_vsph_contact_fit_nu_0},
    {"vsph_contact_fit_nu", call_vsph_contact_fit_nu_1},
    {"vsph_contact_defaults", call_vsph_contact_defaults_0},
    {"vsph_contact_defaults", call_vsph_contact_defaults_1},
    {"vsph_contact_shear_measure", call_vsph_contact_shear_measure_0},
    {"vsph_contact_shear_measure", call_vsph_contact_shear_measure_1},
    {"vsph_contact_shear_free", call_vsph_contact_shear_free_0},
    {"vsph_contact_shear_free", call_vsph_contact_shear_free_1},
    {"vsph_laplacian_form_name", call_vsph_laplacian_form_name_0},
    {"vsph_laplacian_form_name", call_vsph_laplacian_form_name_1},
    {"vsph_laplacian_form_find", call_vsph_laplacian_form_find_0},
    {"vsph_laplacian_form_find", call_vsph_laplacian_form_find_1},
    {"vsph_laplacian_field_name", call_vsph_laplacian_field_name_0},
    {"vsph_laplacian_field_name", call_vsph_laplacian_field_name_1},
    {"vsph_laplacian_params", call_vsph_laplacian_params_0},
    {"vsph_laplacian_params", call_vsph_laplacian_params_1},
    {"vsph_laplacian_props_init", call_vsph_laplacian_props_init_0},
    {"vsph_laplacian_props_init", call_vsph_laplacian_props_init_1},
    {"vsph_laplacian_patch", call_vsph_laplacian_patch_0},
    {"vsph_laplacian_patch", call_vsph_laplacian_patch_1},
    {"vsph_integrate_alloc", call_vsph_integrate_alloc_0},
    {"vsph_integrate_alloc", call_vsph_integrate_alloc_1},
    {"vsph_integrate_free", call_vsph_integrate_free_0},
    {"vsph_integrate_free", call_vsph_integrate_free_1},
    {"vsph_integrate_dt", call_vsph_integrate_dt_0},
    {"vsph_integrate_dt", call_vsph_integrate_dt_1},
    {"vsph_integrate_dt_rule", call_vsph_integrate_dt_rule_0},
    {"vsph_integrate_dt_rule", call_vsph_integrate_dt_rule_1},
    {"vsph_integrate_step", call_vsph_integrate_step_0},
    {"vsph_integrate_step", call_vsph_integrate_step_1},
    {"vsph_integrate_check", call_vsph_integrate_check_0},
    {"vsph_integrate_check", call_vsph_integrate_check_1},
    {"vsph_integrate_diagnostics", call_vsph_integrate_diagnostics_0},
    {"vsph_integrate_diagnostics", call_vsph_integrate_diagnostics_1},
    {"vsph_integrate_pack", call_vsph_integrate_pack_0},
    {"vsph_integrate_pack", call_vsph_integrate_pack_1},
    {"vsph_integrate_wall_count", call_vsph_integrate_wall_count_0},
    {"vsph_integrate_wall_count", call_vsph_integrate_wall_count_1},
    {"vsph_integrate_pack_lean", call_vsph_integrate_pack_lean_0},
    {"vsph_integrate_pack_lean", call_vsph_integrate_pack_lean_1},
    {"vsph_integrate_pack_lean_file", call_vsph_integrate_pack_lean_file_0},
    {"vsph_integrate_pack_lean_file", call_vsph_integrate_pack_lean_file_1},
    {"vsph_integrate_restore_file", call_vsph_integrate_restore_file_0},
    {"vsph_integrate_restore_file", call_vsph_integrate_restore_file_1},
    {"vsph_integrate_unpack", call_vsph_integrate_unpack_0},
    {"vsph_integrate_unpack", call_vsph_integrate_unpack_1},
    {"vsph_integrate_restore", call_vsph_integrate_restore_0},
    {"vsph_integrate_restore", call_vsph_integrate_restore_1},
    {"vsph_integrate_bytes", call_vsph_integrate_bytes_0},
    {"vsph_integrate_bytes", call_vsph_integrate_bytes_1},
    {"vsph_integrate_bytes_estimate", call_vsph_integrate_bytes_estimate_0},
    {"vsph_integrate_bytes_estimate", call_vsph_integrate_bytes_estimate_1},
    {"vsph_materials_drag_row", call_vsph_materials_drag_row_0},
    {"vsph_materials_drag_row", call_vsph_materials_drag_row_1},
    {"vsph_materials_drag_square", call_vsph_materials_drag_square_0},
    {"vsph_materials_drag_square", call_vsph_materials_drag_square_1},
    {"vsph_materials_count", call_vsph_materials_count_0},
    {"vsph_materials_count", call_vsph_materials_count_1},
    {"vsph_materials_get", call_vsph_materials_get_0},
    {"vsph_materials_get", call_vsph_materials_get_1},
    {"vsph_materials_resolve", call_vsph_materials_resolve_0},
    {"vsph_materials_resolve", call_vsph_materials_resolve_1},
    {"vsph_diagnostics_surface_threshold",
     call_vsph_diagnostics_surface_threshold_0},
    {"vsph_diagnostics_surface_threshold",
     call_vsph_diagnostics_surface_threshold_1},
    {"vsph_diagnostics_compute", call_vsph_diagnostics_compute_0},
    {"vsph_diagnostics_compute", call_vsph_diagnostics_compute_1},
    {"vsph_diagnostics_compute_cells", call_vsph_diagnostics_compute_cells_0},
    {"vsph_diagnostics_compute_cells", call_vsph_diagnostics_compute_cells_1},
    {"vsph_diagnostics_probe", call_vsph_diagnostics_probe_0},
    {"vsph_diagnostics_probe", call_vsph_diagnostics_probe_1},
    {"vsph_diagnostics_free", call_vsph_diagnostics_free_0},
    {"vsph_diagnostics_free", call_vsph_diagnostics_free_1},
    {"vsph_sysinfo_load", call_vsph_sysinfo_load_0},
    {"vsph_sysinfo_load", call_vsph_sysinfo_load_1},
    {"vsph_sysinfo_cpu_s", call_vsph_sysinfo_cpu_s_0},
    {"vsph_sysinfo_cpu_s", call_vsph_sysinfo_cpu_s_1},
    {"vsph_sysinfo_thread_cpu_s", call_vsph_sysinfo_thread_cpu_s_0},
    {"vsph_sysinfo_thread_cpu_s", call_vsph_sysinfo_thread_cpu_s_1},
    {"vsph_sysinfo_wait_policy", call_vsph_sysinfo_wait_policy_0},
    {"vsph_sysinfo_wait_policy", call_vsph_sysinfo_wait_policy_1},
    {"vsph_sysinfo_build_isa", call_vsph_sysinfo_build_isa_0},
    {"vsph_sysinfo_build_isa", call_vsph_sysinfo_build_isa_1},
    {"vsph_sysinfo_peak_rss", call_vsph_sysinfo_peak_rss_0},
    {"vsph_sysinfo_peak_rss", call_vsph_sysinfo_peak_rss_1},
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

/* The public headers as the Makefile's PUB_HDR lists them (the one list:
 * make install installs it, make doc documents it), common/api.h (the
 * marker itself) left out, into @p hdr (at most @p max). */
static size_t public_headers(char hdr[][64], size_t max) {
  FILE *f = fopen("Makefile", "r"); /* the tests run in the source tree */
  ck_assert_msg(f != NULL, "Makefile");
  char line[512];
  size_t n = 0;
  for (int in = 0; fgets(line, sizeof line, f);) {
    char *s = line;
    if (!in) {
      if (strncmp(line, "PUB_HDR", 7) || !(s = strchr(line, '='))) continue;
      s++;
    }
    in = strchr(s, '\\') != NULL; /* continued on the next line */
    for (char *w = strtok(s, " \t\n\\"); w; w = strtok(NULL, " \t\n\\"))
      if (n < max && strcmp(w, "common/api.h")) snprintf(hdr[n++], 64, "%s", w);
    if (!in) break;
  }
  fclose(f);
  return n;
}

/* Every function a public header (PUB_HDR) marks VSPH_API has its calls
 * above, so a header made public, or a function added to one, without its
 * calls here fails. Four are left out by name: vsph_status_report
 * (variadic), vsph_status_set_handler (it sets the process's handler),
 * the candidate tests vsph_pair_x86_candidates_avx512 and _avx2, which
 * the inline gather calls on its own iterator only where
 * vsph_pair_x86_simd allows them (on a CPU without AVX-512 the first
 * stops at its first instruction whatever its arguments), and the joint
 * walks vsph_pair_x86_upper_cell_avx512 and _avx2, which
 * vsph_pair_cell_begin calls on the same condition (the sweep tests of
 * tests/check_pair.c compare their chunks with the portable walk's). */
START_TEST(test_every_entry_called) {
  char HDR[64][64];
  const size_t nhdr = public_headers(HDR, 64);
  ck_assert_uint_ge(nhdr, 30); /* the Makefile read */
  size_t n = 0;
  for (size_t h = 0; h < nhdr; h++) {
    FILE *f = fopen(HDR[h], "r"); /* the tests run in the source tree */
    ck_assert_msg(f != NULL, "%s", HDR[h]);
    char text[1 << 16];
    const size_t len = fread(text, 1, sizeof text - 1, f);
    fclose(f);
    ck_assert_msg(len < sizeof text - 1, "%s: longer than %zu bytes", HDR[h],
                  sizeof text - 1);
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
          !strcmp(name, "vsph_status_set_handler") ||
          !strncmp(name, "vsph_pair_x86_candidates_", 25) ||
          !strncmp(name, "vsph_pair_x86_upper_cell_", 25))
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
