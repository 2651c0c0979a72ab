// Fluid-solid coupling (solid/fluid_coupling.hpp) and the solids' damping (solid/damping.hpp):
// exact momentum exchange of the pair coupling, the traction coupling's exact equilibrium under a
// uniform pressure, and the energy the damping takes.
#include <chrono>
#include <cmath>
#include <map>

#include <gtest/gtest.h>

#include "case_text.hpp"
#include "engine/engine.hpp"
#include "scene/scene_builder.hpp"
#include "validation/vibrating_rod.hpp"

using namespace psph;
using psph::test::replaced;

namespace {

// A 2D periodic box of water (16 spacings) around a square block of clay (6 spacings).
const std::string kBlock = R"(
[case]
name = "block"
dimension = 2
[domain]
lower = [0.0, 0.0]
upper = [0.016, 0.016]
periodic = [true, true]
[discretisation]
spacing = 1.0e-3
support_radius = 2.0e-3
[materials.water]
kind = "fluid"
density = 1000.0
viscosity = 1.0
sound_speed = 30.0
[materials.clay]
kind = "elastic"
density = 2000.0
young_modulus = 1.0e6
poisson_ratio = 0.3
[solid]
[solver]
[time]
end = 0.005
[[geometry]]
shape = "box"
lower = [0.0, 0.0]
upper = [0.016, 0.016]
material = "water"
velocity = [0.1, 0.05]
[[geometry]]
shape = "box"
lower = [0.005, 0.005]
upper = [0.011, 0.011]
material = "clay"
)";

std::unique_ptr<Engine> engine_of(const std::string& text) {
  Case c = load_case_text(text, "block.toml");
  build_particles(c);
  return make_engine(c.scene, "cpu");
}

// The field "material" holds indices into the materials sorted by name: clay 0, water 1.
constexpr double kClay = 0, kWater = 1;

std::array<double, 2> momentum(Engine& e) {
  const std::vector<double> m = e.field("mass"), v = e.field("velocity");
  std::array<double, 2> p{0, 0};
  for (int i = 0; i < e.particles(); ++i) p[0] += m[i] * v[2 * i], p[1] += m[i] * v[2 * i + 1];
  return p;
}

}  // namespace

// With the pair coupling every force between fluid and solid has its reaction: the momentum of
// water and clay together stays what it was (the viscous sum without its per-particle correction,
// which is not antisymmetric), while the water drags the block along.
TEST(FluidSolid, PairCouplingExchangesMomentumExactly) {
  auto e = engine_of(replaced(replaced(kBlock, "[solid]", "[solid]\ncoupling = \"pair\""), "[solver]",
                              "[solver]\nlaplacian_correction = \"none\""));
  const std::array<double, 2> p0 = momentum(*e);
  e->run_until(0.005);
  const std::array<double, 2> p1 = momentum(*e);
  const std::vector<double> mat = e->field("material"), v = e->field("velocity");
  double block_vx = 0;
  int n = 0;
  for (int i = 0; i < e->particles(); ++i)
    if (mat[i] == kClay) block_vx += v[2 * i], ++n;
  block_vx /= n;
  std::printf("momentum change over %ld steps: %.2e, %.2e of %.3e; block velocity %.4f m/s\n", e->steps(),
              p1[0] / p0[0] - 1, p1[1] / p0[1] - 1, p0[0], block_vx);
  EXPECT_NEAR(p1[0] / p0[0], 1.0, 1e-10);
  EXPECT_NEAR(p1[1] / p0[1], 1.0, 1e-10);
  EXPECT_GT(block_vx, 0.01);  // dragged from rest towards the water's 0.1 m/s
}

// Water at rest at a background pressure of 500 Pa around an unstrained block, the block taking the
// traction less `reference` ([solid] reference_pressure): the largest |sigma + (p - reference) I|
// in the block once settled (plane strain: sigma_zz aside), p the fluid's mean pressure (returned
// in `p_fluid`).
static double block_stress_error(double reference, double& p_fluid) {
  std::string text = replaced(kBlock, "velocity = [0.1, 0.05]\n", "");
  text = replaced(text, "[solver]", "[solver]\nbackground_pressure = 500.0");
  text = replaced(text, "[solid]", "[solid]\ndamping_rate = 5.0e3\nreference_pressure = " + std::to_string(reference));
  text = replaced(text, "end = 0.005", "end = 0.02");
  auto e = engine_of(text);
  e->run_until(0.02);
  const std::vector<double> mat = e->field("material"), p = e->field("pressure"), s = e->field("stress");
  p_fluid = 0;
  int n = 0;
  for (int i = 0; i < e->particles(); ++i)
    if (mat[i] == kWater) p_fluid += p[i], ++n;
  p_fluid /= n;
  double worst = 0;
  const double load = p_fluid - reference;
  for (int i = 0; i < e->particles(); ++i)
    if (mat[i] == kClay)
      for (int k = 0; k < 4; ++k) worst = std::max(worst, std::fabs(s[4 * i + k] + (k == 0 || k == 3 ? load : 0)));
  std::printf("reference %.0f Pa: fluid pressure %.3f Pa; largest |sigma + (p - p_ref) I| in the block %.3e Pa\n",
              reference, p_fluid, worst);
  return worst;
}

// The traction coupling: a fluid at rest at pressure p holds the block at sigma = -p I, particle
// by particle.
TEST(FluidSolid, TractionCouplingHoldsAUniformPressure) {
  double p_fluid = 0;
  const double worst = block_stress_error(0.0, p_fluid);
  EXPECT_GT(p_fluid, 100.0);
  EXPECT_LT(worst, 1e-3 * p_fluid);
}

// [solid] reference_pressure: the block feels the fluid's pressure less the reference, so a
// background pressure at the reference leaves it unloaded.
TEST(FluidSolid, ReferencePressureIsNoLoad) {
  double p_fluid = 0;
  const double worst = block_stress_error(500.0, p_fluid);
  EXPECT_GT(p_fluid, 100.0);
  EXPECT_LT(worst, 1e-3 * p_fluid);
  EXPECT_LT(std::fabs(p_fluid - 500.0), 0.1 * p_fluid);  // the load left is the fluid's own compression
}

// The damping's monitor: kinetic + elastic + dissipated energy stays the initial energy while the
// damping takes most of it.
TEST(FluidSolid, DampingEnergyIsAccountedFor) {
  Case c = vibrating_rod_case(1, false);
  c.scene.options.solid_damping_rate = 2e4;  // ~ the mode's angular frequency
  auto e = make_engine(c.scene, "cpu");
  auto total = [&] {
    const StepStats s = e->stats();
    return std::array<double, 2>{s.kinetic_energy + s.elastic_energy, s.dissipated_energy};
  };
  const double e0 = total()[0];
  e->run_until(2e-4);
  const std::array<double, 2> t = total();
  std::printf("after %ld steps: kinetic + elastic %.3f, dissipated %.3f of the initial energy\n", e->steps(), t[0] / e0,
              t[1] / e0);
  EXPECT_LT(t[0], 0.5 * e0);
  EXPECT_NEAR((t[0] + t[1]) / e0, 1.0, 0.01);
}

// Clamps hold in a case with fluids too: their walls list their elastic neighbours wherever the
// fluid is (before, walls away from the fluid had no lists, and the rod's partners lost the
// clamp's reaction).
TEST(FluidSolid, ClampsHoldWithAFluidInTheCase) {
  Case c = vibrating_rod_case(1, false);
  const RodVibration dry = run_vibrating_rod(c, 1, false, "cpu");
  Scene& sc = c.scene;
  SceneMaterial water;
  water.name = "water";
  water.props.kind = MaterialKind::Fluid;
  water.props.rest_density = 1000, water.props.sound_speed = 10;
  sc.materials.push_back(water);
  const double dx = sc.options.spacing, x_end = sc.upper[0];
  sc.upper[0] += 0.03;
  for (int k = 0; k < 10; ++k) {  // a column of water two supports beyond the right clamp
    sc.x.push_back(x_end + 0.015 + k * dx), sc.v.push_back(0), sc.mass.push_back(1000 * dx);
    sc.material.push_back(static_cast<int>(sc.materials.size()) - 1), sc.body.push_back(-1), sc.load_mask.push_back(0);
  }
  const RodVibration wet = run_vibrating_rod(c, 1, false, "cpu");
  EXPECT_NEAR(wet.beta2, dry.beta2, 1e-4 * dry.beta2);  // the water only changes the steps a little
  EXPECT_LT(wet.energy_drift, 0.01);
}

// An imposed velocity holds against the fluid's forces: the loads act after every other force.
TEST(FluidSolid, ImposedVelocityHoldsInWater) {
  const std::string text = kBlock + R"(
[[solid_load]]
material = "clay"
lower = [0.005, 0.005]
upper = [0.0061, 0.011]
velocity = [0.02, -0.01]
)";
  auto e = engine_of(text);
  for (int s = 0; s < 50; ++s) e->step(1.0);
  const auto v = e->field("velocity"), g = e->field("solid_load_mask");
  int held = 0;
  for (int i = 0; i < e->particles(); ++i)
    if (g[i] == 1) {
      EXPECT_EQ(v[2 * i], 0.02);
      EXPECT_EQ(v[2 * i + 1], -0.01);
      ++held;
    }
  EXPECT_EQ(held, 6);
}

// With the pair_eos coupling a damaged solid presents its own pressure with its damaged bulk
// modulus, -k(D) tr(eps) (solid/fluid_coupling.hpp): AT-2 (damage from the first strain) on the
// block dragged by the water, displacement form, without crack closure: with it a damaged point in
// compression keeps k0 while mu0 g(D) falls, its pairs' transverse stiffness 5 mu / 3 - k turns
// negative (solid/elastic_force.hpp) and this block went unstable at step 144.
TEST(FluidSolid, ADamagedSolidPresentsItsDamagedPressure) {
  const std::string text = replaced(replaced(replaced(kBlock, "[solid]", "[solid]\nformulation = \"displacement\"\ncoupling = \"pair_eos\""),
                                             "poisson_ratio = 0.3", "poisson_ratio = 0.2"),
                                    "[time]", "[damage]\nmodel = \"at2\"\nmaterials = [\"clay\"]\ncritical_energy_release = 1e-3\nunilateral = false\n[time]");
  auto e = engine_of(text);
  e->run_until(0.002);
  const auto mat = e->field("material"), p = e->field("pressure"), k = e->field("damaged_bulk_modulus");
  const auto eps = e->field("strain"), d = e->field("damage");
  const double k0 = 1e6 / (3 * (1 - 2 * 0.2));
  int degraded = 0;
  for (int i = 0; i < e->particles(); ++i) {
    if (mat[i] != kClay) continue;
    const double tr = eps[4 * i] + eps[4 * i + 3];
    EXPECT_NEAR(p[i], -k[i] * tr, 1e-9 * k0 * std::fabs(tr) + 1e-300) << i;
    EXPECT_NEAR(k[i], k0 * (1 - d[i]) * (1 - d[i]), 1e-9 * k0) << i;
    degraded += k[i] < 0.99 * k0;
  }
  EXPECT_GT(degraded, 0);
}

// The traction coupling loads the faces the fluid wets, not the face a body sits on: a block on a
// plate in water at rest at 500 Pa is pressed onto the plate by p times its top face (its sides
// cancel), as the walls count as the body's continuation in b_i (solid/stress_form.hpp). When they
// did not, the plate face took the traction too (a net force near zero), and the pore water's
// pressure fed back into the first rows above a plate (VALIDATION.md, the wider crop).
TEST(FluidSolid, TractionPressesABodyOntoItsPlate) {
  std::string text = replaced(kBlock, "velocity = [0.1, 0.05]\n", "");
  text = replaced(text, "[solver]", "[solver]\nbackground_pressure = 500.0");
  text = replaced(text, "[solid]", "[materials.plate]\nkind = \"wall\"\n[solid]");
  text = replaced(text, "lower = [0.005, 0.005]", "lower = [0.005, 0.003]");
  text = replaced(text, "upper = [0.011, 0.011]", "upper = [0.011, 0.009]");
  text += "[[geometry]]\nshape = \"box\"\nlower = [0.0, 0.0]\nupper = [0.016, 0.003]\nmaterial = \"plate\"\n";
  auto e = engine_of(text);
  e->step(1.0);
  const std::vector<double> mat = e->field("material"), m = e->field("mass"), a = e->field("acceleration"),
                            p = e->field("pressure");
  constexpr double kPlateClay = 0, kPlateWater = 2;  // clay, plate, water
  double fx = 0, fy = 0, p_fluid = 0;
  int n = 0;
  for (int i = 0; i < e->particles(); ++i) {
    if (mat[i] == kPlateClay) fx += m[i] * a[2 * i], fy += m[i] * a[2 * i + 1];
    if (mat[i] == kPlateWater) p_fluid += p[i], ++n;
  }
  p_fluid /= n;
  const double top = p_fluid * 0.006;  // N/m: the top face's load
  std::printf("fluid %.2f Pa; force on the block (%.3f, %.3f) N/m, top face's load %.3f N/m\n", p_fluid, fx, fy, top);
  EXPECT_GT(p_fluid, 450.0);
  EXPECT_NEAR(fy / -top, 1.0, 0.1);
  EXPECT_LT(std::fabs(fx), 0.02 * top);
}

// The coupled step's profile (core/pass_profile.hpp): the solid's force pass under its stage once
// a step, the fluid's reaction under the coupling's, and the passes' time within the steps' own.
TEST(FluidSolid, ProfileNamesEachStagesPasses) {
  auto e = engine_of(kBlock);
  e->profile().clear();
  const auto t0 = std::chrono::steady_clock::now();
  for (int s = 0; s < 5; ++s) e->step(1.0);
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::map<std::string, PassTime> by_pass;
  for (const PassTime& t : e->profile().passes()) by_pass[t.pass] = t;
  EXPECT_EQ(by_pass["StressForcePass"].stage, "solid");
  EXPECT_EQ(by_pass["StressForcePass"].calls, 5);
  EXPECT_EQ(by_pass["FluidOnSolidPass"].stage, "coupling");
  EXPECT_EQ(by_pass["FluidForcePass"].stage, "fluid");
  EXPECT_GT(e->profile().seconds(), 0.0);
  EXPECT_LE(e->profile().seconds(), wall);
}
