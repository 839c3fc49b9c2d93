#ifndef VSPH_IO_SHEAR_H
#define VSPH_IO_SHEAR_H

struct vsph_contact_shear;

/** @file shear.h
 *  @brief The shear test's results as CSV (analysis/contact): the
 *  profiles with both fits, and a summary that reads back (the report's
 *  cache). Texts are built in memory; the caller writes them with
 *  vsph_files_write (atomic). */

/** @brief The profiles: t, x, u, u_fit, dy, dy_fit per slab and profile
 *  time (the fits' exact solutions at the fitted nu). Caller frees; NULL
 *  after reporting on failure. */
char *vsph_shear_csv_profiles(const struct vsph_contact_shear *cs);

/** @brief One row per profile time: t, nu_u, rms_u, nu_dy, rms_dy, and
 *  the run's n, D0, W, U0, rho0, c0, t_end, steps, wall_s, stable,
 *  t_stop on every row. Caller frees; NULL after reporting on failure. */
char *vsph_shear_csv_summary(const struct vsph_contact_shear *cs);

/** @brief Read a summary back into @p cs (the scalars and fits; no
 *  profiles). @return VSPH_OK, or VSPH_EIO if it cannot be read or is
 *  not a summary (not reported: a missing cache is normal). */
int vsph_shear_csv_load(const char *path, struct vsph_contact_shear *cs);

#endif /* VSPH_IO_SHEAR_H */
