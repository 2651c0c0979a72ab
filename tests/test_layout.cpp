// Particle layouts: concentric shells tile a sphere's volume and keep particles apart; a
// concentric ring with a concentric core of another material leaves no gap and no overlap.
#include <algorithm>
#include <array>
#include <cmath>

#include <gtest/gtest.h>

#include "case_text.hpp"
#include "scene/concentric_layout.hpp"
#include "scene/embedded_cases.hpp"
#include "scene/scene_builder.hpp"

using namespace psph;

namespace {

double nearest(const std::vector<double>& x, int D, int i) {
  const int n = static_cast<int>(x.size()) / D;
  double best = 1e300;
  for (int j = 0; j < n; ++j) {
    if (j == i) continue;
    double d2 = 0;
    for (int k = 0; k < D; ++k) d2 += (x[i * D + k] - x[j * D + k]) * (x[i * D + k] - x[j * D + k]);
    best = std::min(best, d2);
  }
  return std::sqrt(best);
}

}  // namespace

TEST(ConcentricLayout, ShellsTileTheBallAndKeepParticlesApart) {
  const double ball[3] = {2 * 10.0, M_PI * 100.0, 4.0 / 3.0 * M_PI * 1000.0};  // radius 10 spacings
  for (int D = 1; D <= 3; ++D) {
    const std::vector<LayoutPoint> p = concentric_points({0.5, -1.0, 2.0}, 10.0, 1.0, D);
    std::vector<double> x;
    double volume = 0;
    for (const LayoutPoint& q : p) {
      volume += q.volume;
      double r2 = 0;
      for (int k = 0; k < D; ++k) x.push_back(q.x[k]), r2 += std::pow(q.x[k] - (k == 0 ? 0.5 : k == 1 ? -1.0 : 2.0), 2);
      const double shell = std::sqrt(r2) - 0.5;  // radii (k + 1/2) spacings (10 is a whole number of them)
      EXPECT_NEAR(shell, std::round(shell), 1e-9) << "D = " << D;
      // Every particle stands for about a spacing^D: no shell crowded or sparse.
      EXPECT_GT(q.volume, 0.95) << "D = " << D;
      EXPECT_LT(q.volume, 1.05) << "D = " << D;
    }
    EXPECT_NEAR(volume, ball[D - 1], 1e-9 * ball[D - 1]) << "D = " << D;
    double closest = 1e300;
    for (int i = 0; i < static_cast<int>(p.size()); ++i) closest = std::min(closest, nearest(x, D, i));
    EXPECT_GT(closest, D == 3 ? 0.74 : 0.86) << "D = " << D;  // 3D: a Fibonacci spiral near its poles
  }
}

namespace {

const char* kRing = R"(
[case]
name = "ring"
dimension = 2
[domain]
lower = [-0.012, -0.012]
upper = [0.012, 0.012]
[discretisation]
spacing = 1.0e-3
support_radius = 2.0e-3
[materials.clay]
kind = "elastic"
density = 2000.0
young_modulus = 1.0e6
poisson_ratio = 0.3
[materials.water]
kind = "fluid"
density = 1000.0
viscosity = 1.0e-3
sound_speed = 10.0
[time]
end = 1.0e-3
[[geometry]]
shape = "sphere"
center = [0.0, 0.0]
radius = 0.01
material = "clay"
layout = "concentric"
[[geometry]]
shape = "sphere"
center = [0.0, 0.0]
radius = 0.004
material = "water"
layout = "concentric"
)";

}  // namespace

TEST(ConcentricLayout, ACoreOfAnotherMaterialFillsItsShells) {
  Case c = load_case_text(kRing, "ring.toml");
  build_particles(c);
  const Scene& sc = c.scene;
  const double n_sum = lattice_kernel_sum(2, sc.options.kernel, sc.options.support_radius, 1e-3);
  double area[2] = {0, 0};  // clay, water (materials in alphabetical order)
  for (int i = 0; i < sc.count(); ++i) {
    const int m = sc.material[i];
    const double r = std::hypot(sc.x[2 * i], sc.x[2 * i + 1]);
    EXPECT_EQ(m, r < 0.004 ? 1 : 0) << "r = " << r;
    area[m] += sc.mass[i] * n_sum * 1e-6 / sc.materials[m].props.rest_density;
    EXPECT_GT(nearest(sc.x, 2, i), 0.85e-3);
  }
  EXPECT_NEAR(area[1], M_PI * 16e-6, 1e-12);
  EXPECT_NEAR(area[0], M_PI * 84e-6, 1e-12);
}

TEST(ConcentricLayout, ARadiusBetweenSpacingsEndsOnTheSurface) {
  // A concentric disc of 10.4 or 10.6 spacings in lattice water: its shells stretch or squeeze to
  // end on its surface (its area exact), and the lattice outside keeps clear of its last ring.
  for (const char* radius : {"0.0104", "0.0106"}) {
    std::string t = test::replaced(kRing, "radius = 0.01\nmaterial = \"clay\"", std::string("radius = ") + radius + "\nmaterial = \"clay\"");
    t = test::replaced(t, "upper = [0.012, 0.012]", "upper = [0.014, 0.014]");
    t = test::replaced(t, "lower = [-0.012, -0.012]", "lower = [-0.014, -0.014]");
    t = test::replaced(t, "shape = \"sphere\"\ncenter = [0.0, 0.0]\nradius = 0.004\nmaterial = \"water\"\nlayout = \"concentric\"", "shape = \"box\"\nlower = [-0.014, -0.014]\nupper = [0.014, 0.014]\nmaterial = \"water\"");
    // The water box first, the disc over it.
    const auto w = t.find("[[geometry]]\nshape = \"box\"");
    ASSERT_NE(w, std::string::npos);
    t = t.substr(0, t.find("[[geometry]]")) + t.substr(w) + "\n" + t.substr(t.find("[[geometry]]"), w - t.find("[[geometry]]"));
    Case c = load_case_text(t, "disc.toml");
    build_particles(c);
    const Scene& sc = c.scene;
    const double n_sum = lattice_kernel_sum(2, sc.options.kernel, sc.options.support_radius, 1e-3), R = std::stod(radius);
    double area = 0;
    for (int i = 0; i < sc.count(); ++i) {
      if (sc.material[i] == 0) area += sc.mass[i] * n_sum * 1e-6 / sc.materials[0].props.rest_density;
      EXPECT_GT(nearest(sc.x, 2, i), 0.45e-3) << radius;
    }
    EXPECT_NEAR(area, M_PI * R * R, 1e-12) << radius;
  }
}

TEST(ConcentricLayout, LaterShapesAndTheDomainEdgeClipIt) {
  // A box of water over the ring's right half takes it; the domain cuts the ring's top.
  std::string t = test::replaced(kRing, "upper = [0.012, 0.012]", "upper = [0.012, 0.006]");
  t += "[[geometry]]\nshape = \"box\"\nlower = [0.0, -0.012]\nupper = [0.012, 0.006]\nmaterial = \"water\"\n";
  Case c = load_case_text(t, "ring.toml");
  build_particles(c);
  const Scene& sc = c.scene;
  for (int i = 0; i < sc.count(); ++i) {
    EXPECT_LT(sc.x[2 * i + 1], 0.006);
    if (sc.x[2 * i] > 0) EXPECT_EQ(sc.material[i], 1);  // the box's lattice water
  }
}

TEST(ConcentricLayout, OnlySpheresTakeALayout) {
  const std::string msg = test::error_of(
      test::replaced(kRing, "shape = \"sphere\"\ncenter = [0.0, 0.0]\nradius = 0.01", "shape = \"box\"\nlower = [-0.01, -0.01]\nupper = [0.01, 0.01]"));
  EXPECT_NE(msg.find("bad.toml"), std::string::npos) << msg;
  EXPECT_NE(msg.find("geometry[0]"), std::string::npos) << msg;
  EXPECT_NE(msg.find("layout"), std::string::npos) << msg;
  EXPECT_NE(test::error_of(test::replaced(kRing, "layout = \"concentric\"", "layout = \"hexagonal\"")).find("lattice"),
            std::string::npos);
  // Across a periodic seam: refused.
  const std::string seam = test::error_of(test::replaced(kRing, "upper = [0.012, 0.012]", "upper = [0.009, 0.012]\nperiodic = [true, false]"));
  EXPECT_NE(seam.find("periodic"), std::string::npos) << seam;
  EXPECT_NE(seam.find("geometry[0]"), std::string::npos) << seam;
}

// Shares of the domain built apart tile the whole build: the same particles (position, mass,
// material), none lost or doubled, for a lattice with shapes and a concentric body, cut through
// lattice sites and between them. Cases with rigid bodies or jitter are refused by parts.
TEST(SceneBuilder, SharesOfTheDomainTileTheWholeBuild) {
  using Particle = std::array<double, 4>;
  auto particles = [](const Case& c) {
    std::vector<Particle> out;
    const int D = c.scene.dimension;
    for (int i = 0; i < c.scene.count(); ++i)
      out.push_back({c.scene.x[i * D], c.scene.x[i * D + 1], c.scene.mass[i], double(c.scene.material[i])});
    std::sort(out.begin(), out.end());
    return out;
  };
  for (const char* name : {"drainage_2d", "lame_cylinder_2d"}) {
    Case whole = load_case_text(embedded_case_text(name), "whole.toml");
    build_particles(whole);
    const Bounds domain = domain_bounds(whole.scene);
    const double dx = whole.scene.options.spacing;
    for (double cut : {0.37, 0.5 + 0.5 * dx / (domain.upper[0] - domain.lower[0])}) {  // between sites, through one
      std::vector<Particle> shares;
      for (int side = 0; side < 2; ++side) {
        Case part = load_case_text(embedded_case_text(name), "part.toml");
        Bounds b = domain;
        const double x = domain.lower[0] + cut * (domain.upper[0] - domain.lower[0]);
        (side == 0 ? b.upper[0] : b.lower[0]) = x;
        build_particles(part, b);
        for (const Particle& p : particles(part)) {
          EXPECT_TRUE(side == 0 ? p[0] < x : p[0] >= x) << name;
          shares.push_back(p);
        }
      }
      std::sort(shares.begin(), shares.end());
      EXPECT_EQ(shares, particles(whole)) << name << " cut at " << cut;
    }
  }
  Case rigid = load_case_text(embedded_case_text("settling_cylinder_2d"), "rigid.toml");
  Bounds half = domain_bounds(rigid.scene);
  half.upper[0] = 0.5 * (half.lower[0] + half.upper[0]);
  EXPECT_THROW(build_particles(rigid, half), std::invalid_argument);
}
