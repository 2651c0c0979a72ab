// Case-file checking: each kind of bad input is rejected with the file, the key and what was
// expected.
#include <gtest/gtest.h>

#include "case_text.hpp"
#include "scene/case_file.hpp"
#include "scene/embedded_cases.hpp"
#include "scene/scene_builder.hpp"

using namespace psph;

namespace {

std::string base_case() {
  for (const auto& c : embedded_cases())
    if (std::string(c.name) == "poiseuille_2d") return c.text;
  return "";
}

using test::error_of;
using test::replaced;

void expect_error(const std::string& text, std::initializer_list<const char*> parts) {
  const std::string msg = error_of(text);
  ASSERT_FALSE(msg.empty()) << "accepted a bad case";
  EXPECT_NE(msg.find("bad.toml"), std::string::npos) << msg;
  for (const char* p : parts) EXPECT_NE(msg.find(p), std::string::npos) << "'" << p << "' not in: " << msg;
}

}  // namespace

TEST(CaseFile, EmbeddedCasesAreValid) {
  ASSERT_FALSE(embedded_cases().empty());
  for (const auto& c : embedded_cases()) EXPECT_EQ(error_of(c.text), "") << c.name;
}

TEST(CaseFile, UnknownKey) {
  expect_error(replaced(base_case(), "viscosity = 1.0e-3", "viscosity = 1.0e-3\nviscosty = 2.0"),
               {"materials.water.viscosty", "unknown key", "line"});
}

TEST(CaseFile, MissingRequiredValue) {
  expect_error(replaced(base_case(), "spacing = 5.0e-5", ""), {"discretisation.spacing", "missing required"});
  expect_error(replaced(base_case(), "[time]\nend = 0.5", ""), {"time", "missing required table"});
}

TEST(CaseFile, WrongType) {
  expect_error(replaced(base_case(), "density = 1000.0", "density = \"water\""),
               {"materials.water.density", "expected a number, got a string"});
  expect_error(replaced(base_case(), "dimension = 2", "dimension = 2.5"), {"case.dimension", "expected an integer"});
  expect_error(replaced(base_case(), "periodic = [false, true]", "periodic = [false]"),
               {"domain.periodic", "array of 2 booleans"});
}

TEST(CaseFile, NegativeSpacing) {
  expect_error(replaced(base_case(), "spacing = 5.0e-5", "spacing = -5.0e-5"),
               {"discretisation.spacing", "expected a number > 0", "-5e-05"});
}

TEST(CaseFile, ImpossibleTimeStep) {
  expect_error(replaced(base_case(), "[time]", "[solver]\ndt = 1.0\n\n[time]"), {"solver.dt"});
  expect_error(replaced(base_case(), "[time]", "[solver]\ndt = 1.0e-3\n\n[time]"),
               {"solver.dt", "impossible", "stability limit"});
  expect_error(replaced(base_case(), "end = 0.5", "end = -1.0"), {"time.end", "expected a number > 0"});
}

TEST(CaseFile, GeometryWithNoParticles) {
  expect_error(replaced(base_case(), "material = \"water\"", "material = \"empty\""),
               {"geometry", "no fluid, elastic or rigid particles"});
  expect_error(replaced(base_case(), "material = \"water\"", "material = \"oil\""),
               {"geometry[1].material", "\"oil\""});
}

TEST(CaseFile, BadChoiceListsTheOptions) {
  expect_error(replaced(base_case(), "kernel = \"cubic_spline\"", "kernel = \"gaussian\""),
               {"discretisation.kernel", "\"wendland_c2\"", "\"gaussian\""});
}

TEST(CaseFile, PeriodicAxisNeedsWholeSpacingsAndThreeSupports) {
  expect_error(replaced(base_case(), "upper = [1.15e-3, 4.0e-4]\nperiodic", "upper = [1.15e-3, 4.3e-4]\nperiodic"),
               {"discretisation.spacing", "whole number of spacings"});
  expect_error(replaced(base_case(), "support_radius = 1.0e-4", "support_radius = 1.5e-4"),
               {"support_radius", "shorter than 3 support radii"});
}

TEST(CaseFile, NotToml) {
  expect_error("[case\nname = 1", {"not valid TOML", "line 1"});
}

TEST(CaseFile, SmoothingLengthSetsSupportPerKernel) {
  std::string t = replaced(base_case(), "support_radius = 1.0e-4", "smoothing_length = 3.5e-5");
  t = replaced(t, "kernel = \"cubic_spline\"", "kernel = \"quintic_spline\"");
  Case c = load_case_text(t, "ok.toml");
  EXPECT_NEAR(c.scene.options.support_radius, 1.05e-4, 1e-12);
  expect_error(replaced(base_case(), "support_radius = 1.0e-4", "support_radius = 1.0e-4\nsmoothing_length = 5e-5"),
               {"exactly one of support_radius and smoothing_length"});
}

TEST(CaseFile, LatticeAndMasses) {
  Case c = load_case_text(base_case(), "ok.toml");
  build_particles(c);
  // 26 x 8 lattice sites, 20 x 8 of them water.
  EXPECT_EQ(c.scene.count(), 26 * 8);
  int water = 0;
  for (int m : c.scene.material) water += c.scene.materials[m].name == "water";
  EXPECT_EQ(water, 20 * 8);
}
