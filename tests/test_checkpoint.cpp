// Checkpoints: a restored run continues bitwise identically, and bad checkpoint files are refused
// with a message naming the file and what is wrong.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <cstring>
#include <fstream>

#include "engine/engine.hpp"
#include "io/checkpoint_file.hpp"
#include "scene/case_file.hpp"
#include "scene/embedded_cases.hpp"
#include "scene/scene_builder.hpp"
#include "validation/elastic_cube.hpp"

using namespace psph;
namespace fs = std::filesystem;

namespace {

Case embedded(const std::string& name, double spacing_scale = 1) {
  for (const auto& ec : embedded_cases())
    if (name == ec.name) {
      Case c = load_case_text(ec.text, name);
      if (spacing_scale != 1) {
        toml::table t = toml::parse(ec.text);
        set_case_value(t, "discretisation.spacing", toml::value<double>(c.scene.options.spacing * spacing_scale));
        c = parse_case(t, name);
      }
      build_particles(c);
      return c;
    }
  throw std::runtime_error("no case " + name);
}

std::vector<double> state(Engine& e) {
  std::vector<double> out;
  for (const char* f : {"position", "velocity", "density", "pressure", "acceleration"}) {
    const auto v = e.field(f);
    out.insert(out.end(), v.begin(), v.end());
  }
  return out;
}

std::string temp_file(const std::string& name) { return (fs::temp_directory_path() / name).string(); }

template <class F>
std::string error_of(F&& f) {
  try {
    f();
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(Checkpoint, RestoredRunContinuesBitwise) {
  // 2D Poiseuille (walls, summation density), the 3D dam break (continuity, free surface) and a
  // rigid cylinder in a fluid (the body's motion is in the checkpoint).
  for (const char* name : {"poiseuille_2d", "dam_break_3d", "settling_cylinder_2d"}) {
    Case c = embedded(name);
    auto a = make_cpu_engine(c.scene);
    for (int s = 0; s < 20; ++s) a->step(1e9);
    const std::string file = temp_file(std::string("psph_ck_") + name + ".ckpt");
    write_checkpoint_file(file, a->checkpoint(), c.name);
    for (int s = 0; s < 25; ++s) a->step(1e9);

    auto b = make_cpu_engine(c.scene);
    b->restore(read_checkpoint_file(file));
    EXPECT_EQ(b->steps(), 20) << name;
    for (int s = 0; s < 25; ++s) b->step(1e9);
    EXPECT_EQ(a->time(), b->time()) << name;
    EXPECT_EQ(state(*a), state(*b)) << name;  // bitwise
    fs::remove(file);
  }
}

// Checkpoints written before the HDF5 format (the raw one) still restart, bitwise.
TEST(Checkpoint, TheRawFormatStillRestarts) {
  Case c = embedded("settling_cylinder_2d");
  auto a = make_cpu_engine(c.scene);
  for (int s = 0; s < 20; ++s) a->step(1e9);
  const std::string file = temp_file("psph_ck_raw.ckpt");
  write_raw_checkpoint_file(file, a->checkpoint(), c.name);
  std::string head(20, ' ');
  std::ifstream(file).read(head.data(), 20);
  EXPECT_EQ(head, "PORESPH-CHECKPOINT 1");
  for (int s = 0; s < 25; ++s) a->step(1e9);
  auto b = make_cpu_engine(c.scene);
  b->restore(read_checkpoint_file(file));
  for (int s = 0; s < 25; ++s) b->step(1e9);
  EXPECT_EQ(state(*a), state(*b));
  fs::remove(file);
}

#ifdef PORESPH_HAVE_HDF5_TESTS
// The HDF5 file keeps each field's type, components and unit, the clock, the stages' extras and
// the resolved case; its partial file is gone.
TEST(Checkpoint, Hdf5KeepsFieldsWithTheirUnits) {
  Case c = embedded("settling_cylinder_2d");
  auto a = make_cpu_engine(c.scene);
  for (int s = 0; s < 10; ++s) a->step(1e9);
  const Checkpoint ck = a->checkpoint();
  const std::string file = temp_file("psph_ck_units.h5");
  Communicator one;
  write_checkpoint_file(file, ck, CheckpointOrigin{c.name, "[case]\nname = 'x'\n"}, one);
  EXPECT_FALSE(fs::exists(file + ".partial"));
  const Checkpoint r = read_checkpoint_file(file);
  EXPECT_EQ(r.steps, ck.steps);
  EXPECT_EQ(r.time, ck.time);
  EXPECT_EQ(r.rigid_bodies, ck.rigid_bodies);
  EXPECT_FALSE(r.rigid_bodies.empty());
  ASSERT_EQ(r.fields.size(), ck.fields.size());
  for (std::size_t f = 0; f < ck.fields.size(); ++f) {
    EXPECT_EQ(r.fields[f].name, ck.fields[f].name);
    EXPECT_EQ(r.fields[f].unit, ck.fields[f].unit) << ck.fields[f].name;
    EXPECT_EQ(r.fields[f].components, ck.fields[f].components) << ck.fields[f].name;
    EXPECT_TRUE(r.fields[f].type == ck.fields[f].type) << ck.fields[f].name;
    EXPECT_TRUE(r.fields[f].bytes == ck.fields[f].bytes) << ck.fields[f].name;
  }
  EXPECT_EQ(r.field("velocity")->unit, "m/s");
  fs::remove(file);
}
#endif

namespace {
// A registry that stores each real field of `ck` in `bytes` per component (the other fields as they are).
FieldRegistry sizes_of(const Checkpoint& ck, std::size_t bytes) {
  FieldRegistry r;
  for (const CheckpointField& f : ck.fields) {
    FieldHandle h;
    h.info = FieldInfo{f.name, f.type, f.components, f.unit, f.description};
    h.element_bytes = f.type == FieldType::Real && f.components > 0 ? bytes * std::size_t(f.components) : f.element_bytes;
    r.add(std::move(h));
  }
  return r;
}
}  // namespace

// A checkpoint of another precision is converted field by field: double to float rounds to
// nearest, float to double is exact; integer fields and fields of unknown components as they are;
// and a run restores from the converted one.
TEST(Checkpoint, ConvertsBetweenPrecisions) {
  Case c = embedded("settling_cylinder_2d");
  auto a = make_cpu_engine(c.scene);
  for (int s = 0; s < 10; ++s) a->step(1e9);
  Checkpoint ck = a->checkpoint();
  ck.fields.push_back(CheckpointField{"opaque", 3, std::vector<unsigned char>(3 * std::size_t(ck.particles), 7)});
  const Checkpoint narrow = with_precision_of(ck, sizes_of(ck, sizeof(float)), "single");
  EXPECT_EQ(narrow.precision, "single");
  ASSERT_EQ(narrow.fields.size(), ck.fields.size());
  for (std::size_t f = 0; f < ck.fields.size(); ++f) {
    const CheckpointField &from = ck.fields[f], &to = narrow.fields[f];
    if (from.type != FieldType::Real || from.components == 0) {
      EXPECT_TRUE(to.bytes == from.bytes) << from.name;
      continue;
    }
    ASSERT_EQ(to.element_bytes, sizeof(float) * std::size_t(from.components)) << from.name;
    ASSERT_EQ(to.bytes.size() * 2, from.bytes.size()) << from.name;
    for (std::size_t k = 0; k < to.bytes.size() / sizeof(float); ++k) {
      double d;
      float g;
      std::memcpy(&d, from.bytes.data() + 8 * k, 8), std::memcpy(&g, to.bytes.data() + 4 * k, 4);
      ASSERT_EQ(g, float(d)) << from.name << " value " << k;
    }
  }
  ck.fields.pop_back();
  const Checkpoint back = with_precision_of(with_precision_of(ck, sizes_of(ck, 4), "single"), sizes_of(ck, 8), precision_name());
  auto b = make_cpu_engine(c.scene);
  if (sizeof(Real) == 8) {  // a double build restores the widened checkpoint: every value the float one's
    b->restore(with_precision_of(ck, sizes_of(ck, 4), "single"));
    const std::vector<double> x = b->field("velocity"), x_back = [&] {
      auto e = make_cpu_engine(c.scene);
      e->restore(back);
      return e->field("velocity");
    }();
    EXPECT_EQ(x, x_back);
    EXPECT_NE(x, a->field("velocity"));  // rounded to float and back
    b->step(1e9);
    EXPECT_EQ(b->steps(), 11);
  }
  // The raw format keeps each field's type, components and unit.
  const std::string raw = temp_file("psph_ck_other_precision.ckpt");
  const Checkpoint written = a->checkpoint();
  write_raw_checkpoint_file(raw, written, c.name);
  Checkpoint other = read_checkpoint_file(raw);
  ASSERT_EQ(other.fields.size(), written.fields.size());
  for (std::size_t f = 0; f < other.fields.size(); ++f) {
    EXPECT_EQ(other.fields[f].type, written.fields[f].type) << written.fields[f].name;
    EXPECT_EQ(other.fields[f].components, written.fields[f].components) << written.fields[f].name;
    EXPECT_EQ(other.fields[f].unit, written.fields[f].unit) << written.fields[f].name;
  }
  // An earlier raw file said none of them: in another precision it is refused, named.
  for (CheckpointField& f : other.fields) f.components = 0, f.type = FieldType::Byte, f.unit.clear();
  write_raw_checkpoint_file(raw, other, c.name);
  other = read_checkpoint_file(raw);
  other.precision = sizeof(Real) == 8 ? "single" : "double";
  const std::string why = error_of([&] { make_cpu_engine(c.scene)->restore(other); });
  EXPECT_NE(why.find("written in " + other.precision + " precision in the raw format"), std::string::npos) << why;
  fs::remove(raw);
}

TEST(Checkpoint, RefusesAnotherScene) {
  Case c = embedded("poiseuille_2d");
  auto a = make_cpu_engine(c.scene);
  const Checkpoint ck = a->checkpoint();
  Case other = embedded("poiseuille_2d", 0.5);
  auto b = make_cpu_engine(other.scene);
  EXPECT_NE(error_of([&] { b->restore(ck); }).find("particle count"), std::string::npos);
  Case three = embedded("poiseuille_couette");
  auto d = make_cpu_engine(three.scene);
  EXPECT_NE(error_of([&] { d->restore(ck); }).find("dimension"), std::string::npos);
}

TEST(Checkpoint, DamagedFilesAreRefused) {
  Case c = embedded("poiseuille_2d");
  auto a = make_cpu_engine(c.scene);
  const std::string file = temp_file("psph_ck_damaged.ckpt");
  write_checkpoint_file(file, a->checkpoint(), c.name);
  EXPECT_FALSE(fs::exists(file + ".partial"));
  const auto size = fs::file_size(file);

  fs::resize_file(file, size - 8);
  std::string msg = error_of([&] { read_checkpoint_file(file); });
  EXPECT_NE(msg.find(file), std::string::npos) << msg;
  EXPECT_NE(msg.find("truncated"), std::string::npos) << msg;

  std::ofstream(file) << "not a checkpoint\n";
  msg = error_of([&] { read_checkpoint_file(file); });
  EXPECT_NE(msg.find("not a poresph checkpoint"), std::string::npos) << msg;

  std::ofstream(file) << "PORESPH-CHECKPOINT 1\n{\"dimension\": 2}\n";
  msg = error_of([&] { read_checkpoint_file(file); });
  EXPECT_NE(msg.find("damaged checkpoint header"), std::string::npos) << msg;

  msg = error_of([&] { read_checkpoint_file(temp_file("psph_no_such.ckpt")); });
  EXPECT_NE(msg.find("cannot open"), std::string::npos) << msg;
  fs::remove(file);
}

// Large strain with a fluid and continuity density: the fluid reads the solid's volume det F
// before the next strain pass, so F follows the reorderings and the checkpoint.
TEST(Checkpoint, LargeStrainSolidInAFluidContinuesBitwise) {
  Case c = elastic_cube_case(0, SolidCoupling::Traction, 0, SolidModel::SaintVenantKirchhoff);
  c.scene.options.density = DensityMethod::Continuity;
  auto a = make_cpu_engine(c.scene);
  for (int s = 0; s < 20; ++s) a->step(1e9);
  const std::string file = temp_file("psph_ck_svk.ckpt");
  write_checkpoint_file(file, a->checkpoint(), c.name);
  for (int s = 0; s < 25; ++s) a->step(1e9);
  auto b = make_cpu_engine(c.scene);
  b->restore(read_checkpoint_file(file));
  for (int s = 0; s < 25; ++s) b->step(1e9);
  EXPECT_EQ(state(*a), state(*b));
  EXPECT_EQ(a->field("deformation_gradient"), b->field("deformation_gradient"));
  fs::remove(file);
}
