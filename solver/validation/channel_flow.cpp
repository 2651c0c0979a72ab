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

OpenChannelErrors open_channel_errors(const Case& c, const std::string& backend) {
  const Scene& sc = c.scene;
  const SceneOpenBoundary& ob = sc.open_boundary;
  const int D = sc.dimension, flow = ob.axis, samples = 20;
  double mu = 0;
  for (const auto& m : sc.materials)
    if (m.props.kind == MaterialKind::Fluid) mu = m.props.viscosity;
  const double W = 1e-3, dx = sc.options.spacing;  // walls at x = 0 and x = W, as in the body-force channels
  const double lo = ob.lower + ob.thickness, hi = ob.upper - ob.thickness, L = hi - lo;
  const double G = (ob.inlet_pressure - ob.outlet_pressure) / L;
  OpenChannelErrors out;
  out.peak = G * W * W / (8 * mu);
  const int bins = static_cast<int>(std::lround(W / dx));
  std::vector<double> bin_sum(bins, 0.0), bin_count(bins, 0.0), means;
  const auto t0 = std::chrono::steady_clock::now();
  auto engine = make_engine(sc, backend);
  out.particles = engine->particles();
  for (int k = 0; k < samples; ++k) {
    engine->run_until(c.end_time * (0.5 + 0.5 * (k + 1) / samples));
    const std::vector<double> x = engine->field("position"), v = engine->field("velocity");
    const std::vector<double> mat = engine->field("material");
    double sum = 0;
    int count = 0;
    for (int i = 0; i < engine->particles(); ++i) {
      if (sc.materials[static_cast<int>(mat[i])].props.kind != MaterialKind::Fluid) continue;
      const double y = x[i * D + flow], u = v[i * D + flow];
      if (y < lo || y >= hi) continue;
      sum += u, ++count;
      const int bin = static_cast<int>(std::floor(x[i * D] / dx));
      if (y > lo + L / 4 && y < hi - L / 4 && bin >= 0 && bin < bins) bin_sum[bin] += u, bin_count[bin] += 1;
    }
    means.push_back(count ? sum / count : 0.0);
  }
  double mean = 0;
  for (double m : means) mean += m / samples;
  for (double m : means) out.flux_spread = std::max(out.flux_spread, std::fabs(m / mean - 1));
  out.flux_error = mean / (2 * out.peak / 3) - 1;
  for (int b = 0; b < bins; ++b) {
    if (bin_count[b] == 0) continue;
    const double xc = (b + 0.5) * dx, exact = G * xc * (W - xc) / (2 * mu);
    out.profile_error = std::max(out.profile_error, std::fabs(bin_sum[b] / bin_count[b] - exact) / out.peak);
  }
  out.steps = engine->steps();
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

}  // namespace psph
