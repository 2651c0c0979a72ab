#include "validation/vibrating_rod.hpp"

#include <chrono>
#include <cmath>
#include <vector>

#include "engine/engine.hpp"
#include "scene/embedded_cases.hpp"
#include "scene/scene_builder.hpp"
#include "validation/oscillation.hpp"

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

Case vibrating_rod_case(int k, bool clamped_free, SolidFormulation form, double support_over_length) {
  toml::table tbl = toml::parse(embedded_case_text("vibrating_rod_1d"), std::string_view("cases/vibrating_rod_1d.toml"));
  constexpr double length = 0.1333;
  if (support_over_length != 0.05) {  // the clamps stay one support deep
    const double lambda = support_over_length * length;
    tbl["discretisation"].as_table()->insert_or_assign("support_radius", lambda);
    for (toml::table* t : {tbl["domain"].as_table(), tbl["geometry"].as_array()->at(0).as_table()}) {
      t->insert_or_assign("lower", toml::array{-lambda});
      t->insert_or_assign("upper", toml::array{length + lambda});
    }
  }
  if (clamped_free) {
    auto& clamp = *tbl["geometry"].as_array()->at(0).as_table();
    clamp.insert_or_assign("upper", toml::array{0.0});
  }
  Case c = parse_case(tbl, "cases/vibrating_rod_1d.toml");
  build_particles(c);
  Scene& sc = c.scene;
  sc.options.solid_formulation = form;
  const RodGeometry g = rod_geometry(sc, k, clamped_free);
  const double omega = g.beta * g.speed / g.length, amplitude = g.length / 2000;  // eq. C3-41
  for (int i = 0; i < sc.count(); ++i)
    if (sc.material[i] == g.elastic) sc.v[i] = amplitude * omega * std::sin(g.beta * sc.x[i] / g.length);
  // Three periods; a wide support lowers the frequency (to a third for mode 3 at lambda/L = 0.5)
  // and lengthens the acoustic step (0.25 h / c): a quarter of it keeps the energy within 0.2 %.
  c.end_time = (support_over_length > 0.1 ? 9 : 3) * 2 * M_PI / omega;
  if (support_over_length > 0.1) sc.options.dt_factor = 0.25;
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
  ZeroCrossings crossings;
  while (engine->time() < c.end_time) {
    engine->step(c.end_time);
    crossings.add(engine->time(), modal());
    out.energy_drift = std::max(out.energy_drift, std::fabs(energy() / e0 - 1));
  }
  if (const double period = crossings.period(); period > 0) {
    const double beta = 2 * M_PI / period * g.length / g.speed;
    out.beta2 = beta * beta;
  }
  out.steps = engine->steps();
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

}  // namespace psph
