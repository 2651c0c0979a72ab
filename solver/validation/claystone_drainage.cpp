#include "validation/claystone_drainage.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "engine/engine.hpp"
#include "monitors/two_phase.hpp"
#include "scene/embedded_cases.hpp"
#include "scene/scene_builder.hpp"

namespace psph {
namespace {

double monitor(const std::vector<MonitorValue>& row, const std::string& name) {
  for (const MonitorValue& m : row)
    if (m.name == name) return m.value;
  return std::nan("");
}

}  // namespace

Case claystone_case(const std::vector<std::string>& sets) {
  Case c = load_case_text(embedded_case_text("claystone_drainage"), "cases/claystone_drainage.toml", sets);
  build_particles(c);
  return c;
}

ClaystoneDrainage run_claystone_drainage(const Case& c, const std::string& backend, bool stop_at_percolation) {
  const auto t0 = std::chrono::steady_clock::now();
  auto engine = make_engine(c.scene, backend);
  TwoPhaseMonitor two_phase(c.scene, c.monitor_region, c.stress_scale);
  long damageable = 0;  // the clay's particles (the lateral layers do not damage)
  for (int m : c.scene.material) damageable += c.scene.options.damages(m);
  ClaystoneDrainage out;
  out.image_porosity = c.images.at(0).at("coarse_porosity").get<double>();
  const double interval = c.output.monitor_interval > 0 ? c.output.monitor_interval : c.end_time / 100;
  for (double t = 0;;) {
    two_phase.sample(*engine);
    const std::vector<MonitorValue> stages = engine->monitors();
    const TwoPhaseSample& s = two_phase.last();
    if (t == 0) out.porosity_start = s.porosity;
    out.porosity_end = s.porosity, out.saturation_gas_end = s.saturation_gas;
    out.worst_saturation_sum = std::max(out.worst_saturation_sum, std::fabs(s.saturation_liquid + s.saturation_gas - 1));
    out.damaged_end = monitor(stages, "damaged_particles"), out.total_damage_end = monitor(stages, "total_damage");
    out.worst_damage_ratio = std::max(out.worst_damage_ratio, out.total_damage_end / double(std::max(damageable, 1L)));
    if (t >= c.end_time || (stop_at_percolation && two_phase.percolation_time() >= 0)) break;
    t = std::min(c.end_time, t + interval);
    engine->run_until(t);
  }
  out.percolation_time = two_phase.percolation_time();
  out.saturation_at_percolation = two_phase.saturation_at_percolation();
  out.steps = engine->steps(), out.particles = engine->particles();
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

// The CI crop: the fracture's upper part, 16 x 24 x 20 voxels (the crop of tests/test_sample_table.cpp),
// reservoirs of 4 voxels, 20 us with the drive ramped over 50 us (over the case's 100 us the gas
// has not entered the sample by 20 us): 21,504 particles.
const std::vector<std::string> kCiCrop = {
    "sample.image.crop.lower=[16, 12, 30]", "sample.image.crop.upper=[32, 36, 50]", "sample.reservoir_height=8e-8",
    "sample.drive_ramp=5e-5", "time.end=2e-5", "output.monitor_interval=1e-6"};

std::vector<ValidationRecord> claystone_drainage_records(const ValidationContext& ctx) {
  const std::string name = "claystone_drainage";
  std::vector<ValidationRecord> out;
  if (ctx.full) {  // Pazdniakou 2018 Table 5 at 6 MPa with damage: 7.58 ms, S_g 0.5043
    const Case c = claystone_case({"sample.image.particles_per_voxel=2", "discretisation.spacing=1e-8",
                                   "discretisation.support_radius=2e-8", "time.end=0.02"});
    const ClaystoneDrainage r = run_claystone_drainage(c, ctx.backend, true);
    if (ctx.log)
      *ctx.log << "  published cell, " << r.particles << " particles: percolation at " << r.percolation_time
               << " s, gas saturation " << r.saturation_at_percolation << ", " << r.steps << " steps, " << r.seconds << " s\n";
    const double tp = r.percolation_time >= 0 ? r.percolation_time : NAN;
    out.push_back(make_record(name, "percolation time (s), 6 MPa", tp, 7.58e-3, std::fabs(tp / 7.58e-3 - 1), 0.2));
    out.push_back(make_record(name, "gas saturation at percolation, 6 MPa", r.saturation_at_percolation, 0.5043,
                              std::fabs(r.saturation_at_percolation - 0.5043), 0.05));
    return out;
  }
  const ClaystoneDrainage r = run_claystone_drainage(claystone_case(kCiCrop), ctx.backend, false);
  if (ctx.log)
    *ctx.log << "  crop 16x24x20, " << r.particles << " particles, " << r.steps << " steps, " << r.seconds
             << " s: porosity " << r.porosity_start << " -> " << r.porosity_end << " (image " << r.image_porosity
             << "), gas saturation " << r.saturation_gas_end << ", damaged particles " << r.damaged_end
             << ", total damage " << r.total_damage_end << "\n";
  out.push_back(make_record(name, "porosity at t = 0 (fluid volume / sample) / the image's", r.porosity_start,
                            r.image_porosity, std::fabs(r.porosity_start / r.image_porosity - 1), 0.03));
  out.push_back(make_record(name, "max |S_w + S_g - 1| over the rows", r.worst_saturation_sum, 0, r.worst_saturation_sum, 1e-9));
  out.push_back(make_record(name, "max total damage / clay particles (each D <= 1)", r.worst_damage_ratio, 1,
                            r.worst_damage_ratio, 1.0));
  out.push_back(make_record(name, "gas saturation at the end (gas entered: > 0.005)", r.saturation_gas_end, 0.005,
                            0.005 / std::max(r.saturation_gas_end, 1e-12), 1.0));
  return out;
}

}  // namespace psph
