/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
#ifndef VSPH_SOLVER_SCENE_H
#define VSPH_SOLVER_SCENE_H

#include <stddef.h>

#include "../common/api.h"
#include "../common/params.h"
#include "equations.h"
#include "walls.h"

struct vsph_particles;
struct vsph_params;
struct vsph_params_spec;

/** @file scene.h
 *  @brief Scenes as runtime descriptors (THEORY.md section 6). A scene
 *  declares its geometry, body force, walls, initial state and reference
 *  length; nothing it does not declare is computed. Each scene's parameters
 *  live in the "Scene" section, in a typed struct of its own, with defaults
 *  and bounds in its parameter table (solver/scenes/). No I/O. */

/** Vortex patch (THEORY 6.1): given values, then derived ones. */
struct vsph_scene_vortex {
  double R;      /*!< patch radius (m) */
  double l2;     /*!< profile parameter l^2 (m^2) */
  double a;      /*!< weight of the l^2 profile over a rigid rotation,
                      1 - a [reconstructed] (THEORY 6.1) */
  double omega0; /*!< angular velocity at the centre (rad/s) */
  double beta;   /*!< radial body force -beta^2 r (1/s) */
  double nu;     /*!< kinematic viscosity (m^2/s) */
  double rho0;   /*!< reference density */
  double c0;     /*!< sound speed (m/s); 0: THEORY 5's rule */
  double t_end;  /*!< default end time (s) */
  char layout[VSPH_PARAMS_NAME_MAX]; /*!< rings, cartesian [reconstructed] */
};

/** Stretching square (THEORY 6.2). */
struct vsph_scene_square {
  double L;            /*!< side (m) */
  double A0;           /*!< strain rate (1/s) */
  double nu;           /*!< kinematic viscosity (m^2/s) */
  double rho0;         /*!< reference density */
  double c0;           /*!< sound speed (m/s); 0: THEORY 5's rule */
  double t_end;        /*!< default end time (s) */
  size_t poisson_grid; /*!< interior nodes per side; 0: 4 res */
  size_t pressure;     /*!< initial pressure: 1 the Poisson solution, 0 zero */
};

/** Standing wave (THEORY 6.3): given values, then derived ones. */
struct vsph_scene_wave {
  double lambda; /*!< wavelength (m) */
  double eps;    /*!< steepness 2A/lambda [reconstructed] */
  double Re;     /*!< Reynolds number lambda U_max/nu */
  double g;      /*!< gravity (m/s^2) */
  double rho0;   /*!< reference density */
  double c0;     /*!< sound speed (m/s); 0: THEORY 5's rule */
  double t_end;  /*!< default end time (s) */
  /* derived by the scene's setup */
  double L;     /*!< tank width lambda/2 = depth H (m) */
  double k;     /*!< wavenumber 2 pi/lambda (1/m) */
  double omega; /*!< angular frequency, omega^2 = g k tanh(kH) (1/s) */
  double A;     /*!< amplitude eps lambda/2 (m) */
  double nu;    /*!< kinematic viscosity lambda U_max/Re (m^2/s) */
};

/** Channel start-up (Poiseuille or Couette; docs/theory.md, section 9):
 *  walls y = 0 and y = W, periodic in x over `length`, from rest. */
struct vsph_scene_channel {
  double W;      /*!< width between the walls (m) */
  double length; /*!< periodic length along x (m) */
  double Re;     /*!< Poiseuille: U0 (W/2)/nu; Couette: v0 W/nu */
  double nu;     /*!< kinematic viscosity (m^2/s) */
  double rho0;   /*!< reference density */
  double c0;     /*!< sound speed (m/s); 0: THEORY 5's rule */
  double t_end;  /*!< default end time (s) */
  char walls[VSPH_PARAMS_NAME_MAX]; /*!< wall velocity: linear, mirror */
  /* derived by the scene's setup */
  double U;    /*!< Poiseuille: steady centreline speed U0; Couette: v0 */
  double f;    /*!< Poiseuille: drive 2 nu U0/(W/2)^2 (m/s^2); Couette: 0 */
  int couette; /*!< 1: Couette (top wall at v0), 0: Poiseuille */
};

/** Lid-driven cavity (docs/theory.md, section 9): the unit square, the
 *  lid y = L sliding at U from rest. */
struct vsph_scene_cavity {
  double L;     /*!< side (m) */
  double U;     /*!< lid speed (m/s) */
  double Re;    /*!< U L/nu */
  double rho0;  /*!< reference density */
  double c0;    /*!< sound speed (m/s); 0: THEORY 5's rule (10 U) */
  double t_end; /*!< default end time (s) */
  char walls[VSPH_PARAMS_NAME_MAX]; /*!< wall particles: adami, evolving */
  /* derived by the scene's setup */
  double nu; /*!< kinematic viscosity U L/Re (m^2/s) */
};

/** Shear layer (Parshikov et al.'s shear test, Parshikov et al. sections 3 and
 * 5; docs/theory.md section 12): a 3-D periodic box, u_y = +U0 for x > 0 and
 * -U0 for x < 0. The period along x is twice the paper's box, W: its slip walls
 * at x = +-W/2 are then planes of symmetry, so the box is the paper's and its
 * mirror image, with no wall code. */
struct vsph_scene_shear {
  double W;       /*!< the paper's box along x, half the period (m) */
  double Ly;      /*!< period along y (m) */
  double Lz;      /*!< period along z (m) */
  double U0;      /*!< initial speed of each half (m/s) */
  double t_end;   /*!< default end time (s) */
  size_t viscous; /*!< 1: the materials' physical viscosity; 0: none */
  char material[VSPH_PARAMS_NAME_MAX]; /*!< x > 0 (Table 1) */
  char left[VSPH_PARAMS_NAME_MAX];     /*!< x < 0: "same" or a material */
};

/** Stokes flow through a periodic array of cylinders (Parshikov et al.
 * section 5.5; docs/theory.md section 12): 2-D, one cylinder of diameter d in
 * the periodic square of side S, a held body of contact SPH particles, the
 * fluid driven by a uniform force along x. */
struct vsph_scene_cylinders {
  double d;     /*!< cylinder diameter (m) */
  double dS;    /*!< d/S */
  double Re;    /*!< rho U d/eta at the drive's Stokes velocity */
  double t_end; /*!< default end time (s) */
  char material[VSPH_PARAMS_NAME_MAX]; /*!< the fluid (Table 1) */
  /* derived by the scene's setup */
  double S;   /*!< period (m) */
  double U;   /*!< superficial velocity the drive gives in Stokes flow with
                   the physical viscosity, by eq. (39) (m/s) */
  double f;   /*!< the drive (m/s^2) */
  double eta; /*!< the fluid's viscosity (Pa s) */
};

struct vsph_scene;

/** Scene descriptor. */
struct vsph_scene_type {
  const char *name;        /*!< as on the command line */
  const char *description; /*!< one line */
  const char *length_name; /*!< what --res counts across (R, L or H) */
  double area;             /*!< fluid area over ref_length^2: --res N lays about
                                area N^2 particles (memory estimate) */
  const struct vsph_params_spec *params; /*!< the "Scene" section: offsets
                                              into the scene's typed struct */
  size_t nparams;                        /*!< its length */
  /** The scene's own default Courant number of RK4 (Solver:cfl; 0: the
   *  table's, 1): the largest CFL the report's time-step study finds fine
   *  for accuracy on this scene and no less stable than CFL 1
   *  (docs/theory.md section 5). It applies to the study's runs alone: the
   *  WCSPH scheme with RK4 and the rule's step (not where Solver:scheme,
   *  tvf, integrator or dt is given as another). */
  double cfl;
  /** Derive the scene from its typed parameters (VSPH_OK or VSPH_EINVAL). */
  int (*setup)(struct vsph_scene *sc);
  /** Lay out the fluid: @p res particles across the reference length. */
  int (*init)(const struct vsph_scene *sc, size_t res,
              struct vsph_particles **out);
  /** The initial velocity at @p x (its first two components in 2-D), for
   *  a scene whose initial pressure and density are those of the fluid at
   *  rest (the standing wave: a flat surface, hydrostatic), so that a
   *  relaxed start (Solver:relax) can let the particles settle at rest
   *  first and then give them this velocity where they settled. NULL: the
   *  scene cannot start relaxed. */
  void (*rest_velocity)(const struct vsph_scene *sc, const double x[3],
                        double u[3]);
  /** "key=value" settings of the Solver section that this scene takes
   *  instead of the table's defaults, NULL-terminated (NULL: none); see
   *  vsph_scene_solver_defaults. */
  const char *const *solver_defaults;
};

/** A configured scene. */
struct vsph_scene {
  const struct vsph_scene_type *type; /*!< descriptor */
  int dim;                            /*!< dimension (2) */
  double ref_length;                  /*!< R, L or H (m) */
  double rho0;                        /*!< reference density */
  double c0;                          /*!< sound speed (m/s) */
  double mu;                          /*!< dynamic viscosity (Pa s) */
  double U_max;                       /*!< largest initial speed (m/s) */
  double dp_max;                      /*!< largest initial pressure range */
  double t_end;                       /*!< default end time (s) */
  double area;       /*!< fluid volume over ref_length^dim (type->area, or the
                          scene's own when its size is a parameter) */
  int body;          /*!< vsph_equations_body */
  double beta, g, f; /*!< body-force parameters */
  struct vsph_walls walls; /*!< walls (n = 0: none) */
  int nmat; /*!< materials of a contact run (0: one, rho0, c0 and mu);
                 with 2 the scene's init sets each particle's p->mat */
  struct vsph_equations_mat mat[VSPH_EQUATIONS_MAT_MAX]; /*!< rho0, c0,
                 mu of each (eta_num is the run's) */
  double box_lo[3], box_hi[3];                           /*!< escape box */
  /** The scene's own typed parameters: the member of its type. */
  union {
    struct vsph_scene_vortex vortex;   /*!< vortex-patch */
    struct vsph_scene_square square;   /*!< stretching-square */
    struct vsph_scene_wave wave;       /*!< standing-wave */
    struct vsph_scene_channel channel; /*!< poiseuille, couette */
    struct vsph_scene_cavity cavity;   /*!< cavity */
    struct vsph_scene_shear shear;     /*!< shear */
    struct vsph_scene_cylinders cyl;   /*!< cylinders */
  } u;
};

extern VSPH_API const struct vsph_scene_type vsph_vortex_patch_type;
extern VSPH_API const struct vsph_scene_type vsph_stretching_square_type;
extern VSPH_API const struct vsph_scene_type vsph_standing_wave_type;
extern VSPH_API const struct vsph_scene_type vsph_channel_poiseuille_type;
extern VSPH_API const struct vsph_scene_type vsph_channel_couette_type;
extern VSPH_API const struct vsph_scene_type vsph_cavity_type;
extern VSPH_API const struct vsph_scene_type vsph_shear_type;
extern VSPH_API const struct vsph_scene_type vsph_cylinders_type;

/** @brief 1 if @p type is a channel (Poiseuille or Couette: a velocity
 *  profile with a series reference), else 0. */
VSPH_API int vsph_scene_is_channel(const struct vsph_scene_type *type);

/** @brief 1 if runs of @p type write a velocity profile (profile.csv) and
 *  a velocity error: the channels (against their series) and the cavity
 *  (its vertical centreline, against Ghia et al.), else 0. */
VSPH_API int vsph_scene_has_profile(const struct vsph_scene_type *type);

/** @brief Number of scenes. */
VSPH_API size_t vsph_scene_count(void);

/** @brief Scene @p i of the table, or NULL. */
VSPH_API const struct vsph_scene_type *vsph_scene_get(size_t i);

/** @brief Scene called @p name, or NULL. */
VSPH_API const struct vsph_scene_type *vsph_scene_find(const char *name);

/** @brief Give @p prm the Solver settings of @p type's own defaults
 *  (type->solver_defaults: the scenes that need contact SPH, or whose
 *  paper ran it, run it by default): they apply unless Solver:visc is
 *  given (a visc asks for the WCSPH scheme) or Solver:scheme is given as
 *  another scheme than theirs, each only where its key is not given, and
 *  alpha (which sets h = 2 alpha dx) not where Solver:hdx is given.
 *  The scene's own Courant number (type->cfl) applies wherever
 *  Solver:cfl is not given, a visc included, unless Solver:scheme, tvf,
 *  integrator or dt asks for another scheme, integrator or a fixed step.
 *  Called on the parameters as given, before any is read (the cache key
 *  then holds them). @return VSPH_OK, VSPH_ENOMEM. */
VSPH_API int vsph_scene_solver_defaults(const struct vsph_scene_type *type,
                                        struct vsph_params *prm);

/** @brief The Solver defaults of @p type as one line ("scheme=contact
 *  kernel=wendland2 ..."; "" for none) into @p buf. */
VSPH_API void vsph_scene_solver_defaults_text(
    const struct vsph_scene_type *type, char *buf, size_t len);

/** @brief Read the scene's parameters ("Scene:<key>", defaults and bounds
 *  from its table; @p prm may be NULL for all defaults) into its typed
 *  struct and derive the scene. c0 = 0 means THEORY's rule
 *  c0 = 10 max(U_max, sqrt(dp_max / rho0)).
 *  @return VSPH_OK or VSPH_EINVAL. */
VSPH_API int vsph_scene_init(struct vsph_scene *sc,
                             const struct vsph_scene_type *type,
                             struct vsph_params *prm);

/** @brief Sound speed by THEORY section 5's rule, unless @p c0 (the scene's
 *  c0 parameter) is positive. */
VSPH_API double vsph_scene_sound_speed(const struct vsph_scene *sc, double c0);

struct vsph_integrate_props;
struct vsph_kernel_type;

/** @brief Physics, walls and escape box of a run of @p sc with viscous
 *  formulation @p form, kernel @p k and smoothing length @p h; leaves cfl,
 *  rho_band and min_dist at zero for the caller.
 *  @return VSPH_OK or VSPH_EINVAL. */
VSPH_API int vsph_scene_integrate_props(const struct vsph_scene *sc, int form,
                                        const struct vsph_kernel_type *k,
                                        double h,
                                        struct vsph_integrate_props *ip);

/** @brief Set particle i's density from pressure @p pr by the linear state
 *  equation, rho = rho0 + p/c0^2, and its mass m = rho V. */
VSPH_API void vsph_scene_set_pressure(const struct vsph_scene *sc,
                                      struct vsph_particles *p, size_t i,
                                      double pr);

/** @brief A 2-D rectangle of @p nx x @p ny particles at rest at
 *  ((i + 1/2) dx, (j + 1/2) dy), row by row, each of volume dx dy at
 *  pressure 0 (vsph_scene_set_pressure): the cavity's and the channels'
 *  initial set, none on a wall. @return VSPH_OK or VSPH_ENOMEM. */
VSPH_API int vsph_scene_rectangle(const struct vsph_scene *sc, size_t nx,
                                  size_t ny, double dx, double dy,
                                  struct vsph_particles **out);

/** @brief Standing wave's initial velocity u = grad phi0 at (x, y),
 *  phi0 = (A g/omega) cosh[k(y + H)]/cosh(kH) cos(kx) (THEORY 6.3). */
VSPH_API void vsph_standing_wave_velocity(const struct vsph_scene_wave *w,
                                          double x, double y, double u[2]);

/** @brief Vortex patch's initial angular velocity (THEORY 6.1,
 *  [reconstructed]): omega0 [1 - a + a l^2 (1/(l^2 + r^2) +
 *  r^2/(l^2 + R^2)^2)], so omega(0) = omega0 and d omega/dr (R) = 0 for
 *  any a. The one definition of the profile: the reference solution uses
 *  it too. */
VSPH_API double vsph_vortex_patch_omega(double omega0, double l2, double a,
                                        double R, double r);

/** The vortex patch's default a [reconstructed]: the one value that meets
 *  the paper's two stated figures of its own profile, Re = R u_theta(R,0)/nu
 *  = 256 and omega_inf = 0.2848 omega0, with equal and opposite relative
 *  errors (-0.27 % and +0.27 %; at l^2 = 0.1, R = 1, nu = 1e-3, no a meets
 *  both exactly: Re = 256 alone gives omega_inf 0.50 % high, omega_inf
 *  alone Re 0.59 % low). docs/theory.md section 6 derives it. */
#define VSPH_VORTEX_PATCH_A 0.90108

#endif /* VSPH_SOLVER_SCENE_H */
