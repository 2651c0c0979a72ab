#pragma once
// A body-fitted particle layout for a sphere (a disc in 2D, a segment in 1D): shells of one
// spacing's thickness centred on radii (k + 1/2) dx, k = 0, 1, ..., each holding
// round(shell area / dx^(D-1)) particles evenly spread (2D: equal angles, every other ring turned
// by half a step; 3D: a Fibonacci spiral), so that the particles' volumes tile the shells exactly.
// A lattice's staircase boundary softens an elastic body with curved free or loaded surfaces
// (the Lame cylinder, VALIDATION.md): its corner particles hang on by a few neighbours.
#include <array>
#include <vector>

namespace psph {

struct LayoutPoint {
  std::array<double, 3> x{0, 0, 0};
  double volume = 0;  // the part of its shell it stands for (m^D)
};

// The shells whose centre radius is within `radius`.
std::vector<LayoutPoint> concentric_points(const std::array<double, 3>& centre, double radius, double spacing,
                                           int dimension);

}  // namespace psph
