#include "validation/rigid_motion.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

#include "engine/engine.hpp"
#include "engine/rigid_scene.hpp"
#include "scene/embedded_cases.hpp"
#include "scene/scene_builder.hpp"

namespace psph {

Case rigid_case(const std::string& name, double spacing) {
  const std::string file = "cases/" + name + ".toml";
  toml::table tbl = toml::parse(embedded_case_text(name), std::string_view(file));
  if (spacing > 0) set_case_spacing(tbl, spacing);
  Case c = parse_case(tbl, file);
  build_particles(c);
  return c;
}

double sangani_acrivos_square(double c) {
  return 4 * M_PI / (-0.5 * std::log(c) - 0.738 + c - 0.887 * c * c + 2.038 * c * c * c);
}

namespace {

double norm3(const Vec3d& a) { return std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]); }
double dot3(const Vec3d& a, const Vec3d& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Vec3d scaled(const Vec3d& a, double s) { return {a[0] * s, a[1] * s, a[2] * s}; }

}  // namespace

TopTrajectory run_rigid_top(const Case& c, const std::string& backend) {
  const Scene& sc = c.scene;
  const int D = sc.dimension;
  if (D != 3) throw std::logic_error("the rigid top is a 3D case");
  const SceneRigidBodies rb = rigid_bodies_of(sc);
  if (rb.state.size() != 1) throw std::logic_error("the rigid top case has one body");
  const RigidBodyState b0 = rb.state[0];
  // The body's axes are the lattice's: I0 diagonal, I1 = I2 about x and y, I3 about z.
  const double I1 = b0.inertia0[0], I3 = b0.inertia0[8];
  const Vec3d L = b0.angular_momentum, e3{0, 0, 1};
  const double spin = (1 / I3 - 1 / I1) * dot3(L, e3), precession = norm3(L) / I1;
  Vec3d g{0, 0, 0};
  for (const auto& m : sc.materials)
    if (m.props.kind == MaterialKind::Rigid) g = m.body_force;
  double length = 0;  // the body's largest extent
  for (const Vec3d& q : rb.offsets[0]) length = std::max(length, 2 * norm3(q));
  const double omega0_dot_L = dot3(angular_velocity_of(b0, 3), L);

  TopTrajectory out;
  const auto t0 = std::chrono::steady_clock::now();
  auto engine = make_engine(sc, backend);
  out.particles = engine->particles();
  const int samples = 10;
  for (int k = 1; k <= samples; ++k) {
    engine->run_until(c.end_time * k / samples);
    const double t = engine->time();
    const RigidBodyState b = engine->rigid_bodies()[0];
    const Mat3d R = mat_mul(rotation_of(scaled(L, precession * t / norm3(L))), rotation_of(scaled(e3, spin * t)));
    Vec3d X{};
    for (int d = 0; d < 3; ++d) X[d] = b0.centre[d] + b0.velocity[d] * t + 0.5 * g[d] * t * t;
    out.centre_error = std::max(out.centre_error, norm3({b.centre[0] - X[0], b.centre[1] - X[1], b.centre[2] - X[2]}) /
                                                      (0.5 * norm3(g) * t * t));
    out.momentum_drift = std::max(out.momentum_drift, std::fabs(norm3(b.angular_momentum) / norm3(L) - 1));
    out.energy_drift =
        std::max(out.energy_drift, std::fabs(dot3(angular_velocity_of(b, 3), b.angular_momentum) / omega0_dot_L - 1));
    // Every particle against X + R q, by id, to the minimum image.
    const std::vector<double> x = engine->field("position"), id = engine->field("id");
    for (int i = 0; i < engine->particles(); ++i) {
      const int p = static_cast<int>(id[i]);
      const auto it = std::find(rb.members[0].begin(), rb.members[0].end(), p);
      if (it == rb.members[0].end()) continue;
      const Vec3d rq = mat_vec(R, rb.offsets[0][it - rb.members[0].begin()]);
      double e2 = 0;
      for (int d = 0; d < 3; ++d) {
        double e = x[i * 3 + d] - (X[d] + rq[d]);
        const double Lk = sc.upper[d] - sc.lower[d];
        if (sc.periodic[d]) e -= Lk * std::round(e / Lk);
        e2 += e * e;
      }
      out.position_error = std::max(out.position_error, std::sqrt(e2) / length);
    }
  }
  out.precession_turns = precession * engine->time() / (2 * M_PI);
  out.steps = engine->steps();
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

SettlingDrag run_settling_cylinder(Case c, const std::string& backend) {
  Scene& sc = c.scene;
  const int D = sc.dimension;
  int fluid = -1, grain = -1;
  for (int k = 0; k < static_cast<int>(sc.materials.size()); ++k)
    (sc.materials[k].props.kind == MaterialKind::Fluid ? fluid : grain) = k;
  double M_b = 0, M_f = 0;
  int n_b = 0;
  for (int i = 0; i < sc.count(); ++i) {
    if (sc.material[i] == grain) M_b += sc.mass[i], ++n_b;
    else M_f += sc.mass[i];
  }
  // The fluid carries the opposite of the body's weight: no net force on the cell.
  for (int d = 0; d < D; ++d) sc.materials[fluid].body_force[d] = -M_b * sc.materials[grain].body_force[d] / M_f;
  const int axis = D - 1;
  const double weight = -M_b * sc.materials[grain].body_force[axis];  // along -axis (N per unit depth in 2D)
  const double mu = sc.materials[fluid].props.viscosity, rho = sc.materials[fluid].props.rest_density;

  SettlingDrag out;
  out.solid_fraction = double(n_b) / sc.count();
  out.drag_reference = sangani_acrivos_square(out.solid_fraction);
  const auto t0 = std::chrono::steady_clock::now();
  auto engine = make_engine(sc, backend);
  out.particles = engine->particles();
  auto drag_now = [&]() {
    const std::vector<double> v = engine->field("velocity"), m = engine->field("material");
    double u = 0;
    int n = 0;
    for (int i = 0; i < engine->particles(); ++i)
      if (static_cast<int>(m[i]) == fluid) u += v[i * D + axis], ++n;
    const double V = engine->rigid_bodies()[0].velocity[axis];
    const double q = (1 - out.solid_fraction) * (u / n - V);  // mean over the cell, relative to the body
    return weight / ((1 - out.solid_fraction) * mu * q);
  };
  engine->run_until(0.9 * c.end_time);
  const double before = drag_now();
  engine->run_until(c.end_time);
  out.drag = drag_now();
  out.drag_change = std::fabs(out.drag / before - 1);
  const RigidBodyState b = engine->rigid_bodies()[0];
  const double radius = std::sqrt(out.solid_fraction * (sc.upper[0] - sc.lower[0]) * (sc.upper[1] - sc.lower[1]) / M_PI);
  out.reynolds = rho * norm3(b.velocity) * radius / mu;
  out.angular_velocity = angular_velocity_of(b, D)[2];
  out.steps = engine->steps();
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

}  // namespace psph
