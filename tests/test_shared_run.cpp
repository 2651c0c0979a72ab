// A run shared out over the processes that mpirun started writes exactly the numbers of one
// process: every field, the step statistics and the stages' monitors, bitwise, for a case of each
// family. Each process runs the shared simulation; the first also runs it alone and compares.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include "engine/engine.hpp"
#include "io/checkpoint_file.hpp"
#include "parallel/communicator.hpp"
#include "state/checkpoint.hpp"
#include "scene/case_file.hpp"
#include "scene/embedded_cases.hpp"
#include "scene/scene_builder.hpp"

using namespace psph;
namespace fs = std::filesystem;

namespace {

// An embedded case with `--set KEY=VALUE` overrides, its particles built.
Case embedded(const std::string& name, const std::vector<std::string>& sets = {}) {
  Case c = load_case_text(embedded_case_text(name), name, sets);
  build_particles(c);
  return c;
}

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

// Where the shared run's numbers first differ from one process's (empty: nowhere).
std::string first_difference(Engine& shared, Engine* alone) {
  const StepStats s = shared.stats();
  const std::vector<MonitorValue> m = shared.monitors();
  std::vector<std::vector<double>> fields;
  for (const std::string& f : shared.field_names()) fields.push_back(shared.field(f));
  if (!alone) return "";
  const std::vector<std::string> names = alone->field_names();
  for (std::size_t f = 0; f < names.size(); ++f) {
    const std::vector<double> b = alone->field(names[f]);
    if (fields[f].size() != b.size()) return "field " + names[f] + " has another size";
    for (std::size_t i = 0; i < b.size(); ++i)
      if (!same_bits(fields[f][i], b[i])) return "field " + names[f] + " at value " + std::to_string(i);
  }
  const StepStats a = alone->stats();
  if (!same_bits(s.kinetic_energy, a.kinetic_energy)) return "kinetic energy";
  if (!same_bits(s.v_max, a.v_max) || !same_bits(s.a_max, a.a_max)) return "largest speed or acceleration";
  if (!same_bits(s.density_deviation_max, a.density_deviation_max)) return "density deviation";
  const std::vector<MonitorValue> ma = alone->monitors();
  for (std::size_t k = 0; k < ma.size(); ++k)
    if (k >= m.size() || !same_bits(m[k].value, ma[k].value)) return "monitor " + ma[k].name;
  return "";
}

// Returns the shared run's statistics.
SharingStats expect_one_process_numbers(const Case& c, int steps) {
  const std::string& name = c.name;
  Communicator& comm = world();
  EXPECT_GT(comm.size(), 1) << "run under mpirun -n 2 or more";
  auto shared = make_cpu_engine(c.scene, comm);
  Communicator one;
  std::unique_ptr<Engine> alone = comm.rank() == 0 ? make_cpu_engine(c.scene, one) : nullptr;
  EXPECT_EQ(shared->particles(), c.scene.count());
  for (int k = 1; k <= steps; ++k) {
    shared->step(1e30);
    if (alone) alone->step(1e30);
    if (k % std::max(1, steps / 4) == 0) {
      const std::string where = first_difference(*shared, alone.get());
      EXPECT_EQ(where, "") << name << " on " << comm.size() << " processes differs at step " << k << ": " << where;
      if (comm.max(static_cast<long long>(!where.empty()))) break;  // every process leaves together
    }
  }
  return shared->sharing();
}

}  // namespace

TEST(SharedRun, FluidWithWallsAndAPeriodicAxis) { expect_one_process_numbers(embedded("poiseuille_2d"), 200); }

// Also: the particle classes' costs are measured (parallel/cost_calibration.hpp), water above the
// walls far from it, and the domain is cut with them.
TEST(SharedRun, FreeSurfaceIn3D) {
  const SharingStats s = expect_one_process_numbers(embedded("dam_break_3d", {"discretisation.spacing=0.04"}), 60);
  const double* cost = s.class_costs.per_particle;
  EXPECT_TRUE(s.class_costs.measured);
  EXPECT_GT(cost[kFluidCost], cost[kWallFarCost]);
  EXPECT_GE(cost[kWallFarCost], 0);
  EXPECT_GE(s.rebalances, 1);  // the cut with the measured costs
}

TEST(SharedRun, ImplicitViscosity) {
  expect_one_process_numbers(embedded("poiseuille_2d", {"solver.implicit_viscosity=true"}), 100);
}

TEST(SharedRun, RigidBodiesInAFluid) { expect_one_process_numbers(embedded("settling_cylinder_2d"), 100); }

TEST(SharedRun, RigidBodyAlone3D) { expect_one_process_numbers(embedded("rigid_top_3d"), 100); }

// Buffers 1.3 mm thick in a 3 mm channel: on three processes their mirror points lie beyond the
// lists' radius from the box of the process that holds the buffer particle.
TEST(SharedRun, OpenBoundaries) {
  expect_one_process_numbers(embedded("open_channel_2d", {"open_boundary.thickness=1.3e-3"}), 100);
}

TEST(SharedRun, ElasticRodBetweenClamps1D) { expect_one_process_numbers(embedded("vibrating_rod_1d"), 200); }

TEST(SharedRun, ClampedCantileverPlate2D) { expect_one_process_numbers(embedded("oscillating_plate_2d"), 200); }

// Large strain (Saint Venant-Kirchhoff) with PCW damage: each particle's neighbours of t = 0 move
// with it between processes.
TEST(SharedRun, LargeStrainSofteningBar) { expect_one_process_numbers(embedded("softening_bar_2d"), 150); }

TEST(SharedRun, DamageAroundARigidInclusion) { expect_one_process_numbers(embedded("plate_inclusion_2d"), 60); }

TEST(SharedRun, FluidInAnElasticRing) { expect_one_process_numbers(embedded("lame_cylinder_2d"), 100); }

// The claystone drainage cell's CI crop (validation/claystone_drainage.cpp): gas, water, a damaging
// clay and its sleeve, 21,504 particles.
TEST(SharedRun, ClaystoneCrop) {
  expect_one_process_numbers(embedded("claystone_drainage", {"sample.image.crop.lower=[16, 12, 30]",
                                                            "sample.image.crop.upper=[32, 36, 50]",
                                                            "sample.reservoir_height=8e-8", "sample.drive_ramp=5e-5"}),
                             12);
}

// The checkpoint of a shared run is one process's, byte for byte; it restarts on another number of
// processes (here: from this shared run to a new one, and to one process) and the runs go on as
// the uninterrupted one.
TEST(SharedRun, CheckpointsRestartOnAnyNumberOfProcesses) {
  Communicator& comm = world();
  const Case c = embedded("sessile_drop_2d");
  auto shared = make_cpu_engine(c.scene, comm);
  Communicator one;
  std::unique_ptr<Engine> alone = comm.rank() == 0 ? make_cpu_engine(c.scene, one) : nullptr;
  for (int k = 0; k < 30; ++k) {
    shared->step(1e30);
    if (alone) alone->step(1e30);
  }
  // Every process writes its slice of one file (HDF5, collective), and every process reads it whole.
  const std::string file = (fs::temp_directory_path() / ("psph_shared_" + std::to_string(comm.size()) + ".h5")).string();
  write_checkpoint_file(file, shared->checkpoint(), CheckpointOrigin{c.name, ""}, comm);
  const Checkpoint saved = read_checkpoint_file(file);
  if (alone) {
    const Checkpoint ref = alone->checkpoint();
    ASSERT_EQ(saved.particles, ref.particles);
    ASSERT_EQ(saved.fields.size(), ref.fields.size());
    for (std::size_t f = 0; f < ref.fields.size(); ++f)
      EXPECT_TRUE(saved.fields[f].bytes == ref.fields[f].bytes) << "checkpoint field " << ref.fields[f].name;
  }
  comm.barrier();
  if (comm.rank() == 0) fs::remove(file);
  auto resumed = make_cpu_engine(c.scene, comm);
  resumed->restore(saved);
  std::unique_ptr<Engine> resumed_alone = alone ? make_cpu_engine(c.scene, one) : nullptr;
  if (resumed_alone) resumed_alone->restore(saved);
  for (int k = 0; k < 30; ++k) {
    resumed->step(1e30);
    if (alone) alone->step(1e30), resumed_alone->step(1e30);
  }
  EXPECT_EQ(first_difference(*resumed, alone.get()), "");
  if (alone) EXPECT_EQ(first_difference(*resumed_alone, alone.get()), "");
}

TEST(SharedRun, TwoPhasesWithWetting) { expect_one_process_numbers(embedded("sessile_drop_2d"), 80); }

// The domain cut anew at every list build (solver.rebalance_imbalance = 1): particles migrate
// between other boxes, and no number changes.
TEST(SharedRun, CutAnewAtEveryListBuild) {
  const SharingStats s =
      expect_one_process_numbers(embedded("sessile_drop_2d", {"solver.rebalance_imbalance=1.0"}), 80);
  EXPECT_GT(s.rebalances, 0);
  EXPECT_GT(s.halo_particles, 0);
}

// More processes than particles: some hold none, and take part in every reduction, gather and
// checkpoint all the same.
TEST(SharedRun, ProcessesWithoutParticles) {
  Communicator& comm = world();
  ShearBox b;
  b.dimension = 2, b.per_axis = 8, b.length = 1;
  b.density = 1, b.viscosity = 1e-2, b.sound_speed = 10, b.amplitude = 0.1;
  Scene sc = shear_box_scene(b);
  const int keep = comm.size() - 1;  // particles 0 .. keep - 1 (neighbours along x)
  sc.x.resize(std::size_t(keep) * 2), sc.v.resize(std::size_t(keep) * 2);
  sc.mass.resize(keep), sc.material.resize(keep);
  if (!sc.body.empty()) sc.body.resize(keep);
  if (!sc.load_mask.empty()) sc.load_mask.resize(keep);
  auto shared = make_cpu_engine(sc, comm);
  Communicator one;
  std::unique_ptr<Engine> alone = comm.rank() == 0 ? make_cpu_engine(sc, one) : nullptr;
  EXPECT_EQ(shared->particles(), keep);
  for (int k = 0; k < 20; ++k) {
    shared->step(1e30);
    if (alone) alone->step(1e30);
  }
  EXPECT_EQ(first_difference(*shared, alone.get()), "");
  const Checkpoint saved = shared->checkpoint();
  EXPECT_EQ(saved.particles, keep);
  EXPECT_EQ(comm.sum(static_cast<long long>(saved.fields[0].bytes.size() / saved.fields[0].element_bytes)), keep);
}

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  Communicator& comm = world();
  if (comm.rank() != 0) {  // one report: the first process's
    auto& listeners = ::testing::UnitTest::GetInstance()->listeners();
    delete listeners.Release(listeners.default_result_printer());
  }
  const int rc = RUN_ALL_TESTS();
  finalise_world();
  return rc;
}
