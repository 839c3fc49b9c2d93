#ifndef VSPH_IO_VTK_H
#define VSPH_IO_VTK_H

#include <stddef.h>
#include <stdio.h>

struct vsph_particles;

/** @file vtk.h
 *  @brief Particle snapshots for ParaView and VisIt: legacy VTK POLYDATA
 *  files (points, velocity, density, pressure, id), and the PVD collection
 *  that lists them with their times. */

/** @brief Snapshot of the particles with id < @p n_fluid, in id order, at
 *  time @p t, written atomically to DIR/NAME. @return VSPH_OK, VSPH_ENOMEM
 *  or VSPH_EIO. */
int vsph_vtk_write(const char *dir, const char *name,
                   const struct vsph_particles *p, size_t n_fluid, double t);

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
