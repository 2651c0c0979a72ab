// Rigid bodies (rigid/): the case keys, contact between bodies (momentum kept exactly, energy
// nearly, no overlap) and with walls (a body rests on a floor).
#include <cmath>

#include <gtest/gtest.h>

#include "case_text.hpp"
#include "engine/engine.hpp"
#include "rigid/rigid_bodies.hpp"
#include "scene/scene_builder.hpp"

using namespace psph;
using psph::test::expect_refused;
using psph::test::replaced;

namespace {

// Two 2D boxes of 4 x 4 particles, 3 spacings apart along x and offset by 2 spacings in y,
// approaching each other in an empty periodic box: an off-centre collision.
const std::string kPair = R"(
[case]
name = "pair"
dimension = 2
[domain]
lower = [0.0, 0.0]
upper = [0.024, 0.024]
periodic = [true, true]
[discretisation]
spacing = 1.0e-3
support_radius = 2.0e-3
[materials.a_grain]
kind = "rigid"
density = 2650.0
sound_speed = 20.0
[materials.b_grain]
kind = "rigid"
density = 1000.0
sound_speed = 20.0
[time]
end = 0.03
[[geometry]]
shape = "box"
lower = [0.004, 0.008]
upper = [0.008, 0.012]
material = "a_grain"
velocity = [0.1, 0.0]
[[geometry]]
shape = "box"
lower = [0.011, 0.0096]
upper = [0.015, 0.0136]
material = "b_grain"
velocity = [-0.1, 0.0]
angular_velocity = 2.0
)";

std::unique_ptr<Engine> engine_of(const std::string& text) {
  Case c = load_case_text(text, "rigid.toml");
  build_particles(c);
  return make_engine(c.scene, "cpu");
}

// Linear momentum (x, y) and angular momentum about the origin (z) of all bodies.
std::array<double, 3> momenta(const Engine& e) {
  std::array<double, 3> p{0, 0, 0};
  for (const RigidBodyState& b : e.rigid_bodies()) {
    p[0] += b.mass * b.velocity[0], p[1] += b.mass * b.velocity[1];
    p[2] += b.angular_momentum[2] + b.mass * (b.centre[0] * b.velocity[1] - b.centre[1] * b.velocity[0]);
  }
  return p;
}

}  // namespace

TEST(Rigid, CaseKeys) {
  // Each rigid geometry is one body; the particles carry it.
  Case c = load_case_text(kPair, "rigid.toml");
  build_particles(c);
  ASSERT_EQ(c.scene.body_angular_velocity.size(), 2u);
  int in_a = 0, in_b = 0;
  for (int b : c.scene.body) (b == 0 ? in_a : b == 1 ? in_b : in_a) += b >= 0;
  EXPECT_EQ(in_a, 16);
  EXPECT_EQ(in_b, 16);
  EXPECT_DOUBLE_EQ(c.scene.body_angular_velocity[1][2], 2.0);
  expect_refused(kPair, "sound_speed = 20.0\n[materials.b_grain]", "\n[materials.b_grain]", "materials.a_grain.sound_speed");
  expect_refused(kPair, "velocity = [0.1, 0.0]", "velocity = [0.1, 0.0]\nangular_velocity = [1.0, 2.0]",
                 "geometry[0].angular_velocity");
  expect_refused(kPair, "upper = [0.008, 0.012]", "upper = [0.0042, 0.0082]", "geometry[0]: this rigid body holds no particle");
  expect_refused(kPair, "upper = [0.008, 0.012]", "upper = [0.005, 0.009]", "geometry[0]: this rigid body's 1 particles");
  expect_refused(kPair, "shape = \"box\"\nlower = [0.004, 0.008]\nupper = [0.008, 0.012]",
                 "shape = \"grain_pack\"\nlower = [0.004, 0.008]\nupper = [0.008, 0.012]\ngrain_radius = 0.0005\nmin_gap = 0.0\n"
                 "solid_fraction = 0.05",
                 "geometry[0].material");
  // With a fluid: its explicit viscous force is what the body takes.
  const std::string wet = replaced(kPair, "[time]", R"([materials.water]
kind = "fluid"
density = 1000.0
viscosity = 1.0e-3
sound_speed = 1.0
[solver]
implicit_viscosity = true
[time])");
  EXPECT_NE(psph::test::error_of(wet).find("solver.implicit_viscosity"), std::string::npos) << psph::test::error_of(wet);
}

TEST(Rigid, CollisionKeepsMomentumExactlyAndEnergyNearly) {
  auto e = engine_of(kPair);
  const auto p0 = momenta(*e);
  const double ke0 = e->stats().kinetic_energy;
  double closest = 1e9;  // between the two bodies' particles, over the run
  while (e->time() < 0.03) {
    for (int s = 0; s < 20; ++s) e->step(0.03);
    const auto x = e->field("position"), body = e->field("rigid_body");
    for (int i = 0; i < e->particles(); ++i)
      for (int j = 0; j < e->particles(); ++j)
        if (body[i] == 0 && body[j] == 1)
          closest = std::min(closest, std::hypot(x[2 * i] - x[2 * j], x[2 * i + 1] - x[2 * j + 1]));
  }
  const auto p1 = momenta(*e);
  const double scale = 2 * 0.1 * e->rigid_bodies()[0].mass;
  EXPECT_NEAR(p1[0], p0[0], 1e-12 * scale);
  EXPECT_NEAR(p1[1], p0[1], 1e-12 * scale);
  EXPECT_NEAR(p1[2], p0[2], 1e-12 * scale * 0.024);
  // They met and came apart: the light b bounced back (head on and elastic: +0.19 m/s).
  EXPECT_GT(e->rigid_bodies()[1].velocity[0], 0.05);
  EXPECT_NE(e->rigid_bodies()[0].angular_momentum[2], 0.0);
  EXPECT_GT(closest, 0.95e-3);  // the contact stiffness keeps them a spacing apart
  // The contact is conservative: the kinetic energy after is the one before, to the step's error.
  EXPECT_NEAR(e->stats().kinetic_energy / ke0, 1.0, 5e-3);
}

TEST(Rigid, ABodyBouncesOnAFloor) {
  // A grain released a spacing above a wall, under gravity, lands on it without sinking in and,
  // the contact being conservative (no friction or damping, as in the paper), bounces back up.
  const std::string floor = replaced(replaced(replaced(kPair, R"([materials.b_grain]
kind = "rigid"
density = 1000.0
sound_speed = 20.0)", R"([materials.floor]
kind = "wall")"), "velocity = [0.1, 0.0]", ""), R"(lower = [0.011, 0.0096]
upper = [0.015, 0.0136]
material = "b_grain"
velocity = [-0.1, 0.0]
angular_velocity = 2.0)", R"(lower = [0.0, 0.0]
upper = [0.024, 0.007]
material = "floor")");
  const std::string falling = replaced(replaced(floor, "sound_speed = 20.0\n", "sound_speed = 20.0\nbody_force = [0.0, -9.81]\n"),
                                       "periodic = [true, true]", "periodic = [true, false]");
  auto e = engine_of(falling);
  const double y0 = e->rigid_bodies()[0].centre[1];
  double lowest = y0, t_low = 0, apex = 0;
  while (e->time() < 0.032) {
    e->step(0.032);
    const double y = e->rigid_bodies()[0].centre[1];
    if (y < lowest) lowest = y, t_low = e->time();
    if (e->time() > 0.02) apex = std::max(apex, y);
  }
  // The bottom row started at 8.5 mm, the floor's top row is at 6.5 mm: contact after a fall of
  // one spacing (sqrt(2 mm / g) = 14.3 ms), which the overlap exceeds by less than 1 % of a spacing.
  EXPECT_NEAR(y0 - lowest, 1.0e-3, 1e-5) << y0 << " " << lowest;
  EXPECT_NEAR(t_low, std::sqrt(2 * 1.0e-3 / 9.81), 2e-4);
  EXPECT_NEAR(apex, y0, 1e-5);  // back up to 1 % of the fall (measured 0.2 %)
}
