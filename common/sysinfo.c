/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
#include "sysinfo.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

void vsph_sysinfo_load(double la[3]) {
  if (!la) return;
  la[0] = la[1] = la[2] = (double)NAN;
  FILE *f = fopen("/proc/loadavg", "r"); /* size 0 to stat: read a line */
  if (!f) return;
  char line[128];
  if (fgets(line, sizeof line, f) &&
      sscanf(line, "%lf %lf %lf", &la[0], &la[1], &la[2]) != 3)
    la[0] = la[1] = la[2] = (double)NAN;
  fclose(f);
}

double vsph_sysinfo_cpu_s(void) {
  struct timespec ts;
  if (clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts)) return (double)NAN;
  return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

double vsph_sysinfo_thread_cpu_s(void) {
  struct timespec ts;
  if (clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts)) return (double)NAN;
  return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

const char *vsph_sysinfo_wait_policy(char *buf, size_t n) {
  if (!buf || !n) return "";
  const char *w = getenv("OMP_WAIT_POLICY"), *c = getenv("GOMP_SPINCOUNT");
  if (w && c)
    snprintf(buf, n, "OMP_WAIT_POLICY=%.40s GOMP_SPINCOUNT=%.40s", w, c);
  else if (w || c)
    snprintf(buf, n, "%s=%.40s", w ? "OMP_WAIT_POLICY" : "GOMP_SPINCOUNT",
             w ? w : c);
  else
    snprintf(buf, n, "libgomp default");
  return buf;
}

const char *vsph_sysinfo_build_isa(void) {
#if defined(__x86_64__) && defined(__AVX512F__) && defined(__AVX512VL__)
  return "x86-64-v4";
#elif defined(__x86_64__) && defined(__AVX2__) && defined(__FMA__)
  return "x86-64-v3";
#elif defined(__x86_64__)
  return "x86-64";
#else
  return "other";
#endif
}

size_t vsph_sysinfo_peak_rss(void) {
  FILE *f = fopen("/proc/self/status", "r");
  if (!f) return 0;
  char line[256];
  size_t kb = 0;
  while (fgets(line, sizeof line, f))
    if (!strncmp(line, "VmHWM:", 6)) {
      kb = (size_t)strtoull(line + 6, NULL, 10);
      break;
    }
  fclose(f);
  return kb * 1024;
}
