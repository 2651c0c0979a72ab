// Loads on elastic solids (solid/solid_load.hpp): a confining traction on every face of a block
// compresses it as the constitutive law says; an imposed velocity stretches a rod by velocity x
// duration and holds it.
#include <array>
#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "case_text.hpp"
#include "stretched_rod.hpp"
#include "engine/engine.hpp"
#include "scene/scene_builder.hpp"

using namespace psph;
using psph::test::expect_refused;

namespace {

// A 2D plane-strain block of 20 x 20 spacings, damped, confined by sigma = 1 kPa on its four
// faces (a traction on each face's outermost layer, ramped over 2 ms).
const std::string kConfined = R"(
[case]
name = "confined"
dimension = 2
[domain]
lower = [0.0, 0.0]
upper = [0.02, 0.02]
[discretisation]
spacing = 1.0e-3
support_radius = 2.0e-3
[materials.clay]
kind = "elastic"
density = 1000.0
young_modulus = 1.0e6
poisson_ratio = 0.25
[solid]
damping_rate = 5.0e3
[time]
end = 0.01
[[geometry]]
shape = "box"
lower = [0.0, 0.0]
upper = [0.02, 0.02]
material = "clay"
[[solid_load]]
material = "clay"
lower = [0.0, 0.0]
upper = [0.001, 0.02]
traction = [1.0e3, 0.0]
ramp_time = 2.0e-3
[[solid_load]]
material = "clay"
lower = [0.019, 0.0]
upper = [0.02, 0.02]
traction = [-1.0e3, 0.0]
ramp_time = 2.0e-3
[[solid_load]]
material = "clay"
lower = [0.0, 0.0]
upper = [0.02, 0.001]
traction = [0.0, 1.0e3]
ramp_time = 2.0e-3
[[solid_load]]
material = "clay"
lower = [0.0, 0.019]
upper = [0.02, 0.02]
traction = [0.0, -1.0e3]
ramp_time = 2.0e-3
)";

std::unique_ptr<Engine> engine_of(const std::string& text) {
  Case c = load_case_text(text, "load.toml");
  build_particles(c);
  return make_engine(c.scene, "cpu");
}

}  // namespace

TEST(SolidLoad, ConfiningTractionCompressesABlockAsTheLawSays) {
  auto e = engine_of(kConfined);
  e->run_until(0.01);
  // The uniform strain fitted to every particle's displacement, u = eps (x0 - centre), per axis.
  const auto x0 = e->field("reference_position"), u = e->field("displacement");
  double num[2] = {0, 0}, den[2] = {0, 0};
  for (int i = 0; i < e->particles(); ++i)
    for (int k = 0; k < 2; ++k) {
      const double r = x0[2 * i + k] - 0.01;
      num[k] += u[2 * i + k] * r, den[k] += r * r;
    }
  // Plane strain under an in-plane pressure sigma: eps_xx = eps_yy = -sigma / (2 (lambda + mu)).
  const double E = 1.0e6, nu = 0.25, lambda = E * nu / ((1 + nu) * (1 - 2 * nu)), mu = E / (2 * (1 + nu));
  const double exact = -1.0e3 / (2 * (lambda + mu));
  for (int k = 0; k < 2; ++k) EXPECT_NEAR(num[k] / den[k] / exact, 1.0, 0.03) << "axis " << k;
  EXPECT_LT(e->stats().kinetic_energy, 1e-10);
}

TEST(SolidLoad, ImposedVelocityStretchesARodAndHoldsIt) {
  const std::string rod = test::stretched_rod_case();  // tests/stretched_rod.hpp
  auto e = engine_of(rod);
  e->run_until(0.05);
  const auto u = e->field("displacement"), strain = e->field("strain"), g = e->field("solid_load_mask");
  const auto m = e->field("material");
  double end_u = 0, lo = 1e9, hi = -1e9;
  for (int i = 0; i < e->particles(); ++i) {
    if (g[i] == 1) end_u = u[i];
    if (g[i] == 0 && m[i] == 1) lo = std::min(lo, strain[i]), hi = std::max(hi, strain[i]);
  }
  EXPECT_NEAR(end_u, 5.0e-5, 5.0e-5 * 0.01);  // v x duration, to the overshoot of one step
  // Uniform strain between the clamp (its mirror plane at x = 0) and the moving end at 0.0985 m
  // (measured -0.5 %: the group's two particles move together, half a spacing of stretch lost).
  EXPECT_LT(hi - lo, 1e-3 * hi);
  EXPECT_NEAR(lo / (5.0e-5 / 0.0985), 1.0, 0.01);
  expect_refused(rod, "velocity = [0.01]", "velocity = [0.01]\ntraction = [1.0]", "give exactly one of traction");
  expect_refused(rod, "material = \"steel\"\nlower = [0.098]", "material = \"clamp\"\nlower = [0.098]",
                 "solid_load[0].material");
  expect_refused(rod, "velocity = [0.01]", "velocity = [0.01]\nramp = 1.0", "solid_load[0].ramp");
}

// An imposed velocity along the named axes only (`axes`, Deptulski eq. 4.31: a face pulled along y
// and free to slide along x): the top layer of a block, pulled up, follows the imposed y velocity
// exactly and contracts freely along x (nu = 0.25), where with every axis held it cannot move.
TEST(SolidLoad, AnImposedVelocityHoldsOnlyItsAxes) {
  const std::string pulled = test::replaced(
      kConfined.substr(0, kConfined.find("[[solid_load]]")) + R"([[solid_load]]
material = "clay"
lower = [0.0, 0.019]
upper = [0.02, 0.02]
velocity = [0.0, 0.01]
axes = ["y"]
[[solid_load]]
material = "clay"
lower = [0.0, 0.0]
upper = [0.02, 0.001]
velocity = [0.0, 0.0]
axes = ["y"]
)", "end = 0.01", "end = 0.004");
  auto top_layer = [](Engine& e) {
    const auto x0 = e.field("reference_position"), u = e.field("displacement"), v = e.field("velocity");
    double ux = 0, uy_min = 1e9, uy_max = -1e9, vy = 0;
    for (int i = 0; i < e.particles(); ++i) {
      if (x0[2 * i + 1] < 0.019) continue;
      ux = std::max(ux, std::fabs(u[2 * i])), vy = std::max(vy, std::fabs(v[2 * i + 1] - 0.01));
      uy_min = std::min(uy_min, u[2 * i + 1]), uy_max = std::max(uy_max, u[2 * i + 1]);
    }
    return std::array<double, 4>{ux, uy_min, uy_max, vy};
  };
  auto e = engine_of(pulled);
  e->run_until(0.004);
  const auto free_x = top_layer(*e);
  EXPECT_GT(free_x[0], 1e-7);  // the layer contracts along x
  EXPECT_NEAR(free_x[1], 4e-5, 4e-5 * 1e-6);  // v t along y, every particle of it
  EXPECT_NEAR(free_x[2], 4e-5, 4e-5 * 1e-6);
  EXPECT_EQ(free_x[3], 0.0);
  auto held = engine_of(test::replaced(pulled, "axes = [\"y\"]\n", ""));
  held->run_until(0.004);
  EXPECT_EQ(top_layer(*held)[0], 0.0);
  expect_refused(pulled, "axes = [\"y\"]\n[[solid_load]]", "axes = [\"z\"]\n[[solid_load]]", "solid_load[0].axes");
  expect_refused(pulled, "axes = [\"y\"]\n[[solid_load]]", "axes = [\"y\", \"y\"]\n[[solid_load]]", "distinct axes among \"xy\"");
  expect_refused(pulled, "axes = [\"y\"]\n[[solid_load]]", "axes = []\n[[solid_load]]", "solid_load[0].axes");
  expect_refused(kConfined, "ramp_time = 2.0e-3\n[[solid_load]]", "ramp_time = 2.0e-3\naxes = [\"x\"]\n[[solid_load]]",
                 "expected velocity for it to apply to");
}

// A rigid inclusion in the confined block (Pazdniakou §5.2.4: it meets the clay by contact only):
// the clay closes on it and the contact carries load, so the block compresses less than without
// it; the inclusion stays centred and takes no net force.
TEST(SolidLoad, ARigidInclusionStiffensAConfinedBlock) {
  auto fitted_strain = [](Engine& e, bool with_disc) {
    const auto x0 = e.field("reference_position"), u = e.field("displacement"), m = e.field("material");
    double num = 0, den = 0;
    for (int i = 0; i < e.particles(); ++i) {
      if (with_disc && m[i] != 0) continue;  // clay only (materials: clay, grain)
      for (int k = 0; k < 2; ++k) {
        const double r = x0[2 * i + k] - 0.01;
        num += u[2 * i + k] * r, den += r * r;
      }
    }
    return num / den;
  };
  auto plain = engine_of(kConfined);
  plain->run_until(0.01);
  const double without = fitted_strain(*plain, false);
  const std::string with_disc = psph::test::replaced(kConfined + R"(
[[geometry]]
shape = "sphere"
center = [0.01, 0.01]
radius = 0.004
material = "grain"
)", "[solid]", R"([materials.grain]
kind = "rigid"
density = 2650.0
[solid])");
  auto e = engine_of(with_disc);
  e->run_until(0.01);
  const double with = fitted_strain(*e, true);
  const RigidBodyState b = e->rigid_bodies().at(0);
  std::printf("fitted strain of the confined block: %.4e without, %.4e with a rigid disc\n", without, with);
  EXPECT_LT(std::fabs(with), 0.95 * std::fabs(without));
  EXPECT_NEAR(b.centre[0], 0.01, 1e-9);
  EXPECT_NEAR(b.centre[1], 0.01, 1e-9);
  EXPECT_LT(std::hypot(b.velocity[0], b.velocity[1]), 1e-9);
}
