// The compressibility estimate (scene/compressibility.hpp) on cases whose terms are known in closed
// form, and its two ways out: the sound speed and the drive it names bring the estimate to 1 %.
#include <gtest/gtest.h>

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

double term(const CompressibilityEstimate& e, const std::string& what, const std::string& detail_part = "") {
  double v = 0;
  for (const auto& t : e.terms)
    if (t.what == what && t.detail.find(detail_part) != std::string::npos) v += t.value;
  return v;
}

}  // namespace

// Water 1 m high at rest under g = 1 m/s^2 with c = 20 m/s and a free surface: the head g H / c^2
// and free fall over the height, 2 g H / c^2.
TEST(Compressibility, DamBreakHeadAndFreeFall) {
  const CompressibilityEstimate e = estimate_compressibility(embedded("dam_break_3d"));
  EXPECT_NEAR(term(e, "body force"), 1.0 / 400, 1e-12);
  EXPECT_NEAR(term(e, "speed", "free fall"), 2.0 / 400, 1e-12);
  EXPECT_FALSE(e.exceeds());
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
