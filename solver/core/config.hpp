#pragma once
// Build-wide switches shared by host and device code.

#if defined(__CUDACC__)
#define PSPH_HD __host__ __device__
#define PSPH_INLINE __forceinline__
#else
#define PSPH_HD
#define PSPH_INLINE inline
#endif

namespace psph {

// Working precision of every particle field. Double by default: positions of a 1e-3 m domain move
// by ~1e-11 m per step in the creeping-flow validations, below float resolution at that magnitude.
#if defined(PORESPH_SINGLE_PRECISION)
using Real = float;
#else
using Real = double;
#endif

constexpr const char* precision_name() { return sizeof(Real) == 4 ? "single" : "double"; }

}  // namespace psph
