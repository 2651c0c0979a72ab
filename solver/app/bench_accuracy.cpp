#include "app/bench_accuracy.hpp"

#include <algorithm>
#include <cmath>

#include "scene/embedded_cases.hpp"
#include "scene/scene_builder.hpp"
#include "validation/channel_flow.hpp"
#include "validation/sphere_array.hpp"

namespace psph {

std::vector<AccuracyRecord> accuracy_sweep(const std::string& backend, bool spheres, std::ostream* log) {
  std::vector<AccuracyRecord> out;
  const std::vector<std::string> kernels{"cubic_spline", "wendland_c2", "quintic_spline"};
  const std::vector<double> times{0.01, 0.04, 0.08, 1.0};  // Pazdniakou Fig. 2
  for (const std::string& kernel : kernels)
    for (double ratio : {2.0, 3.0, 4.0}) {
      toml::table tbl = toml::parse(embedded_case_text("poiseuille_couette_2d"), std::string_view("poiseuille_couette_2d"));
      set_case_value(tbl, "discretisation.kernel", toml::value<std::string>(kernel));
      const double dx = 1e-4 / ratio, L = 1e-3;
      set_case_value(tbl, "discretisation.spacing", toml::value<double>(dx));
      // Walls of whole spacings (at least 1.5 support radii), so that the lattice puts the wall
      // surface halfway between the last fluid and the first wall particle at every resolution.
      const double wall = std::ceil(1.5e-4 / dx - 1e-9) * dx;
      tbl["domain"]["lower"].as_array()->at(0).as_floating_point()->get() = -wall;
      tbl["domain"]["upper"].as_array()->at(0).as_floating_point()->get() = L + wall;
      toml::array& geo = *tbl["geometry"].as_array();
      geo[0].as_table()->at("lower").as_array()->at(0).as_floating_point()->get() = -wall;
      geo[1].as_table()->at("upper").as_array()->at(0).as_floating_point()->get() = L + wall;
      Case c = parse_case(tbl, "cases/poiseuille_couette_2d.toml");
      build_particles(c);
      const ChannelErrors e = channel_flow_errors(c, backend, times);
      AccuracyRecord r{"poiseuille_couette_2d", kernel, ratio, e.particles, e.steps, e.seconds,
                       *std::max_element(e.errors.begin(), e.errors.end())};
      out.push_back(r);
      if (log)
        *log << r.case_name << " " << kernel << " R/dx = " << ratio << ": error " << 100 * r.error << " %, "
             << r.seconds << " s (" << r.particles << " particles, " << r.steps << " steps)" << std::endl;
    }
  if (spheres)
    for (double phi : {0.343, 0.45, 0.5236}) {
      const Case c = sphere_array_case(phi, 2.0);
      const Permeability p = measure_permeability(c, backend);
      AccuracyRecord r{"sphere_array_" + std::to_string(phi).substr(0, 5), "cubic_spline", 2.0, p.particles, p.steps,
                       p.seconds, std::fabs(p.K / sphere_array_reference(phi) - 1)};
      out.push_back(r);
      if (log)
        *log << r.case_name << " R/dx = 2: error " << 100 * r.error << " %, " << r.seconds << " s" << std::endl;
    }
  return out;
}

}  // namespace psph
