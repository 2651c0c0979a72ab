// [[geometry]] shape = "image" (scene/read_image.cpp): the Berea image of ../shared/data/rocks as
// a case's geometry, in 3D (a crop, coarsened, its largest pore kept) and in 2D (one slice): each
// particle takes the material of its voxel's label; the report reaches Case::images; and every
// refusal names the key.
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "case_text.hpp"
#include "image/phase_volume.hpp"
#include "image/pore_components.hpp"
#include "image/volume_source.hpp"
#include "scene/case_file.hpp"
#include "scene/scene_builder.hpp"

using namespace psph;

namespace {

const std::string kRocks = PORESPH_ROCKS_DIR;  // empty where the build found none

// The tests of the real rocks are skipped (and reported so) where there are none.
#define REQUIRE_ROCKS() \
  if (kRocks.empty()) GTEST_SKIP() << "no segmented rock images (../shared/data/rocks) on this machine"

// A 20^3 crop of the Berea image (porosity 0.21 there) at 2.5 um voxels, one particle per voxel; its file is given
// relative to the case file, which is read as if it were in the rocks' folder.
const std::string kCase = R"([case]
name = "berea_crop"
dimension = 3
[domain]
lower = [0.0, 0.0, 0.0]
upper = [5.0e-5, 5.0e-5, 5.0e-5]
[discretisation]
spacing = 2.5e-6
support_radius = 5.0e-6
[materials.water]
kind = "fluid"
density = 1000.0
viscosity = 1.0e-3
sound_speed = 1.0
[materials.rock]
kind = "wall"
[time]
end = 1.0e-6
[[geometry]]
shape = "image"
file = "berea_110.raw"
dimensions = [110, 110, 110]
crop = { lower = [40, 40, 30], upper = [60, 60, 50] }
voxel_size = 2.5e-6
particles_per_voxel = 1
labels = { "0" = "water", "1" = "rock" }
)";

Case built(const std::string& text) {
  Case c = load_case_text(text, kRocks + "/case.toml");
  build_particles(c);
  return c;
}

// The Berea labels, x fastest.
std::vector<std::int64_t> berea() {
  RawSpec raw;
  raw.dimensions = {110, 110, 110};
  auto v = open_raw_volume(kRocks + "/berea_110.raw", raw);
  std::vector<std::int64_t> all, slice;
  for (long z = 0; z < 110; ++z) v->read_slice(z, slice), all.insert(all.end(), slice.begin(), slice.end());
  return all;
}

}  // namespace

TEST(ImageCase, EachParticleTakesTheMaterialOfItsVoxel) {
  REQUIRE_ROCKS();
  const Case c = built(kCase);
  const auto labels = berea();
  ASSERT_EQ(c.scene.count(), 8000);
  long pore = 0;
  for (int i = 0; i < c.scene.count(); ++i) {
    long q[3];
    for (int k = 0; k < 3; ++k) q[k] = long(c.scene.x[3 * i + k] / 2.5e-6);
    const std::int64_t l = labels[std::size_t(((q[2] + 30) * 110 + q[1] + 40) * 110 + q[0] + 40)];
    const bool fluid = c.scene.materials[std::size_t(c.scene.material[i])].props.kind == MaterialKind::Fluid;
    EXPECT_EQ(fluid, l == 0) << "particle " << i;
    pore += fluid;
  }
  ASSERT_EQ(c.images.size(), 1u);
  EXPECT_NEAR(c.images[0]["porosity"].get<double>(), double(pore) / 8000, 1e-12);
}

// Coarsened 2 x 2 x 2, the largest pore kept, the others made rock: the fluid particles are the
// largest component's voxels.
TEST(ImageCase, TheLargestPoreIsKeptAndTheOthersFilled) {
  REQUIRE_ROCKS();
  const std::string text = test::replaced(test::replaced(kCase, "crop = { lower = [40, 40, 30], upper = [60, 60, 50] }",
                                                         "crop = { lower = [0, 0, 0], upper = [40, 40, 40] }\ncoarsen = 2\n"
                                                         "pores = \"largest\"\nother_pores = \"rock\""),
                                          "voxel_size = 2.5e-6", "voxel_size = 1.25e-6");
  const Case c = built(text);
  long fluid = 0;
  for (int m : c.scene.material) fluid += c.scene.materials[std::size_t(m)].props.kind == MaterialKind::Fluid;
  RawSpec raw;
  raw.dimensions = {110, 110, 110};
  auto v = open_raw_volume(kRocks + "/berea_110.raw", raw);
  PhaseSpec s;
  s.labels = {{0, 0, 0}, {1, 1, 1}};
  s.phases = 2, s.pore_phases = 1, s.crop_upper = {40, 40, 40}, s.coarsen = {2, 2, 2};
  const PoreComponents pc = pore_components(read_phases(*v, s), 1, 6, "berea");
  ASSERT_GT(pc.components.size(), 1u);
  EXPECT_EQ(fluid, pc.components[0].voxels);
  EXPECT_EQ(c.images[0]["components"].get<long>(), long(pc.components.size()));
}

// A 2D case on slice 5 of the crop (porosity 0.31): the slice's voxels, x and y.
TEST(ImageCase, A2DCaseTakesOneSlice) {
  REQUIRE_ROCKS();
  std::string text = test::replaced(test::replaced(kCase, "dimension = 3", "dimension = 2"), "lower = [0.0, 0.0, 0.0]",
                                    "lower = [0.0, 0.0]");
  text = test::replaced(test::replaced(text, "upper = [5.0e-5, 5.0e-5, 5.0e-5]", "upper = [5.0e-5, 5.0e-5]"),
                        "particles_per_voxel = 1", "particles_per_voxel = 1\nslice = 5");
  const Case c = built(text);
  const auto labels = berea();
  ASSERT_EQ(c.scene.count(), 400);
  for (int i = 0; i < c.scene.count(); ++i) {
    const long x = long(c.scene.x[2 * i] / 2.5e-6), y = long(c.scene.x[2 * i + 1] / 2.5e-6);
    const std::int64_t l = labels[std::size_t((35 * 110 + y + 40) * 110 + x + 40)];
    EXPECT_EQ(c.scene.materials[std::size_t(c.scene.material[i])].props.kind == MaterialKind::Fluid, l == 0) << i;
  }
  // Coarsened 2 in x and y (a 2D case does not coarsen along z): 10 x 10 coarse voxels of 2.5 um.
  const Case coarse = built(test::replaced(text, "voxel_size = 2.5e-6", "voxel_size = 1.25e-6\ncoarsen = 2"));
  EXPECT_EQ(coarse.scene.count(), 100);
  EXPECT_EQ(coarse.images[0]["coarsen"], nlohmann::json({2, 2, 1}));
}

TEST(ImageCase, BadImagesAreRefusedNamingTheKey) {
  REQUIRE_ROCKS();
  auto refused = [&](const std::string& from, const std::string& to, const std::vector<std::string>& says) {
    std::string msg;
    try {
      built(test::replaced(kCase, from, to));
    } catch (const CaseError& e) {
      msg = e.what();
    }
    for (const auto& s : says) EXPECT_NE(msg.find(s), std::string::npos) << s << " not in: " << msg;
  };
  refused("\"1\" = \"rock\"", "\"2\" = \"rock\"", {"geometry[0].labels", "label 1 (slice 30) is in no range"});
  refused("\"1\" = \"rock\"", "\"1\" = \"stone\"", {"geometry[0].labels.1", "\"stone\""});
  refused("\"1\" = \"rock\"", "\"one\" = \"rock\"", {"geometry[0].labels.one", "a range of labels"});
  refused("file = \"berea_110.raw\"", "file = \"missing.raw\"", {"geometry[0].file", "missing.raw"});
  refused("dimensions = [110, 110, 110]", "dimensions = [110, 110, 100]", {"geometry[0].file", "expected 1210000 bytes"});
  refused("file = \"berea_110.raw\"", "file = \"berea_110.raw\"\nformat = \"npy\"", {"geometry[0].dimensions", "format = \"raw\""});
  refused("particles_per_voxel = 1", "particles_per_voxel = 2", {"geometry[0].particles_per_voxel", "2 x discretisation.spacing"});
  refused("voxel_size = 2.5e-6", "voxel_size = 2.5e-6\norigin = [1.0e-5, 0.0, 0.0]", {"geometry[0].origin", "inside the domain"});
  refused("upper = [60, 60, 50] }", "upper = [60, 60, 150] }", {"geometry[0].crop", "110 voxels along z"});
  refused("labels = { \"0\" = \"water\", \"1\" = \"rock\" }", "labels = { \"0..1\" = \"rock\" }\npores = \"largest\"",
          {"geometry[0].pores", "mapped to a fluid"});
  refused("labels = { \"0\" = \"water\", \"1\" = \"rock\" }", "labels = { \"0..1\" = \"rock\", \"1\" = \"water\" }",
          {"geometry[0].labels.1", "do not overlap"});
  refused("labels = { \"0\" = \"water\", \"1\" = \"rock\" }", "labels = { \"0\" = \"water\", \"99999999999999999999\" = \"rock\" }",
          {"geometry[0].labels.99999999999999999999", "a range of labels"});
  refused("dimensions = [110, 110, 110]", "dimensions = [110, 0, 110]", {"geometry[0].dimensions", "at least 1 voxel"});
  refused("crop = { lower = [40, 40, 30], upper = [60, 60, 50] }",  // porosity 0.0125 there
          "crop = { lower = [10, 20, 30], upper = [30, 40, 50] }\npores = \"percolating\"\npercolation_axis = \"z\"",
          {"geometry[0].pores", "percolates along z: none does"});
}

// The map's order in the file names the phases (a TOML table is sorted by key): with "2" listed
// before "10", a 2 x 2 block of two 2s and two 10s goes to label 2's material (by key it would go to 10's).
TEST(ImageCase, TheLabelMapKeepsTheFilesOrder) {
  const std::string file = (std::filesystem::temp_directory_path() / "poresph_tie.raw").string();
  std::ofstream(file, std::ios::binary) << std::string("\x0a\x0a\x02\x02", 4);
  const std::string text = R"([case]
name = "tie"
dimension = 2
[domain]
lower = [0.0, 0.0]
upper = [2.0e-3, 2.0e-3]
[discretisation]
spacing = 1.0e-3
support_radius = 2.0e-3
[materials.quartz]
kind = "elastic"
density = 2650.0
young_modulus = 1.0e9
poisson_ratio = 0.2
[materials.clay]
kind = "elastic"
density = 2000.0
young_modulus = 1.0e8
poisson_ratio = 0.2
[time]
end = 1.0e-6
[[geometry]]
shape = "image"
file = ")" + file + R"("
dimensions = [2, 2, 1]
coarsen = 2
voxel_size = 1.0e-3
labels = { "2" = "quartz", "10" = "clay" }
)";
  Case c = load_case_text(text, "tie.toml");
  build_particles(c);
  ASSERT_EQ(c.scene.count(), 4);
  for (int m : c.scene.material) EXPECT_EQ(c.scene.materials[std::size_t(m)].name, "quartz");
}
