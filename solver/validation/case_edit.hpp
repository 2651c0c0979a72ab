#pragma once
// Editing a parsed case table for a validation variant (another spacing, support, load): the
// pieces the variants share.
#include <cmath>

#include <toml++/toml.h>

namespace psph {

inline toml::array pair_of(double a, double b) { return toml::array{a, b}; }

// A domain bound at x on a lattice of spacing s whose points fall on multiples of s: half a
// spacing past the multiple of s nearest to x.
inline double lattice_aligned(double x, double s) { return std::round(x / s) * s + s / 2; }

}  // namespace psph
