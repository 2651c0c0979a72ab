// Rigid inclusions from an image (scene/read_image.cpp): the shipped claystone sample's mineral
// grains (label 2) as a rigid material, each face-connected grain one rigid body; grains below
// inclusion_min_voxels take small_inclusions' material; walls deep in the rock dropped
// (wall_depth); a few steps run with the bodies in water; image files along the search path.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <set>

#include "case_text.hpp"
#include "engine/engine.hpp"
#include "image/phase_volume.hpp"
#include "image/pore_components.hpp"
#include "image/volume_source.hpp"
#include "scene/case_file.hpp"
#include "scene/scene_builder.hpp"

using namespace psph;

namespace {

const std::string kCases = PORESPH_CASES_DIR;

// A 20^3 crop of the one-pore sample at 1 um voxels, one particle per voxel.
const std::string kCase = R"([case]
name = "claystone_crop"
dimension = 3
[domain]
lower = [0.0, 0.0, 0.0]
upper = [2.0e-5, 2.0e-5, 2.0e-5]
[discretisation]
spacing = 1.0e-6
support_radius = 2.0e-6
[materials.water]
kind = "fluid"
density = 1000.0
viscosity = 1.0e-3
sound_speed = 0.5
[materials.clay]
kind = "wall"
[materials.grain]
kind = "rigid"
density = 2650.0
[time]
end = 1.0e-6
[[geometry]]
shape = "image"
file = "claystone/claystone_one_pore.npy"
crop = { lower = [15, 15, 15], upper = [35, 35, 35] }
voxel_size = 1.0e-6
particles_per_voxel = 1
labels = { "0" = "water", "1" = "clay", "2" = "grain" }
)";

Case built(const std::string& text) {
  Case c = load_case_text(text, kCases + "/crop.toml");
  build_particles(c);
  return c;
}

// The crop's labels, x fastest, and its grains' face-connected components.
PhaseVolume crop_labels() {
  auto v = open_volume(kCases + "/claystone/claystone_one_pore.npy", "npy", nullptr, 0);
  PhaseSpec s;
  s.labels = {{0, 0, 0}, {1, 1, 1}, {2, 2, 2}};
  s.phases = 3, s.crop_lower = {15, 15, 15}, s.crop_upper = {35, 35, 35};
  return read_phases(*v, s);
}

long voxel_index(const Case& c, int i) {
  long q[3];
  for (int k = 0; k < 3; ++k) q[k] = long(c.scene.x[std::size_t(3 * i + k)] / 1e-6);
  return (q[2] * 20 + q[1]) * 20 + q[0];
}

}  // namespace

// Two particles per voxel along each axis: the crop cuts grains down to a voxel or two.
std::string fine(const std::string& text) {
  return test::replaced(test::replaced(test::replaced(text, "particles_per_voxel = 1", "particles_per_voxel = 2"),
                                       "spacing = 1.0e-6", "spacing = 5.0e-7"),
                        "support_radius = 2.0e-6", "support_radius = 1.0e-6");
}

TEST(ImageInclusions, EachGrainIsOneRigidBody) {
  const Case c = built(fine(kCase));
  const PhaseVolume v = crop_labels();
  const PoreComponents grains = pore_components(v, 1u << 2, 6, "crop");
  ASSERT_GT(grains.components.size(), 3u);
  std::set<int> bodies;
  std::vector<int> body_of_grain(grains.components.size(), -1);
  for (int i = 0; i < c.scene.count(); ++i) {
    const long q = voxel_index(c, i);
    const int b = c.scene.body[std::size_t(i)];
    ASSERT_EQ(b >= 0, v.phase[std::size_t(q)] == 2) << "particle " << i;
    if (b < 0) continue;
    bodies.insert(b);
    int& mine = body_of_grain[std::size_t(grains.label[std::size_t(q)])];
    if (mine < 0) mine = b;
    EXPECT_EQ(mine, b) << "a grain split between bodies";
  }
  EXPECT_EQ(bodies.size(), grains.components.size()) << "one body per grain";
}

TEST(ImageInclusions, SmallGrainsTakeAnotherMaterial) {
  const Case c = built(test::replaced(kCase, "\"2\" = \"grain\" }", "\"2\" = \"grain\" }\ninclusion_min_voxels = 20\nsmall_inclusions = \"clay\""));
  const PoreComponents grains = pore_components(crop_labels(), 1u << 2, 6, "crop");
  std::size_t big = 0;
  long big_voxels = 0;
  for (const auto& g : grains.components)
    if (g.voxels >= 20) ++big, big_voxels += g.voxels;
  ASSERT_GT(big, 0u);
  ASSERT_LT(big, grains.components.size());
  std::set<int> bodies;
  long rigid = 0;
  for (int b : c.scene.body)
    if (b >= 0) bodies.insert(b), ++rigid;
  EXPECT_EQ(bodies.size(), big);
  EXPECT_EQ(rigid, big_voxels);
}

TEST(ImageInclusions, RefusalsNameTheKey) {
  auto message = [&](const std::string& from, const std::string& to) {
    try {
      built(test::replaced(kCase, from, to));
    } catch (const CaseError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  const std::string labels = "\"2\" = \"grain\" }";
  // A grain of two voxels at one particle per voxel has no inertia: the message says which one.
  EXPECT_NE(message(labels, labels).find("geometry[0] (inclusion "), std::string::npos);
  EXPECT_NE(message(labels, labels + "\ninclusion_min_voxels = 5").find("geometry[0].small_inclusions"), std::string::npos);
  EXPECT_NE(message(labels, labels + "\ninclusion_min_voxels = 5\nsmall_inclusions = \"grain\"").find("not rigid"),
            std::string::npos);
  EXPECT_NE(message(labels, "\"2\" = \"clay\" }\ninclusion_min_voxels = 5").find("rigid material for it to apply"),
            std::string::npos);
}

TEST(ImageInclusions, DeepWallsAreDroppedAndTheBodiesRun) {
  const std::string small = "\"2\" = \"grain\" }\ninclusion_min_voxels = 4\nsmall_inclusions = \"clay\"";
  const Case all = built(test::replaced(kCase, "\"2\" = \"grain\" }", small));
  const Case trimmed = built(test::replaced(kCase, "\"2\" = \"grain\" }", small + "\nwall_depth = 2.0e-6"));
  const PhaseVolume v = crop_labels();
  long clay = 0, near = 0;
  for (long z = 0; z < 20; ++z)
    for (long y = 0; y < 20; ++y)
      for (long x = 0; x < 20; ++x) {
        if (v.at(x, y, z) != 1) continue;
        ++clay;
        bool is_near = x < 2 || y < 2 || z < 2 || x >= 18 || y >= 18 || z >= 18;
        for (long dz = -2; dz <= 2 && !is_near; ++dz)
          for (long dy = -2; dy <= 2 && !is_near; ++dy)
            for (long dx = -2; dx <= 2 && !is_near; ++dx) is_near = v.at(x + dx, y + dy, z + dz) != 1;
        near += is_near;
      }
  ASSERT_LT(near, clay);
  EXPECT_EQ(all.scene.count() - trimmed.scene.count(), clay - near);
  auto engine = make_engine(trimmed.scene, "cpu");
  for (int k = 0; k < 5; ++k) engine->step(1.0);
  EXPECT_EQ(engine->rigid_bodies().size(), std::size_t(*std::max_element(trimmed.scene.body.begin(), trimmed.scene.body.end()) + 1));
  for (double x : engine->field("position")) ASSERT_TRUE(std::isfinite(x));
}

// An image is found next to the case file, else in PORESPH_IMAGE_PATH's folders; the resolved case
// names it by its absolute path; none found: the message lists where it looked.
TEST(ImageFiles, FoundAlongTheSearchPathAndResolvedAbsolute) {
  const Case here = load_case_text(kCase, kCases + "/crop.toml");
  EXPECT_NE(here.source_text.find(kCases + "/claystone/claystone_one_pore.npy"), std::string::npos)
      << here.source_text;
  const std::string bare = test::replaced(kCase, "claystone/claystone_one_pore.npy", "claystone_one_pore.npy");
  const std::string elsewhere = testing::TempDir() + "case.toml";
  std::string msg;
  try {
    load_case_text(bare, elsewhere);
  } catch (const CaseError& e) {
    msg = e.what();
  }
  EXPECT_NE(msg.find("geometry[0].file"), std::string::npos) << msg;
  EXPECT_NE(msg.find(testing::TempDir() + "claystone_one_pore.npy"), std::string::npos) << msg;
  setenv("PORESPH_IMAGE_PATH", ("/nonexistent:" + kCases + "/claystone").c_str(), 1);
  const Case found = load_case_text(bare, elsewhere);
  unsetenv("PORESPH_IMAGE_PATH");
  EXPECT_NE(found.source_text.find(kCases + "/claystone/claystone_one_pore.npy"), std::string::npos);
}
