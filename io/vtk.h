/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
#ifndef VSPH_IO_VTK_H
#define VSPH_IO_VTK_H

#include <signal.h>
#include <stddef.h>
#include <stdio.h>

#include "../common/api.h"

struct vsph_particles;
struct vsph_diagnostics;

/** @file vtk.h
 *  @brief Particle snapshots for ParaView and VisIt: VTK XML PolyData
 *  files (.vtp) in the form ParaView writes itself (binary appended data,
 *  zlib-compressed in VTK's block layout, UInt64 headers), read back here
 *  for the report, and the PVD collection that lists them with their
 *  times, which ParaView opens as one time series. Every array is named
 *  and described, with its unit, in the file's own FieldData
 *  (array_descriptions). Only file formats: no numerics. A NULL argument
 *  is refused with VSPH_EINVAL (reported); vsph_vtk_snapshot_free of NULL
 *  does nothing. */

/** Block size of the compressed arrays (bytes before compression): VTK's
 *  default (vtkXMLWriter::BlockSize). */
#define VSPH_VTK_BLOCK 32768

/** Name prefix of a snapshot's scratch file in its folder, where the file
 *  system cannot make an unnamed one (common/scratch.h): a run's folder
 *  knows a stale one, left by a kill, as its own temporary. */
#define VSPH_VTK_SCRATCH ".vsph-vtk-"

/** @brief Snapshot of the particles with id < @p n_fluid, in id order, at
 *  time @p t (s), with the diagnostics @p dg (indexed by id; NULL: none),
 *  written atomically to DIR/NAME.
 *
 *  Points (m; 3 components, z = 0 in 2-D) as vertices; PointData:
 *  velocity (m/s, 3 components, u_z = 0 in 2-D), density (kg/m^d),
 *  pressure (Pa), volume m/rho (m^d), material (UInt8; two-material
 *  contact runs only), with @p dg the vorticity (1/s: in 2-D the scalar
 *  vorticity_z, signed; in 3-D the 3-vector vorticity; none in 1-D), div_r
 *  and free_surface (UInt8), and id (Int64). FieldData: TimeValue (the
 *  exact double @p t) and array_descriptions (one string per array:
 *  "name: what (unit)"). Every number is stored bitwise: a snapshot read
 *  back with vsph_vtk_read equals what was written, and the bytes of the
 *  file do not depend on the number of threads that compressed them.
 *  If @p stop is not NULL, *stop is checked before each compressed block
 *  (32 KiB): once it is set the file is abandoned before it is opened.
 *  @return VSPH_OK, VSPH_EINVAL (@p n_fluid above the set's particles
 *  or the diagnostics'), VSPH_EINTR (stopped through @p stop; nothing
 *  written), VSPH_ENOMEM, VSPH_ELIB (zlib failed) or VSPH_EIO. */
VSPH_API int vsph_vtk_write(const char *dir, const char *name,
                            const struct vsph_particles *p, size_t n_fluid,
                            double t, const struct vsph_diagnostics *dg,
                            const volatile sig_atomic_t *stop);

/** @brief vsph_vtk_write with @p where[id] the index in @p p of fluid
 *  particle id (an integrator's map, as an evaluation leaves it), checked
 *  first, in place of a particle order of its own (8 bytes a particle).
 *  The same file. @return as vsph_vtk_write, or VSPH_EINVAL (the map is
 *  not the particles'; nothing written). */
VSPH_API int vsph_vtk_write_mapped(const char *dir, const char *name,
                                   const struct vsph_particles *p,
                                   size_t n_fluid, const size_t *where,
                                   double t, const struct vsph_diagnostics *dg,
                                   const volatile sig_atomic_t *stop);

/** A snapshot read back (arrays of n tuples in id order, 3 components for
 *  vectors; an array the file lacks reads as zeros). */
struct vsph_vtk_snapshot {
  size_t n;       /*!< particles */
  double t;       /*!< time (s), the file's TimeValue */
  int vort_ncomp; /*!< the file's vorticity components: 1 (2-D
                       vorticity_z), 3 (3-D vorticity) or 0 (none) */
  double *pos;    /*!< positions (m), x y z per particle */
  double *vel;    /*!< velocities (m/s) */
  double *rho;    /*!< densities (kg/m^d) */
  double *p;      /*!< pressures (Pa) */
  double *vol;    /*!< volumes (m^d) */
  double *vort;   /*!< vorticity (1/s), x y z per particle; from a 2-D file
                       (0, 0, omega_z) */
  double *divr;   /*!< div r (dimensionless) */
  double *surf;   /*!< free-surface flag as 0 or 1 */
  double *mat;    /*!< material index (0 where the file has none) */
  int frame_bits; /*!< 0: a snapshot, every number as written; else a
                       frame (vsph_vtk_write_frame): its floats rounded to
                       this many mantissa bits, no density or volume */
  unsigned frame_fields; /*!< a frame's VSPH_VTK_FRAME_* (0: a snapshot,
                              which holds every field) */
};

/** A frame's fields beyond the positions and time (vsph_vtk_write_frame):
 *  the velocity (a profile's), and the pressure, 2-D vorticity and
 *  free-surface flag (a picture's). */
enum { VSPH_VTK_FRAME_VELOCITY = 1u, VSPH_VTK_FRAME_SCALARS = 2u };

/** @brief Read a snapshot written by vsph_vtk_write or a frame written by
 *  vsph_vtk_write_frame (binary appended, zlib-compressed VTK XML
 *  PolyData in this machine's byte order).
 *  @return VSPH_OK, VSPH_EIO (unreadable, not such a snapshot, e.g. one
 *  of an older ASCII vsph, or damaged; reported) or VSPH_ENOMEM. */
VSPH_API int vsph_vtk_read(const char *path, struct vsph_vtk_snapshot *s);

/** @brief Frame of snapshot @p s written atomically to DIR/NAME: what a
 *  picture or a profile reads, compact enough for a run archive. The
 *  positions, and the fields @p fields names (VSPH_VTK_FRAME_*: the
 *  velocity; the pressure, 2-D vorticity and free-surface flag), floats
 *  as Float32 rounded to nearest at @p bits mantissa bits (1-23: a
 *  relative error of at most 2^-(bits+1) beyond single precision's
 *  2^-24); TimeValue exact; FieldData frame_bits = @p bits and
 *  frame_fields = @p fields. No density, volume, div_r, material, id or
 *  vertex cells (ParaView shows its points with the Point Gaussian
 *  representation). vsph_vtk_read reads it back with frame_bits and
 *  frame_fields set, the fields it lacks as zeros.
 *  Float subnormals (below 1.2e-38 in magnitude) keep fewer bits.
 *  @return VSPH_OK, VSPH_EINVAL (@p bits or @p fields out of range, or
 *  @p s itself a frame), VSPH_ENOMEM, VSPH_ELIB or VSPH_EIO. */
VSPH_API int vsph_vtk_write_frame(const char *dir, const char *name,
                                  const struct vsph_vtk_snapshot *s, int bits,
                                  unsigned fields);

/** @brief Free the arrays of a snapshot read back. */
VSPH_API void vsph_vtk_snapshot_free(struct vsph_vtk_snapshot *s);

/** A PVD collection being written (DIR/snapshots.pvd). */
struct vsph_vtk_pvd {
  FILE *f;         /*!< the open index */
  const char *dir; /*!< its folder (borrowed) */
};

/** @brief Start DIR/snapshots.pvd. @return VSPH_OK or VSPH_EIO. */
VSPH_API int vsph_vtk_pvd_open(struct vsph_vtk_pvd *pvd, const char *dir);

/** @brief Go on with DIR/snapshots.pvd, cut back to its first @p keep
 *  bytes (a resumed run's: its entries up to a checkpoint).
 *  @return VSPH_OK or VSPH_EIO. */
VSPH_API int vsph_vtk_pvd_reopen(struct vsph_vtk_pvd *pvd, const char *dir,
                                 long keep);

/** @brief List snapshot @p file at time @p t (s), printed to 10
 *  significant digits as energy.csv prints its t, so the two match
 *  exactly (flushed: the index is usable while the run goes on).
 *  @return VSPH_OK or VSPH_EIO. */
VSPH_API int vsph_vtk_pvd_add(struct vsph_vtk_pvd *pvd, double t,
                              const char *file);

/** @brief vsph_vtk_pvd_add for part @p part of the time step (0 the fluid,
 *  1 its walls: ParaView reads the parts of one time as one multiblock).
 *  @return VSPH_OK, VSPH_EINVAL (another part, or a closed collection)
 *  or VSPH_EIO. */
VSPH_API int vsph_vtk_pvd_add_part(struct vsph_vtk_pvd *pvd, double t, int part,
                                   const char *file);

/** @brief The particles beyond the fluid (ids from @p n_fluid on) of
 *  @p p at time @p t as DIR/NAME, VTK XML PolyData like a snapshot, in id
 *  order: positions, velocity, density, pressure, id and `type` (1 a wall
 *  particle: ids below n_fluid + @p n_wall, the fixed walls and the
 *  cavity's lid; 2 an image of a fluid particle, a mirror ghost or a
 *  periodic image), mass and smoothing length (@p h, the fluid's), each
 *  described. @return VSPH_OK, VSPH_EINVAL (a NULL argument, @p h not
 *  positive), VSPH_ENOMEM, VSPH_EIO. */
VSPH_API int vsph_vtk_write_walls(const char *dir, const char *name,
                                  const struct vsph_particles *p,
                                  size_t n_fluid, size_t n_wall, double h,
                                  double t);

/** @brief Close the collection. @return VSPH_OK or VSPH_EIO. */
VSPH_API int vsph_vtk_pvd_close(struct vsph_vtk_pvd *pvd);

#endif /* VSPH_IO_VTK_H */
