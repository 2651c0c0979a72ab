// Two fluids: the case options ([interface], phase, contact_angle, the density default) and the
// interface passes on a flat and a curved interface.
#include <cmath>

#include <gtest/gtest.h>

#include "case_text.hpp"
#include "engine/engine.hpp"
#include "scene/case_file.hpp"
#include "scene/embedded_cases.hpp"
#include "scene/scene_builder.hpp"
#include "state/derived_fields.hpp"
#include "validation/laplace_bubble.hpp"

using namespace psph;

namespace {

std::string bubble_text() { return embedded_case_text("laplace_bubble_2d"); }

using test::error_of;
using test::replaced;

}  // namespace

TEST(TwoFluids, CaseOptions) {
  const Case c = load_case_text(bubble_text(), "laplace.toml");
  EXPECT_EQ(c.scene.options.surface_tension, 1e-3);
  for (const auto& m : c.scene.materials) EXPECT_EQ(m.props.colour, m.name == "gas" ? -1 : 1) << m.name;
  EXPECT_EQ(c.scene.options.density, DensityMethod::Summation);  // equal densities
  // A density ratio selects the number-density form by default.
  const Case ratio = load_case_text(replaced(bubble_text(), "phase = \"gas\"\ndensity = 1000.0", "phase = \"gas\"\ndensity = 1.0"), "r.toml");
  EXPECT_EQ(ratio.scene.options.density, DensityMethod::NumberSummation);
  EXPECT_EQ(phase_of(ratio.scene.materials[0].props), Phase::Gas);  // "gas" sorts before "water"
}

TEST(TwoFluids, BadInput) {
  // Surface tension without a gas.
  const std::string no_gas = error_of(replaced(bubble_text(), "phase = \"gas\"\n", ""));
  EXPECT_NE(no_gas.find("interface.surface_tension"), std::string::npos) << no_gas;
  EXPECT_NE(no_gas.find("phase = \"gas\""), std::string::npos) << no_gas;
  // A wall without a contact angle in a case with surface tension.
  const std::string wall = error_of(replaced(bubble_text(), "[interface]", "[materials.rock]\nkind = \"wall\"\n\n[interface]"));
  EXPECT_NE(wall.find("materials.rock.contact_angle"), std::string::npos) << wall;
  const std::string angle =
      error_of(replaced(bubble_text(), "[interface]", "[materials.rock]\nkind = \"wall\"\ncontact_angle = 200.0\n\n[interface]"));
  EXPECT_NE(angle.find("between 0 and 180"), std::string::npos) << angle;
  EXPECT_NE(error_of(replaced(bubble_text(), "phase = \"gas\"", "phase = \"oil\"")).find("materials.gas.phase"),
            std::string::npos);
}

TEST(TwoFluids, ContactAngleSetsTheWallColour) {
  const Case c = load_case_text(
      replaced(bubble_text(), "[interface]", "[materials.rock]\nkind = \"wall\"\ncontact_angle = 60.0\n\n[interface]"), "w.toml");
  for (const auto& m : c.scene.materials)
    if (m.name == "rock") EXPECT_NEAR(m.props.colour, 0.5, 1e-6);
}

namespace {

// Over the particles within one spacing of the initial sphere (disc) of radius R: the normal
// points outward, and the mean curvature times R is returned.
double mean_kappa_R(const Case& c, double R) {
  const int D = c.scene.dimension;
  auto e = make_engine(c.scene, "cpu");
  const std::vector<double> x = e->field("position"), n = e->field("colour_gradient");
  const std::vector<double> kappa = e->field("curvature"), colour = e->field("colour");
  const double centre = 0.5 * (c.scene.upper[0] - c.scene.lower[0]);
  int band = 0;
  double mean_kappa = 0;
  for (int i = 0; i < e->particles(); ++i) {
    double r2 = 0, outward = 0;
    for (int k = 0; k < D; ++k) r2 += (x[D * i + k] - centre) * (x[D * i + k] - centre), outward += n[D * i + k] * (x[D * i + k] - centre);
    EXPECT_GE(colour[i], -1 - 1e-6);
    EXPECT_LE(colour[i], 1 + 1e-6);
    if (std::fabs(std::sqrt(r2) - R) > 1e-4) continue;  // within one spacing of the interface
    EXPECT_GT(outward, 0) << "normal not outward at r = " << std::sqrt(r2);
    mean_kappa += kappa[i], ++band;
  }
  EXPECT_GT(band, 20);
  return band ? mean_kappa / band * R : 0.0;
}

}  // namespace

// At the first force evaluation of the bubble (a disc on the lattice), the interface normal
// points out of the gas (gas -> liquid), and the curvature is negative (kappa = -div n^ ~ -1/R)
// so that the surface force points into the gas.
TEST(TwoFluids, NormalAndCurvatureSignsOnABubble) {
  const double k = mean_kappa_R(laplace_bubble_case(8), 8e-4);
  EXPECT_LT(k, 0);
  EXPECT_NEAR(k, -1, 0.25);  // a lattice disc: within 25 % of -1/R before relaxing
}

// The same in 3D: kappa = -div n^ ~ -2/R on a lattice sphere.
TEST(TwoFluids, CurvatureOfA3DBubble) {
  const double k = mean_kappa_R(laplace_bubble_case(6, "quintic_spline", 3, 3), 6e-4);
  EXPECT_NEAR(k, -2, 0.5);
}

// A uniform pressure exerts no force, also across a flat interface at density ratio 1000: the
// number-density form with the Hu & Adams volume weights (fluid/momentum.hpp) is symmetric in the
// particle volumes, where eq. 54b would weigh each gas particle's pressure by its water
// neighbours' 1000 times larger masses. The walls carry the background pressure too.
TEST(TwoFluids, UniformPressureExertsNoForceAtADensityRatio) {
  std::string text = embedded_case_text("two_phase_poiseuille_2d");
  text = replaced(text, "body_force = [0.0, 1.0e-4]", "body_force = [0.0, 0.0]");
  text = replaced(text, "body_force = [0.0, 0.1]", "body_force = [0.0, 0.0]");
  text = replaced(text, "[time]", "[solver]\nbackground_pressure = 1.0\n\n[time]");
  Case c = load_case_text(text, "two_phase_p0.toml");
  build_particles(c);
  EXPECT_EQ(c.scene.options.density, DensityMethod::NumberSummation);
  for (const auto& m : c.scene.materials) {
    EXPECT_EQ(m.props.background_pressure, 1.0f) << m.name;
    if (m.name == "wall") EXPECT_EQ(m.props.rest_density, 1000.0f);  // the densest fluid's
  }
  auto e = make_engine(c.scene, "cpu");
  const std::vector<double> a = e->field("acceleration"), p = e->field("pressure"), mat = e->field("material");
  // Scale: the acceleration 1 Pa would give a gas particle across one spacing.
  const double scale = 1.0 / (1.0 * c.scene.options.spacing);
  double worst = 0;
  for (int i = 0; i < e->particles(); ++i) {
    EXPECT_NEAR(p[i], 1.0, 1e-4) << "particle " << i;
    if (c.scene.materials[static_cast<int>(mat[i])].props.kind == MaterialKind::Fluid)
      worst = std::max(worst, std::hypot(a[2 * i], a[2 * i + 1]));
  }
  EXPECT_LT(worst, 1e-4 * scale);
}

// Implicit viscosity: the gas's viscous limit no longer sets the step, the solve converges in a
// few iterations, and a tensor Laplacian (explicit only) is refused.
TEST(TwoFluids, ImplicitViscosityLiftsTheViscousLimit) {
  std::string text = embedded_case_text("two_phase_poiseuille_2d");
  for (bool implicit : {false, true}) {
    Case c = load_case_text(implicit ? replaced(text, "[time]", "[solver]\nimplicit_viscosity = true\n\n[time]") : text, "t.toml");
    build_particles(c);
    auto e = make_engine(c.scene, "cpu");
    for (int k = 0; k < 3; ++k) e->step(1.0);
    const StepStats st = e->stats();
    if (implicit) {
      EXPECT_EQ(st.dt_limit, "acoustic");
      EXPECT_GT(e->last_dt(), 100 * 3.1e-6);  // the gas's viscous limit is 3.1e-6 s
      EXPECT_GT(st.linear_iterations, 0);
      EXPECT_LT(st.linear_iterations, 200);
    } else {
      EXPECT_EQ(st.dt_limit, "viscous");
      EXPECT_EQ(st.linear_iterations, 0);
    }
  }
  const std::string tensor =
      error_of(replaced(text, "[time]", "[solver]\nimplicit_viscosity = true\nlaplacian_correction = \"tensor\"\n\n[time]"));
  EXPECT_NE(tensor.find("solver.laplacian_correction"), std::string::npos) << tensor;
}
