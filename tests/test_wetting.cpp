// Wetting at walls: the geometric condition (interface/wall_wetting.hpp) against the constant wall
// colour of Pazdniakou eq. 10, on a drop that starts as a circular cap meeting the wall at the
// contact angle (cases/sessile_drop_2d.toml), at its first force evaluation.
#include <cmath>

#include <gtest/gtest.h>

#include "case_text.hpp"
#include "engine/engine.hpp"
#include "scene/embedded_cases.hpp"
#include "validation/sessile_drop.hpp"

using namespace psph;

namespace {

struct WallView {
  std::vector<double> x, colour, n, mat;
  double wall = -1e300;  // the wall plane
  double left = 1e300, right = -1e300;  // contact points: the liquid's extent in the first fluid row
};

WallView first_evaluation(double theta, bool geometric, std::unique_ptr<Engine>& e) {
  Case c = sessile_drop_case(theta, theta);
  c.scene.options.geometric_wetting = geometric;
  e = make_engine(c.scene, "cpu");
  WallView v{e->field("position"), e->field("colour"), e->field("colour_gradient"), e->field("material")};
  const double sp = c.scene.options.spacing;
  for (int i = 0; i < e->particles(); ++i)
    if (c.scene.materials[static_cast<int>(v.mat[i])].props.kind == MaterialKind::Wall) v.wall = std::max(v.wall, v.x[2 * i + 1]);
  v.wall += 0.5 * sp;
  for (int i = 0; i < e->particles(); ++i)
    if (v.x[2 * i + 1] > v.wall && v.x[2 * i + 1] < v.wall + sp && v.colour[i] > 0)
      v.left = std::min(v.left, v.x[2 * i]), v.right = std::max(v.right, v.x[2 * i]);
  return v;
}

}  // namespace

// Away from the contact line the walls continue the fluid's colour, so no normal (and no force)
// appears along a wall under water or gas; near it the walls' normals meet the wall at theta
// through the liquid: cos(theta) = -n^ . n_wall.
TEST(Wetting, GeometricWallsContinueTheFluidAndTurnTheNormals) {
  for (double theta : {60.0, 120.0}) {
    std::unique_ptr<Engine> e;
    const WallView v = first_evaluation(theta, true, e);
    ASSERT_LT(v.left, v.right);
    const double R = 3e-4, h = 1e-4;  // support radius; smoothing length = spacing here
    int far = 0, turned = 0;
    for (int i = 0; i < e->particles(); ++i) {
      const double x = v.x[2 * i], y = v.x[2 * i + 1];
      const double to_line = std::min(std::fabs(x - v.left), std::fabs(x - v.right));
      const double nx = v.n[2 * i], ny = v.n[2 * i + 1], len = std::hypot(nx, ny);
      if (std::fabs(y - v.wall) < R && to_line > 2 * R) {
        const bool under_liquid = x > v.left && x < v.right;
        if (y < v.wall && y > v.wall - 2 * h)  // the walls that fluid particles see
          EXPECT_NEAR(v.colour[i], under_liquid ? 1 : -1, 1e-5) << "wall at x = " << x;
        if (y > v.wall && std::fabs(v.colour[i]) > 0.999) {  // clear of the drop's own interface
          EXPECT_LT(len * h, 1e-3) << "spurious normal at x = " << x << ", y = " << y;
          ++far;
        }
      }
      if (y < v.wall && y > v.wall - h && to_line < h && len * h > 0.1) {
        EXPECT_NEAR(std::acos(-ny / len) * 180 / M_PI, theta, 0.5) << "wall at x = " << x;
        ++turned;
      }
    }
    EXPECT_GT(far, 40);
    EXPECT_GE(turned, 2);
  }
}

// The constant wall colour cos(theta) (paper eq. 10, `wetting = "wall_colour"`) puts a spurious
// interface along every wall: a normal of about 0.7 / h under the water at theta = 120.
TEST(Wetting, ConstantWallColourMarksTheWallAsAnInterface) {
  std::unique_ptr<Engine> e;
  const WallView v = first_evaluation(120, false, e);
  const double centre = 0.5 * (v.left + v.right);
  double worst = 0;
  for (int i = 0; i < e->particles(); ++i) {
    const double x = v.x[2 * i], y = v.x[2 * i + 1];
    if (y < v.wall) {
      if (y > v.wall - 3e-4) EXPECT_NEAR(v.colour[i], -0.5, 1e-6);
    } else if (y < v.wall + 1e-4 && std::fabs(x - centre) < 2e-4) {
      worst = std::max(worst, std::hypot(v.n[2 * i], v.n[2 * i + 1]) * 1e-4);
    }
  }
  EXPECT_GT(worst, 0.3);
}

// The case key: geometric by default, the paper's constant colour on request, anything else refused.
TEST(Wetting, CaseKey) {
  const std::string text = test::replaced(
      embedded_case_text("laplace_bubble_2d"), "[interface]", "[materials.rock]\nkind = \"wall\"\ncontact_angle = 30.0\n\n[interface]");
  EXPECT_TRUE(load_case_text(text, "w.toml").scene.options.geometric_wetting);
  EXPECT_FALSE(load_case_text(test::replaced(text, "[interface]", "[interface]\nwetting = \"wall_colour\""), "w.toml")
                   .scene.options.geometric_wetting);
  const std::string bad = test::error_of(test::replaced(text, "[interface]", "[interface]\nwetting = \"sharp\""));
  EXPECT_NE(bad.find("interface.wetting"), std::string::npos) << bad;
}
