#ifndef VSPH_COMMON_CONSTS_H
#define VSPH_COMMON_CONSTS_H

/** @file consts.h
 *  @brief Mathematical constants (M_PI is not declared under -std=c11) and
 *  the project version. */

#define VSPH_PI 3.14159265358979323846
#define VSPH_SQRTPI 1.77245385090551602730
#define VSPH_VERSION "0.1.0"

/** Maximum spatial dimension. */
#define VSPH_CONSTS_MAXDIM 3

#endif /* VSPH_COMMON_CONSTS_H */
