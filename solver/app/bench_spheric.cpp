// SPHERIC test 2 at any spacing (cases/spheric_dam_break_3d.toml), for `poresph bench`.
#include <sstream>

#include "app/bench_cases.hpp"
#include "scene/embedded_cases.hpp"
#include "scene/scene_builder.hpp"

namespace psph {

// The tank's walls stay 4 spacings thick (one support radius) at every spacing, so that the
// particle count, the figure the published particle-steps per second divide by, is not inflated
// by layers that never meet the water.
Case spheric_dam_break_case(double spacing) {
  const std::string file = "cases/spheric_dam_break_3d.toml";
  toml::table t = toml::parse(embedded_case_text("spheric_dam_break_3d"), file);
  set_case_spacing(t, spacing);
  const double w = 4 * spacing;
  const toml::array lower{-w, -w, -w}, upper{3.22 + w, 1.0 + w, 2.0 + w};
  for (toml::table* box : {t["domain"].as_table(), t["geometry"][0].as_table()})
    box->insert_or_assign("lower", lower), box->insert_or_assign("upper", upper);
  std::ostringstream os;
  os << t;
  Case c = load_case_text(os.str(), file);
  build_particles(c);
  return c;
}

}  // namespace psph
