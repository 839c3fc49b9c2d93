/* vsph run: the free-surface WCSPH solver on one scene (THEORY 5-6), with
 * energy bookkeeping, VTK snapshots and run metadata; vsph scenes. */
#include "cmd_run.h"

#include <math.h>
#include <omp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../analysis/references.h"
#include "../common/consts.h"
#include "../common/params.h"
#include "../common/status.h"
#include "../kernels/kernel.h"
#include "../solver/integrate.h"
#include "../solver/lattice.h"
#include "../solver/particles.h"
#include "../solver/scene.h"
#include "../solver/viscous.h"
#include "args.h"
#include "writers.h"

static const char *const CMD = "run";

/* The Solver section: key, default, meaning (one place for the defaults). */
struct solver_param {
  const char *key, *def, *help;
};
static const struct solver_param SOLVER[] = {
    {"visc", "mgf", "viscous formulation: mgf, meaf, pvwf"},
    {"kernel", "gaussian", "gaussian, cubic, quintic, wendland2, wendland4"},
    {"res", "40", "particles across the reference length (R, L or H)"},
    {"hdx", "1.3333333333333333", "h/dx"},
    {"t_end", "0", "end time (s); 0: the scene's"},
    {"cfl", "1", "Courant number of the RK4 time step"},
    {"delta", "0", "delta-SPH coefficient; 0: off (0.1 is usual)"},
    {"rho_band", "0.2", "stop as unstable when |rho/rho0 - 1| exceeds it"},
    {"min_gap", "0.05",
     "stop as unstable when two particles come closer "
     "than min_gap dx (pairing)"},
    {"outputs", "200", "energy rows over the run"},
    {"snapshots", "10", "VTK snapshots over the run; 0: none"},
    {"perturb", "0", "random shift of the initial lattice, fraction of dx"},
    {"seed", "2385", "seed of that shift (mt19937)"},
};
#define NSOLVER (sizeof SOLVER / sizeof SOLVER[0])

static void usage(FILE *f) {
  fputs(
      "usage: vsph run SCENE [--visc mgf|meaf|pvwf] [--kernel NAME] [--res N]\n"
      "                [--t-end T] [--cfl C] [--threads T] [--out DIR]\n"
      "                [--set Section:key=value ...] [--params FILE] "
      "[--quiet]\n"
      "\n"
      "Run the weakly compressible free-surface solver (classical RK4) on a\n"
      "scene (see vsph scenes). --res counts particles across the scene's\n"
      "reference length. Parameters come from FILE (YAML subset: Solver: and\n"
      "Scene: sections), then --set, then the options; an unknown key is an\n"
      "error. Writes to DIR (default runs/SCENE-VISC-RES):\n"
      "  energy.csv          t, Ek, Ep, Ec, P_visc, P_delta, residual, Px,\n"
      "                      Py, Lz, dEk_dt, Ek_ref, dEk_ref (one row per\n"
      "                      output, flushed as written)\n"
      "  snap_NNNN.vtk       particle snapshots (legacy VTK), snapshots.pvd\n"
      "  used_parameters.yml every parameter, defaults filled in\n"
      "  run.json            version, scene, visc, kernel, n_particles,\n"
      "                      steps, wall_s, pairs_per_s, status (ok or\n"
      "                      unstable), unstable_time, unstable_reason, ...\n"
      "A run that goes unstable stops cleanly, keeps its output and is marked\n"
      "unstable in run.json (exit status 0: stability is a result).\n",
      f);
}

static int write_used(struct vsph_params *prm, const char *dir) {
  FILE *f = vsph_writers_open(dir, "used_parameters.yml");
  if (!f) return VSPH_EIO;
  fprintf(f, "# vsph %s: every parameter of this run, defaults filled in\n",
          VSPH_VERSION);
  const char *sections[2] = {"Solver", "Scene"};
  for (int s = 0; s < 2; s++) {
    fprintf(f, "%s:\n", sections[s]);
    const size_t len = strlen(sections[s]);
    for (size_t i = 0; i < vsph_params_count(prm); i++) {
      const char *k, *v;
      int used;
      vsph_params_entry(prm, i, &k, &v, &used);
      if (!strncmp(k, sections[s], len) && k[len] == ':')
        fprintf(f, "  %s: %s\n", k + len + 1, v);
    }
  }
  return vsph_writers_close(f, dir, "used_parameters.yml");
}

struct run_info {
  const char *scene, *visc, *kernel, *status, *reason;
  size_t res, n, steps;
  double t_end, t, unstable_t, wall, pairs, h, dx, c0, bytes;
  int threads;
  size_t n_fallback;
};

static int write_run_json(const char *dir, const struct run_info *ri,
                          const struct vsph_scene *sc) {
  cJSON *o = cJSON_CreateObject();
  cJSON_AddStringToObject(o, "version", VSPH_VERSION);
  cJSON_AddStringToObject(o, "scene", ri->scene);
  cJSON_AddStringToObject(o, "visc", ri->visc);
  cJSON_AddStringToObject(o, "kernel", ri->kernel);
  cJSON_AddNumberToObject(o, "res", (double)ri->res);
  cJSON_AddNumberToObject(o, "n_particles", (double)ri->n);
  cJSON_AddNumberToObject(o, "h", ri->h);
  cJSON_AddNumberToObject(o, "dx", ri->dx);
  cJSON_AddNumberToObject(o, "c0", ri->c0);
  cJSON_AddNumberToObject(o, "mu", sc->mu);
  cJSON_AddNumberToObject(o, "U_max", sc->U_max);
  cJSON_AddNumberToObject(o, "t_end", ri->t_end);
  cJSON_AddNumberToObject(o, "t", ri->t);
  cJSON_AddNumberToObject(o, "steps", (double)ri->steps);
  cJSON_AddNumberToObject(o, "threads", ri->threads);
  cJSON_AddNumberToObject(o, "wall_s", ri->wall);
  vsph_writers_number(o, "pairs_per_s",
                      ri->wall > 0 ? ri->pairs / ri->wall : (double)NAN);
  vsph_writers_number(
      o, "particle_steps_per_s",
      ri->wall > 0 ? (double)ri->n * ri->steps / ri->wall : (double)NAN);
  cJSON_AddNumberToObject(o, "memory_bytes", ri->bytes);
  cJSON_AddNumberToObject(o, "pvwf_fallback_particles", (double)ri->n_fallback);
  cJSON_AddStringToObject(o, "status", ri->status);
  if (!strcmp(ri->status, "unstable")) {
    cJSON_AddNumberToObject(o, "unstable_time", ri->unstable_t);
    cJSON_AddStringToObject(o, "unstable_reason", ri->reason);
  }
  return vsph_writers_json_file(o, dir, "run.json");
}

int vsph_cmd_run_params(struct vsph_params *prm, const char *scene,
                        const char *out_dir, int quiet,
                        struct vsph_cmd_run_result *result) {
  int rc = 0;
  memset(result, 0, sizeof *result);
  const struct vsph_scene_type *type = vsph_scene_find(scene);
  if (!type)
    return vsph_args_fail(CMD, "unknown scene '%s' (see vsph scenes)", scene);
  /* Solver section, defaults in the SOLVER table. */
  const char *visc_name, *kernel_name;
  double val[NSOLVER];
  int st = VSPH_OK;
  for (size_t k = 0; k < NSOLVER && !st; k++) {
    char key[64];
    snprintf(key, sizeof key, "Solver:%s", SOLVER[k].key);
    if (k == 0)
      st = vsph_params_get_string_or(prm, key, SOLVER[k].def, &visc_name);
    else if (k == 1)
      st = vsph_params_get_string_or(prm, key, SOLVER[k].def, &kernel_name);
    else
      st = vsph_params_get_double_or(prm, key, atof(SOLVER[k].def), &val[k]);
  }
  if (st) {
    rc = vsph_args_status(CMD, st);
    return rc;
  }
  const double res_d = val[2], hdx = val[3], cfl = val[5], delta = val[6];
  const double band = val[7], min_gap = val[8];
  const double outputs = val[9], snapshots = val[10];
  const double perturb = val[11], seed = val[12];
  const int form = vsph_viscous_find(visc_name);
  const struct vsph_kernel_type *kernel = vsph_kernel_find(kernel_name);
  if (form < 0) {
    rc = vsph_args_fail(CMD, "unknown formulation '%s' (mgf, meaf, pvwf)",
                        visc_name);
  } else if (!kernel) {
    rc = vsph_args_fail(CMD, "unknown kernel '%s'", kernel_name);
  } else if (!(res_d >= 4 && res_d <= 4000 && res_d == floor(res_d))) {
    rc = vsph_args_fail(CMD, "res must be an integer in 4-4000, got %g", res_d);
  } else if (!(hdx > 0 && hdx <= 8)) {
    rc = vsph_args_fail(CMD, "hdx must lie in (0, 8], got %g", hdx);
  } else if (!(cfl > 0 && cfl <= 4)) {
    rc = vsph_args_fail(CMD, "cfl must lie in (0, 4], got %g", cfl);
  } else if (!(val[4] >= 0)) {
    rc = vsph_args_fail(CMD, "t_end must be >= 0, got %g", val[4]);
  } else if (!(delta >= 0 && delta <= 1)) {
    rc = vsph_args_fail(CMD, "delta must lie in [0, 1], got %g", delta);
  } else if (!(band > 0)) {
    rc = vsph_args_fail(CMD, "rho_band must be > 0, got %g", band);
  } else if (!(min_gap >= 0 && min_gap < 1)) {
    rc = vsph_args_fail(CMD, "min_gap must lie in [0, 1), got %g", min_gap);
  } else if (!(perturb >= 0 && perturb < 0.5) || !(seed >= 0)) {
    rc = vsph_args_fail(CMD, "perturb must lie in [0, 0.5) and seed >= 0");
  } else if (!(outputs >= 1 && outputs <= 1e6) || !(snapshots >= 0)) {
    rc = vsph_args_fail(CMD, "outputs must be >= 1 and snapshots >= 0");
  }
  if (rc) return rc;
  struct vsph_scene sc;
  if ((st = vsph_scene_init(&sc, type, prm))) {
    rc = vsph_args_status(CMD, st);
    return rc;
  }
  const char *unused = vsph_params_unused(prm);
  if (unused) {
    rc = vsph_args_fail(CMD, "unknown parameter '%s'", unused);
    return rc;
  }
  const size_t res = (size_t)res_d;
  const double t_end = val[4] > 0 ? val[4] : sc.t_end;
  char dirbuf[512];
  if (!out_dir) {
    snprintf(dirbuf, sizeof dirbuf, "runs/%s-%s-%zu", type->name, visc_name,
             res);
    out_dir = dirbuf;
  }

  /* Set up: particles, physics, integrator. */
  struct vsph_particles *fluid = NULL;
  if ((st = type->init(&sc, res, &fluid))) {
    rc = vsph_args_status(CMD, st);
    return rc;
  }
  const double dx = sc.ref_length / (double)res, h = hdx * dx;
  if (perturb > 0 &&
      (st = vsph_lattice_perturb(fluid, perturb * dx, (unsigned long)seed,
                                 (size_t)-1))) {
    vsph_particles_free(fluid);
    return vsph_args_status(CMD, st);
  }
  struct vsph_integrate_props ip;
  if ((st = vsph_scene_integrate_props(&sc, form, kernel, h, &ip))) {
    vsph_particles_free(fluid);
    rc = vsph_args_status(CMD, st);
    return rc;
  }
  ip.cfl = cfl;
  ip.rho_band = band;
  ip.min_dist = min_gap * dx;
  ip.eq.delta = delta;
  const size_t n = fluid->n;
  struct vsph_integrate *s = vsph_integrate_alloc(&ip, fluid);
  struct vsph_references_scene *ref = vsph_references_scene_alloc(&sc);
  if (!s || !ref) {
    vsph_integrate_free(s);
    vsph_references_scene_free(ref);
    rc = vsph_args_status(CMD, VSPH_ENOMEM);
    return rc;
  }
  /* Only now, with every input checked, write anything. */
  if (vsph_writers_mkdir(out_dir) || write_used(prm, out_dir)) {
    vsph_integrate_free(s);
    vsph_references_scene_free(ref);
    rc = vsph_args_status(CMD, VSPH_EIO);
    return rc;
  }
  char path[1024];
  snprintf(path, sizeof path, "%s/energy.csv", out_dir);
  FILE *csv = fopen(path, "w");
  snprintf(path, sizeof path, "%s/snapshots.pvd", out_dir);
  FILE *pvd = snapshots > 0 ? fopen(path, "w") : NULL;
  if (!csv || (snapshots > 0 && !pvd)) {
    if (csv) fclose(csv);
    vsph_integrate_free(s);
    vsph_references_scene_free(ref);
    rc = vsph_args_fail(CMD, "cannot write into %s", out_dir);
    return rc;
  }
  fprintf(csv,
          "t,Ek,Ep,Ec,P_visc,P_delta,residual,Px,Py,Lz,dEk_dt,Ek_ref,"
          "dEk_ref\n");
  if (pvd)
    fprintf(pvd,
            "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" "
            "version=\"0.1\">\n<Collection>\n");
  if (!quiet)
    fprintf(stderr,
            "vsph run: %s, %s, %s, %zu particles, h = %.4g, c0 = %.4g, "
            "t_end = %g -> %s\n",
            type->name, visc_name, kernel->name, n, h, sc.c0, t_end, out_dir);

  const double t0 = omp_get_wtime();
  double last_progress = t0, pairs = 0.0, unstable_t = 0.0;
  const double out_dt = t_end / outputs;
  const double snap_dt = snapshots > 0 ? t_end / snapshots : (double)INFINITY;
  double next_out = 0.0, next_snap = 0.0;
  size_t nsnap = 0;
  int unstable = 0;
  for (;;) {
    const int final = s->t >= t_end * (1.0 - 1e-12);
    if (s->t >= next_out * (1.0 - 1e-12) || final || unstable) {
      struct vsph_equations_energy en;
      struct vsph_equations_budget b;
      double Er, dEr;
      if (!unstable && (st = vsph_integrate_diagnostics(s, &en, &b))) break;
      if (!unstable) {
        vsph_references_scene_eval(ref, s->t, &Er, &dEr);
        fprintf(csv,
                "%.10g,%.12e,%.12e,%.12e,%.12e,%.12e,%.6e,%.6e,%.6e,%.12e,"
                "%.12e,%.12e,%.12e\n",
                s->t, en.Ek, en.Ep, en.Ec, b.P_visc, b.P_delta, b.residual,
                en.P[0], en.P[1], en.Lz, b.dEk, Er, dEr);
        fflush(csv);
      }
      while (next_out <= s->t * (1.0 + 1e-12)) next_out += out_dt;
    }
    if (pvd && (s->t >= next_snap * (1.0 - 1e-12) || final || unstable)) {
      char name[64];
      snprintf(name, sizeof name, "snap_%04zu.vtk", nsnap++);
      if ((st = vsph_writers_vtk(out_dir, name, s->p, s->n_fluid, s->t))) break;
      fprintf(pvd, "<DataSet timestep=\"%.10g\" file=\"%s\"/>\n", s->t, name);
      fflush(pvd);
      while (next_snap <= s->t * (1.0 + 1e-12)) next_snap += snap_dt;
    }
    if (final || unstable) break;
    double dt = vsph_integrate_dt(s);
    if (s->t + dt > t_end) dt = t_end - s->t;
    st = vsph_integrate_step(s, dt);
    pairs += (double)s->interactions;
    if (st || vsph_integrate_check(s)) {
      if (st) { /* the neighbour search refused the state */
        const char *m = vsph_args_last_error();
        snprintf(s->reason, sizeof s->reason, "%s",
                 m ? m : "neighbour search failed");
        st = VSPH_OK;
      }
      unstable = 1;
      unstable_t = s->t;
    }
    const double now = omp_get_wtime();
    if (!quiet && now - last_progress > 2.0) {
      last_progress = now;
      const double frac = s->t / t_end;
      fprintf(stderr,
              "vsph run: t = %.4g / %g (%.1f%%), step %zu, %.3g pairs/s, "
              "ETA %.0f s\n",
              s->t, t_end, 100 * frac, s->steps, pairs / (now - t0),
              (now - t0) * (1 - frac) / fmax(frac, 1e-9));
    }
  }
  const double wall = omp_get_wtime() - t0;
  fclose(csv);
  if (pvd) {
    fprintf(pvd, "</Collection>\n</VTKFile>\n");
    fclose(pvd);
  }
  struct run_info ri = {.scene = type->name,
                        .visc = visc_name,
                        .kernel = kernel->name,
                        .status = unstable ? "unstable" : "ok",
                        .reason = s->reason,
                        .res = res,
                        .n = n,
                        .steps = s->steps,
                        .t_end = t_end,
                        .t = s->t,
                        .unstable_t = unstable_t,
                        .wall = wall,
                        .pairs = pairs,
                        .h = h,
                        .dx = dx,
                        .c0 = sc.c0,
                        .bytes = (double)vsph_integrate_bytes(s),
                        .threads = omp_get_max_threads(),
                        .n_fallback = s->vws ? s->vws->n_fallback : 0};
  if (st || write_run_json(out_dir, &ri, &sc)) {
    rc = vsph_args_status(CMD, st ? st : VSPH_EIO);
  } else if (unstable && quiet < 2) {
    fprintf(stderr, "vsph run: unstable at t = %.6g: %s (output kept in %s)\n",
            unstable_t, s->reason, out_dir);
  } else if (!quiet) {
    fprintf(stderr, "vsph run: done, %zu steps in %.2f s (%.3g pairs/s)\n",
            s->steps, wall, pairs / wall);
  }
  result->unstable = unstable;
  result->unstable_time = unstable_t;
  snprintf(result->reason, sizeof result->reason, "%s", s->reason);
  result->n_particles = n;
  result->steps = s->steps;
  result->t = s->t;
  result->wall_s = wall;
  result->pairs = pairs;
  result->h = h;
  result->dx = dx;
  result->c0 = sc.c0;
  result->mu = sc.mu;
  vsph_integrate_free(s);
  vsph_references_scene_free(ref);
  return rc;
}

int vsph_cmd_run_main(int argc, char **argv) {
  if (argc >= 2 && (!strcmp(argv[1], "--help") || !strcmp(argv[1], "-h"))) {
    usage(stdout);
    return 0;
  }
  if (argc < 2 || argv[1][0] == '-')
    return vsph_args_fail(CMD, "missing SCENE (see vsph scenes)");
  const struct vsph_scene_type *type = vsph_scene_find(argv[1]);
  if (!type)
    return vsph_args_fail(CMD, "unknown scene '%s' (see vsph scenes)", argv[1]);
  struct vsph_params *prm = vsph_params_alloc();
  if (!prm) return vsph_args_status(CMD, VSPH_ENOMEM);
  const char *out_dir = NULL, *params_file = NULL;
  const char *opt_visc = NULL, *opt_kernel = NULL, *opt_res = NULL,
             *opt_tend = NULL, *opt_cfl = NULL;
  size_t threads = 0;
  int quiet = 0, rc = 0;
  /* First pass: the file comes first whatever the order on the line. */
  for (int i = 2; i < argc; i++)
    if (!strcmp(argv[i], "--params") && i + 1 < argc) params_file = argv[i + 1];
  if (params_file && vsph_params_read(prm, params_file)) {
    rc = vsph_args_status(CMD, VSPH_EINVAL);
    goto done;
  }
  for (int i = 2; i < argc; i++) {
    const char *a = argv[i], *v;
    if (!strcmp(a, "--help") || !strcmp(a, "-h")) {
      usage(stdout);
      goto done;
    } else if (!strcmp(a, "--quiet")) {
      quiet = 1;
      continue;
    }
    if (!(v = vsph_args_value(CMD, argc, argv, &i))) {
      rc = 2;
      goto done;
    }
    if (!strcmp(a, "--params")) {
      continue;
    } else if (!strcmp(a, "--visc")) {
      opt_visc = v;
    } else if (!strcmp(a, "--kernel")) {
      opt_kernel = v;
    } else if (!strcmp(a, "--res")) {
      opt_res = v;
    } else if (!strcmp(a, "--t-end")) {
      opt_tend = v;
    } else if (!strcmp(a, "--cfl")) {
      opt_cfl = v;
    } else if (!strcmp(a, "--out")) {
      out_dir = v;
    } else if (!strcmp(a, "--threads")) {
      if (vsph_args_size(CMD, a, v, &threads)) {
        rc = 2;
        goto done;
      }
    } else if (!strcmp(a, "--set")) {
      char key[256];
      const char *eq = strchr(v, '=');
      if (!eq || (size_t)(eq - v) >= sizeof key) {
        rc = vsph_args_fail(CMD, "--set wants Section:key=value, got '%s'", v);
        goto done;
      }
      memcpy(key, v, (size_t)(eq - v));
      key[eq - v] = '\0';
      if (vsph_params_set(prm, key, eq + 1)) {
        rc = vsph_args_status(CMD, VSPH_EINVAL);
        goto done;
      }
    } else {
      rc = vsph_args_fail(CMD, "unknown option '%s' (see --help)", a);
      goto done;
    }
  }
  /* Explicit options override the file and --set. */
  const char *opt_keys[5] = {"Solver:visc", "Solver:kernel", "Solver:res",
                             "Solver:t_end", "Solver:cfl"};
  const char *opt_vals[5] = {opt_visc, opt_kernel, opt_res, opt_tend, opt_cfl};
  for (int k = 0; k < 5; k++)
    if (opt_vals[k]) vsph_params_set(prm, opt_keys[k], opt_vals[k]);

  if (threads > 0) omp_set_num_threads((int)threads);
  struct vsph_cmd_run_result res;
  rc = vsph_cmd_run_params(prm, type->name, out_dir, quiet, &res);
done:
  vsph_params_free(prm);
  return rc;
}

int vsph_cmd_run_scenes(int argc, char **argv) {
  (void)argv;
  if (argc > 1 && strcmp(argv[1], "--help") && strcmp(argv[1], "-h"))
    return vsph_args_fail("scenes", "unknown option '%s'", argv[1]);
  printf(
      "usage: vsph run SCENE [options]   (vsph run --help)\n\n"
      "Solver: section (all scenes)\n");
  for (size_t k = 0; k < NSOLVER; k++)
    printf("  %-12s %-20s %s\n", SOLVER[k].key, SOLVER[k].def, SOLVER[k].help);
  for (size_t i = 0; i < vsph_scene_count(); i++) {
    const struct vsph_scene_type *t = vsph_scene_get(i);
    printf("\n%s: %s\n  --res counts particles across %s. Scene: section\n",
           t->name, t->description, t->length_name);
    for (size_t k = 0; k < t->nparams; k++)
      printf("  %-12s %-20.10g %s\n", t->params[k].key, t->params[k].def,
             t->params[k].help);
  }
  return 0;
}
