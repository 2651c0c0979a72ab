#include "validation/vibrating_rod.hpp"

#include <chrono>
#include <cmath>
#include <vector>

#include "engine/engine.hpp"
#include "scene/embedded_cases.hpp"
#include "scene/scene_builder.hpp"

namespace psph {

namespace {

struct RodGeometry {
  double length = 0, speed = 0, beta = 0;
  int elastic = -1;
};

RodGeometry rod_geometry(const Scene& sc, int k, bool clamped_free) {
  RodGeometry g;
  g.length = 0.1333;  // cases/vibrating_rod_1d.toml
  for (int m = 0; m < static_cast<int>(sc.materials.size()); ++m)
    if (sc.materials[m].props.kind == MaterialKind::Elastic) g.elastic = m, g.speed = sc.materials[m].props.sound_speed;
  g.beta = clamped_free ? (2 * k - 1) * M_PI / 2 : k * M_PI;
  return g;
}

}  // namespace

Case vibrating_rod_case(int k, bool clamped_free) {
  toml::table tbl = toml::parse(embedded_case_text("vibrating_rod_1d"), std::string_view("cases/vibrating_rod_1d.toml"));
  if (clamped_free) {
    auto& clamp = *tbl["geometry"].as_array()->at(0).as_table();
    clamp.insert_or_assign("upper", toml::array{0.0});
  }
  Case c = parse_case(tbl, "cases/vibrating_rod_1d.toml");
  build_particles(c);
  Scene& sc = c.scene;
  const RodGeometry g = rod_geometry(sc, k, clamped_free);
  const double omega = g.beta * g.speed / g.length, amplitude = g.length / 2000;  // eq. C3-41
  for (int i = 0; i < sc.count(); ++i)
    if (sc.material[i] == g.elastic) sc.v[i] = amplitude * omega * std::sin(g.beta * sc.x[i] / g.length);
  c.end_time = 3 * 2 * M_PI / omega;
  return c;
}

RodVibration run_vibrating_rod(const Case& c, int k, bool clamped_free, const std::string& backend) {
  const Scene& sc = c.scene;
  const RodGeometry g = rod_geometry(sc, k, clamped_free);
  const auto t0 = std::chrono::steady_clock::now();
  auto engine = make_engine(sc, backend);
  RodVibration out;
  out.particles = engine->particles();
  out.beta2_local = g.beta * g.beta;
  // Mode shape at the reference positions (fixed for the run; the engine may reorder particles,
  // so it is read back with them).
  auto modal = [&] {
    const std::vector<double> x0 = engine->field("reference_position"), u = engine->field("displacement");
    const std::vector<double> mat = engine->field("material");
    double q = 0;
    for (int i = 0; i < engine->particles(); ++i)
      if (static_cast<int>(mat[i]) == g.elastic) q += u[i] * std::sin(g.beta * x0[i] / g.length);
    return q;
  };
  auto energy = [&] {
    const StepStats s = engine->stats();
    return s.kinetic_energy + s.elastic_energy;
  };
  const double e0 = energy();
  std::vector<double> crossings;
  double q_prev = 0, t_prev = 0;
  while (engine->time() < c.end_time) {
    engine->step(c.end_time);
    const double q = modal(), t = engine->time();
    if (t_prev > 0 && ((q_prev < 0 && q >= 0) || (q_prev > 0 && q <= 0)))
      crossings.push_back(t_prev + (t - t_prev) * q_prev / (q_prev - q));
    q_prev = q, t_prev = t;
    out.energy_drift = std::max(out.energy_drift, std::fabs(energy() / e0 - 1));
  }
  // Crossings every half period: T = 2 (t_n - t_1) / (n - 1).
  if (crossings.size() >= 2) {
    const double period = 2 * (crossings.back() - crossings.front()) / (crossings.size() - 1);
    const double beta = 2 * M_PI / period * g.length / g.speed;
    out.beta2 = beta * beta;
  }
  out.steps = engine->steps();
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

}  // namespace psph
