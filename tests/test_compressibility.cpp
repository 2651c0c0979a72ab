// The compressibility estimate (scene/compressibility.hpp) on cases whose terms are known in closed
// form, and its two ways out: the sound speed and the drive it names bring the estimate to 1 %.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <string>

#include "scene/case_file.hpp"
#include "scene/compressibility.hpp"
#include "scene/embedded_cases.hpp"
#include "scene/scene_builder.hpp"

using namespace psph;

namespace {

Case embedded(const std::string& name, const std::vector<std::string>& sets = {}) {
  Case c = load_case_text(embedded_case_text(name), "cases/" + name + ".toml", sets);
  build_particles(c);
  return c;
}

std::string num(double v) {
  std::ostringstream o;
  o.precision(17);
  o << v;
  return o.str();
}

double term(const CompressibilityEstimate& e, const std::string& what, const std::string& detail_part = "",
            const std::string& fluid = "") {
  double v = 0;
  for (const auto& t : e.terms)
    if (t.what == what && t.detail.find(detail_part) != std::string::npos && (fluid.empty() || t.fluid == fluid)) v += t.value;
  return v;
}

}  // namespace

// Water 1 m high at rest under g = 1 m/s^2 with c = 20 m/s and a free surface: the head g H / c^2
// and the impact of free fall over the height onto a wall, sqrt(2 g H) / c (7 %: the case warns;
// measured 4.3 %).
TEST(Compressibility, DamBreakHeadAndFreeFall) {
  const CompressibilityEstimate e = estimate_compressibility(embedded("dam_break_3d"));
  EXPECT_NEAR(term(e, "body force"), 1.0 / 400, 1e-12);
  EXPECT_NEAR(term(e, "impact", "free fall"), std::sqrt(2.0) / 20, 1e-12);
  EXPECT_TRUE(e.exceeds());
}

// A straight channel along a periodic force carries no pressure field (no head term); its speed is
// the plane Poiseuille peak g w^2 / (8 nu) = 1.25e-4 m/s in the 1 mm gap, (v/c)^2 at c = 0.01 m/s.
TEST(Compressibility, StraightChannelHasNoHeadAndItsPoiseuillePeak) {
  const CompressibilityEstimate e = estimate_compressibility(embedded("poiseuille_2d"));
  EXPECT_EQ(term(e, "body force"), 0.0);
  EXPECT_NEAR(term(e, "speed", "Stokes flow"), 1.5625e-4, 1e-9);
}

// Past 1 %, the sound speed it names and the drive factor it names each give 1 %.
TEST(Compressibility, TheWaysOutHoldOnePercent) {
  const CompressibilityEstimate e = estimate_compressibility(embedded("poiseuille_2d", {"materials.water.sound_speed=5e-4"}));
  ASSERT_TRUE(e.exceeds());
  const CompressibilityEstimate faster = estimate_compressibility(
      embedded("poiseuille_2d", {"materials.water.sound_speed=" + std::to_string(e.sound_speed_needed)}));
  EXPECT_NEAR(faster.total, 0.01, 1e-4);
  const double g = 1e-3 * e.drive_factor;
  const CompressibilityEstimate gentler = estimate_compressibility(
      embedded("poiseuille_2d", {"materials.water.sound_speed=5e-4", "materials.water.body_force=[0.0, " + std::to_string(g) + "]"}));
  EXPECT_NEAR(gentler.total, 0.01, 1e-4);
}

// Through a sphere array (a pressure field turns the flow) the pressure settles in L^2 nu /
// (pi^2 c^2 K), K bounded by the sections: positive, falling as 1/c^2, and a run shorter than three
// of it is told to raise the sound speed to the one that makes it a third of the run. A straight
// channel has no pressure field to settle.
TEST(Compressibility, PressureSettlingTime) {
  const CompressibilityEstimate e = estimate_compressibility(embedded("sphere_array"));
  ASSERT_GT(e.settle_time, 0.0);
  const CompressibilityEstimate fast = estimate_compressibility(embedded("sphere_array", {"materials.water.sound_speed=" + num(2 * e.settle_sound_speed)}));
  EXPECT_NEAR(fast.settle_time, e.settle_time / 4, 1e-9 * e.settle_time);
  const CompressibilityEstimate brief = estimate_compressibility(embedded("sphere_array", {"time.end=" + num(e.settle_time)}));
  ASSERT_TRUE(brief.settles_late());
  const CompressibilityEstimate enough = estimate_compressibility(embedded(
      "sphere_array", {"time.end=" + num(e.settle_time), "materials.water.sound_speed=" + num(brief.settle_sound_speed_needed)}));
  EXPECT_NEAR(enough.settle_time, enough.end_time / 3, 1e-6 * enough.end_time);
  EXPECT_EQ(estimate_compressibility(embedded("poiseuille_2d")).settle_time, 0.0);
}

// A driven drainage's impacts (v/c, Joukowsky): a Haines jump at sigma / (6 mu_liquid) in 2D
// (drainage_2d: 1e-3 / (6 x 2.5e-3) m/s at c = 3 m/s); the gas's jet after percolation at
// sqrt(2 dP / rho) (dP = 1000 x 5 x 2.4e-3 Pa, the larger reservoir) only where the run goes on past
// it. The sound speed named for 1 % gives 1 % with these 1/c terms too.
TEST(Compressibility, DrainageImpacts) {
  const CompressibilityEstimate e = estimate_compressibility(embedded("drainage_2d"));
  EXPECT_NEAR(term(e, "impact", "Haines", "gas"), 1e-3 / (6 * 2.5e-3) / 3, 1e-12);
  EXPECT_EQ(term(e, "impact", "percolates"), 0.0);
  const CompressibilityEstimate on = estimate_compressibility(embedded("drainage_2d", {"time.after_percolation=0.01"}));
  EXPECT_NEAR(term(on, "impact", "percolates", "gas"), std::sqrt(2 * 1000 * 5 * 2.4e-3 / 1000) / 3, 1e-12);
  ASSERT_TRUE(on.exceeds());
  const CompressibilityEstimate faster = estimate_compressibility(embedded(
      "drainage_2d", {"time.after_percolation=0.01", "materials.water.sound_speed=" + num(on.sound_speed_needed),
                      "materials.gas.sound_speed=" + num(on.sound_speed_needed)}));
  EXPECT_NEAR(faster.total, 0.01, 1e-4);
}
