// Open pressure inlet and outlet (boundary/open_boundary.hpp) on the channel of
// cases/open_channel_2d.toml: the case keys, the buffers' imposed state, the inlet injecting its
// own fluid once the outlet's fluid has come round through the periodic seam, and the same channel
// in 3D.
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "case_text.hpp"
#include "engine/engine.hpp"
#include "scene/embedded_cases.hpp"
#include "validation/channel_flow.hpp"

using namespace psph;
using psph::test::error_of;
using psph::test::expect_refused;
using psph::test::replaced;

namespace {

const std::string channel = embedded_case_text("open_channel_2d");

// The channel with a gas under [materials] that the inlet injects, at `inlet_pressure`.
std::string gas_inlet(const std::string& inlet_pressure) {
  std::string t = replaced(channel, "[materials.wall]",
                           "[materials.gas]\nkind = \"fluid\"\nphase = \"gas\"\ndensity = 100.0\n"
                           "viscosity = 1.0e-4\nsound_speed = 0.03\n\n[materials.wall]");
  t = replaced(t, "inlet_material = \"water\"", "inlet_material = \"gas\"");
  return replaced(t, "inlet_pressure = 2.8e-3", "inlet_pressure = " + inlet_pressure);
}

struct Counts {
  int gas = 0, water_in_inlet = 0;
};

}  // namespace

TEST(OpenBoundary, CaseKeys) {
  EXPECT_EQ(error_of(channel), "");
  expect_refused(channel, "periodic = [false, true]", "periodic = [false, false]", "bad.toml: open_boundary.axis: expected an axis declared periodic");
  expect_refused(channel, "axis = \"y\"", "axis = \"z\"", "expected an axis of this 2D case, got \"z\"");
  expect_refused(channel, "inlet_material = \"water\"", "inlet_material = \"wall\"", "open_boundary.inlet_material: expected the name of a fluid");
  expect_refused(channel, "outlet_pressure = 0.0", "outlet_pressure = 0.0\nthickness = 5.0e-5",
          "open_boundary.thickness: expected a buffer at least one support radius");
  expect_refused(channel, "outlet_pressure = 0.0\n", "", "open_boundary.outlet_pressure: missing");
  expect_refused(channel, "inlet_pressure = 2.8e-3", "inlet_pressure = nan", "open_boundary.inlet_pressure (line 33): expected a finite number");
}

// At the first evaluation the inlet buffer holds the inlet's fluid (a full lattice: the scene's
// volume per particle at the inlet fluid's density) at the inlet's pressure, the outlet buffer its
// own fluid at the outlet's.
TEST(OpenBoundary, BuffersCarryTheirPressureAndTheInletItsFluid) {
  Case c = load_case_text(gas_inlet("2.8e-3"), "gas_inlet.toml");
  build_particles(c);
  auto e = make_engine(c.scene, "cpu");
  const std::vector<double> x = e->field("position"), p = e->field("pressure"), mat = e->field("material"),
                            m = e->field("mass");
  const double b = 1e-4, top = 3e-3;
  double water_mass = 0;
  for (int i = 0; i < e->particles(); ++i)
    if (c.scene.materials[static_cast<int>(mat[i])].name == "water") water_mass = m[i];
  int inlet = 0, outlet = 0;
  for (int i = 0; i < e->particles(); ++i) {
    const std::string& name = c.scene.materials[static_cast<int>(mat[i])].name;
    if (name == "wall") continue;
    const double y = x[2 * i + 1];
    if (y < b) {
      ++inlet;
      EXPECT_EQ(name, "gas");
      EXPECT_NEAR(m[i], water_mass / 10, 1e-6 * water_mass);
      EXPECT_NEAR(p[i], 2.8e-3, 1e-9);
    } else if (y >= top - b) {
      ++outlet;
      EXPECT_EQ(name, "water");
      EXPECT_NEAR(p[i], 0.0, 1e-9);
    } else {
      EXPECT_EQ(name, "water");
    }
  }
  EXPECT_EQ(inlet, 40);  // two rows of 20 across the channel
  EXPECT_EQ(outlet, 40);
}

// Driven ten times harder, the water leaving through the outlet comes back as gas: gas enters the
// channel, and the inlet buffer never holds water.
TEST(OpenBoundary, TheInletInjectsGas) {
  Case c = load_case_text(gas_inlet("2.8e-2"), "gas_inlet.toml");
  build_particles(c);
  auto e = make_engine(c.scene, "cpu");
  auto count = [&] {
    const std::vector<double> x = e->field("position"), mat = e->field("material");
    Counts n;
    for (int i = 0; i < e->particles(); ++i) {
      const std::string& name = c.scene.materials[static_cast<int>(mat[i])].name;
      if (name == "gas") ++n.gas;
      if (name == "water" && x[2 * i + 1] < 1e-4) ++n.water_in_inlet;
    }
    return n;
  };
  const Counts first = count();
  e->run_until(0.4);
  const Counts last = count();
  EXPECT_EQ(first.water_in_inlet, 0);
  EXPECT_EQ(last.water_in_inlet, 0);
  EXPECT_GT(last.gas, first.gas + 40) << "at least two more rows of gas";
}

// With the inlet at the upper end the same pressures drive the channel the other way, at the same
// rate (the characteristic correction acts along each buffer's inward normal).
TEST(OpenBoundary, AnInletAtTheUpperEndDrivesTheFlowDown) {
  Case c = load_case_text(replaced(channel, "inlet_material = \"water\"", "inlet_material = \"water\"\ninlet_side = \"upper\""),
                          "upper_inlet.toml");
  build_particles(c);
  auto e = make_engine(c.scene, "cpu");
  e->run_until(0.4);
  const std::vector<double> x = e->field("position"), v = e->field("velocity"), mat = e->field("material");
  double sum = 0;
  int n = 0;
  for (int i = 0; i < e->particles(); ++i)
    if (c.scene.materials[static_cast<int>(mat[i])].name == "water" && x[2 * i + 1] > 1e-4 && x[2 * i + 1] < 2.9e-3)
      sum += v[2 * i + 1], ++n;
  const double exact_mean = 2.0 / 3.0 * 1.25e-4;
  EXPECT_LT(sum / n, -0.8 * exact_mean);  // 0.4 s: within the first row's crossing, before the wobble
  EXPECT_GT(sum / n, -1.2 * exact_mean);
}

// The channel in 3D as a slot periodic across z (8 spacings, four supports): the profile between
// the plates is the plane one, u(x) = G x (W - x) / (2 mu), whatever the third axis.
TEST(OpenBoundary, AThreeDimensionalSlotCarriesThePlaneProfile) {
  std::string t = replaced(channel, "dimension = 2", "dimension = 3");
  t = replaced(t, "lower = [-1.5e-4, 0.0]\nupper = [1.15e-3, 3.0e-3]\nperiodic = [false, true]",
               "lower = [-1.5e-4, 0.0, 0.0]\nupper = [1.15e-3, 3.0e-3, 4.0e-4]\nperiodic = [false, true, true]");
  t = replaced(t, "lower = [-1.5e-4, 0.0]\nupper = [1.15e-3, 3.0e-3]\nmaterial = \"wall\"",
               "lower = [-1.5e-4, 0.0, 0.0]\nupper = [1.15e-3, 3.0e-3, 4.0e-4]\nmaterial = \"wall\"");
  t = replaced(t, "lower = [0.0, 0.0]\nupper = [1.0e-3, 3.0e-3]\nmaterial = \"water\"",
               "lower = [0.0, 0.0, 0.0]\nupper = [1.0e-3, 3.0e-3, 4.0e-4]\nmaterial = \"water\"");
  t = replaced(t, "end = 3.0", "end = 1.5");
  Case c = load_case_text(t, "open_slot_3d.toml");
  build_particles(c);
  const OpenChannelErrors e = open_channel_errors(c, "cpu");
  std::printf("3D slot: profile %.2f %% of u_peak, flow rate %+.2f %%, samples within %.2f %%; %d particles, %ld steps\n",
              100 * e.profile_error, 100 * e.flux_error, 100 * e.flux_spread, e.particles, e.steps);
  EXPECT_LT(e.profile_error, 0.03);
  EXPECT_LT(std::fabs(e.flux_error), 0.03);
}
