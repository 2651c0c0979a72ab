// The stress form of elasticity (solid/stress_form.hpp) and its clamps (solid/clamp.hpp): mirror
// partners, rigid rotations at free surfaces, and energy conservation between clamps.
#include <cmath>
#include <map>

#include <gtest/gtest.h>

#include "case_text.hpp"
#include "engine/engine.hpp"
#include "scene/embedded_cases.hpp"
#include "scene/scene_builder.hpp"
#include "engine/clamp_partners.hpp"
#include "integrate/timestep.hpp"

using namespace psph;
using psph::test::replaced;

namespace {

Case built(const std::string& text) {
  Case c = load_case_text(text, "case.toml");
  build_particles(c);
  return c;
}

bool is_wall(const Scene& sc, int i) { return sc.materials[sc.material[i]].props.kind == MaterialKind::Wall; }

// A free 2D block of 20 x 20 spacings of clay in an empty box.
const std::string kFreeBlock = R"(
[case]
name = "block"
dimension = 2
[domain]
lower = [-0.2, -0.2]
upper = [0.2, 0.2]
[discretisation]
spacing = 0.01
support_radius = 0.02
[materials.clay]
kind = "elastic"
density = 2000.0
young_modulus = 1.0e6
poisson_ratio = 0.1
[time]
end = 1.0
[[geometry]]
shape = "box"
lower = [-0.1, -0.1]
upper = [0.1, 0.1]
material = "clay"
)";

}  // namespace

// Every wall within a support of the rod mirrors the particle at its image through the clamp plane
// (x -> -x at the left end, x -> 2L - x at the right), and the partner points back; the deepest
// layer, a full support from the rod, is no neighbour of it and has none.
TEST(StressForm, ClampWallsMirrorTheirImageInTheRod) {
  const Case c = built(embedded_case_text("vibrating_rod_1d"));
  const Scene& sc = c.scene;
  const std::vector<std::int32_t> mirror = clamp_mirror_partners(sc);
  const double L = 0.1333, dx = sc.options.spacing;
  int paired = 0;
  for (int w = 0; w < sc.count(); ++w) {
    if (!is_wall(sc, w)) continue;
    const double gap = sc.x[w] < 0 ? dx / 2 - sc.x[w] : sc.x[w] - (L - dx / 2);  // to the nearest rod particle
    if (gap >= sc.options.support_radius * (1 - 1e-9)) {
      EXPECT_EQ(mirror[w], -1);
      continue;
    }
    ASSERT_GE(mirror[w], 0) << "wall at x = " << sc.x[w];
    const double image = sc.x[w] < 0 ? -sc.x[w] : 2 * L - sc.x[w];
    EXPECT_NEAR(sc.x[mirror[w]], image, 1e-3 * dx);
    EXPECT_EQ(mirror[mirror[w]], w);
    ++paired;
  }
  EXPECT_EQ(paired, 18);
}

// The plate's clamp: walls at (-x, y) mirror the plate at (x, y); the wall layers beyond a support
// of the plate have no partner.
TEST(StressForm, ClampWallsMirrorTheirImageInThePlate) {
  const Case c = built(embedded_case_text("oscillating_plate_2d"));
  const Scene& sc = c.scene;
  const std::vector<std::int32_t> mirror = clamp_mirror_partners(sc);
  const double dx = sc.options.spacing, support = sc.options.support_radius;
  int paired = 0, unpaired = 0;
  for (int w = 0; w < sc.count(); ++w) {
    if (!is_wall(sc, w)) continue;
    if (-sc.x[2 * w] > support) {
      EXPECT_EQ(mirror[w], -1);
      ++unpaired;
      continue;
    }
    ASSERT_GE(mirror[w], 0);
    EXPECT_NEAR(sc.x[2 * mirror[w]], -sc.x[2 * w], 1e-3 * dx);
    EXPECT_NEAR(sc.x[2 * mirror[w] + 1], sc.x[2 * w + 1], 1e-3 * dx);
    ++paired;
  }
  EXPECT_EQ(paired, 2 * 10);  // two layers of ten
  EXPECT_GT(unpaired, 0);
}

// A free 2D block spun as a rigid body: the small-strain stress form sees no strain in a rotation
// (sym grad u = 0 to first order), also on its free surfaces, so almost no energy leaves the
// rotation; the displacement form's transverse pair term resists it where the support is truncated.
TEST(StressForm, ARigidRotationOfAFreeBlockCostsNoEnergy) {
  const std::string text = kFreeBlock;
  std::map<SolidFormulation, double> share;
  for (SolidFormulation form : {SolidFormulation::Stress, SolidFormulation::Displacement}) {
    Case c = built(text);
    c.scene.options.solid_formulation = form;
    const double omega = 0.1;  // rad/s: 1e-3 rad after 0.01 s
    for (int i = 0; i < c.scene.count(); ++i)
      c.scene.v[2 * i] = -omega * c.scene.x[2 * i + 1], c.scene.v[2 * i + 1] = omega * c.scene.x[2 * i];
    auto e = make_engine(c.scene, "cpu");
    const double k0 = e->stats().kinetic_energy;
    e->run_until(0.01);
    share[form] = e->stats().elastic_energy / k0;
  }
  std::printf("elastic energy / initial kinetic after a 1e-3 rad rotation: stress form %.2e, displacement form %.2e\n",
              share[SolidFormulation::Stress], share[SolidFormulation::Displacement]);
  EXPECT_LT(share[SolidFormulation::Stress], 1e-4);
  EXPECT_GT(share[SolidFormulation::Displacement], 100 * share[SolidFormulation::Stress]);
}

// Monaghan's artificial viscosity and XSPH on a solid (solid/artificial_viscosity.hpp): a block
// squeezed by its initial velocity keeps its momentum exactly, and the viscosity takes energy from
// it step by step (the kinetic + elastic energy never rises); without them the energy is kept.
TEST(StressForm, ArtificialViscosityKeepsMomentumAndTakesEnergy) {
  const std::string text = replaced(replaced(kFreeBlock, "[time]", R"([solid]
artificial_viscosity = 1.0
artificial_viscosity_beta = 2.0
xsph = 0.5
[time])"), "upper = [0.1, 0.1]", "upper = [0.1, 0.12]");
  auto energy_after = [&](const std::string& t, double& momentum_error) {
    Case c = built(t);
    for (int i = 0; i < c.scene.count(); ++i)  // squeezed along x, drifting along y
      c.scene.v[2 * i] = -0.01 * std::sin(M_PI * c.scene.x[2 * i] / 0.1), c.scene.v[2 * i + 1] = 0.003;
    auto e = make_engine(c.scene, "cpu");
    auto momentum = [&] {
      const auto v = e->field("velocity"), m = e->field("mass");
      std::array<double, 2> p{0, 0};
      for (int i = 0; i < e->particles(); ++i) p[0] += m[i] * v[2 * i], p[1] += m[i] * v[2 * i + 1];
      return p;
    };
    const auto p0 = momentum();
    const double e0 = e->stats().kinetic_energy + e->stats().elastic_energy;
    double previous = e0, rise = 0;
    for (int s = 0; s < 400; ++s) {
      e->step(1.0);
      const double en = e->stats().kinetic_energy + e->stats().elastic_energy;
      rise = std::max(rise, en - previous);
      previous = en;
    }
    const auto p1 = momentum();
    momentum_error = std::hypot(p1[0] - p0[0], p1[1] - p0[1]) / std::hypot(p0[0], p0[1]);
    EXPECT_LT(rise, 1e-3 * e0);
    return previous / e0;
  };
  double err_visc = 0, err_plain = 0;
  const double with = energy_after(text, err_visc);
  const double without = energy_after(replaced(text, "artificial_viscosity = 1.0\nartificial_viscosity_beta = 2.0\nxsph = 0.5\n", ""), err_plain);
  EXPECT_LT(err_visc, 1e-12);
  EXPECT_LT(with, 0.9);
  EXPECT_NEAR(without, 1.0, 1e-3);
}

// The solid's artificial viscosity limits the step as the kinematic viscosity it amounts to,
// nu = alpha h_s c / (2 (d + 2)) (integrate/timestep.hpp): in 2D its viscous limit is h_s / (alpha c),
// 2.5 times below the acoustic one at the softening bar's alpha = 10, where the step of the
// acoustic limit alone damaged the bar near its grips within 7 us (validation/softening_bar.cpp).
// Without it, or on fluids only, the limits are those of before.
TEST(StressForm, ArtificialViscosityLimitsTheStep) {
  Material m[2];
  m[0].kind = MaterialKind::Elastic, m[0].sound_speed = 6758.5;
  m[1].kind = MaterialKind::Fluid, m[1].sound_speed = 1500;  // the solid's c, not the fluid's, enters
  const double h = 2.5e-3;
  EXPECT_EQ(time_step_limits(h, time_step_inputs(m, 2, false, 0), 0, 0, 1).viscous, std::numeric_limits<double>::infinity());
  const TimeStepLimits l = time_step_limits(h, time_step_inputs(m, 2, false, 0, 10, 0, 2), 70, 0, 1);
  EXPECT_NEAR(l.viscous, h / (10 * 6758.5), 1e-20);
  EXPECT_STREQ(l.limiting(), "viscous");
  // The quadratic term with |v_ij| <= 2 v_max, in 3D.
  EXPECT_NEAR(time_step_limits(h, time_step_inputs(m, 2, false, 0, 10, 1, 3), 70, 0, 1).viscous,
              0.125 * h * h / (h * (10 * 6758.5 + 2 * 70) / 10), 1e-20);
  // The engine steps by it: the free block (h_s = 0.01 m) with alpha = 10.
  auto e = make_engine(built(replaced(kFreeBlock, "[time]", "[solid]\nartificial_viscosity = 10.0\n[time]")).scene, "cpu");
  e->step(1.0);
  const double c = std::sqrt((1e6 / (3 * (1 - 0.2)) + 4 * 1e6 / (2 * 1.1) / 3) / 2000);  // E = 1 MPa, nu = 0.1
  EXPECT_EQ(e->stats().dt_limit, "viscous");
  EXPECT_NEAR(e->last_dt(), 0.01 / (10 * c), 1e-9 * 0.01 / (10 * c));
}

// Saint Venant-Kirchhoff is objective: a free block set spinning at 10 rad/s turns as a rigid body
// through half a radian, keeping its shape (E = (F^T F - I) / 2 sees the stretch of any motion
// that is no rotation). The small-strain law reads the linearised rotation u = theta x x0 as no
// strain at all: its particles fly off along their initial velocities and the block grows by
// sqrt(1 + (omega t)^2) = 1.118 at no elastic cost. The large-strain solid keeps its neighbours of
// t = 0 all along (neighbours/reference_list.hpp).
TEST(StressForm, SaintVenantKirchhoffIsObjectiveUnderLargeRotations) {
  const std::string text = replaced(replaced(replaced(replaced(kFreeBlock, "poisson_ratio = 0.1", "poisson_ratio = 0.3"), "[time]",
                                                              "[solid]\nmodel = \"saint_venant_kirchhoff\"\n[time]"),
                                             "lower = [-0.1, -0.1]", "lower = [-0.1, -0.05]"),
                                    "upper = [0.1, 0.1]", "upper = [0.1, 0.05]");
  std::map<SolidModel, double> lo, hi;  // the range of |x| / |x0| over particles away from the centre
  double turned = 0;
  for (SolidModel model : {SolidModel::SaintVenantKirchhoff, SolidModel::Linear}) {
    Case c = built(text);
    c.scene.options.solid_model = model;
    const double omega = 10.0;  // rad/s: 0.5 rad after 0.05 s
    for (int i = 0; i < c.scene.count(); ++i)
      c.scene.v[2 * i] = -omega * c.scene.x[2 * i + 1], c.scene.v[2 * i + 1] = omega * c.scene.x[2 * i];
    auto e = make_engine(c.scene, "cpu");
    e->run_until(0.05);
    const auto x = e->field("position"), x0 = e->field("reference_position");
    lo[model] = 1e9, hi[model] = 0;
    for (int i = 0; i < e->particles(); ++i) {
      const double r0 = std::hypot(x0[2 * i], x0[2 * i + 1]);
      if (r0 < 0.05) continue;
      const double ratio = std::hypot(x[2 * i], x[2 * i + 1]) / r0;
      lo[model] = std::min(lo[model], ratio), hi[model] = std::max(hi[model], ratio);
      if (model == SolidModel::SaintVenantKirchhoff && x0[2 * i] > 0.09 && std::fabs(x0[2 * i + 1]) < 0.006)
        turned = std::atan2(x[2 * i + 1], x[2 * i]) - std::atan2(x0[2 * i + 1], x0[2 * i]);
    }
  }
  std::printf("|x| / |x0| after 0.5 rad: Saint Venant-Kirchhoff %.4f..%.4f, linear %.4f..%.4f; turned %.4f rad\n",
              lo[SolidModel::SaintVenantKirchhoff], hi[SolidModel::SaintVenantKirchhoff], lo[SolidModel::Linear],
              hi[SolidModel::Linear], turned);
  EXPECT_NEAR(lo[SolidModel::SaintVenantKirchhoff], 1.0, 0.01);
  EXPECT_NEAR(hi[SolidModel::SaintVenantKirchhoff], 1.0, 0.01);
  EXPECT_NEAR(turned, 0.5, 0.02);
  EXPECT_GT(lo[SolidModel::Linear], 1.1);
}

// Ganzenmüller's hourglass control (solid/hourglass.hpp). A chequerboard velocity on a periodic
// block (each particle moving against its four nearest neighbours) is a zero-energy mode of the
// stress form: nothing resists it, and its kinetic energy stays. With the control it oscillates,
// trading that energy against the penalty's (a quarter period ~10 ms at alpha 0.1).
TEST(StressForm, HourglassControlHoldsTheChequerboardMode) {
  const std::string periodic = replaced(replaced(kFreeBlock, "upper = [0.2, 0.2]", "upper = [0.1, 0.1]\nperiodic = [true, true]"),
                                        "lower = [-0.2, -0.2]", "lower = [-0.1, -0.1]");
  auto kinetic_min = [&](double alpha) {
    Case c = built(periodic);
    c.scene.options.solid_hourglass = alpha;
    for (int i = 0; i < c.scene.count(); ++i) {
      const long ix = std::lround(c.scene.x[2 * i] / 0.01 - 0.5), iy = std::lround(c.scene.x[2 * i + 1] / 0.01 - 0.5);
      c.scene.v[2 * i + 1] = (ix + iy) % 2 ? 1e-4 : -1e-4;
    }
    auto e = make_engine(c.scene, "cpu");
    const double k0 = e->stats().kinetic_energy;
    double lowest = 1;
    while (e->time() < 0.03) {
      e->step(1.0);
      lowest = std::min(lowest, e->stats().kinetic_energy / k0);
    }
    return lowest;
  };
  const double without = kinetic_min(0), with = kinetic_min(0.1);
  std::printf("chequerboard mode's lowest kinetic energy over 30 ms / initial: %.3f without control, %.3f with alpha 0.1\n",
              without, with);
  EXPECT_GT(without, 0.99);
  EXPECT_LT(with, 0.05);
}

// A linear displacement (here a uniform stretch and a rotation set going) is what each particle's
// corrected gradient sees, on the free surfaces too: the control adds to it only at second order in
// the strain (the strain sums take the current pairs' kernel gradients with the corrections of the
// reference state), 1e-7 of the elastic forces here.
TEST(StressForm, HourglassControlLeavesLinearFieldsAlone) {
  auto accelerations = [&](double alpha) {
    Case c = built(kFreeBlock);
    c.scene.options.solid_hourglass = alpha;
    for (int i = 0; i < c.scene.count(); ++i) {
      const double x = c.scene.x[2 * i], y = c.scene.x[2 * i + 1];
      c.scene.v[2 * i] = 0.02 * x - 0.05 * y, c.scene.v[2 * i + 1] = 0.05 * x + 0.01 * y;
    }
    auto e = make_engine(c.scene, "cpu");
    e->step(1.0);
    return e->field("acceleration");
  };
  const std::vector<double> plain = accelerations(0), controlled = accelerations(0.1);
  double diff = 0, scale = 0;
  for (std::size_t k = 0; k < plain.size(); ++k)
    diff = std::max(diff, std::fabs(controlled[k] - plain[k])), scale = std::max(scale, std::fabs(plain[k]));
  std::printf("linear field after one step: control changes the accelerations by %.2e of their largest (%.3e m/s^2)\n",
              diff / scale, scale);
  EXPECT_GT(scale, 0);
  EXPECT_LT(diff, 1e-6 * scale);
}

// A block between two plates squeezed sideways (a traction on its x faces, ramped, damped to rest).
// Bonded plates (clamp = "stick") hold its rows next to them: the first shortens half as much.
// Lubricated ones (clamp = "slip") hold the normal displacement only: every row shortens alike,
// the uniaxial -sigma / E' of the rows far from the plates.
TEST(StressForm, SlipClampsLetTheSolidSlideAlongThePlates) {
  const std::string squeezed = replaced(kFreeBlock, "[time]", R"([materials.plate]
kind = "wall"
clamp = "stick"
[solid]
damping_rate = 300.0
[[solid_load]]
material = "clay"
lower = [-0.1, -0.1]
upper = [-0.09, 0.1]
traction = [1000.0, 0.0]
ramp_time = 0.02
[[solid_load]]
material = "clay"
lower = [0.09, -0.1]
upper = [0.1, 0.1]
traction = [-1000.0, 0.0]
ramp_time = 0.02
[time])") + R"([[geometry]]
shape = "box"
lower = [-0.15, -0.13]
upper = [0.15, -0.1]
material = "plate"
[[geometry]]
shape = "box"
lower = [-0.15, 0.1]
upper = [0.15, 0.13]
material = "plate"
)";
  auto row_strains = [&](const std::string& text) {
    auto e = make_engine(built(text).scene, "cpu");
    e->run_until(0.1);
    const std::vector<double> x0 = e->field("reference_position"), eps = e->field("strain"), mat = e->field("material");
    std::array<double, 2> sum{0, 0}, n{0, 0};  // the row next to the lower plate, the middle row
    for (int i = 0; i < e->particles(); ++i) {
      if (mat[i] != 0 || std::fabs(x0[2 * i]) > 0.05) continue;
      const double y = x0[2 * i + 1];
      const int row = std::fabs(y + 0.095) < 1e-6 ? 0 : std::fabs(y - 0.005) < 1e-6 ? 1 : -1;
      if (row >= 0) sum[row] += eps[4 * i], n[row] += 1;
    }
    return std::array<double, 2>{sum[0] / n[0], sum[1] / n[1]};
  };
  const auto stick = row_strains(squeezed), slip = row_strains(replaced(squeezed, "clamp = \"stick\"", "clamp = \"slip\""));
  std::printf("eps_xx next to the plate / in the middle: stick %.3e / %.3e, slip %.3e / %.3e\n", stick[0], stick[1], slip[0], slip[1]);
  EXPECT_LT(stick[1], -5e-4);
  EXPECT_GT(stick[0], 0.6 * stick[1]);  // held: measured 0.52 of the middle's shortening
  EXPECT_NEAR(slip[0], slip[1], 0.05 * std::fabs(slip[1]));
  EXPECT_NE(psph::test::error_of(replaced(squeezed, "clamp = \"stick\"", "clamp = \"glued\"")).find("materials.plate.clamp"), std::string::npos);
}
