#include "validation/oscillating_plate.hpp"

#include <chrono>
#include <cmath>
#include <vector>

#include "engine/engine.hpp"
#include "scene/embedded_cases.hpp"
#include "scene/scene_builder.hpp"
#include "validation/oscillation.hpp"

namespace psph {

namespace {

constexpr double kLength = 0.2, kThickness = 0.02, kL = 1.875104;  // cases/oscillating_plate_2d.toml

// Cantilever mode shape (clamped at x = 0, free at x = L).
double mode_shape(double x) {
  const double k = kL / kLength;
  const double a = (std::cos(kL) + std::cosh(kL)) / (std::sin(kL) + std::sinh(kL));
  return std::cos(k * x) - std::cosh(k * x) - a * (std::sin(k * x) - std::sinh(k * x));
}

const Material& plate_material(const Scene& sc) {
  for (const auto& m : sc.materials)
    if (m.props.kind == MaterialKind::Elastic) return m.props;
  throw std::logic_error("oscillating plate without an elastic material");
}

}  // namespace

Case oscillating_plate_case(double speed_ratio, double spacing, SolidFormulation form) {
  toml::table tbl = toml::parse(embedded_case_text("oscillating_plate_2d"), std::string_view("cases/oscillating_plate_2d.toml"));
  if (spacing > 0) set_case_spacing(tbl, spacing);
  if (form == SolidFormulation::Displacement) {
    set_case_value(tbl, "solid.formulation", toml::value<std::string>("displacement"));
    set_case_value(tbl, "materials.plate.poisson_ratio", toml::value<double>(0.2));
  }
  Case c = parse_case(tbl, "cases/oscillating_plate_2d.toml");
  build_particles(c);
  Scene& sc = c.scene;
  const double c_p = plate_material(sc).sound_speed, tip = mode_shape(kLength);
  for (int i = 0; i < sc.count(); ++i)
    if (sc.materials[sc.material[i]].props.kind == MaterialKind::Elastic)
      sc.v[i * 2 + 1] = speed_ratio * c_p * mode_shape(sc.x[i * 2]) / tip;
  return c;
}

PlateVibration run_oscillating_plate(const Case& c, const std::string& backend) {
  const Scene& sc = c.scene;
  const Material& m = plate_material(sc);
  // Plane strain: E / (1 - nu^2) from the bulk and shear moduli.
  const double k = m.bulk_modulus, mu = m.shear_modulus;
  const double E = young_modulus(k, mu), nu = poisson_ratio(k, mu);
  const double wave = kL / kLength;
  PlateVibration out;
  out.omega_exact = std::sqrt(E * kThickness * kThickness * std::pow(wave, 4) / (12 * m.rest_density * (1 - nu * nu)));
  const auto t0 = std::chrono::steady_clock::now();
  auto engine = make_engine(sc, backend);
  out.particles = engine->particles();
  auto energy = [&] {
    const StepStats s = engine->stats();
    return s.kinetic_energy + s.elastic_energy;
  };
  const double e0 = energy();
  ZeroCrossings crossings;
  const double sample = 2 * M_PI / out.omega_exact / 200;
  for (double t = sample; t <= c.end_time * (1 + 1e-9); t += sample) {
    engine->run_until(t);
    const std::vector<double> x0 = engine->field("reference_position"), u = engine->field("displacement");
    const std::vector<double> mat = engine->field("material");
    double q = 0;
    for (int i = 0; i < engine->particles(); ++i) {
      if (sc.materials[static_cast<int>(mat[i])].props.kind != MaterialKind::Elastic) continue;
      q += u[2 * i + 1] * mode_shape(x0[2 * i]);
      if (x0[2 * i] > kLength - sc.options.spacing) out.tip_amplitude = std::max(out.tip_amplitude, std::fabs(u[2 * i + 1]));
    }
    crossings.add(engine->time(), q);
    out.energy_drift = std::max(out.energy_drift, std::fabs(energy() / e0 - 1));
  }
  if (const double period = crossings.period(); period > 0) out.omega = 2 * M_PI / period;
  out.steps = engine->steps();
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

}  // namespace psph
