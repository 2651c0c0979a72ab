#pragma once
// A body-fitted particle layout for a sphere (a disc in 2D, a segment in 1D) of radius R: shells
// of thickness dr = R / round(R / dx) (the spacing itself when R is a whole number of spacings)
// centred on radii (k + 1/2) dr, the last ending on the surface, each holding
// round(shell measure / dx^D) particles evenly spread (2D: equal angles, every other ring turned
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

std::vector<LayoutPoint> concentric_points(const std::array<double, 3>& centre, double radius, double spacing,
                                           int dimension);

}  // namespace psph
