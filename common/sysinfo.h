/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
#ifndef VSPH_COMMON_SYSINFO_H
#define VSPH_COMMON_SYSINFO_H

#include "../common/api.h"

/** @file sysinfo.h
 *  @brief What a timing needs beside it to be read fairly on a shared
 *  machine: the load average, the process's CPU time, the OpenMP wait
 *  policy in force, the peak resident memory. Linux (/proc); elsewhere the
 *  figures are NaN or 0 and the timings still run. Part of the library:
 *  vsph_sysinfo_build_isa says which copy of it the loader picked. */

#include <stddef.h>

/** @brief The 1, 5 and 15 minute load averages into @p la (NaN if
 *  /proc/loadavg cannot be read; nothing for a NULL @p la). */
VSPH_API void vsph_sysinfo_load(double la[3]);

/** @brief CPU time of this process so far, all threads (s). */
VSPH_API double vsph_sysinfo_cpu_s(void);

/** @brief CPU time of the calling thread alone (s), NaN where the clock is
 *  missing: a run's when it is one of several runs sharing the process,
 *  each on a thread of its own (a report's lanes). */
VSPH_API double vsph_sysinfo_thread_cpu_s(void);

/** @brief The OpenMP wait policy this process runs under, as the
 *  environment gives it: "GOMP_SPINCOUNT=1000" (what the vsph program
 *  sets unless told otherwise), "OMP_WAIT_POLICY=...", both, or "libgomp
 *  default"), into the caller's @p buf of @p n bytes (128 hold any).
 *  @return @p buf, or "" where @p buf is NULL or @p n 0. */
VSPH_API const char *vsph_sysinfo_wait_policy(char *buf, size_t n);

/** @brief The instruction set this code was built for: "x86-64-v4",
 *  "x86-64-v3" (AVX2 and FMA: the default build on a CPU that has them),
 *  "x86-64" (the baseline: the installed program and library where
 *  the CPU lacks x86-64-v3) or "other" (not x86-64). */
VSPH_API const char *vsph_sysinfo_build_isa(void);

/** @brief Peak resident memory of this process so far (bytes; 0 if
 *  unknown). */
VSPH_API size_t vsph_sysinfo_peak_rss(void);

#endif /* VSPH_COMMON_SYSINFO_H */
