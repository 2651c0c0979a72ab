// The engine in another length unit (engine/unit_scaled_engine.hpp, what a float build runs at
// nanometre supports): in double, every case's run in a power-of-two unit is the run in SI, bit for
// bit, through everything the engine hands out, its checkpoints included. A dimensional option left
// unscaled (engine/scene_units.cpp) or a unit missing from the table shows here.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <cstring>
#include <filesystem>

#include "core/length_unit.hpp"
#include "engine/engine.hpp"
#include "engine/unit_scaled_engine.hpp"
#include "io/checkpoint_file.hpp"
#include "scene/case_file.hpp"
#include "scene/scene_builder.hpp"

using namespace psph;

namespace {

struct UnitCase {
  const char* file;
  std::vector<std::string> sets;
  int steps;
};

Scene scene_of(const UnitCase& uc) {
  Case c = load_case_file(std::string(PORESPH_CASES_DIR) + "/" + uc.file, uc.sets);
  build_particles(c);
  return c.scene;
}

std::unique_ptr<Engine> in_unit(const Scene& sc, int exponent) {
  const LengthUnit u{exponent, sc.dimension};
  return std::make_unique<UnitScaledEngine>(sc, u, [](const Scene& s) { return make_cpu_engine(s); });
}

// Everything the engine hands out, the same to the bit.
void expect_same(Engine& si, Engine& scaled, const std::string& what) {
  SCOPED_TRACE(what + " at step " + std::to_string(si.steps()));
  ASSERT_EQ(si.steps(), scaled.steps());
  EXPECT_EQ(si.time(), scaled.time());
  EXPECT_EQ(si.last_dt(), scaled.last_dt());
  for (const std::string& name : si.field_names()) EXPECT_EQ(si.field(name), scaled.field(name)) << name;
  const StepStats a = si.stats(), b = scaled.stats();
  EXPECT_EQ(a.v_max, b.v_max);
  EXPECT_EQ(a.a_max, b.a_max);
  EXPECT_EQ(a.kinetic_energy, b.kinetic_energy);
  EXPECT_EQ(a.elastic_energy, b.elastic_energy);
  EXPECT_EQ(a.density_deviation_max, b.density_deviation_max);
  EXPECT_EQ(a.dt_limit, b.dt_limit);
  const std::vector<MonitorValue> ma = si.monitors(), mb = scaled.monitors();
  ASSERT_EQ(ma.size(), mb.size());
  for (std::size_t k = 0; k < ma.size(); ++k) EXPECT_EQ(ma[k].value, mb[k].value) << ma[k].name;
  const std::vector<RigidBodyState> ra = si.rigid_bodies(), rb = scaled.rigid_bodies();
  ASSERT_EQ(ra.size(), rb.size());
  for (std::size_t k = 0; k < ra.size(); ++k) {
    EXPECT_EQ(ra[k].mass, rb[k].mass);
    EXPECT_EQ(ra[k].centre, rb[k].centre);
    EXPECT_EQ(ra[k].angular_momentum, rb[k].angular_momentum);
    EXPECT_EQ(ra[k].inertia0, rb[k].inertia0);
  }
  EXPECT_EQ(si.density_watch().peak, scaled.density_watch().peak);
  EXPECT_EQ(si.density_watch().peak_time, scaled.density_watch().peak_time);
}

void expect_same_checkpoints(const Checkpoint& a, const Checkpoint& b) {
  EXPECT_EQ(a.time, b.time);
  EXPECT_EQ(a.first_dt, b.first_dt);
  EXPECT_EQ(a.dissipated_energy, b.dissipated_energy);
  EXPECT_EQ(a.rigid_bodies, b.rigid_bodies);
  ASSERT_EQ(a.fields.size(), b.fields.size());
  for (std::size_t k = 0; k < a.fields.size(); ++k) EXPECT_TRUE(a.fields[k].bytes == b.fields[k].bytes) << a.fields[k].name;
}

void run_both(const UnitCase& uc, int exponent) {
  const Scene sc = scene_of(uc);
  auto si = make_cpu_engine(sc);
  auto scaled = in_unit(sc, exponent);
  const std::string what = std::string(uc.file) + " in 2^" + std::to_string(exponent) + " m";
  expect_same(*si, *scaled, what);
  for (int k = 0; k < uc.steps; ++k) si->step(1e30), scaled->step(1e30);
  expect_same(*si, *scaled, what);
  // Checkpoints come out in SI and go back in from SI: the scaled engine restores the SI one.
  const Checkpoint c = si->checkpoint();
  expect_same_checkpoints(c, scaled->checkpoint());
  auto restored = in_unit(sc, exponent);
  restored->restore(c);
  for (int k = 0; k < 3; ++k) si->step(1e30), restored->step(1e30);
  expect_same(*si, *restored, what + ", restored");
}

// Together they set every option that engine/scene_units.cpp scales: lengths, the fixed step,
// viscosities, body forces, force regions and their ramps, surface tension and wetting, open
// boundaries, solid loads (traction ramps, imposed velocities), damping, the background pressure's
// rate, damage, rigid bodies, 1D, 2D and 3D.
const std::vector<UnitCase>& cases() {
  static const std::vector<UnitCase> all = {
      {"poiseuille_2d.toml", {"solver.dt=1e-4"}, 20},
      {"two_phase_poiseuille_2d.toml", {}, 20},
      {"sessile_drop_2d.toml", {}, 20},
      {"capillary_entry_2d.toml", {}, 20},
      {"drainage_open_2d.toml", {}, 20},
      {"pressurised_pore_2d.toml", {}, 20},
      {"plate_inclusion_2d.toml", {}, 20},
      {"softening_bar_2d.toml", {}, 20},
      {"lame_cylinder_2d.toml", {}, 20},
      {"settling_cylinder_2d.toml", {}, 20},
      {"vibrating_rod_1d.toml", {}, 20},
      {"rigid_top_3d.toml", {}, 10},
      {"elastic_cube_3d.toml", {}, 5},
      {"claystone_drainage.toml", {}, 3},
  };
  return all;
}

}  // namespace

TEST(LengthUnit, PowersOfUnits) {
  EXPECT_EQ(length_power("m", 2), 1);
  EXPECT_EQ(length_power("kg", 2), 2);
  EXPECT_EQ(length_power("J", 3), 3);
  EXPECT_EQ(length_power("Pa", 3), 0);
  EXPECT_EQ(length_power("1/(m s)", 3), -2);
  EXPECT_THROW(length_power("furlong", 3), std::logic_error);
  const LengthUnit u{-24, 3};
  EXPECT_EQ(u.to_si(u.to_engine(4e-8, 1), 1), 4e-8);
  EXPECT_EQ(u.to_engine(1.0, 1), std::ldexp(1.0, 24));
}

// The float build's own choice: the power of two nearest the support radius.
TEST(LengthUnit, FloatBuildsRunNearTheSupportRadius) {
  const LengthUnit u = engine_length_unit(4e-8, 3);
  if (sizeof(Real) == 8) EXPECT_TRUE(u.si());
  else EXPECT_EQ(u.exponent, -25);
}

TEST(LengthUnit, EveryCaseRunsTheSameInAnyUnit) {
  if (sizeof(Real) != 8) GTEST_SKIP() << "bitwise in double only";
  for (const UnitCase& uc : cases()) {
    const Scene sc = scene_of(uc);
    const int near = int(std::lround(std::log2(sc.options.support_radius)));
    run_both(uc, near);
    if (HasFatalFailure()) return;
  }
  run_both(cases().front(), 17);  // far from the support: lengths of 2^-17 units
}

// The raw checkpoint format says each field's unit: a scaled engine restores it. An earlier raw
// file said neither components nor units: a scaled engine takes them from its registry. A unit
// that is not the field's is refused, named.
TEST(LengthUnit, RawCheckpointsRestoreInAnyUnit) {
  const UnitCase uc{"sessile_drop_2d.toml", {}, 5};
  const Scene sc = scene_of(uc);
  auto si = make_cpu_engine(sc);
  for (int k = 0; k < uc.steps; ++k) si->step(1e30);
  const std::string file = (std::filesystem::temp_directory_path() /
                            ("psph_unit_raw_" + std::to_string(::getpid()) + ".ckpt")).string();
  write_raw_checkpoint_file(file, si->checkpoint(), "sessile");
  const Checkpoint fresh = read_checkpoint_file(file);
  std::filesystem::remove(file);
  Checkpoint earlier = fresh, wrong = fresh;
  for (CheckpointField& f : earlier.fields) f.components = 0, f.type = FieldType::Byte, f.unit.clear();
  auto scaled = in_unit(sc, -10), from_earlier = in_unit(sc, -10);
  scaled->restore(fresh);
  from_earlier->restore(earlier);
  si->step(1e30), scaled->step(1e30), from_earlier->step(1e30);
  if (sizeof(Real) == 8) expect_same(*si, *scaled, "restored from the raw format");
  if (sizeof(Real) == 8) expect_same(*si, *from_earlier, "restored from an earlier raw file");
  wrong.fields[0].unit = "furlong";
  try {
    in_unit(sc, -10)->restore(wrong);
    ADD_FAILURE() << "a field in furlongs was restored";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("field '" + wrong.fields[0].name + "' has the unit 'furlong'"), std::string::npos)
        << e.what();
  }
}
