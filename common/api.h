/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
#ifndef VSPH_COMMON_API_H
#define VSPH_COMMON_API_H

/** @file api.h
 *  @brief The export marker of libvsph's public interface. The library is
 *  built with hidden visibility (-fvisibility=hidden): libvsph.so exports
 *  exactly what its installed headers declare with VSPH_API, and nothing
 *  of the program's layers (runs/, reports/, cli/) or of the library's
 *  internal helpers. tests/check_library.c holds the exported list to the
 *  headers. */
#if defined(__GNUC__) || defined(__clang__)
#define VSPH_API __attribute__((visibility("default")))
#else
#define VSPH_API
#endif

#endif /* VSPH_COMMON_API_H */
