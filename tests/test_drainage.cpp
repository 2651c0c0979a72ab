// Drainage machinery: the seeded grain pack, body forces on a region, and the two-phase monitors
// (saturations, phase pressures, percolation).
#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "case_text.hpp"
#include "core/fluid_table.hpp"
#include "engine/engine.hpp"
#include "monitors/two_phase.hpp"
#include "scene/case_file.hpp"
#include "scene/embedded_cases.hpp"
#include "scene/grain_pack.hpp"
#include "scene/scene_builder.hpp"

using namespace psph;
using test::error_of;
using test::replaced;

namespace {

GrainPackSpec spec2d(std::uint64_t seed) {
  GrainPackSpec s;
  s.lower = {0, 0, 0}, s.upper = {1, 2, 0};
  s.grain_radius = 0.08, s.radius_spread = 0.2, s.min_gap = 0.03, s.solid_fraction = 0.3, s.seed = seed;
  return s;
}

}  // namespace

TEST(GrainPack, SeededGapsAndFraction) {
  const GrainPack a = generate_grain_pack(spec2d(1), 2), b = generate_grain_pack(spec2d(1), 2);
  const GrainPack c = generate_grain_pack(spec2d(2), 2);
  ASSERT_EQ(a.grains.size(), b.grains.size());
  for (std::size_t k = 0; k < a.grains.size(); ++k) EXPECT_EQ(a.grains[k].centre, b.grains[k].centre);
  EXPECT_NE(a.grains.front().centre, c.grains.front().centre);
  EXPECT_GE(a.solid_fraction, 0.3);
  for (const auto* p : {&a, &c})
    for (std::size_t i = 0; i < p->grains.size(); ++i) {
      const Grain& g = p->grains[i];
      EXPECT_GE(g.radius, 0.08 * 0.8 - 1e-12);
      EXPECT_LE(g.radius, 0.08 * 1.2 + 1e-12);
      for (std::size_t j = 0; j < i; ++j) {
        const Grain& o = p->grains[j];
        const double d = std::hypot(g.centre[0] - o.centre[0], g.centre[1] - o.centre[1]);
        EXPECT_GE(d - g.radius - o.radius, 0.03 - 1e-12) << "grains " << i << " and " << j;
      }
    }
  // The solid fraction measured on a fine lattice agrees with the generator's estimate.
  long in = 0, all = 0;
  for (double x = 0.0025; x < 1; x += 0.005)
    for (double y = 0.0025; y < 2; y += 0.005) {
      const double p[2] = {x, y};
      in += in_grain_pack(spec2d(1), a.grains, p, 2), ++all;
    }
  EXPECT_NEAR(double(in) / all, a.solid_fraction, 0.01);
}

TEST(GrainPack, UnreachableFractionIsACaseError) {
  const std::string text = embedded_case_text("drainage_2d");
  const std::string msg = error_of(replaced(text, "solid_fraction = 0.33", "solid_fraction = 0.8"));
  EXPECT_NE(msg.find("bad.toml: geometry[4].solid_fraction"), std::string::npos) << msg;
  EXPECT_NE(msg.find("reach a solid fraction of only"), std::string::npos) << msg;
  EXPECT_NE(error_of(replaced(text, "seed = 1", "seed = -3")).find("geometry[4].seed"), std::string::npos);
}

TEST(ForceRegion, OnlyItsMaterialInsideItsBox) {
  FluidTable<2> mats;
  mats.count = 2;
  mats.body_force[0] = Vec<2>{{0, -1}}, mats.body_force[1] = Vec<2>::zero();
  mats.region_count = 1;
  mats.region[0].material = 1;
  mats.region[0].lower = Point<2>{{0, 1}}, mats.region[0].upper = Point<2>{{1, 2}};
  mats.region[0].acceleration = Vec<2>{{0, -5}};
  EXPECT_EQ(mats.body_force_at(1, Point<2>{{0.5, 1.5}})[1], -5);
  EXPECT_EQ(mats.body_force_at(1, Point<2>{{0.5, 0.5}})[1], 0);
  EXPECT_EQ(mats.body_force_at(0, Point<2>{{0.5, 1.5}})[1], -1);  // another material
  EXPECT_EQ(mats.body_force_at(1, Point<2>{{0.5, 2.0}})[1], 0);     // the upper face is outside
}

TEST(ForceRegion, CaseFileErrors) {
  const std::string text = embedded_case_text("drainage_2d");
  const Case c = load_case_text(text, "d.toml");
  ASSERT_EQ(c.scene.force_regions.size(), 2u);
  EXPECT_EQ(c.scene.materials[c.scene.force_regions[0].material].name, "gas");
  EXPECT_EQ(c.scene.force_regions[0].acceleration[1], -5.0);
  const std::string wall = error_of(replaced(text, "material = \"gas\"\nlower = [0.0, 7.2e-3]", "material = \"rock\"\nlower = [0.0, 7.2e-3]"));
  EXPECT_NE(wall.find("body_force_region[0].material: expected the name of a fluid"), std::string::npos) << wall;
  const std::string box = error_of(replaced(text, "lower = [0.0, 7.2e-3]", "lower = [0.0, 9.9e-3]"));
  EXPECT_NE(box.find("body_force_region[0].upper"), std::string::npos) << box;
  EXPECT_EQ(c.scene.force_regions[0].ramp_time, 0.0);
  const std::string ramp = "body_force = [0.0, -5.0]\nramp_time = ";
  EXPECT_EQ(load_case_text(replaced(text, "body_force = [0.0, -5.0]", ramp + "0.1"), "d.toml").scene.force_regions[0].ramp_time, 0.1);
  const std::string negative = error_of(replaced(text, "body_force = [0.0, -5.0]", ramp + "-0.1"));
  EXPECT_NE(negative.find("body_force_region[0].ramp_time"), std::string::npos) << negative;
  EXPECT_NE(negative.find("expected a number >= 0"), std::string::npos) << negative;
}

TEST(Monitors, RegionAndAxisFromTheCase) {
  const std::string text = embedded_case_text("drainage_2d");
  const Case c = load_case_text(text, "d.toml");
  EXPECT_TRUE(c.two_phase);
  EXPECT_EQ(c.monitor_region.flow_axis, 1);
  EXPECT_DOUBLE_EQ(c.monitor_region.percolation_distance, 1.5e-4);
  EXPECT_NE(error_of(replaced(text, "flow_axis = \"y\"", "flow_axis = \"z\"")).find("monitors.flow_axis"), std::string::npos);
  EXPECT_NE(error_of(replaced(text, "region_upper = [4.5e-3, 7.2e-3]", "region_upper = [4.5e-3, 9.9e-3]"))
                .find("monitors.region_upper"),
            std::string::npos);
  // Single-fluid cases have no two-phase monitors.
  EXPECT_FALSE(load_case_text(embedded_case_text("poiseuille_2d"), "p.toml").two_phase);
}

// Gas particles on a line along the flow axis percolate; a gap wider than the connection
// distance breaks the cluster; a chain that crosses a periodic side connects through it.
TEST(Monitors, Percolation) {
  Scene sc;
  sc.dimension = 2;
  sc.upper = {1, 1, 0};
  sc.periodic = {true, false, false};
  MonitorRegion r;
  r.upper = {1, 1, 0};
  r.flow_axis = 1;
  r.percolation_distance = 0.015;
  std::vector<double> x;
  std::vector<int> gas;
  auto add = [&](double a, double b) {
    gas.push_back(static_cast<int>(x.size() / 2));
    x.push_back(a), x.push_back(b);
  };
  for (int k = 0; k < 100; ++k) add(0.5, 0.005 + 0.01 * k);
  EXPECT_TRUE(gas_percolates(sc, r, x, gas));
  x.clear(), gas.clear();
  for (int k = 0; k < 100; ++k)
    if (k != 50) add(0.5, 0.005 + 0.01 * k);  // a gap of 0.02
  EXPECT_FALSE(gas_percolates(sc, r, x, gas));
  // Two halves joined only across the periodic side x = 0 / x = 1.
  x.clear(), gas.clear();
  for (int k = 0; k < 50; ++k) add(0.995, 0.005 + 0.01 * k);
  for (int k = 50; k < 100; ++k) add(0.003, 0.005 + 0.01 * k);
  EXPECT_TRUE(gas_percolates(sc, r, x, gas));
  sc.periodic = {false, false, false};
  EXPECT_FALSE(gas_percolates(sc, r, x, gas));
}

// Saturations and phase means on the drainage case at rest: the sample holds water only.
TEST(Monitors, SaturationAndPressuresAtStart) {
  Case c = load_case_text(embedded_case_text("drainage_2d"), "d.toml");
  build_particles(c);
  auto e = make_engine(c.scene, "cpu");
  TwoPhaseMonitor m(c.scene, c.monitor_region);
  const std::vector<std::string> cols = m.columns();
  const std::vector<double> row = m.sample(*e);
  ASSERT_EQ(row.size(), cols.size());
  EXPECT_EQ(cols.front(), "saturation_liquid");
  EXPECT_EQ(m.last().saturation_liquid, 1.0);
  EXPECT_EQ(m.last().saturation_gas, 0.0);
  EXPECT_TRUE(std::isnan(m.last().pressure_gas));  // no gas in the sample
  EXPECT_LT(m.percolation_time(), 0);
  EXPECT_EQ(cols.back(), "v_max_over_sigma_mu");
}

// The phase pressures are reported over the fluids' initial background pressure: a case at
// 2 Pa more reports the same means, its pressure field 2 Pa higher.
TEST(Monitors, PressuresOverTheBackgroundPressure) {
  double liquid[2] = {0, 0}, field[2] = {0, 0};
  for (int k = 0; k < 2; ++k) {
    const std::string text = embedded_case_text("drainage_2d");
    Case c = load_case_text(k ? replaced(text, "[time]", "[solver]\nbackground_pressure = 2.0\n\n[time]") : text, "d.toml");
    build_particles(c);
    auto e = make_engine(c.scene, "cpu");
    TwoPhaseMonitor m(c.scene, c.monitor_region);
    m.sample(*e);
    liquid[k] = m.last().pressure_liquid;
    const std::vector<double> p = e->field("pressure"), mat = e->field("material");
    for (std::size_t i = 0; i < p.size(); ++i)
      if (c.scene.materials[static_cast<int>(mat[i])].props.kind == MaterialKind::Fluid) field[k] = std::max(field[k], p[i]);
  }
  EXPECT_NEAR(field[1] - field[0], 2.0, 1e-9);
  EXPECT_NEAR(liquid[1], liquid[0], 1e-9);
}

// A ramped region starts with no force: at t = 0 the reservoir gas's acceleration lacks the
// region's whole body force; outside the region only the walls' pressure (which carries the body
// force of their fluid neighbours) tells the difference, there and next to walls inside.
TEST(ForceRegion, RampStartsFromZero) {
  const std::string text = embedded_case_text("drainage_2d");
  Case full = load_case_text(text, "d.toml"), ramped = load_case_text(text, "d.toml");
  ramped.scene.force_regions[0].ramp_time = 0.1;
  build_particles(full), build_particles(ramped);
  auto a = make_engine(full.scene, "cpu"), b = make_engine(ramped.scene, "cpu");
  const std::vector<double> x = a->field("position"), mat = a->field("material"),
                            accel_full = a->field("acceleration"), accel_ramped = b->field("acceleration");
  const SceneForceRegion& f = full.scene.force_regions[0];
  int inside = 0, outside = 0;
  double mean_in = 0, mean_out = 0;
  for (int i = 0; i < a->particles(); ++i) {
    const double dy = accel_full[2 * i + 1] - accel_ramped[2 * i + 1];
    if (static_cast<int>(mat[i]) == f.material && x[2 * i + 1] >= f.lower[1] && x[2 * i + 1] < f.upper[1])
      ++inside, mean_in += dy;
    else
      ++outside, mean_out += std::fabs(dy);
  }
  EXPECT_NEAR(mean_in / inside, f.acceleration[1], 0.05 * std::fabs(f.acceleration[1]));
  EXPECT_LT(mean_out / outside, 0.01 * std::fabs(f.acceleration[1]));
  EXPECT_GT(inside, 100);
}
