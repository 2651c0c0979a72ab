#include "validation/laplace_bubble.hpp"

#include <chrono>
#include <cmath>

#include "engine/engine.hpp"
#include "scene/embedded_cases.hpp"
#include "scene/scene_builder.hpp"

namespace psph {

Case laplace_bubble_case(double radius_spacings, const std::string& kernel, double support_spacings, int dimension) {
  toml::table tbl = toml::parse(embedded_case_text("laplace_bubble_2d"), std::string_view("cases/laplace_bubble_2d.toml"));
  const double dx = 1e-4, R = radius_spacings * dx;
  const double L = dx * std::max(dimension == 3 ? 16.0 : 24.0, std::ceil(4 * radius_spacings));
  auto point = [&](double v) {
    toml::array a;
    for (int k = 0; k < dimension; ++k) a.push_back(v);
    return a;
  };
  set_case_value(tbl, "case.dimension", toml::value<int64_t>(dimension));
  set_case_value(tbl, "domain.lower", point(0.0));
  set_case_value(tbl, "domain.upper", point(L));
  toml::array periodic;
  for (int k = 0; k < dimension; ++k) periodic.push_back(true);
  set_case_value(tbl, "domain.periodic", periodic);
  set_case_value(tbl, "discretisation.kernel", toml::value<std::string>(kernel));
  set_case_value(tbl, "discretisation.support_radius", toml::value<double>(support_spacings * dx));
  auto& geometry = *tbl["geometry"].as_array();
  geometry.at(0).as_table()->insert_or_assign("lower", point(0.0));
  geometry.at(0).as_table()->insert_or_assign("upper", point(L));
  geometry.at(1).as_table()->insert_or_assign("center", point(L / 2));
  geometry.at(1).as_table()->insert_or_assign("radius", R);
  Case c = parse_case(tbl, "cases/laplace_bubble_2d.toml");
  build_particles(c);
  return c;
}

BubbleMeasurement measure_bubble(const Case& c, const std::string& backend) {
  const Scene& sc = c.scene;
  const int D = sc.dimension;
  const auto t0 = std::chrono::steady_clock::now();
  auto engine = make_engine(sc, backend);
  BubbleMeasurement out;
  out.particles = engine->particles();
  out.capillary_speed = capillary_speed(sc);
  const double t_end = c.end_time, support = sc.options.support_radius;
  const int samples = 10;
  for (int k = 0; k <= samples; ++k) {
    // Samples over the last fifth of the run average out the residual acoustic oscillation.
    engine->run_until(t_end * (0.8 + 0.2 * k / samples));
    const std::vector<double> x = engine->field("position"), p = engine->field("pressure");
    const std::vector<double> m = engine->field("mass"), rho = engine->field("density");
    const std::vector<double> mat = engine->field("material"), v = engine->field("velocity");
    const int n = engine->particles();
    auto is_gas = [&](int i) { return sc.materials[static_cast<int>(mat[i])].props.colour < 0; };
    double volume = 0, centre[3] = {0, 0, 0};
    for (int i = 0; i < n; ++i)
      if (is_gas(i)) {
        volume += m[i] / rho[i];
        for (int d = 0; d < D; ++d) centre[d] += m[i] / rho[i] * x[i * D + d];
      }
    for (int d = 0; d < D; ++d) centre[d] /= volume;
    const double R = D == 2 ? std::sqrt(volume / M_PI) : std::cbrt(3 * volume / (4 * M_PI));
    double pg = 0, pl = 0, speed = 0;
    int ng = 0, nl = 0;
    for (int i = 0; i < n; ++i) {
      double r2 = 0, v2 = 0;
      for (int d = 0; d < D; ++d) r2 += (x[i * D + d] - centre[d]) * (x[i * D + d] - centre[d]), v2 += v[i * D + d] * v[i * D + d];
      const double r = std::sqrt(r2);
      speed = std::max(speed, std::sqrt(v2));
      if (is_gas(i) && r < R - support) pg += p[i], ++ng;
      if (!is_gas(i) && r > R + support) pl += p[i], ++nl;
    }
    out.radius += R / (samples + 1);
    out.jump += (ng && nl ? pg / ng - pl / nl : 0.0) / (samples + 1);
    out.spurious_speed = speed;
  }
  out.jump_exact = sc.options.surface_tension * (D - 1) / out.radius;
  out.steps = engine->steps();
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

}  // namespace psph
