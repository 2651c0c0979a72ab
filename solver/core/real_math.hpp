#pragma once
// The C math functions that the per-particle code calls unqualified, overloaded for float: in a
// float build ::fabs(double), ::pow(double, double)... would carry every call through double on
// the host (-Wdouble-promotion); CUDA's device code has the float versions too. Inside namespace
// psph these are found first; the double ones are the C library's, so a double build is unchanged.
#include <cmath>

#include "core/config.hpp"

namespace psph {

PSPH_HD inline float fabs(float x) { return ::fabsf(x); }
PSPH_HD inline double fabs(double x) { return ::fabs(x); }
PSPH_HD inline float sqrt(float x) { return ::sqrtf(x); }
PSPH_HD inline double sqrt(double x) { return ::sqrt(x); }
PSPH_HD inline float pow(float x, float y) { return ::powf(x, y); }
PSPH_HD inline double pow(double x, double y) { return ::pow(x, y); }
PSPH_HD inline float log(float x) { return ::logf(x); }
PSPH_HD inline double log(double x) { return ::log(x); }
PSPH_HD inline float fmax(float x, float y) { return ::fmaxf(x, y); }
PSPH_HD inline double fmax(double x, double y) { return ::fmax(x, y); }

}  // namespace psph
