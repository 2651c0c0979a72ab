#pragma once
// Build-wide switches shared by host and device code.

#if defined(__CUDACC__)
#define PSPH_HD __host__ __device__
#define PSPH_INLINE __forceinline__
#else
#define PSPH_HD
#define PSPH_INLINE inline
#endif

// Forces inlining of a neighbour-loop body (a lambda) into its loop; GCC otherwise keeps large
// bodies out of line, which costs ~30 % in the force pass (measured with perf).
#if defined(__GNUC__) && !defined(__CUDA_ARCH__)
#define PSPH_PAIR __attribute__((always_inline))
#else
#define PSPH_PAIR
#endif

namespace psph {

// Working precisions. `Real`: every particle field and the pair loops. `Coord`: positions,
// reference positions and displacements, and the time integration of positions. Double by default:
// positions of a 1e-3 m domain move by ~1e-11 m per step in the creeping-flow validations, below
// float resolution at that magnitude. `mixed` keeps Coord double and computes each pair difference
// in double before handing it to the float pair code (neighbours/cell_grid.hpp).
#if defined(PORESPH_SINGLE_PRECISION)
using Real = float;
using Coord = float;
#elif defined(PORESPH_MIXED_PRECISION)
using Real = float;
using Coord = double;
#else
using Real = double;
using Coord = double;
#endif

constexpr const char* precision_name() {
  return sizeof(Real) == 8 ? "double" : sizeof(Coord) == 8 ? "mixed" : "single";
}

}  // namespace psph
