/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
#ifndef VSPH_RUNS_ARCHIVE_H
#define VSPH_RUNS_ARCHIVE_H

#include <stddef.h>
#include <stdio.h>

/** @file archive.h
 *  @brief An archive of finished runs, compact enough to keep in a
 *  repository (reports/full/ holds the FULL report's): of each sealed run
 *  of a report's runs/ folder, what the report's parts read (energy.csv,
 *  run.json, used_parameters.yml, the profile and centreline tables, a
 *  shear test's summary and profiles), never its checkpoint, and of its
 *  snapshots only the frames a report's pictures and profiles read
 *  (vsph_archive_store_frames), rounded and compressed.
 *
 *  Each entry ARCHIVE/runs/NAME is itself a folder of its run's kind
 *  (runs/folder), sealed under the run's own key: the version and source
 *  hash that made it, then its settings, then each file it holds with its
 *  size and CRC-32. So an entry says what made it and proves its files,
 *  whatever the sources are today. ARCHIVE/index.tsv lists the entries:
 *  name, kind, status, version, source hash, the commit (when known),
 *  a fingerprint of the settings, wall time, steps and particles.
 *
 *  Storing is idempotent: an entry whose seal already holds for its run's
 *  key is kept untouched; one of another key (the run was redone) is
 *  replaced, unless the run began before the one the entry keeps
 *  (run.json's date), which stays. A run folder whose seal does not hold
 *  (unfinished, stopped at a checkpoint, damaged) is left out and said,
 *  and so is an older run. */

/** What one vsph_archive_store did. */
struct vsph_archive_counts {
  size_t stored;  /*!< entries written (new, or replacing another key's) */
  size_t kept;    /*!< entries already there under the same key */
  size_t skipped; /*!< run folders left out: not sealed */
};

/** Mantissa bits an archive's frames keep (vsph_vtk_write_frame): a
 *  relative error of at most 2^-11 = 4.9e-4 (beyond single precision's),
 *  so a position within 2^-12 m below 1 m, 0.08 of a particle spacing at
 *  the stretching square's L/dx = 320 (0.16 from 1 to 2 m), and a value
 *  within an eighth of a picture's colour level (256 over a scale that
 *  spans zero); at 10 bits the FULL report's 23 frames come to about 9 MB
 *  (docs/usage.md, the FULL archive). */
#define VSPH_ARCHIVE_FRAME_BITS 10

/** The snapshots a run archive keeps of some runs, as frames
 *  (vsph_vtk_write_frame): what a report's parts read from them. */
struct vsph_archive_frames {
  size_t n;                /*!< runs with frames ... */
  const char *const *name; /*!< ... each run's folder name ... */
  const unsigned *want;    /*!< ... and its VSPH_JOBS_FRAME_* (runs/jobs.h):
                                the first snapshot's or the last's pressure,
                                vorticity and free-surface flag, every
                                snapshot's velocities */
  int bits;                /*!< mantissa bits (VSPH_ARCHIVE_FRAME_BITS) */
};

/** @brief vsph_archive_store, keeping of the runs @p frames names (NULL:
 *  none) the snapshots and fields it asks for as frames, snap_NNNN.vtp in
 *  the entry (its seal lists them). An entry already there under the same
 *  key but without them is stored again. */
int vsph_archive_store_frames(const char *report, const char *archive,
                              const char *commit,
                              const struct vsph_archive_frames *frames,
                              FILE *progress,
                              struct vsph_archive_counts *counts);

/** @brief Store the sealed runs of report folder @p report (its runs/
 *  sub-folder) in archive @p archive (made if new; refused, untouched,
 *  when it is not empty and not a vsph run archive), then write its
 *  index.tsv. The commit column holds @p commit (may be NULL) for entries
 *  made by this build's sources (their source hash is this build's), else
 *  "unknown". A line per run left out goes to @p progress (may be NULL).
 *  @return VSPH_OK; VSPH_EINVAL (a folder refused, one line reported);
 *  VSPH_EIO; VSPH_ENOMEM. */
int vsph_archive_store(const char *report, const char *archive,
                       const char *commit, FILE *progress,
                       struct vsph_archive_counts *counts);

/** The baseline's tolerance (tests/check_baseline.c holds the code to
 *  it, the archive judges by it): a figure of reports/baseline.csv agrees
 *  when within REL of the other, relative, plus ABS. */
#define VSPH_ARCHIVE_BASELINE_REL 1e-6
#define VSPH_ARCHIVE_BASELINE_ABS 1e-9

/** The largest history or baseline file vsph_archive_summarise reads
 *  (bytes): 80 commits' baseline.csv is a few kB each. */
#define VSPH_ARCHIVE_READ_MAX (16L << 20)

/** What vsph_archive_summarise judges the entries against. */
struct vsph_archive_judge {
  const char *history;  /*!< scripts/source-commits' folder (commits.tsv:
                             source hash and commit of recent commits;
                             COMMIT.csv: reports/baseline.csv then), or NULL */
  const char *baseline; /*!< the current reports/baseline.csv, or NULL */
  const char *commit;   /*!< this build's commit (make archive), or NULL */
  size_t nplan;         /*!< runs of the current FULL plan ... */
  const char *const *plan_name; /*!< ... each run's folder name ... */
  const char *const *plan_key;  /*!< ... and its key (key.txt's first part) */
};

/** @brief Write @p archive's entries.md: each entry (scene, formulation,
 *  resolution, particles, time reached, status, steps, wall time, what
 *  made it) and whether it still stands for the current code, by the
 *  rule: (1) the current FULL plan asks for a run of its name with its
 *  settings, and (2) its scene's rows of reports/baseline.csv are the same
 *  now as at the commit that made it (the rows tests/check_baseline.c
 *  holds to the code at 1e-6: a change to a scene's numerics changes
 *  them). An entry whose commit or rows then are not known is said to be
 *  unjudged, with why. @return VSPH_OK, VSPH_EINVAL (not an archive),
 *  VSPH_EIO, VSPH_ENOMEM. */
int vsph_archive_summarise(const char *archive,
                           const struct vsph_archive_judge *jd);

/** What vsph_archive_standing says of one run of the plan. */
enum vsph_archive_verdict {
  VSPH_ARCHIVE_ABSENT = -2,   /*!< no whole entry of its name (none, or
                                   one whose seal does not hold) */
  VSPH_ARCHIVE_UNJUDGED = -1, /*!< whole, but its commit's baseline rows
                                   are not known (no history) */
  VSPH_ARCHIVE_STALE = 0,     /*!< whole, and it does not stand */
  VSPH_ARCHIVE_STANDS = 1     /*!< whole, and it stands */
};

/** @brief Entry @p name of @p archive, when it is whole (its seal
 *  holds): its folder into @p dir (@p len bytes) and the key it is sealed
 *  under (key.txt before "files:", the run's own) into *@p key (caller
 *  frees). Reads only. @return 1; 0 when there is no whole entry of that
 *  name (*@p key NULL; not reported). */
int vsph_archive_entry(const char *archive, const char *name, char *dir,
                       size_t len, char **key);

/** @brief Why entry @p name of @p archive is not whole, where it is
 *  there but its seal is broken (a file missing, changed or added) into
 *  @p why (@p len bytes). Reads only. @return 1 (damaged: @p why names
 *  the file); 0 (no such entry, or it is whole). */
int vsph_archive_entry_damage(const char *archive, const char *name, char *why,
                              size_t len);

/** @brief Write @p text as @p archive's summary.md (the FULL report's
 *  claims and convergence tables, from its assembly from the archive),
 *  under the archive's claim, after judging it an archive. @return
 *  VSPH_OK; VSPH_EINVAL (not an archive); VSPH_EIO. */
int vsph_archive_write_summary(const char *archive, const char *text);

/** @brief Whether @p archive is a run archive vsph wrote (its top, and
 *  each entry of its runs/ a folder of a run's kind with nothing else in
 *  it), reading only. @return VSPH_OK; VSPH_EINVAL (one line said). */
int vsph_archive_check(const char *archive);

/** @brief Which runs of the FULL plan in @p jd stand in @p archive, by
 *  the rule of vsph_archive_summarise: @p stands[k] (jd->nplan of them)
 *  is the vsph_archive_verdict of entry plan_name[k]. Reads only; an
 *  archive that does not exist holds nothing. @return VSPH_OK;
 *  VSPH_EINVAL (@p archive is not a run archive). */
int vsph_archive_standing(const char *archive,
                          const struct vsph_archive_judge *jd, int *stands);

#endif /* VSPH_RUNS_ARCHIVE_H */
