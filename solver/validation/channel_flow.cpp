#include "validation/channel_flow.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "engine/engine.hpp"
#include "validation/analytic.hpp"

namespace psph {

ChannelErrors channel_flow_errors(const Case& c, const std::string& backend, const std::vector<double>& times) {
  const Scene& sc = c.scene;
  const int D = sc.dimension, flow = D - 1;
  const SceneMaterial* water = nullptr;
  for (const auto& m : sc.materials)
    if (m.props.kind == MaterialKind::Fluid) water = &m;
  double V = 0;  // moving-wall speed along the flow axis
  for (const auto& g : c.geometry) V = std::max(V, g.velocity[flow]);
  const double L = 1e-3, g = water->body_force[flow];
  const double nu = water->props.viscosity / water->props.rest_density;
  const auto t0 = std::chrono::steady_clock::now();
  auto engine = make_engine(sc, backend);
  ChannelErrors out;
  out.particles = engine->particles();
  for (double t : times) {
    engine->run_until(t);
    const std::vector<double> x = engine->field("position"), v = engine->field("velocity");
    const std::vector<double> mat = engine->field("material");
    double peak = V, err = 0;  // the profile's peak includes the moving wall
    for (int i = 0; i < engine->particles(); ++i) {
      if (sc.materials[static_cast<int>(mat[i])].props.kind != MaterialKind::Fluid) continue;
      const double exact = poiseuille_couette_velocity(x[i * D], t, L, g, V, nu);
      peak = std::max(peak, std::fabs(exact));
      err = std::max(err, std::fabs(v[i * D + flow] - exact));
    }
    out.times.push_back(t), out.errors.push_back(err / peak), out.peaks.push_back(peak);
  }
  out.steps = engine->steps();
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

TwoPhaseChannelErrors two_phase_channel_errors(const Case& c, const std::string& backend) {
  const Scene& sc = c.scene;
  const int D = sc.dimension, flow = D - 1;
  double F = 0, mu_gas = 0, mu_liquid = 0;
  for (const auto& m : sc.materials) {
    if (m.props.kind != MaterialKind::Fluid) continue;
    (m.props.colour < 0 ? mu_gas : mu_liquid) = m.props.viscosity;
    F = m.body_force[flow] * m.props.rest_density;  // the same force per volume in both phases
  }
  const auto t0 = std::chrono::steady_clock::now();
  auto engine = make_engine(sc, backend);
  engine->run_until(c.end_time);
  const std::vector<double> x = engine->field("position"), v = engine->field("velocity");
  const std::vector<double> mat = engine->field("material");
  auto is_fluid = [&](int i) { return sc.materials[static_cast<int>(mat[i])].props.kind == MaterialKind::Fluid; };
  double l = 0;
  for (int i = 0; i < engine->particles(); ++i)
    if (is_fluid(i)) l = std::max(l, std::fabs(x[i * D]) + sc.options.spacing / 2);
  TwoPhaseChannelErrors out;
  // Gas peak at x = (l/2)(mu_g - mu_l)/(mu_g + mu_l); the liquid's is at the interface.
  out.gas_peak = two_phase_poiseuille_velocity(0.5 * l * (mu_gas - mu_liquid) / (mu_gas + mu_liquid), l, F, mu_gas, mu_liquid);
  out.liquid_peak = two_phase_poiseuille_velocity(0.0, l, F, mu_gas, mu_liquid);
  for (int i = 0; i < engine->particles(); ++i) {
    if (!is_fluid(i)) continue;
    const double err = std::fabs(v[i * D + flow] - two_phase_poiseuille_velocity(x[i * D], l, F, mu_gas, mu_liquid));
    out.error_of_gas_peak = std::max(out.error_of_gas_peak, err / out.gas_peak);
    if (x[i * D] > 0) out.error_of_liquid_peak = std::max(out.error_of_liquid_peak, err / out.liquid_peak);
  }
  out.particles = engine->particles();
  out.steps = engine->steps();
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

}  // namespace psph
