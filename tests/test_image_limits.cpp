// The memory bound of a segmented image (image/image_memory.hpp): an image that would need more
// than the machine has (here a small PORESPH_IMAGE_MEMORY_LIMIT) is refused before it is read,
// naming the file, its voxels, the estimate and the bound; coarsening brings it under; an image
// under the machine's own bound reads; a tiny TIFF whose pages claim billions of pixels is refused
// before a page is allocated; a bound that is not a number of bytes is refused naming the variable.
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <unistd.h>

#include "image/image_error.hpp"
#include "image/image_memory.hpp"
#include "image/phase_volume.hpp"
#include "image/volume_source.hpp"
#include "image_error_text.hpp"

using namespace psph;
namespace fs = std::filesystem;

namespace {

constexpr const char* kLimit = "PORESPH_IMAGE_MEMORY_LIMIT";

// A folder of this process's own: ctest runs each test as a process, several at once, and two that
// wrote the same file raced (one read a file the other had just truncated).
std::string temp(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("poresph_test_image_limits_" + std::to_string(getpid()));
  fs::create_directories(dir);
  return (dir / name).string();
}

// Sets (or unsets) the bound for the test's scope, and restores what was there.
class BoundScope {
 public:
  explicit BoundScope(const char* value) {
    if (const char* old = std::getenv(kLimit)) old_ = old;
    value ? setenv(kLimit, value, 1) : unsetenv(kLimit);
  }
  ~BoundScope() { old_ ? setenv(kLimit, old_->c_str(), 1) : unsetenv(kLimit); }

 private:
  std::optional<std::string> old_;
};

// A 64^3 uint8 raw volume: pores (label 0) in a third of the voxels.
std::string cube_file() {
  const std::string file = temp("cube64.raw");
  std::vector<char> bytes(64 * 64 * 64);
  for (std::size_t k = 0; k < bytes.size(); ++k) bytes[k] = char(k % 3 == 0 ? 0 : 1);
  std::ofstream(file, std::ios::binary).write(bytes.data(), std::streamsize(bytes.size()));
  return file;
}

PhaseSpec pore_is_zero(int coarsen = 1) {
  PhaseSpec s;
  s.labels = {{0, 0, 0}, {1, 255, 1}};
  s.phases = 2, s.pore_phases = 1;
  s.coarsen = {coarsen, coarsen, coarsen};
  return s;
}

PhaseVolume read_cube(int coarsen = 1) {
  RawSpec raw;
  raw.dimensions = {64, 64, 64};
  auto src = open_volume(cube_file(), "raw", &raw);
  return read_phases(*src, pore_is_zero(coarsen));
}

void says(const std::string& message, const std::string& what) {
  EXPECT_NE(message.find(what), std::string::npos) << message;
}

}  // namespace

// 64^3 coarse voxels at 5 bytes (1.3 MB), slices of 64 x 64 at 12, the counts and the label
// tables: 2.18 MB against a bound of 2 MB; coarsened 2 x 2 x 2: 1.0 MB.
TEST(ImageLimits, AnImageOverTheBoundIsRefusedWithItsEstimateAndCoarseningBringsItUnder) {
  BoundScope bound("2000000");
  const std::string message = error_of([] { read_cube(); });
  says(message, cube_file() + ": 64 x 64 x 64 voxels need about 0.0020 GiB to read");
  says(message, "64 x 64 x 64 coarse voxels at 5 bytes each, slices of 64 x 64 voxels at 12 bytes each");
  says(message, "coarsen or crop it");
  says(message, "; expected at most 0.0019 GiB, the bound PORESPH_IMAGE_MEMORY_LIMIT sets");
  const PhaseVolume coarse = read_cube(2);
  EXPECT_EQ(coarse.size, (std::array<long, 3>{32, 32, 32}));
  EXPECT_EQ(coarse.fine_voxels[0] + coarse.fine_voxels[1], 64L * 64 * 64);
}

TEST(ImageLimits, AnImageUnderTheMachinesMemoryReads) {
  BoundScope bound(nullptr);
  std::string source;
  EXPECT_GT(image_memory_limit("cube", &source), 1e6);
  EXPECT_FALSE(source.empty());
  const PhaseVolume v = read_cube();
  EXPECT_EQ(v.size, (std::array<long, 3>{64, 64, 64}));
  EXPECT_EQ(v.fine_voxels[0], (64L * 64 * 64 + 2) / 3);
}

TEST(ImageLimits, ABoundThatIsNoByteCountIsRefusedNamingTheVariable) {
  for (const char* bad : {"lots", "-5", "0", "1e999", "12 GB"}) {
    BoundScope bound(bad);
    says(error_of([] { read_cube(); }), cube_file() + ": PORESPH_IMAGE_MEMORY_LIMIT: expected a positive number of bytes");
  }
  BoundScope bound("1e9");  // a number in any notation strtod reads
  EXPECT_EQ(read_cube().size[0], 64);
}

#ifdef PORESPH_HAVE_TIFF
// A 110-byte TIFF whose one page says 46,000 x 46,000 pixels (2.1e9, within TIFF's bounds): 49 GiB
// to read, refused against a bound of 1 GiB before a page is allocated or decoded.
TEST(ImageLimits, ATinyTiffClaimingHugePagesIsRefusedBeforeReading) {
  const std::string file = temp("huge_page.tif");
  std::string b = std::string("II*\0", 4) + std::string("\x08\0\0\0", 4);
  auto u16 = [&](unsigned v) { b += char(v & 0xff), b += char(v >> 8 & 0xff); };
  auto u32 = [&](unsigned long v) { u16(unsigned(v & 0xffff)), u16(unsigned(v >> 16)); };
  auto entry = [&](unsigned tag, unsigned type, unsigned long value) { u16(tag), u16(type), u32(1), u32(value); };
  u16(8);
  entry(256, 4, 46000);  // width
  entry(257, 4, 46000);  // length
  entry(258, 3, 8);      // bits per sample
  entry(259, 3, 1);      // no compression
  entry(262, 3, 1);      // BlackIsZero
  entry(273, 4, 200);    // the strip: past the end of the file
  entry(278, 4, 46000);  // rows per strip
  entry(279, 4, 46000UL * 46000UL % 4294967296UL);
  u32(0);
  std::ofstream(file, std::ios::binary) << b;
  BoundScope bound("1073741824");
  const std::string message = error_of([&] {
    auto src = open_volume(file, "tiff", nullptr);
    read_phases(*src, pore_is_zero());
  });
  says(message, file + ": 46000 x 46000 x 1 voxels need about ");
  says(message, "; expected at most 1.0 GiB, the bound PORESPH_IMAGE_MEMORY_LIMIT sets");
}
#endif
