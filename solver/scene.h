#ifndef VSPH_SOLVER_SCENE_H
#define VSPH_SOLVER_SCENE_H

#include <stddef.h>

#include "walls.h"

struct vsph_particles;
struct vsph_params;

/** @file scene.h
 *  @brief Scenes as runtime descriptors (THEORY.md section 6). A scene
 *  declares its geometry, body force, walls, initial state and reference
 *  length; nothing it does not declare is computed. Parameters live in the
 *  "Scene" section with the defaults of THEORY section 6. No I/O. */

/** Most parameters a scene has. */
#define VSPH_SCENE_MAXPARAMS 12

/** One scene parameter: "Scene:<key>", its default and meaning. */
struct vsph_scene_param {
  const char *key;  /*!< name under Scene: */
  double def;       /*!< default (THEORY section 6) */
  const char *help; /*!< meaning and unit */
};

struct vsph_scene;

/** Scene descriptor. */
struct vsph_scene_type {
  const char *name;        /*!< as on the command line */
  const char *description; /*!< one line */
  const char *length_name; /*!< what --res counts across (R, L or H) */
  const struct vsph_scene_param *params; /*!< parameter table */
  size_t nparams;                        /*!< its length */
  /** Derive the scene from sc->v (VSPH_OK or VSPH_EINVAL). */
  int (*setup)(struct vsph_scene *sc);
  /** Lay out the fluid: @p res particles across the reference length. */
  int (*init)(const struct vsph_scene *sc, size_t res,
              struct vsph_particles **out);
};

/** A configured scene. */
struct vsph_scene {
  const struct vsph_scene_type *type; /*!< descriptor */
  double v[VSPH_SCENE_MAXPARAMS];     /*!< parameter values, table order */
  int dim;                            /*!< dimension (2) */
  double ref_length;                  /*!< R, L or H (m) */
  double rho0;                        /*!< reference density */
  double c0;                          /*!< sound speed (m/s) */
  double mu;                          /*!< dynamic viscosity (Pa s) */
  double U_max;                       /*!< largest initial speed (m/s) */
  double dp_max;                      /*!< largest initial pressure range */
  double t_end;                       /*!< default end time (s) */
  int body;                           /*!< vsph_equations_body */
  double beta, g;                     /*!< body-force parameters */
  struct vsph_walls walls;            /*!< walls (n = 0: none) */
  double box_lo[3], box_hi[3];        /*!< escape box */
  double d[8]; /*!< scene-specific derived values (see each scene) */
};

extern const struct vsph_scene_type vsph_vortex_patch_type;
extern const struct vsph_scene_type vsph_stretching_square_type;
extern const struct vsph_scene_type vsph_standing_wave_type;

/** @brief Number of scenes. */
size_t vsph_scene_count(void);

/** @brief Scene @p i of the table, or NULL. */
const struct vsph_scene_type *vsph_scene_get(size_t i);

/** @brief Scene called @p name, or NULL. */
const struct vsph_scene_type *vsph_scene_find(const char *name);

/** @brief Read the scene's parameters ("Scene:<key>", defaults from the
 *  table) from @p prm and derive the scene. c0 = 0 means THEORY's rule
 *  c0 = 10 max(U_max, sqrt(dp_max / rho0)).
 *  @return VSPH_OK or VSPH_EINVAL. */
int vsph_scene_init(struct vsph_scene *sc, const struct vsph_scene_type *type,
                    struct vsph_params *prm);

/** @brief Sound speed by THEORY section 5's rule, unless the scene's c0
 *  parameter (index @p ic0) is positive. */
double vsph_scene_sound_speed(const struct vsph_scene *sc, size_t ic0);

struct vsph_integrate_props;
struct vsph_kernel_type;

/** @brief Physics, walls and escape box of a run of @p sc with viscous
 *  formulation @p form, kernel @p k and smoothing length @p h; leaves cfl,
 *  rho_band and min_dist at zero for the caller.
 *  @return VSPH_OK or VSPH_EINVAL. */
int vsph_scene_integrate_props(const struct vsph_scene *sc, int form,
                               const struct vsph_kernel_type *k, double h,
                               struct vsph_integrate_props *ip);

/** @brief Set particle i's density from pressure @p pr by the linear state
 *  equation, rho = rho0 + p/c0^2, and its mass m = rho V. */
void vsph_scene_set_pressure(const struct vsph_scene *sc,
                             struct vsph_particles *p, size_t i, double pr);

/** @brief Standing wave's initial velocity u = grad phi0 at (x, y),
 *  phi0 = (A g/omega) cosh[k(y + H)]/cosh(kH) cos(kx) (THEORY 6.3). */
void vsph_standing_wave_velocity(double A, double g, double k, double H,
                                 double omega, double x, double y, double u[2]);

/** @brief Vortex patch's initial angular velocity (THEORY 6.1,
 *  [reconstructed]): omega0 l^2 [1/(l^2 + r^2) + r^2/(l^2 + R^2)^2]. */
double vsph_vortex_patch_omega(double omega0, double l2, double R, double r);

#endif /* VSPH_SOLVER_SCENE_H */
