/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
#ifndef VSPH_RUNS_JOBS_H
#define VSPH_RUNS_JOBS_H

#include <signal.h>
#include <stddef.h>
#include <stdio.h>

struct vsph_csv;

/** @file jobs.h
 *  @brief Runs as jobs: the one interface through which a report asks for
 *  runs. Every part declares the runs it reads (a plan) before any is
 *  run; the missing ones are then run in this process, as child processes
 *  (--jobs N) or as a Slurm job array (vsph report submit), and read
 *  back through vsph_jobs_store_get, which checks each folder's seal
 *  (runs/folder). A job is one command (`vsph run ... --cache` or
 *  `vsph contact ... --cache`) whose folder ends sealed: the cache, and
 *  the proof that the run ended, whichever way ran it. A job stopped by
 *  a signal (or Slurm's time limit) leaves a checkpoint, and the next
 *  time resumes from it. */

/* What a job runs: the solver on a scene (`vsph run`), or the shear test
 * of section 12 (`vsph contact`). */
enum { VSPH_JOBS_RUN = 0, VSPH_JOBS_SHEAR };

/** @brief Add to @p prm, as given on a command line, the defaults the
 *  command of a job of @p kind adds on @p scene (RUN: the scene's own
 *  Solver defaults, vsph_scene_solver_defaults; SHEAR: the measurement's,
 *  vsph_contact_defaults; @p scene is then not read): the one place a
 *  scene's defaults are applied, by `vsph run`, `vsph contact` and a
 *  report's jobs alike, so that a run's key is the same whichever made it.
 *  @return VSPH_OK; VSPH_EINVAL (NULL @p prm, an unknown scene or kind);
 *  VSPH_ENOMEM. */
struct vsph_params;
int vsph_jobs_defaults(int kind, const char *scene, struct vsph_params *prm);

/* Settings a job holds at most. */
#define VSPH_JOBS_NSET 20

/* One run a report needs: the command that makes its folder, and what
 * the scheduler knows of it. */
struct vsph_jobs_job {
  int kind;                      /* VSPH_JOBS_RUN or VSPH_JOBS_SHEAR */
  char scene[32];                /* RUN: the scene */
  char dir[512];                 /* its output folder */
  char set[VSPH_JOBS_NSET][128]; /* "Section:key=value" */
  size_t nset, nprof;            /* SHEAR: profile times */
  char label[160];               /* as progress names it */
  char family[64]; /* "scene formulation" (or "shear test"): its rate */
  char *key;       /* its key.txt (owned) */
  double particles, steps, bytes; /* the solver's estimate */
  double neighbours;              /* of each particle, every pass */
  int cached;                     /* its key.txt matches */
  int archived;    /* a run archive holds it, standing: a budget skips it */
  int here;        /* a quick report makes it here, never reads it from a run
                      archive: a baseline row's run, or one whose snapshots a
                      part reads (vsph_jobs_plan_here) */
  unsigned frames; /* what parts read from its snapshots, which a run
                      archive keeps as frames: VSPH_JOBS_FRAME_* */
  int failed;      /* the pool: did not end */
  /* an assembly from a run archive: the entry its files are read from
   * when its own folder lacks it ("" otherwise), and the key that entry
   * is sealed under (the run's own, of the build that made it; owned) */
  char from[512];
  char *from_key;
};

/** The runs of a report (or of any caller that wants many runs): where
 *  they go, and, once planned, every run that will be read, listed before
 *  any is run. */
struct vsph_jobs {
  const char *dir; /*!< the runs go in DIR/runs/NAME */
  int full;        /*!< the report's fidelity, for the plan's title and
                        the Slurm assembly's command */
  const volatile sig_atomic_t *stop; /*!< stop request, or NULL */
  int planned;     /*!< 1: a sealed plan: only listed, cached runs are read;
                        0: a run is made when it is read (tests) */
  double after_s;  /*!< the work after the runs (a report's assembly), in
                        seconds: part of the time left they print */
  double budget_s; /*!< > 0: vsph_jobs_local_run and vsph_jobs_pool_run run only
                        the missing runs that fit this many seconds (the
                        caller's clock stops them through stop) */
  struct vsph_jobs_job *job; /*!< the plan */
  size_t n, cap;
};

/** A solver run a report needs. */
struct vsph_jobs_spec {
  const char *scene;        /* scene name */
  const char *visc;         /* formulation name */
  size_t res;               /* particles across */
  double t_end;             /* end time (s) */
  const char *const *extra; /* "Section:key=value" settings, NULL-ended */
  const char *tag;          /* folder suffix, or NULL */
};

/* One run's figures, from the cache or a fresh run. */
struct vsph_jobs_run {
  char dir[512];     /* its output folder */
  int ok;            /* 1: finished, 0: stopped as unstable */
  double t_unstable; /* when, if unstable */
  char reason[160];  /* why */
  double wall_s, pairs;
  double cpu_s, load; /* CPU time; 1-minute load average at its start */
  size_t n, steps, res;
  struct vsph_csv *energy; /* energy.csv */
  size_t nrow;             /* its rows; the columns: */
  const double *t, *Ek, *Pv, *res_b, *dEk, *Ekr, *dEkr;
  const double *Ep, *Ec, *Emr, *dEmr; /* energies; reference E_m, dE_m/dt */
};

/** @brief Drop every job of @p J's plan (the plan is then empty). */
void vsph_jobs_plan_free(struct vsph_jobs *J);

/* The job of a solver run: its folder, settings and key (runs/rundir's),
 * and whether the cache holds it. Free with vsph_jobs_free. */
int vsph_jobs_run(const struct vsph_jobs *J, const struct vsph_jobs_spec *rs,
                  struct vsph_jobs_job *j);

/* The job of a shear test: folder runs/contact-TAG, @p n settings. */
int vsph_jobs_shear(const struct vsph_jobs *J, const char *tag,
                    const char (*set)[96], size_t n, size_t nprof,
                    struct vsph_jobs_job *j);

void vsph_jobs_free(struct vsph_jobs_job *j);

/* Add @p j to J (which takes its key), once per folder; a second
 * job with the same folder and another key is a bug (two specs, one
 * folder). Estimates its cost. Without a plan, frees @p j. */
int vsph_jobs_plan_add(struct vsph_jobs *J, struct vsph_jobs_job *j);

/* The same for a solver run. */
int vsph_jobs_plan_run(struct vsph_jobs *J, const struct vsph_jobs_spec *rs);

/* The same, the run marked `here`: a quick report makes it itself even
 * where a run archive holds it standing (a baseline row's run, whose
 * figures the archive's rule is judged by; a run whose snapshots a part
 * reads, which the archive does not keep). Planned both ways, it is
 * `here`. */
int vsph_jobs_plan_here(struct vsph_jobs *J, const struct vsph_jobs_spec *rs);

/* What a report's parts read from a run's snapshots (the report's
 * pictures and profiles): a run archive keeps these as frames
 * (vsph_archive_store_frames). */
enum {
  VSPH_JOBS_FRAME_FIRST = 1u, /* the first snapshot's picture fields */
  VSPH_JOBS_FRAME_LAST = 2u,  /* the last snapshot's picture fields */
  VSPH_JOBS_FRAME_ALL = 4u    /* every snapshot's velocities */
};

/* The same as vsph_jobs_plan_here, the run's snapshots read as @p frames
 * says (VSPH_JOBS_FRAME_*; planned twice, the union). */
int vsph_jobs_plan_frames(struct vsph_jobs *J, const struct vsph_jobs_spec *rs,
                          unsigned frames);

/* Make sure the folder of @p j holds its run before a part reads it: with
 * a sealed plan, it must be listed and cached (else a failure naming it);
 * without a plan (the tests), it is run here if not cached. */
int vsph_jobs_ready(const struct vsph_jobs *J, const struct vsph_jobs_job *j);

/* The command of @p j as arguments (NULL-ended, pointing into @p j and
 * @p buf): @p exe, then run or contact, --out, --cache and the settings;
 * --quiet --threads T when @p threads > 0. */
size_t vsph_jobs_argv(const struct vsph_jobs_job *j, const char *exe,
                      size_t threads, char buf[2][24], const char **argv,
                      size_t cap);

/* The same as one shell line (arguments quoted where needed). */
void vsph_jobs_command(const struct vsph_jobs_job *j, const char *exe,
                       size_t threads, char *out, size_t len);

/* The plan as a table (tab-separated: status, folder, key fingerprint,
 * particles, steps, memory, command), those missing first. */
int vsph_jobs_plan_print(const struct vsph_jobs *J, const char *exe, FILE *f);

/* The missing runs of the plan in this process, @p width at a time (one
 * thread each; the report passes its thread count: two on 2 cores), the
 * costliest first. */
int vsph_jobs_local_run(struct vsph_jobs *J, int width);

/* One run as the estimate of the time left sees it. */
enum { VSPH_JOBS_ETA_WAITING = 0, VSPH_JOBS_ETA_RUNNING, VSPH_JOBS_ETA_DONE };
struct vsph_jobs_eta {
  double cost;        /* particles x neighbours x steps: DONE, the steps it took
                         (0: it failed and measures nothing); else the plan's */
  double wall;        /* DONE: its wall time; RUNNING: its time so far */
  int state;          /* VSPH_JOBS_ETA_* */
  const char *family; /* runs of one family share a rate */
  double per_step;    /* particles x neighbours: a step's pair interactions
                         (0: not known, its steps then weigh nothing) */
};

/* A step's work beyond its pair interactions (the neighbour search, the
 * integrator's sweeps, walls, diagnostics, output), in pair interactions:
 * fitted as wall/steps = c + r x (x: particles x neighbours) per family
 * over the quick report's runs on the project's 2-core machine, c/r is
 * 2.0-5.0e4 for the free-surface scenes' families (median 2.4e4) and
 * 1.7e3-3.8e4 for the channels'; 2e4 sits between the two groups (the
 * channels' runs are many and small). Replayed on six whole make-report
 * logs, the time left then stays within 0.80-1.28 of the truth from the
 * first tenth on (1e4: 0.71-1.21; 3e4: 0.87-1.33; 0.61-1.82 with a fixed
 * part per run from the family's last two runs); docs/usage.md. */
#define VSPH_JOBS_STEP_WORK 2.0e4

/* The wall time left of @p n runs, in the order they start, @p width at a
 * time. A run's work is its pair interactions and VSPH_JOBS_STEP_WORK for
 * each of its steps (cost / per_step of them), so that a small run's many
 * steps weigh what they cost; a run not done takes its family's rate, the
 * wall time of all its finished runs over their work, or, in a family with
 * none finished, all finished runs' rate. A running run's time so far is
 * taken off. The runs are laid on the @p width lanes in their order, each
 * on the lane free first. @return the seconds left, or -1 while no run
 * has finished (nothing to measure a rate by). */
double vsph_jobs_local_eta(const struct vsph_jobs_eta *r, size_t n,
                           size_t width);

/** @brief Which of @p m runs of wall times @p t (s, in the order they
 *  would start) fit a budget of @p budget seconds on @p lanes lanes: each
 *  laid on the lane free first, kept (@p keep[k] = 1) when it ends within
 *  the budget, or when it is longer than the whole budget and its lane is
 *  still empty (it goes on from its checkpoint in the next sitting).
 *  @return how many are kept. */
size_t vsph_jobs_local_fit(const double *t, size_t m, size_t lanes,
                           double budget, unsigned char *keep);

/* The same as child processes of @p exe, @p njobs at a time with
 * @p threads threads each; a run that fails is recorded (runs/failed.txt,
 * its log in runs/logs/) and the others go on. */
int vsph_jobs_pool_run(struct vsph_jobs *J, const char *exe, size_t njobs,
                       size_t threads);

/* Submit the missing runs as one Slurm job array and the assembly as a
 * job after it (afterany). */
struct vsph_jobs_slurm {
  const char *exe;       /* vsph, absolute */
  const char *partition; /* or NULL */
  const char *time;      /* Slurm's time limit, or NULL: estimated */
  size_t threads;        /* --cpus-per-task of each run */
  const char *only;      /* the report's --only, for the assembly, or NULL */
};
int vsph_jobs_slurm_submit(struct vsph_jobs *J,
                           const struct vsph_jobs_slurm *s);

/* The folder of a Slurm report, made if new, as an absolute path into
 * @p abs (the jobs run elsewhere); one that #SBATCH lines cannot carry
 * (a space, a quote, '%') is refused, and left unmade. */
int vsph_jobs_slurm_dir(const char *dir, char *abs, size_t len);

/** @brief A run's tables (run.json, energy.csv) from any folder @p dir
 *  that holds them (a run archive's entry): what vsph_jobs_store_get reads,
 *  without a plan. Free with vsph_jobs_store_run_free.
 *  @return VSPH_OK, or a failure naming the file. */
int vsph_jobs_store_load(const char *dir, struct vsph_jobs_run *out);

/** @brief A run of the plan read back (vsph_jobs_ready, then its seal,
 *  run.json and energy.csv).
 *  @return VSPH_OK, or a failure naming the run or the file. */
int vsph_jobs_store_get(const struct vsph_jobs *J,
                        const struct vsph_jobs_spec *rs,
                        struct vsph_jobs_run *out);

/** @brief Free what vsph_jobs_store_get read; idempotent. */
void vsph_jobs_store_run_free(struct vsph_jobs_run *r);

/** @brief Table @p name (e.g. "profile.csv", "summary.csv") of the sealed
 *  run in folder @p dir of the plan, read (io/csv) after its seal is
 *  checked. NULL after reporting when the run is not planned and sealed
 *  or the table cannot be read. */
struct vsph_csv *vsph_jobs_store_table(const struct vsph_jobs *J,
                                       const char *dir, const char *name);

/** @brief The path of file @p name of the sealed run in folder @p dir of
 *  the plan, for a reader of its own (a VTK snapshot), into @p path:
 *  VSPH_OK if the plan lists the run, its seal holds and lists the file;
 *  else a failure naming it. */
int vsph_jobs_store_file(const struct vsph_jobs *J, const char *dir,
                         const char *name, char *path, size_t len);

/** @brief The folder the files of planned run @p dir are read from: a
 *  run archive's entry when the assembly reads it from there, else
 *  @p dir itself. */
const char *vsph_jobs_where(const struct vsph_jobs *J, const char *dir);

/** @brief Whether the seal of the planned run in folder @p dir lists file
 *  @p name (1) or not (0), saying nothing: an archived run keeps no
 *  snapshots, and a part then leaves out what it draws from them. */
int vsph_jobs_store_holds(const struct vsph_jobs *J, const char *dir,
                          const char *name);

/** @brief The path of file @p name of planned run @p dir as a file of the
 *  report folder J->dir sees it (for a gnuplot script there):
 *  "runs/NAME/name", or the relative path to the run archive's entry the
 *  run is read from. */
void vsph_jobs_store_data_path(const struct vsph_jobs *J, const char *dir,
                               const char *name, char *buf, size_t len);

/** @brief The index of the last snapshot (snap_NNNN.vtp) under the seal
 *  of the planned run in folder @p dir: the end, or the stop of an
 *  unstable run; -1 (reported) if it has none. */
int vsph_jobs_store_last_snapshot(const struct vsph_jobs *J, const char *dir);

/** @brief Peak resident memory (bytes) of a whole `vsph run SCENE --visc
 *  VISC --res RES --t-end T_END` (its energy rows and snapshots as the
 *  run's defaults, 200 and 10) in a process of its own (this program
 *  started again through /proc/self/exe, so nothing of the caller's
 *  memory counts), as its run.json says, in a temporary folder removed
 *  after; 0 if it cannot be run. For vsph bench. */
double vsph_jobs_store_peak_rss(const char *scene, const char *visc, size_t res,
                                double t_end);

#endif /* VSPH_RUNS_JOBS_H */
