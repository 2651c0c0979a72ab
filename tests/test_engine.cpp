// Engine behaviour: reproducibility for any thread count, conservation, integrators, 1D runs and
// the instability diagnostics.
#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <cmath>

#include "core/instability.hpp"
#include "engine/engine.hpp"
#include "kernels/kernel.hpp"
#include "scene/case_file.hpp"
#include "scene/embedded_cases.hpp"
#include "scene/scene_builder.hpp"

using namespace psph;

namespace {

Case embedded(const std::string& name, const std::vector<std::pair<std::string, double>>& overrides = {}) {
  for (const auto& ec : embedded_cases())
    if (name == ec.name) {
      toml::table t = toml::parse(ec.text);
      for (const auto& [k, v] : overrides) set_case_value(t, k, toml::value<double>(v));
      Case c = parse_case(t, name);
      build_particles(c);
      return c;
    }
  throw std::runtime_error("no case " + name);
}

// A periodic unit box of fluid with a shear wave v_x = 0.1 sin(2 pi y) (no walls).
Scene shear_box(int n, int dimension = 2) {
  ShearBox b;
  b.dimension = dimension, b.per_axis = n, b.length = 1;
  b.density = 1, b.viscosity = 1e-2, b.sound_speed = 10, b.amplitude = 0.1;
  return shear_box_scene(b);
}

// A closed 2D tank (walls 4 spacings thick) with water up to `water_top`, and a [solver] block.
std::string tank_case(const std::string& solver, double water_top) {
  return R"(
[case]
name = "tank"
dimension = 2
[domain]
lower = [-0.2, -0.2]
upper = [1.2, 1.4]
[discretisation]
spacing = 0.05
smoothing_length = 0.065
kernel = "wendland_c2"
[materials.water]
kind = "fluid"
density = 1.0
viscosity = 0.0
sound_speed = 20.0
body_force = [0.0, -1.0]
[materials.wall]
kind = "wall"
[solver]
)" + solver + R"(
[time]
end = 3.0
[[geometry]]
shape = "box"
lower = [-0.2, -0.2]
upper = [1.2, 1.4]
material = "wall"
[[geometry]]
shape = "box"
lower = [0.0, 0.0]
upper = [1.0, 1.4]
material = "empty"
[[geometry]]
shape = "box"
lower = [0.0, 0.0]
upper = [1.0, )" + std::to_string(water_top) + R"(]
material = "water"
)";
}

}  // namespace

TEST(Engine, IdenticalForAnyThreadCount) {
  Case c = embedded("poiseuille_2d");
  std::vector<std::vector<double>> v;
  for (int threads : {1, 2}) {
    omp_set_num_threads(threads);
    auto e = make_cpu_engine(c.scene);
    for (int s = 0; s < 30; ++s) e->step(1.0);
    v.push_back(e->field("velocity"));
    auto x = e->field("position");
    v.back().insert(v.back().end(), x.begin(), x.end());
  }
  omp_set_num_threads(2);
  EXPECT_EQ(v[0], v[1]);  // bitwise: gather sums, no atomics
}

TEST(Engine, PeriodicBoxConservesMomentum) {
  for (int dim : {1, 2, 3}) {
    Scene sc = shear_box(dim == 3 ? 10 : 24, dim);
    auto e = make_cpu_engine(sc);
    auto momentum = [&] {
      const auto v = e->field("velocity"), m = e->field("mass");
      double p = 0;
      for (int i = 0; i < e->particles(); ++i) p += m[i] * v[i * dim];
      return p;
    };
    const double p0 = momentum();
    const double ke0 = e->stats().kinetic_energy;
    for (int s = 0; s < 40; ++s) e->step(1.0);
    EXPECT_NEAR(momentum(), p0, 1e-12) << dim << "D";
    // Viscosity damps the shear wave (dim 1 has no shear: the wave is a compression wave there).
    if (dim > 1) EXPECT_LT(e->stats().kinetic_energy, ke0) << dim << "D";
  }
}

TEST(Engine, ShearWaveDecaysAtTheViscousRate) {
  // v_x = A sin(2 pi y) decays as exp(-4 pi^2 nu t) (nu = 1e-2 m^2/s here).
  Scene sc = shear_box(40);
  auto e = make_cpu_engine(sc);
  const double ke0 = e->stats().kinetic_energy;
  const double t = 0.5;
  e->run_until(t);
  const double ratio = std::sqrt(e->stats().kinetic_energy / ke0);
  const double exact = std::exp(-4 * M_PI * M_PI * 1e-2 * t);
  EXPECT_NEAR(ratio / exact, 1.0, 0.02);
}

TEST(Engine, LeapfrogAndVerletAgreeOnPoiseuille) {
  Case a = embedded("poiseuille_2d");
  Case b = a;
  b.scene.options.integrator = Integrator::Leapfrog;
  auto ea = make_cpu_engine(a.scene), eb = make_cpu_engine(b.scene);
  ea->run_until(0.1), eb->run_until(0.1);
  const auto va = ea->field("velocity"), vb = eb->field("velocity");
  double vmax = 0, diff = 0;
  for (std::size_t i = 0; i < va.size(); ++i) vmax = std::max(vmax, std::fabs(va[i])), diff = std::max(diff, std::fabs(va[i] - vb[i]));
  EXPECT_GT(vmax, 1e-5);
  EXPECT_LT(diff, 0.01 * vmax);
}

TEST(Engine, ContinuityAndNormalisedSummationRun) {
  for (auto method : {DensityMethod::Continuity, DensityMethod::NormalisedSummation}) {
    Case c = embedded("poiseuille_2d");
    c.scene.options.density = method;
    auto e = make_cpu_engine(c.scene);
    e->run_until(0.05);
    const StepStats s = e->stats();
    EXPECT_GT(s.v_max, 1e-6);
    EXPECT_LT(s.density_deviation_max, 1e-2);
  }
}

TEST(Engine, TimeStepLandsOnRequestedTimes) {
  Case c = embedded("poiseuille_2d");
  auto e = make_cpu_engine(c.scene);
  e->run_until(0.0123);
  EXPECT_DOUBLE_EQ(e->time(), 0.0123);
}

TEST(Engine, BlowUpStopsWithADiagnostic) {
  Case c = embedded("poiseuille_2d");
  c.scene.options.fixed_dt = 0.05;  // far beyond the acoustic limit (2.5e-3 s)
  c.scene.options.max_density_deviation = 0.1;
  c.scene.options.stop_on_density_deviation = true;
  auto e = make_cpu_engine(c.scene);
  try {
    e->run_until(0.5);
    FAIL() << "an unstable run did not stop";
  } catch (const InstabilityError& err) {
    const std::string msg = err.what();
    EXPECT_TRUE(msg.find("left the domain") != std::string::npos || msg.find("non-finite") != std::string::npos ||
                msg.find("no longer weakly compressible") != std::string::npos)
        << msg;
    EXPECT_NE(msg.find("at t = "), std::string::npos) << msg;
  }
}

// Past its bound the density is watched, not stopped (solver.on_density_deviation = "warn"): the
// first step past it is kept with the particle, and the process's ledger holds the peak.
TEST(Engine, DensityWatchKeepsTheFirstExceedance) {
  Case c = embedded("poiseuille_2d");
  c.scene.options.max_density_deviation = 1e-5;
  take_density_deviation_peak();
  auto e = make_cpu_engine(c.scene);
  e->run_until(0.2);
  const DensityWatch& w = e->density_watch();
  ASSERT_TRUE(w.exceeded());
  EXPECT_GT(w.first.value, 1e-5);
  EXPECT_GE(w.peak, w.first.value);
  EXPECT_LE(w.first.time, w.peak_time + 1e-12);
  EXPECT_GT(w.first.time, 0.0);
  EXPECT_NE(w.first.where.find("material water"), std::string::npos) << w.first.where;
  EXPECT_DOUBLE_EQ(take_density_deviation_peak(), w.peak);
  EXPECT_EQ(take_density_deviation_peak(), -1.0);  // taken
  EXPECT_LE(e->stats().density_deviation_max, w.peak);
}

TEST(Engine, FieldsByName) {
  Case c = embedded("poiseuille_2d");
  auto e = make_cpu_engine(c.scene);
  const auto names = e->field_names();
  for (const char* n : {"position", "velocity", "pressure", "density", "material", "id"})
    EXPECT_NE(std::find(names.begin(), names.end(), n), names.end()) << n;
  EXPECT_EQ(e->field("velocity").size(), std::size_t(2 * e->particles()));
  EXPECT_THROW(e->field("colour"), std::invalid_argument);
}

TEST(Engine, VerletSkinDoesNotChangeResults) {
  // Lists with a skin are rebuilt less often; the physics must not notice (only summation order).
  std::vector<std::vector<double>> v;
  for (double skin : {0.0, 0.3}) {
    Case c = embedded("poiseuille_2d");
    c.scene.options.neighbour_skin = skin;
    auto e = make_cpu_engine(c.scene);
    e->run_until(0.05);
    const auto vel = e->field("velocity"), id = e->field("id");
    std::vector<double> by_id(vel.size());
    for (int i = 0; i < e->particles(); ++i)
      for (int k = 0; k < 2; ++k) by_id[static_cast<int>(id[i]) * 2 + k] = vel[i * 2 + k];
    v.push_back(by_id);
  }
  double scale = 0, diff = 0;
  for (std::size_t i = 0; i < v[0].size(); ++i)
    scale = std::max(scale, std::fabs(v[0][i])), diff = std::max(diff, std::fabs(v[0][i] - v[1][i]));
  EXPECT_GT(scale, 1e-6);
  EXPECT_LT(diff, 1e-9 * scale);
}

TEST(Engine, HydrostaticTankStaysAtRest) {
  // Water at rest in a 2D tank under gravity (free surface), density by continuity: it must settle, not
  // gain energy (continuity evaluated with the drift velocity, fluid/continuity.hpp).
  const std::string text = tank_case("density = \"continuity\"\nartificial_viscosity = 0.1\ndensity_diffusion = 0.1\nwall_noslip = \"prescribed\"", 1.2);
  Case c = load_case_text(text, "tank.toml");
  build_particles(c);
  auto e = make_cpu_engine(c.scene);
  e->run_until(3.0);
  const StepStats s = e->stats();
  EXPECT_LT(s.v_max, 0.03);  // sqrt(g H) = 1.1 m/s: the tank is at rest to 3 %
  EXPECT_LT(s.density_deviation_max, 0.005);  // hydrostatic: rho g H / c^2 = 0.3 %
}

TEST(Engine, JitterMovesFluidOnly) {
  Case a = embedded("poiseuille_2d");
  Case b = embedded("poiseuille_2d", {{"discretisation.jitter", 0.2}});
  ASSERT_EQ(a.scene.x.size(), b.scene.x.size());
  double moved_fluid = 0, moved_wall = 0;
  for (int i = 0; i < a.scene.count(); ++i)
    for (int k = 0; k < 2; ++k) {
      const double d = std::fabs(a.scene.x[i * 2 + k] - b.scene.x[i * 2 + k]);
      double& m = a.scene.materials[a.scene.material[i]].props.kind == MaterialKind::Fluid ? moved_fluid : moved_wall;
      m = std::max(m, d);
    }
  EXPECT_GT(moved_fluid, 0.05 * 5e-5);
  EXPECT_LE(moved_fluid, 0.2 * 5e-5 * (1 + 1e-9));
  EXPECT_EQ(moved_wall, 0.0);
}

TEST(Engine, WallRestDensityIsTheFullInitialSum) {
  // Every wall particle's rest density (summation mode) is its full initial kernel sum, also for
  // walls that start far from the fluid and get no neighbour list afterwards. Brute force check.
  const std::string text = tank_case("wall_pressure = \"summation\"", 0.3);
  Case c = load_case_text(text, "tank.toml");
  build_particles(c);
  const Scene& sc = c.scene;
  const Kernel<2> k = Kernel<2>::make(KernelType::WendlandC2, Real(0.13));
  auto e = make_cpu_engine(sc);
  const auto rho0 = e->field("rest_density"), id = e->field("id");
  int walls = 0;
  for (int i = 0; i < e->particles(); ++i) {
    const int p = static_cast<int>(id[i]);
    if (sc.materials[sc.material[p]].props.kind != MaterialKind::Wall) continue;
    double sum = 0;
    for (int q = 0; q < sc.count(); ++q) {
      const double dx = sc.x[2 * p] - sc.x[2 * q], dy = sc.x[2 * p + 1] - sc.x[2 * q + 1];
      sum += sc.mass[q] * k.W(Real(std::sqrt(dx * dx + dy * dy)));
    }
    ASSERT_NEAR(rho0[i], sum, 1e-12 * sum) << "wall particle " << p;
    ++walls;
  }
  EXPECT_GT(walls, 300);
}

// A clock so far along that a step no longer advances it: the run stops (exit 3), it does not
// sit at one time for ever.
TEST(Engine, AStepThatMakesNoProgressIsAnInstability) {
  Case c = embedded("poiseuille_2d");
  auto e = make_engine(c.scene, "cpu");
  Checkpoint ck = e->checkpoint();
  ck.time = 1e20;
  e->restore(ck);
  try {
    e->step(2e20);
    ADD_FAILURE() << "a step at t = 1e20 s went on";
  } catch (const InstabilityError& x) {
    EXPECT_NE(std::string(x.what()).find("makes no progress"), std::string::npos) << x.what();
  }
}

// [solver] background_pressure_rate: the fluid's pressure rises at the rate, particle by particle
// (a uniform pressure barely moves a periodic box: its density varies by the wave's 0.1 %), and
// a restart carries it on.
TEST(Engine, TheBackgroundPressureRisesAtItsRate) {
  // restart: the second half of the run by an engine restored from a checkpoint at t / 2.
  auto run = [&](double rate, double t, bool restart = false) {
    Scene sc = shear_box(16);
    for (auto& m : sc.materials) m.props.background_pressure = 1.0;
    sc.options.background_pressure_rate = rate;
    auto e = make_cpu_engine(sc);
    if (restart) {
      e->run_until(t / 2);
      const Checkpoint ck = e->checkpoint();
      e = make_cpu_engine(sc);
      e->restore(ck);
    }
    e->run_until(t);
    const std::vector<double> p = e->field("pressure"), id = e->field("id");
    std::vector<double> by_id(p.size());
    for (std::size_t i = 0; i < p.size(); ++i) by_id[std::size_t(id[i])] = p[i];
    return by_id;
  };
  const double t = 0.2, rate = 50.0;
  const std::vector<double> fixed = run(0, t), rising = run(rate, t), restarted = run(rate, t, true);
  double worst = 0, restart_diff = 0;
  for (std::size_t i = 0; i < fixed.size(); ++i) {
    worst = std::max(worst, std::fabs(rising[i] - fixed[i] - rate * t));
    restart_diff = std::max(restart_diff, std::fabs(restarted[i] - rising[i]));
  }
  EXPECT_LT(worst, 1e-2 * rate * t);  // measured 0.2 %: the shear wave's density varies
  EXPECT_LT(restart_diff, 1e-6 * rate * t);  // a restart without the rise would be rate t / 2 off
}

namespace profile_names {
template <int D>
struct SomePass {
  void operator()(int) const {}
};
}  // namespace profile_names

// The profile (core/pass_profile.hpp) names a pass after its functor, without namespaces or
// template arguments; a lambda after the function it is in.
TEST(Engine, ProfileNamesPassesAfterTheirFunctors) {
  EXPECT_EQ(pass_name_of<profile_names::SomePass<3>>(), "SomePass");
  auto lambda = [](int) {};
  EXPECT_EQ(pass_name_of<decltype(lambda)>(), "TestBody()::{lambda(int)#1}");
}

// A pure fluid's steps: each pass under its stage, once a step for the once-a-step passes, and no
// stage that the case does not need (solid, damage, coupling, interface).
TEST(Engine, ProfileHasTheStagesACaseNeedsOnly) {
  auto e = make_engine(shear_box(24), "cpu");
  e->profile().clear();
  for (int s = 0; s < 5; ++s) e->step(1.0);
  std::vector<std::string> stages;
  for (const PassTime& t : e->profile().stages()) {
    stages.push_back(t.stage);
    EXPECT_GT(t.seconds, 0.0) << t.stage;
  }
  for (const char* s : {"fluid", "integrate", "time step", "health check"})
    EXPECT_NE(std::find(stages.begin(), stages.end(), s), stages.end()) << s;
  for (const char* s : {"solid", "damage", "coupling", "interface"})
    EXPECT_EQ(std::find(stages.begin(), stages.end(), s), stages.end()) << s;
  int density = 0;
  for (const PassTime& t : e->profile().passes()) {
    if (t.pass != "DensitySummationPass") continue;
    ++density;
    EXPECT_EQ(t.stage, "fluid");
    EXPECT_EQ(t.calls, 5);
  }
  EXPECT_EQ(density, 1);
}
