#pragma once
// Monitor columns of rigid bodies (rigid/): per body b, its centre of mass (unwrapped across
// periodic sides), velocity and angular velocity (z in 2D), in the case's order of its geometries.
#include <string>
#include <vector>

#include "engine/engine.hpp"

namespace psph {

inline std::vector<std::string> rigid_body_columns(int dimension, int bodies) {
  std::vector<std::string> out;
  const char* axis = "xyz";
  for (int b = 0; b < bodies; ++b) {
    const std::string p = "body" + std::to_string(b) + "_";
    for (int k = 0; k < dimension; ++k) out.push_back(p + axis[k]);
    for (int k = 0; k < dimension; ++k) out.push_back(p + "v" + axis[k]);
    if (dimension == 2) out.push_back(p + "omega");
    if (dimension == 3)
      for (int k = 0; k < 3; ++k) out.push_back(p + "omega_" + axis[k]);
  }
  return out;
}

inline std::vector<double> rigid_body_row(const Engine& e) {
  std::vector<double> out;
  const int D = e.dimension();
  for (const RigidBodyState& b : e.rigid_bodies()) {
    for (int k = 0; k < D; ++k) out.push_back(b.centre[k]);
    for (int k = 0; k < D; ++k) out.push_back(b.velocity[k]);
    const Vec3d w = angular_velocity_of(b, D);
    if (D == 2) out.push_back(w[2]);
    if (D == 3) out.insert(out.end(), w.begin(), w.end());
  }
  return out;
}

}  // namespace psph
