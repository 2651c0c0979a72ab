#include "validation/rock_drainage.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "engine/engine.hpp"
#include "monitors/two_phase.hpp"
#include "scene/scene_builder.hpp"
#include "validation/rock_permeability.hpp"

namespace psph {
namespace {

constexpr double kVoxel = 5.345e-6;  // m, one particle per voxel
constexpr long kSleeve = 3, kReservoir = 6;  // voxels

toml::array vec3(double x, double y, double z) { return toml::array{x, y, z}; }

}  // namespace

Case berea_drainage_case(const std::array<long, 3>& lower, const std::array<long, 3>& size, double end) {
  toml::table t = berea_case_table("berea_drainage");
  const double X = double(size[0] + 2 * kSleeve) * kVoxel, Y = double(size[1] + 2 * kSleeve) * kVoxel;
  const double Z = double(size[2] + 2 * kReservoir) * kVoxel, s = double(kSleeve) * kVoxel, r = double(kReservoir) * kVoxel;
  set_case_value(t, "domain.upper", vec3(X, Y, Z));
  set_case_value(t, "monitors.region_lower", vec3(s, s, r));
  set_case_value(t, "monitors.region_upper", vec3(X - s, Y - s, Z - r));
  set_case_value(t, "time.end", toml::value<double>(end));
  toml::array& forced = *t["body_force_region"].as_array();
  forced.at(0).as_table()->insert_or_assign("lower", vec3(0, 0, Z - r));
  forced.at(0).as_table()->insert_or_assign("upper", vec3(X, Y, Z));
  forced.at(1).as_table()->insert_or_assign("upper", vec3(X, Y, r));
  toml::array& geo = *t["geometry"].as_array();
  geo.at(0).as_table()->insert_or_assign("upper", vec3(X, Y, Z));
  geo.at(1).as_table()->insert_or_assign("upper", vec3(X - s, Y - s, Z));
  toml::table& image = *geo.at(2).as_table();
  toml::table crop;
  crop.insert("lower", toml::array{lower[0], lower[1], lower[2]});
  crop.insert("upper", toml::array{lower[0] + size[0], lower[1] + size[1], lower[2] + size[2]});
  image.insert_or_assign("crop", crop);
  Case c = parse_case(t, "cases/berea_drainage.toml");
  build_particles(c);
  return c;
}

RockDrainage run_rock_drainage(const Case& c, const std::string& backend) {
  const auto t0 = std::chrono::steady_clock::now();
  auto engine = make_engine(c.scene, backend);
  TwoPhaseMonitor monitor(c.scene, c.monitor_region);
  RockDrainage out;
  const double interval = c.output.monitor_interval;
  for (double t = 0; t < c.end_time && monitor.percolation_time() < 0;) {
    t = std::min(c.end_time, t + interval);
    engine->run_until(t);
    monitor.sample(*engine);
  }
  const TwoPhaseSample& s = monitor.last();
  out.percolation_time = monitor.percolation_time();
  out.saturation_gas = s.saturation_gas;
  out.capillary_pressure = s.pressure_gas - s.pressure_liquid;
  // rho g H: the forced gas's density and force over both reservoirs' heights
  for (const auto& region : c.scene.force_regions)
    out.driving_pressure += c.scene.materials[std::size_t(region.material)].props.rest_density *
                            std::fabs(region.acceleration[2]) * (region.upper[2] - region.lower[2]);
  out.steps = engine->steps(), out.particles = engine->particles();
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

}  // namespace psph
