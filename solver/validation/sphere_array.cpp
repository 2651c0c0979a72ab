#include "validation/sphere_array.hpp"

#include <chrono>
#include <cmath>
#include <stdexcept>

#include "engine/engine.hpp"
#include "scene/embedded_cases.hpp"
#include "scene/scene_builder.hpp"

namespace psph {

double sphere_array_reference(double phi) {
  if (std::fabs(phi - 0.343) < 1e-6) return 3.1728e-8;
  if (std::fabs(phi - 0.45) < 1e-6) return 1.5904e-8;
  if (std::fabs(phi - 0.5236) < 1e-6) return 1.0107e-8;
  throw std::invalid_argument("no reference permeability for solid fraction " + std::to_string(phi));
}

Case sphere_array_case(double phi, double support_per_spacing, const std::string& kernel) {
  const std::string text = embedded_case_text("sphere_array");
  toml::table tbl = toml::parse(text, std::string_view("cases/sphere_array.toml"));
  const double L = 2e-3, support = 1e-4;
  const double R = std::cbrt(phi * 3 * L * L * L / (4 * M_PI));  // Pazdniakou eq. 81
  set_case_value(tbl, "discretisation.spacing", toml::value<double>(support / support_per_spacing));
  set_case_value(tbl, "discretisation.kernel", toml::value<std::string>(kernel));
  tbl["geometry"].as_array()->at(1).as_table()->insert_or_assign("radius", R);
  Case c = parse_case(tbl, "cases/sphere_array.toml");
  build_particles(c);
  return c;
}

Permeability measure_permeability(const Case& c, const std::string& backend) {
  const Scene& sc = c.scene;
  const SceneMaterial* water = nullptr;
  for (const auto& m : sc.materials)
    if (m.props.kind == MaterialKind::Fluid) water = &m;
  const double g = water->body_force[2], mu = water->props.viscosity, rho0 = water->props.rest_density;
  double volume = 1;
  for (int k = 0; k < 3; ++k) volume *= sc.upper[k] - sc.lower[k];
  const auto t0 = std::chrono::steady_clock::now();
  auto engine = make_engine(sc, backend);
  auto darcy_velocity = [&] {
    const std::vector<double> v = engine->field("velocity"), m = engine->field("mass");
    const std::vector<double> rho = engine->field("density"), mat = engine->field("material");
    double q = 0;
    for (int i = 0; i < engine->particles(); ++i)
      if (sc.materials[static_cast<int>(mat[i])].props.kind == MaterialKind::Fluid) q += v[i * 3 + 2] * m[i] / rho[i];
    return q / volume;
  };
  double t = 0, q_prev = 0, q = 0;
  const double interval = 0.05, t_max = 5.0;
  for (;;) {
    t += interval;
    engine->run_until(t);
    q = darcy_velocity();
    if ((t > 0.1 && std::fabs(q - q_prev) < 5e-3 * std::fabs(q)) || t >= t_max) break;
    q_prev = q;
  }
  Permeability p;
  p.K = mu * q / (rho0 * g);
  p.time = t, p.steps = engine->steps(), p.particles = engine->particles();
  p.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return p;
}

}  // namespace psph
