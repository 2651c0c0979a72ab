// [sample] (scene/sample_table.hpp) on a crop of the shipped synthetic claystone: the cell it
// expands to (domain, reservoirs, lateral layer, plates, drive, confinement, monitors), each
// particle's material against the image voxel by voxel, the resolved case read back, the
// refusals, and `--set` overrides (load_case_text's sets).
#include <cmath>

#include <gtest/gtest.h>

#include "image/volume_source.hpp"
#include "scene/case_file.hpp"
#include "scene/scene_builder.hpp"

using namespace psph;

namespace {

constexpr double kVoxel = 2.0e-8;
constexpr long kMargin = 4;  // empty voxels beyond the lateral faces: two support radii
// Voxels [16, 12, 30] to [32, 36, 50] of claystone_one_pore.npy (the fracture's upper part), lateral
// layer 2 voxels, reservoirs 4, plates 1.
const std::string kCase = R"([case]
name = "claystone_cell"
dimension = 3
[discretisation]
spacing = 2.0e-8
support_radius = 4.0e-8
[materials.water]
kind = "fluid"
density = 1000.0
viscosity = 1.0e-7
sound_speed = 0.5
[materials.gas]
kind = "fluid"
phase = "gas"
density = 1000.0
viscosity = 1.0e-9
sound_speed = 0.5
[materials.clay]
kind = "elastic"
density = 1000.0
young_modulus = 60.0
poisson_ratio = 0.1
[materials.plate]
kind = "wall"
[time]
end = 1.0e-6
[sample]
image = { file = "claystone/claystone_one_pore.npy", voxel_size = 2.0e-8, crop = { lower = [16, 12, 30], upper = [32, 36, 50] }, labels = { "0" = "water", "1" = "clay", "2" = "clay" } }
lateral_material = "clay"
lateral_thickness = 4.0e-8
plate_material = "plate"
reservoir_material = "gas"
reservoir_height = 8.0e-8
pressure_drop = 0.3
confinement = 0.12
)";

Case built(const std::string& text, const std::vector<std::string>& sets = {}) {
  Case c = load_case_text(text, "sample_test.toml", sets);
  build_particles(c);
  return c;
}

std::string replaced(std::string s, const std::string& from, const std::string& to) {
  const std::size_t at = s.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return s.replace(at, from.size(), to);
}

std::string error_of(const std::string& text, const std::vector<std::string>& sets = {}) {
  try {
    load_case_text(text, "sample_test.toml", sets);
  } catch (const CaseError& e) {
    return e.what();
  }
  return "";
}

// The crop's labels, x fastest.
std::vector<std::int64_t> crop_labels() {
  std::vector<std::string> tried;
  auto v = open_npy_volume(std::string(PORESPH_CASES_DIR) + "/claystone/claystone_one_pore.npy");
  std::vector<std::int64_t> out, slice;
  for (long z = 30; z < 50; ++z) {
    v->read_slice(z, slice);
    for (long y = 12; y < 36; ++y)
      for (long x = 16; x < 32; ++x) out.push_back(slice[std::size_t(y * 50 + x)]);
  }
  return out;
}

}  // namespace

TEST(SampleTable, ExpandsToTheReferencesCell) {
  const Case c = built(kCase);
  const Scene& sc = c.scene;
  // 16 x 24 x 20 voxels, lateral 2, reservoirs 4, the margins.
  EXPECT_NEAR(sc.upper[0], (20 + 2 * kMargin) * kVoxel, 1e-15);
  EXPECT_NEAR(sc.upper[1], (28 + 2 * kMargin) * kVoxel, 1e-15);
  EXPECT_NEAR(sc.upper[2], 28 * kVoxel, 1e-15);
  EXPECT_FALSE(sc.periodic[0] || sc.periodic[1]);
  EXPECT_TRUE(sc.periodic[2]);
  EXPECT_EQ(c.monitor_region.flow_axis, 2);
  EXPECT_NEAR(c.monitor_region.lower[2], 4 * kVoxel, 1e-15);
  EXPECT_NEAR(c.monitor_region.upper[2], 24 * kVoxel, 1e-15);
  EXPECT_NEAR(c.monitor_region.lower[0], (kMargin + 2) * kVoxel, 1e-15);
  // rho_g |F| (2 H_r) = 0.3 Pa, on the gas, in the two reservoirs.
  ASSERT_EQ(sc.force_regions.size(), 2u);
  for (const auto& f : sc.force_regions) EXPECT_NEAR(f.acceleration[2], -0.3 / (1000 * 2 * 4 * kVoxel), 1e-6);
  EXPECT_NEAR(sc.force_regions[0].upper[2], 4 * kVoxel, 1e-15);
  EXPECT_NEAR(sc.force_regions[1].lower[2], 24 * kVoxel, 1e-15);
  EXPECT_EQ(c.scene.count(), 20 * 28 * 28);
  EXPECT_EQ(c.scene.solid_loads.size(), 4u);
}

TEST(SampleTable, EachParticleTakesItsPlaceInTheCell) {
  const Case c = built(kCase);
  const Scene& sc = c.scene;
  const auto labels = crop_labels();
  auto name = [&](long i) { return sc.materials[std::size_t(sc.material[std::size_t(i)])].name; };
  long checked = 0;
  for (long i = 0; i < sc.count(); ++i) {
    const long x = long(std::floor(sc.x[std::size_t(3 * i)] / kVoxel)) - kMargin;
    const long y = long(std::floor(sc.x[std::size_t(3 * i + 1)] / kVoxel)) - kMargin;
    ASSERT_TRUE(x >= 0 && y >= 0 && x < 20 && y < 28) << "a particle in the margin";
    const long z = long(std::floor(sc.x[std::size_t(3 * i + 2)] / kVoxel));
    const bool lateral = x < 2 || y < 2 || x >= 18 || y >= 26;
    if (z < 4 || z >= 24) {  // the reservoirs: gas inside walls
      ASSERT_EQ(name(i), lateral ? "plate" : "gas") << x << " " << y << " " << z;
      continue;
    }
    const bool plate = z == 4 || z == 23;
    if (lateral) {
      ASSERT_EQ(name(i), plate ? "plate" : "clay") << x << " " << y << " " << z;
      continue;
    }
    const std::int64_t l = labels[std::size_t(((z - 4) * 24 + (y - 2)) * 16 + (x - 2))];
    ASSERT_EQ(name(i), l == 0 ? "water" : plate ? "plate" : "clay") << x << " " << y << " " << z;
    ++checked;
  }
  EXPECT_EQ(checked, 16 * 24 * 20);
}

TEST(SampleTable, TheResolvedCaseReadsBackToTheSameCell) {
  const Case c = built(kCase);
  EXPECT_EQ(c.source_text.find("[sample]"), std::string::npos);
  const Case again = built(c.source_text);
  ASSERT_EQ(again.scene.count(), c.scene.count());
  EXPECT_EQ(again.scene.material, c.scene.material);
  EXPECT_EQ(again.scene.x, c.scene.x);
}

TEST(SampleTable, ConfinementIsATractionOnTheLateralFaces) {
  const Case c = built(kCase);
  const auto& loads = c.scene.solid_loads;
  ASSERT_EQ(loads.size(), 4u);
  for (const auto& l : loads) {
    double norm = 0;
    for (int k = 0; k < 3; ++k) norm += l.value[k] * l.value[k];
    EXPECT_NEAR(std::sqrt(norm), 0.12, 1e-12);
    EXPECT_EQ(l.value[2], 0.0);
    EXPECT_NEAR(l.lower[2], 5 * kVoxel, 1e-15);  // between the plates
    EXPECT_NEAR(l.upper[2], 23 * kVoxel, 1e-15);
  }
  EXPECT_GT(loads[0].value[0], 0);  // the lower x face pushed along +x: its outermost layer
  EXPECT_NEAR(loads[0].lower[0], kMargin * kVoxel, 1e-15);
  EXPECT_NEAR(loads[0].upper[0], (kMargin + 1) * kVoxel, 1e-15);
  EXPECT_LT(loads[1].value[0], 0);
  const Case none = built(replaced(kCase, "confinement = 0.12\n", ""));
  EXPECT_TRUE(none.scene.solid_loads.empty());
}

TEST(SampleTable, SetOverridesAValueBeforeTheCaseIsRead) {
  const Case c = built(kCase, {"sample.confinement=0.16", "case.name=renamed", "time.end=2e-6"});
  EXPECT_NEAR(std::fabs(c.scene.solid_loads[0].value[0]), 0.16, 1e-12);
  EXPECT_EQ(c.name, "renamed");  // a bare word is a string
  EXPECT_EQ(c.end_time, 2e-6);
  EXPECT_NE(c.source_text.find("0.16"), std::string::npos);
  EXPECT_NE(error_of(kCase, {"sample.confinement=-1"}).find("sample.confinement"), std::string::npos);
  EXPECT_NE(error_of(kCase, {"bad key=1"}).find("expected KEY=VALUE"), std::string::npos);
  EXPECT_NE(error_of(kCase, {"=1"}).find("expected KEY=VALUE"), std::string::npos);
  // "!KEY" (--unset) removes it: without confinement, no loads; an absent key is refused; a --set
  // without a value is not an unset; overrides apply in order.
  EXPECT_TRUE(built(kCase, {"!sample.confinement"}).scene.solid_loads.empty());
  EXPECT_NE(error_of(kCase, {"!sample.confinment"}).find("--unset sample.confinment: expected a key or table"), std::string::npos);
  EXPECT_NE(error_of(kCase, {"!damage"}).find("--unset damage"), std::string::npos);
  EXPECT_NE(error_of(kCase, {"sample.confinement"}).find("expected KEY=VALUE"), std::string::npos);
  EXPECT_EQ(built(kCase, {"!sample.confinement", "sample.confinement=0.2"}).scene.solid_loads.size(), 4u);
  EXPECT_TRUE(built(kCase, {"sample.confinement=0.2", "!sample.confinement"}).scene.solid_loads.empty());
  EXPECT_NE(error_of(kCase, {"case.name=\xc3\xa9"}).find("expected an ASCII TOML value"), std::string::npos);
  EXPECT_NE(error_of(kCase, {"sample.image.file.x=1"}).find("expected a key inside tables"), std::string::npos);
  EXPECT_NE(error_of(kCase, {"sample.confinement=\"a lot\""}).find("expected a number"), std::string::npos);
}

TEST(SampleTable, RefusesWhatItCannotBuild) {
  EXPECT_NE(error_of(kCase + "[domain]\nlower = [0.0, 0.0, 0.0]\nupper = [1.0, 1.0, 1.0]\n").find("domain"), std::string::npos);
  EXPECT_NE(error_of(replaced(kCase, "lateral_thickness = 4.0e-8", "lateral_thickness = 3.0e-8")).find("sample.lateral_thickness"),
            std::string::npos);
  EXPECT_NE(error_of(replaced(kCase, "lateral_thickness = 4.0e-8", "lateral_thickness = 2.0e-8")).find("at least the support radius"),
            std::string::npos);
  EXPECT_NE(error_of(replaced(kCase, "reservoir_material", "plate_thickness = 2.0e-7\nreservoir_material")).find("sample.plate_thickness"),
            std::string::npos);
  // A crop's upper 0 is the file's end (50 voxels along z: 20 from 30), as the image reader takes it.
  EXPECT_EQ(built(replaced(kCase, "upper = [32, 36, 50]", "upper = [32, 36, 0]")).scene.count(), 20 * 28 * 28);
  EXPECT_NE(error_of(replaced(kCase, "lateral_material = \"clay\"", "lateral_material = \"plate\"")).find("sample.confinement"),
            std::string::npos);
  EXPECT_NE(error_of(replaced(kCase, "reservoir_material = \"gas\"", "reservoir_material = \"clay\"")).find("sample.reservoir_material"),
            std::string::npos);
  EXPECT_NE(error_of(replaced(kCase, "pressure_drop = 0.3\n", "")).find("sample.pressure_drop"), std::string::npos);
  EXPECT_NE(error_of(replaced(kCase, "confinement = 0.12", "confinement = 0.12\nconfinment_ramp = 1.0")).find("sample.confinment_ramp"),
            std::string::npos);
  // The image's keys are read as the geometry the sample made, with their line in the file.
  const std::string label = error_of(replaced(kCase, "\"2\" = \"clay\"", "\"2\" = \"marble\""));
  EXPECT_NE(label.find("geometry[3].labels.2 (line 28)"), std::string::npos) << label;
  EXPECT_NE(error_of(replaced(kCase, "voxel_size = 2.0e-8,", "origin = [0.0, 0.0, 0.0], voxel_size = 2.0e-8,")).find("sample.image.origin"),
            std::string::npos);
}

// plate_guard_thickness: the clay's voxels next to each plate are the lateral material (undamaged),
// the pores and the clay farther in as they were.
TEST(SampleTable, AGuardOfTheLateralMaterialBesideThePlates) {
  const std::string sleeve = "[materials.sleeve]\nkind = \"elastic\"\ndensity = 1000.0\nyoung_modulus = 60.0\npoisson_ratio = 0.1\n[time]";
  const std::string text = replaced(replaced(replaced(kCase, "[time]", sleeve), "lateral_material = \"clay\"", "lateral_material = \"sleeve\""),
                                    "reservoir_material", "plate_guard_thickness = 2.0e-8\nreservoir_material");
  const Case c = built(text), plain = built(kCase);
  const Scene& sc = c.scene;
  ASSERT_EQ(sc.count(), plain.scene.count());
  auto name = [](const Scene& s, long i) { return s.materials[std::size_t(s.material[std::size_t(i)])].name; };
  long guarded = 0;
  for (long i = 0; i < sc.count(); ++i) {
    const long x = long(std::floor(sc.x[std::size_t(3 * i)] / kVoxel)) - kMargin;
    const long y = long(std::floor(sc.x[std::size_t(3 * i + 1)] / kVoxel)) - kMargin;
    const long z = long(std::floor(sc.x[std::size_t(3 * i + 2)] / kVoxel));
    if (x < 2 || y < 2 || x >= 18 || y >= 26 || z < 4 || z >= 24) continue;  // the layers and the reservoirs
    const std::string was = name(plain.scene, i), now = name(sc, i);
    const bool guard = z == 5 || z == 22;
    ASSERT_EQ(now, guard && was == "clay" ? "sleeve" : was) << x << " " << y << " " << z;
    guarded += now == "sleeve";
  }
  EXPECT_GT(guarded, 2 * 16 * 24 / 3);  // most of the two rows is clay
  EXPECT_NE(error_of(replaced(text, "plate_guard_thickness = 2.0e-8", "plate_guard_thickness = 1.8e-7")).find("sample.plate_guard_thickness"),
            std::string::npos);
  const std::string wall = error_of(replaced(text, "lateral_material = \"sleeve\"", "lateral_material = \"plate\""));
  EXPECT_NE(wall.find("sample.plate_guard_thickness"), std::string::npos) << wall;
  EXPECT_NE(error_of(replaced(kCase, "labels =", "end_guard = \"clay\", labels =")).find("sample.image.end_guard"), std::string::npos);
}
