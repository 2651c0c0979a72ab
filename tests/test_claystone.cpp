// The synthetic claystone (solver/image/claystone_sample.hpp): the samples shipped in
// cases/claystone/ are what the generator makes from seed 1; the one-pore sample's porosity, its
// percolating fracture (wide entry at the top, narrow outlet at the bottom) and disconnected small
// pores; the two-pore variant's two pores, each open to one face only; and another seed, another
// sample.
#include <fstream>
#include <iterator>

#include <gtest/gtest.h>

#include "image/claystone_sample.hpp"
#include "image/phase_volume.hpp"
#include "image/pore_components.hpp"
#include "image/volume_source.hpp"

using namespace psph;

namespace {

const std::string kCases = PORESPH_CASES_DIR;

PhaseVolume phases_of(const ClaystoneSample& s) {
  PhaseVolume v;
  v.size = s.size, v.file_size = s.size;
  for (std::uint8_t l : s.label) v.phase.push_back(l == 0 ? 0 : 1);
  return v;
}

std::string bytes_of(const std::string& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

ClaystoneSample sample(bool two_pores, std::uint64_t seed = 1) {
  ClaystoneSpec spec;
  spec.two_pores = two_pores, spec.seed = seed;
  return make_claystone(spec);
}

double fraction(const ClaystoneSample& s, std::uint8_t label) {
  return double(std::count(s.label.begin(), s.label.end(), label)) / double(s.label.size());
}

// Voxels of component c in the layer z.
long in_layer(const PoreComponents& pc, const std::array<long, 3>& n, int c, long z) {
  long k = 0;
  for (long i = z * n[0] * n[1]; i < (z + 1) * n[0] * n[1]; ++i) k += pc.label[std::size_t(i)] == c;
  return k;
}

}  // namespace

TEST(Claystone, ShippedSamplesAreTheGeneratorsOutput) {
  for (const bool two : {false, true}) {
    const std::string shipped = kCases + "/claystone/claystone_" + (two ? "two_pores" : "one_pore") + ".npy";
    const std::string fresh = testing::TempDir() + "claystone_fresh.npy";
    write_npy(fresh, sample(two));
    EXPECT_EQ(bytes_of(fresh), bytes_of(shipped)) << shipped << " is not what seed 1 makes: run cases/claystone/generate.sh";
    // and our own reader reads it back as the same labels
    auto src = open_volume(shipped, "npy", nullptr, 0);
    PhaseSpec spec;
    spec.labels = {{0, 0, 0}, {1, 1, 1}, {2, 2, 2}}, spec.phases = 3, spec.pore_phases = 1;
    const PhaseVolume v = read_phases(*src, spec);
    EXPECT_EQ(v.phase, sample(two).label);
  }
}

TEST(Claystone, OnePercolatingFractureAmongDisconnectedPores) {
  const ClaystoneSample s = sample(false);
  EXPECT_NEAR(fraction(s, 0), 0.128, 0.002);
  EXPECT_GT(fraction(s, 2), 0.05);  // mineral grains
  for (int connectivity : {6, 26}) {
    const PoreComponents pc = pore_components(phases_of(s), 1, connectivity, "claystone");
    ASSERT_GT(pc.components.size(), 100u) << "small pores around the fracture";
    EXPECT_TRUE(pc.components[0].percolates[2]);
    EXPECT_FALSE(pc.components[0].percolates[0] || pc.components[0].percolates[1]);
    for (std::size_t c = 1; c < pc.components.size(); ++c) EXPECT_FALSE(pc.components[c].percolates[2]) << c;
    EXPECT_LT(pc.components[1].voxels, pc.components[0].voxels / 20);
    // wide at the entry (top), narrow at the outlet (bottom)
    EXPECT_GT(in_layer(pc, s.size, 0, s.size[2] - 1), 5 * in_layer(pc, s.size, 0, 0));
    EXPECT_GT(in_layer(pc, s.size, 0, 0), 0);
  }
}

TEST(Claystone, TwoPoresEachOpenToOneFace) {
  const ClaystoneSample s = sample(true);
  EXPECT_NEAR(fraction(s, 0), 0.128, 0.002);
  const PoreComponents pc = pore_components(phases_of(s), 1, 26, "claystone");
  for (const auto& c : pc.components) EXPECT_FALSE(c.percolates[2]);
  ASSERT_GE(pc.components.size(), 2u);
  EXPECT_EQ(pc.components[0].voxels, pc.components[1].voxels);  // one is the other reflected
  const long top = s.size[2] - 1;
  for (int c : {0, 1}) EXPECT_NE(in_layer(pc, s.size, c, top) > 0, in_layer(pc, s.size, c, 0) > 0) << c;
  EXPECT_GT(in_layer(pc, s.size, 0, top) + in_layer(pc, s.size, 1, top), 0);
}

TEST(Claystone, AnotherSeedAnotherSample) {
  EXPECT_NE(sample(false, 1).label, sample(false, 2).label);
}
