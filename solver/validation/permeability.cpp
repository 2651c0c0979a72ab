#include "validation/permeability.hpp"

#include <chrono>
#include <cmath>

#include "engine/engine.hpp"

namespace psph {

Permeability measure_permeability(const Case& c, const std::string& backend, const PermeabilityRun& run) {
  const Scene& sc = c.scene;
  const SceneMaterial* water = nullptr;
  for (const auto& m : sc.materials)
    if (m.props.kind == MaterialKind::Fluid) water = &m;
  const int D = sc.dimension;
  int axis = 0;
  for (int k = 1; k < D; ++k)
    if (std::fabs(water->body_force[k]) > std::fabs(water->body_force[axis])) axis = k;
  const double g = water->body_force[axis], mu = water->props.viscosity, rho0 = water->props.rest_density;
  double volume = run.bulk_volume;
  if (volume <= 0) {
    volume = 1;
    for (int k = 0; k < D; ++k) volume *= sc.upper[k] - sc.lower[k];
  }
  const auto t0 = std::chrono::steady_clock::now();
  auto engine = make_engine(sc, backend);
  auto darcy_velocity = [&] {
    const std::vector<double> v = engine->field("velocity"), m = engine->field("mass");
    const std::vector<double> rho = engine->field("density"), mat = engine->field("material");
    double q = 0;
    for (int i = 0; i < engine->particles(); ++i)
      if (sc.materials[static_cast<int>(mat[i])].props.kind == MaterialKind::Fluid) q += v[i * D + axis] * m[i] / rho[i];
    return q / volume;
  };
  double t = 0, q_prev = 0, q = 0;
  for (;;) {
    t += run.interval;
    engine->run_until(t);
    q = darcy_velocity();
    if ((t > run.min_time && std::fabs(q - q_prev) < run.change * std::fabs(q)) || t >= run.max_time) break;
    q_prev = q;
  }
  Permeability p;
  p.K = mu * q / (rho0 * g);
  p.time = t, p.steps = engine->steps(), p.particles = engine->particles();
  p.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return p;
}

}  // namespace psph
