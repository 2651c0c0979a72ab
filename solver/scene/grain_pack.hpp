#pragma once
// A synthetic porous medium: non-overlapping spherical (3D) or circular (2D) grains placed by
// random sequential addition inside a box, from a seed, until a solid fraction is reached. Every
// two grains keep a gap of at least `min_gap`, so that each throat is resolved by a few particles.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace psph {

struct GrainPackSpec {
  std::array<double, 3> lower{0, 0, 0}, upper{0, 0, 0};
  double grain_radius = 0;    // mean radius (m)
  double radius_spread = 0;   // radii uniform in grain_radius * (1 +- spread)
  double min_gap = 0;         // m, between grain surfaces
  double solid_fraction = 0;  // target fraction of the box's volume (grains clipped to the box)
  std::uint64_t seed = 1;
};

struct Grain {
  std::array<double, 3> centre{0, 0, 0};
  double radius = 0;
};

struct GrainPack {
  std::vector<Grain> grains;
  double solid_fraction = 0;  // reached, counting each grain's part inside the box (estimated)
};

// Throws std::invalid_argument (with the fraction reached) when the target cannot be reached.
GrainPack generate_grain_pack(const GrainPackSpec& spec, int dimension);

// True when x (D components) is inside the box and inside a grain.
bool in_grain_pack(const GrainPackSpec& spec, const std::vector<Grain>& grains, const double* x, int dimension);

}  // namespace psph
