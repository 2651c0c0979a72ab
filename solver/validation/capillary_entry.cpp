#include "validation/capillary_entry.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "engine/engine.hpp"
#include "scene/embedded_cases.hpp"
#include "scene/scene_builder.hpp"
#include "state/derived_fields.hpp"

namespace psph {
namespace {

// The slit: the gap between the two wall boxes (geometry 2 and 3) along x.
struct Slit {
  double x0 = 0, x1 = 0, mouth = 0;  // walls' inner faces, top of the slit
};

Slit slit_of(const Case& c) {
  const Bounds a = c.geometry.at(2).shape->bounds(), b = c.geometry.at(3).shape->bounds();
  return Slit{a.upper[0], b.lower[0], a.upper[1]};
}

double drive_of(const Case& c) {
  const SceneForceRegion& f = c.scene.force_regions.at(0);
  return c.scene.materials[f.material].props.rest_density * std::fabs(f.acceleration[1]) * (f.upper[1] - f.lower[1]);
}

double entry_pressure_of(const Case& c) {
  const Slit s = slit_of(c);
  double cos_theta = 1;
  for (const auto& m : c.scene.materials)
    if (m.props.kind == MaterialKind::Wall) cos_theta = m.props.colour;
  return 2 * c.scene.options.surface_tension * cos_theta / (s.x1 - s.x0);
}

}  // namespace

Case capillary_entry_case(double ratio) {
  const std::string file = "cases/capillary_entry_2d.toml";
  toml::table tbl = toml::parse(embedded_case_text("capillary_entry_2d"), std::string_view(file));
  Case c = parse_case(tbl, file);
  SceneForceRegion& f = c.scene.force_regions.at(0);
  const double H = f.upper[1] - f.lower[1], rho = c.scene.materials[f.material].props.rest_density;
  f.acceleration[1] = -ratio * entry_pressure_of(c) / (rho * H);
  build_particles(c);
  return c;
}

EntryResult run_capillary_entry(const Case& c, const std::string& backend) {
  const Scene& sc = c.scene;
  const int D = sc.dimension;
  const Slit slit = slit_of(c);
  EntryResult out;
  out.entry_pressure = entry_pressure_of(c);
  out.drive = drive_of(c);
  out.width = slit.x1 - slit.x0;
  const auto t0 = std::chrono::steady_clock::now();
  auto engine = make_engine(sc, backend);
  out.particles = engine->particles();
  engine->run_until(c.end_time);
  const std::vector<double> x = engine->field("position"), mat = engine->field("material");
  for (int i = 0; i < engine->particles(); ++i) {
    const Material& m = sc.materials[static_cast<int>(mat[i])].props;
    const double xi = x[i * D], yi = x[i * D + 1];
    if (phase_of(m) == Phase::Gas && xi > slit.x0 && xi < slit.x1 && yi < slit.mouth)
      out.depth = std::max(out.depth, slit.mouth - yi);
  }
  out.steps = engine->steps();
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

}  // namespace psph
