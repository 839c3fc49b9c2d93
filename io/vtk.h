#ifndef VSPH_IO_VTK_H
#define VSPH_IO_VTK_H

#include <stddef.h>
#include <stdio.h>

struct vsph_particles;
struct vsph_diagnostics;

/** @file vtk.h
 *  @brief Particle snapshots for ParaView and VisIt: VTK XML PolyData
 *  files (.vtp: points as vertices; velocity, density, pressure, volume,
 *  the material index of a two-material contact run, and with
 *  diagnostics vorticity, div_r and the free_surface flag; id;
 *  the time as TimeValue field data), and the PVD collection that lists
 *  them with their times, which ParaView opens as one time series. */

/** @brief Snapshot of the particles with id < @p n_fluid, in id order, at
 *  time @p t, with the diagnostics @p dg (indexed by id; NULL: none),
 *  written atomically to DIR/NAME. @return VSPH_OK, VSPH_ENOMEM or
 *  VSPH_EIO. */
int vsph_vtk_write(const char *dir, const char *name,
                   const struct vsph_particles *p, size_t n_fluid, double t,
                   const struct vsph_diagnostics *dg);

/** A snapshot read back (arrays of n tuples, 3 components for vectors). */
struct vsph_vtk_snapshot {
  size_t n;     /*!< particles */
  double t;     /*!< time (s) */
  double *pos;  /*!< positions, x y z per particle */
  double *vel;  /*!< velocities */
  double *p;    /*!< pressures */
  double *vort; /*!< vorticity (0 if the file has none) */
  double *surf; /*!< free-surface flag as 0 or 1 (0 if none) */
};

/** @brief Read a snapshot written by vsph_vtk_write.
 *  @return VSPH_OK, VSPH_EIO (unreadable or not a vsph snapshot, reported)
 *  or VSPH_ENOMEM. */
int vsph_vtk_read(const char *path, struct vsph_vtk_snapshot *s);

/** @brief Free the arrays of a snapshot read back. */
void vsph_vtk_snapshot_free(struct vsph_vtk_snapshot *s);

/** A PVD collection being written (DIR/snapshots.pvd). */
struct vsph_vtk_pvd {
  FILE *f;         /*!< the open index */
  const char *dir; /*!< its folder (borrowed) */
};

/** @brief Start DIR/snapshots.pvd. @return VSPH_OK or VSPH_EIO. */
int vsph_vtk_pvd_open(struct vsph_vtk_pvd *pvd, const char *dir);

/** @brief List snapshot @p file at time @p t (flushed: the index is
 *  usable while the run goes on). @return VSPH_OK or VSPH_EIO. */
int vsph_vtk_pvd_add(struct vsph_vtk_pvd *pvd, double t, const char *file);

/** @brief Close the collection. @return VSPH_OK or VSPH_EIO. */
int vsph_vtk_pvd_close(struct vsph_vtk_pvd *pvd);

#endif /* VSPH_IO_VTK_H */
