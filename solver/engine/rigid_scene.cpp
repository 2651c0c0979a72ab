#include "engine/rigid_scene.hpp"

#include <cmath>

namespace psph {

SceneRigidBodies rigid_bodies_of(const Scene& sc) {
  const int D = sc.dimension;
  const int nb = static_cast<int>(sc.body_angular_velocity.size());
  SceneRigidBodies out;
  out.members.resize(nb);
  for (int i = 0; i < sc.count(); ++i)
    if (!sc.body.empty() && sc.body[i] >= 0) out.members[sc.body[i]].push_back(i);
  for (int b = 0; b < nb; ++b) {
    const std::vector<int>& mem = out.members[b];
    std::vector<double> m;
    std::vector<Vec3d> x;
    for (int i : mem) {
      Vec3d p{0, 0, 0};
      for (int k = 0; k < D; ++k) {
        // The minimum image of the body's first particle: a body may straddle a periodic side.
        p[k] = sc.x[i * D + k];
        const double L = sc.upper[k] - sc.lower[k], ref = sc.x[mem.front() * D + k];
        if (sc.periodic[k]) p[k] -= L * std::round((p[k] - ref) / L);
      }
      m.push_back(sc.mass[i]), x.push_back(p);
    }
    Vec3d v{0, 0, 0};
    double mass = 0;
    for (std::size_t q = 0; q < mem.size(); ++q) {
      mass += m[q];
      for (int k = 0; k < D; ++k) v[k] += m[q] * sc.v[mem[q] * D + k];
    }
    for (double& c : v) c /= mass;
    out.state.push_back(rigid_body_from_points(m, x, v, sc.body_angular_velocity[b], D));
    std::vector<Vec3d> off;
    for (const Vec3d& p : x)
      off.push_back({p[0] - out.state.back().centre[0], p[1] - out.state.back().centre[1], p[2] - out.state.back().centre[2]});
    out.offsets.push_back(off);
    // A body is one geometry, hence one material (scene/scene_builder.cpp).
    const std::array<double, 3>& g = sc.materials[sc.material[mem.front()]].body_force;
    out.weight.push_back({mass * g[0], mass * g[1], mass * g[2]});
  }
  return out;
}

void add_rigid_rotation(Scene& sc) {
  const int D = sc.dimension;
  if (D == 1) return;
  const SceneRigidBodies rb = rigid_bodies_of(sc);
  for (std::size_t b = 0; b < rb.members.size(); ++b)
    for (std::size_t q = 0; q < rb.members[b].size(); ++q) {
      const Vec3d dv = cross(sc.body_angular_velocity[b], rb.offsets[b][q]);
      for (int k = 0; k < D; ++k) sc.v[rb.members[b][q] * D + k] += dv[k];
    }
}

}  // namespace psph
