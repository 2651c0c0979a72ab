// Pressure probes ([[probe]], monitors/pressure_probes.hpp): the Shepard mean of the fluid around a
// point, and the case file's checks.
#include <cmath>

#include <gtest/gtest.h>

#include "case_text.hpp"
#include "monitors/pressure_probes.hpp"
#include "scene/case_file.hpp"
#include "scene/embedded_cases.hpp"

using namespace psph;

namespace {

// A 3D lattice of spacing s over [0, 1]^3: fluid below y = 0.5 with p = 3 + 2 y, a wall above
// at p = 1000 (which a probe must ignore).
struct Lattice {
  std::vector<double> x, p, volume, material;
};
Lattice lattice(double s) {
  Lattice l;
  const int n = static_cast<int>(std::lround(1 / s));
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j)
      for (int k = 0; k <= n; ++k) {
        const double y = j * s;
        l.x.insert(l.x.end(), {i * s, y, k * s});
        const bool fluid = y < 0.5;
        l.p.push_back(fluid ? 3 + 2 * y : 1000.0);
        l.volume.push_back(s * s * s);
        l.material.push_back(fluid ? 0 : 1);
      }
  return l;
}

Scene lattice_scene(double s) {
  Scene sc;
  sc.dimension = 3;
  sc.options.kernel = KernelType::WendlandC2;
  sc.options.support_radius = 2.6 * s;
  SceneMaterial fluid, wall;
  fluid.props.kind = MaterialKind::Fluid;
  wall.props.kind = MaterialKind::Wall;
  sc.materials = {fluid, wall};
  return sc;
}

}  // namespace

TEST(Probes, ShepardMeanReadsALinearPressureAndIgnoresWalls) {
  const double s = 0.05;
  const Lattice l = lattice(s);
  const Scene sc = lattice_scene(s);
  // Inside the fluid, on a lattice point: the mean of a linear field over a symmetric neighbourhood.
  // At the fluid's top row (y = 0.45), the wall above is left out: the mean leans below, never
  // towards the wall's 1000 Pa. Far above the fluid: dry, 0.
  const std::vector<Probe> probes = {{"inside", {0.5, 0.2, 0.5}}, {"top", {0.5, 0.45, 0.5}}, {"dry", {0.5, 0.9, 0.5}}};
  const std::vector<double> r = probe_pressures(sc, probes, l.x, l.p, l.volume, l.material);
  ASSERT_EQ(r.size(), 3u);
  EXPECT_NEAR(r[0], 3 + 2 * 0.2, 1e-9);
  EXPECT_LT(r[1], 3 + 2 * 0.45);
  EXPECT_GT(r[1], 3 + 2 * 0.45 - 2 * 2.6 * s);
  EXPECT_EQ(r[2], 0.0);
  EXPECT_EQ(probe_columns(probes), (std::vector<std::string>{"pressure_inside", "pressure_top", "pressure_dry"}));
}

TEST(Probes, CaseFileNamesEachProbesMistake) {
  std::string text;
  for (const auto& c : embedded_cases())
    if (std::string(c.name) == "poiseuille_2d") text = c.text;
  const std::string good = text + "\n[[probe]]\nname = \"P1\"\nposition = [0.0, 0.0]\n";
  EXPECT_EQ(test::error_of(good), "");
  EXPECT_EQ(load_case_text(good, "ok.toml").probes.at(0).name, "P1");
  test::expect_refused(good, "name = \"P1\"", "name = \"P 1\"", "probe[0].name");
  test::expect_refused(good, "position = [0.0, 0.0]", "position = [0.0, 99.0]", "inside the domain");
  test::expect_refused(good, "position = [0.0, 0.0]", "position = [0.0]", "probe[0].position");
  const std::string msg = test::error_of(good + "\n[[probe]]\nname = \"P1\"\nposition = [0.0, 0.0]\n");
  EXPECT_NE(msg.find("probe[1].name"), std::string::npos) << msg;
  EXPECT_NE(msg.find("twice"), std::string::npos) << msg;
}
