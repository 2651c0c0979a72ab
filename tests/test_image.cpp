// Segmented images (solver/image/): the real rocks of ../shared/data/rocks read as raw and as TIFF
// against the porosities their provenance states, the same voxels through .npy files in C and
// Fortran order and other types and byte orders, TIFF variants written here with libtiff (tiles,
// 16 bits, WhiteIsZero (the labels are the stored values), a numbered series), majority coarsening with its tie rule, connected pore
// components and percolation, and every refusal naming the file.
#ifdef PORESPH_HAVE_TIFF
#include <tiffio.h>
#endif

#include <cstdio>
#include <functional>
#include <filesystem>
#include <cstring>
#include <fstream>

#include <gtest/gtest.h>

#include "image/image_error.hpp"
#include "image/phase_volume.hpp"
#include "image/pore_components.hpp"
#include "image/volume_source.hpp"
#include "image_error_text.hpp"

using namespace psph;
namespace fs = std::filesystem;

namespace {

const std::string kRocks = PORESPH_ROCKS_DIR;  // empty where the build found none

// The tests of the real rocks are skipped (and reported so) where there are none.
#define REQUIRE_ROCKS() \
  if (kRocks.empty()) GTEST_SKIP() << "no segmented rock images (../shared/data/rocks) on this machine"

std::string temp(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / "poresph_test_image";
  fs::create_directories(dir);
  return (dir / name).string();
}

// Pore = label 0 (phase 0), everything else solid (phase 1).
PhaseSpec pore_is_zero() {
  PhaseSpec s;
  s.labels = {{0, 0, 0}, {1, 1L << 40, 1}, {-(1L << 40), -1, 1}};
  s.phases = 2, s.pore_phases = 1;
  return s;
}

RawSpec berea_spec() {
  RawSpec r;
  r.dimensions = {110, 110, 110};
  return r;
}

void write_bytes(const std::string& file, const std::string& header, const std::vector<unsigned char>& bytes) {
  std::ofstream out(file, std::ios::binary);
  out << header;
  out.write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
}

// An .npy of format 1.0 with the given dict (padded to 64 bytes with its newline).
void write_npy(const std::string& file, const std::string& dict, const std::vector<unsigned char>& bytes) {
  std::string h = dict;
  while ((10 + h.size() + 1) % 64) h += ' ';
  h += '\n';
  std::string head = "\x93NUMPY\x01";
  head += '\0';
  head += char(h.size() & 0xff), head += char(h.size() >> 8);
  write_bytes(file, head + h, bytes);
}

// The whole volume's labels, x fastest.
std::vector<std::int64_t> all_labels(VolumeSource& v) {
  const auto n = v.size();
  const auto axes = v.storage_axes();
  std::array<long, 3> dims{};
  for (int s = 0; s < 3; ++s) dims[axes[s]] = n[s];
  std::vector<std::int64_t> out(std::size_t(dims[0] * dims[1] * dims[2])), slice;
  for (long s = 0; s < n[2]; ++s) {
    v.read_slice(s, slice);
    for (long j = 0; j < n[1]; ++j)
      for (long i = 0; i < n[0]; ++i) {
        std::array<long, 3> q{};
        q[axes[0]] = i, q[axes[1]] = j, q[axes[2]] = s;
        out[std::size_t((q[2] * dims[1] + q[1]) * dims[0] + q[0])] = slice[std::size_t(j * n[0] + i)];
      }
  }
  return out;
}

}  // namespace

// ../shared/data/rocks/README.md: Berea, 110^3 uint8, 236,764 pore voxels (0.1779); Ketton,
// 256 big-endian 8-bit pages of 256 x 256, 0 and 255, porosity given as 0.1277 there, but
// 2,128,392 voxels of 0 (0.12686) by VTK's TIFF reader and by a walk of the file's pages by hand.
TEST(Image, TheRealRocksHaveTheirStatedPorosities) {
  REQUIRE_ROCKS();
  const RawSpec raw = berea_spec();
  auto berea = open_volume(kRocks + "/berea_110.raw", "auto", &raw);
  const PhaseVolume b = read_phases(*berea, pore_is_zero());
  EXPECT_EQ(b.size, (std::array<long, 3>{110, 110, 110}));
  EXPECT_EQ(b.fine_voxels[0], 236764);
  EXPECT_EQ(b.label_voxels.size(), 2u);
  EXPECT_NEAR(porosity(b, 1, false), 0.1779, 5e-5);
#ifdef PORESPH_HAVE_TIFF
  auto ketton = open_volume(kRocks + "/ketton_256.tif", "auto", nullptr);
  const PhaseVolume k = read_phases(*ketton, pore_is_zero());
  EXPECT_EQ(k.size, (std::array<long, 3>{256, 256, 256}));
  EXPECT_EQ(k.label_voxels.size(), 2u);
  EXPECT_EQ(k.label_voxels.count(255), 1u);
  EXPECT_EQ(k.fine_voxels[0], 2128392);
#endif
}

// A crop of the Berea image written as .npy in C order (x slowest) and in Fortran order, and as
// big-endian uint16 and float32: the same voxels as the raw file read in its own order.
TEST(Image, NumpyFilesInEitherOrderAndTypeGiveTheSameVoxels) {
  REQUIRE_ROCKS();
  RawSpec raw = berea_spec();
  auto berea = open_volume(kRocks + "/berea_110.raw", "raw", &raw);
  const std::vector<std::int64_t> all = all_labels(*berea);
  const long n[3] = {7, 5, 3};  // a 7 x 5 x 3 crop at the origin
  auto at = [&](long x, long y, long z) { return all[std::size_t((z * 110 + y) * 110 + x)] + 3 * x; };  // varied labels
  std::vector<unsigned char> c_u8, f_u8, c_u16be, c_f32;
  for (long x = 0; x < n[0]; ++x)
    for (long y = 0; y < n[1]; ++y)
      for (long z = 0; z < n[2]; ++z) {
        const auto l = at(x, y, z);
        c_u8.push_back((unsigned char)l);
        c_u16be.push_back((unsigned char)(l >> 8)), c_u16be.push_back((unsigned char)l);
        const float f = float(l);
        unsigned char b[4];
        std::memcpy(b, &f, 4);
        c_f32.insert(c_f32.end(), b, b + 4);
      }
  for (long z = 0; z < n[2]; ++z)
    for (long y = 0; y < n[1]; ++y)
      for (long x = 0; x < n[0]; ++x) f_u8.push_back((unsigned char)at(x, y, z));
  const std::string shape = "'shape': (7, 5, 3), }";
  write_npy(temp("c.npy"), "{'descr': '|u1', 'fortran_order': False, " + shape, c_u8);
  write_npy(temp("f.npy"), "{'descr': '|u1', 'fortran_order': True, " + shape, f_u8);
  write_npy(temp("be.npy"), "{'descr': '>u2', 'fortran_order': False, " + shape, c_u16be);
  write_npy(temp("f32.npy"), "{'descr': '<f4', 'fortran_order': False, " + shape, c_f32);
  for (const char* file : {"c.npy", "f.npy", "be.npy", "f32.npy"}) {
    SCOPED_TRACE(file);
    auto v = open_volume(temp(file), "auto", nullptr);
    const std::vector<std::int64_t> got = all_labels(*v);
    ASSERT_EQ(got.size(), 105u);
    for (long z = 0; z < n[2]; ++z)
      for (long y = 0; y < n[1]; ++y)
        for (long x = 0; x < n[0]; ++x) EXPECT_EQ(got[std::size_t((z * 5 + y) * 7 + x)], at(x, y, z)) << x << y << z;
  }
  // The crop of the raw file itself.
  PhaseSpec one = pore_is_zero();
  one.crop_upper = {7, 5, 3};
  EXPECT_EQ(read_phases(*berea, one).size, (std::array<long, 3>{7, 5, 3}));
}

#ifdef PORESPH_HAVE_TIFF
namespace {

// A TIFF of `pages` pages of w x h with sample(x, y, page), `bits` per sample, optionally tiled
// (16 x 16) and WhiteIsZero, in the given byte order ("b" or "l" in libtiff's mode).
void write_tiff(const std::string& file, int w, int h, int pages, int bits, bool tiled, bool white_is_zero,
                const char* order, const std::function<std::uint32_t(int, int, int)>& sample) {
  TIFF* t = TIFFOpen(file.c_str(), (std::string("w") + order).c_str());
  ASSERT_NE(t, nullptr);
  for (int p = 0; p < pages; ++p) {
    TIFFSetField(t, TIFFTAG_IMAGEWIDTH, w);
    TIFFSetField(t, TIFFTAG_IMAGELENGTH, h);
    TIFFSetField(t, TIFFTAG_BITSPERSAMPLE, bits);
    TIFFSetField(t, TIFFTAG_SAMPLESPERPIXEL, 1);
    TIFFSetField(t, TIFFTAG_PHOTOMETRIC, white_is_zero ? PHOTOMETRIC_MINISWHITE : PHOTOMETRIC_MINISBLACK);
    TIFFSetField(t, TIFFTAG_PLANARCONFIG, PLANARCONFIG_CONTIG);
    auto stored = [&](int x, int y) { return sample(x, y, p); };  // labels are stored values either way
    auto put = [&](unsigned char* row, int k, std::uint32_t v) {
      if (bits == 8) row[k] = (unsigned char)v;
      else if (bits == 16) reinterpret_cast<std::uint16_t*>(row)[k] = (std::uint16_t)v;
      else reinterpret_cast<std::uint32_t*>(row)[k] = v;
    };
    if (tiled) {
      TIFFSetField(t, TIFFTAG_TILEWIDTH, 16);
      TIFFSetField(t, TIFFTAG_TILELENGTH, 16);
      std::vector<unsigned char> tile(TIFFTileSize(t));
      for (int y0 = 0; y0 < h; y0 += 16)
        for (int x0 = 0; x0 < w; x0 += 16) {
          std::fill(tile.begin(), tile.end(), 0);
          for (int y = y0; y < std::min(y0 + 16, h); ++y)
            for (int x = x0; x < std::min(x0 + 16, w); ++x) put(tile.data() + (y - y0) * TIFFTileRowSize(t), x - x0, stored(x, y));
          TIFFWriteTile(t, tile.data(), x0, y0, 0, 0);
        }
    } else {
      TIFFSetField(t, TIFFTAG_ROWSPERSTRIP, 3);
      std::vector<unsigned char> row(TIFFScanlineSize(t));
      for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) put(row.data(), x, stored(x, y));
        TIFFWriteScanline(t, row.data(), y, 0);
      }
    }
    TIFFWriteDirectory(t);
  }
  TIFFClose(t);
}

}  // namespace

TEST(Image, TiffStacksInStripsTilesAndSeriesAreRead) {
  auto label = [](int x, int y, int p) { return std::uint32_t((x * 7 + y * 3 + p * 11) % 5 + (x > 20 ? 300 : 0)); };
  const int w = 37, h = 21, pages = 4;
  struct Variant {
    const char* file;
    int bits;
    bool tiled, white;
    const char* order;
  } variants[] = {{"strips16be.tif", 16, false, false, "b"}, {"tiles16le.tif", 16, true, false, "l"},
                  {"white32.tif", 32, false, true, "b"}, {"tiles32be_white.tif", 32, true, true, "b"}};
  for (const Variant& v : variants) {
    SCOPED_TRACE(v.file);
    write_tiff(temp(v.file), w, h, pages, v.bits, v.tiled, v.white, v.order, label);
    auto vol = open_volume(temp(v.file), "auto", nullptr);
    EXPECT_EQ(vol->size(), (std::array<long, 3>{w, h, pages}));
    const auto got = all_labels(*vol);
    for (int p = 0; p < pages; ++p)
      for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) ASSERT_EQ(got[std::size_t((p * h + y) * w + x)], label(x, y, p)) << x << " " << y << " " << p;
  }
  // A numbered series: slice_0003.tif ... slice_0006.tif, one page each.
  for (int p = 0; p < pages; ++p) {
    char name[32];
    std::snprintf(name, sizeof name, "slice_%04d.tif", p + 3);
    write_tiff(temp(name), w, h, 1, 8, false, false, "l", [&](int x, int y, int) { return label(x, y, p) % 256; });
  }
  auto series = open_volume(temp("slice_####.tif"), "tiff", nullptr, 3);
  EXPECT_EQ(series->size(), (std::array<long, 3>{w, h, pages}));
  const auto got = all_labels(*series);
  EXPECT_EQ(got[std::size_t((2 * h + 4) * w + 30)], label(30, 4, 2) % 256);
  EXPECT_NE(error_of([&] { open_volume(temp("strips16be.tif"), "tiff", nullptr, 2); }).find("numbered series"),
            std::string::npos);
}
#endif  // PORESPH_HAVE_TIFF

// Majority per 2 x 2 x 2 block; a 4 : 4 tie goes to the pore phase, a tie between solids to the one
// listed first.
TEST(Image, CoarseningTakesTheMajorityAndTiesGoToThePore) {
  // Labels: 0 pore, 1 and 2 solids. Block 0: five 1 and three 0 -> 1; block 1: four 0 and four 2
  // -> pore; block 2: four 2 and four 1 -> 1 (listed first); and a column of odd length dropped.
  std::vector<unsigned char> v(5 * 2 * 2, 0);
  auto set = [&](int x, int y, int z, unsigned char l) { v[std::size_t((z * 2 + y) * 5 + x)] = l; };
  for (int z = 0; z < 2; ++z)
    for (int y = 0; y < 2; ++y) {
      set(0, y, z, 1), set(1, y, z, (y + z) ? 1 : 0);
      set(2, y, z, z ? 2 : 0), set(3, y, z, z ? 0 : 2);
      set(4, y, z, 2);
    }
  set(1, 1, 1, 0), set(1, 0, 1, 0);  // block 0: 1 at (0, *, *) four times, (1, 1, 0) once
  write_bytes(temp("blocks.raw"), "", v);
  RawSpec raw;
  raw.dimensions = {5, 2, 2};
  auto vol = open_volume(temp("blocks.raw"), "raw", &raw);
  PhaseSpec s;
  s.labels = {{1, 1, 0}, {2, 2, 1}, {0, 0, 2}};  // phases: 0 = label 1, 1 = label 2, 2 = pore
  s.phases = 3, s.pore_phases = 1u << 2;
  s.coarsen = {2, 2, 2};
  const PhaseVolume c = read_phases(*vol, s);
  ASSERT_EQ(c.size, (std::array<long, 3>{2, 1, 1}));
  EXPECT_EQ(c.at(0, 0, 0), 0);  // five 1, three 0
  EXPECT_EQ(c.at(1, 0, 0), 2);  // four 0, four 2: the pore
  EXPECT_EQ(c.fine_voxels[2] + c.fine_voxels[1] + c.fine_voxels[0], 16);  // the fifth column dropped
  // Solids tied: 2 and 1 four each -> the phase listed first (label 1).
  std::vector<unsigned char> t(8);
  for (int k = 0; k < 8; ++k) t[std::size_t(k)] = k < 4 ? 2 : 1;
  write_bytes(temp("tie.raw"), "", t);
  raw.dimensions = {2, 2, 2};
  auto tie = open_volume(temp("tie.raw"), "raw", &raw);
  EXPECT_EQ(read_phases(*tie, s).at(0, 0, 0), 0);
}

// Two pores: a straight tube along z (percolates along z) and an L of two voxels touching a third
// by an edge only (one component with 18- and 26-connectivity, two with 6) and a voxel touching
// it by a corner only (joined with 26).
TEST(Image, PoreComponentsFollowTheConnectivity) {
  const long n = 6;
  std::vector<unsigned char> v(n * n * n, 1);
  auto pore = [&](long x, long y, long z) { v[std::size_t((z * n + y) * n + x)] = 0; };
  for (long z = 0; z < n; ++z) pore(0, 0, z);  // the tube
  pore(3, 3, 2), pore(4, 3, 2);                // the L's face pair
  pore(5, 4, 2);                               // an edge from (4, 3, 2)
  pore(4, 5, 3);                               // a corner from (5, 4, 2)
  write_bytes(temp("pores.raw"), "", v);
  RawSpec raw;
  raw.dimensions = {n, n, n};
  auto vol = open_volume(temp("pores.raw"), "raw", &raw);
  const PhaseVolume p = read_phases(*vol, pore_is_zero());
  const std::string f = "pores.raw";
  const PoreComponents c6 = pore_components(p, 1, 6, f), c18 = pore_components(p, 1, 18, f),
                       c26 = pore_components(p, 1, 26, f);
  ASSERT_EQ(c6.components.size(), 4u);
  ASSERT_EQ(c18.components.size(), 3u);
  ASSERT_EQ(c26.components.size(), 2u);
  EXPECT_EQ(c6.components[0].voxels, n);  // the tube, largest
  EXPECT_EQ(c6.components[0].percolates, (std::array<bool, 3>{false, false, true}));
  EXPECT_EQ(c26.components[1].voxels, 4);
  EXPECT_EQ(c26.components[1].percolates, (std::array<bool, 3>{false, false, false}));
  EXPECT_EQ(c26.label[std::size_t((3 * n + 5) * n + 4)], 1);
  EXPECT_EQ(c26.label[std::size_t((1 * n + 1) * n + 1)], -1);
  EXPECT_NE(error_of([&] { pore_components(p, 1, 8, f); }).find("6, 18 or 26"), std::string::npos);
}

TEST(Image, BadImagesAreRefusedNamingTheFile) {
  REQUIRE_ROCKS();
  RawSpec raw = berea_spec();
  raw.dimensions = {110, 110, 109};
  auto says = [](const std::string& msg, const std::string& what) {
    EXPECT_NE(msg.find(what), std::string::npos) << msg;
  };
  says(error_of([&] { open_volume(kRocks + "/berea_110.raw", "raw", &raw); }), "berea_110.raw: expected 1318900 bytes");
  raw = berea_spec();
  raw.order = "xxz";
  says(error_of([&] { open_volume(kRocks + "/berea_110.raw", "raw", &raw); }), "axis order");
  says(error_of([&] { open_volume(kRocks + "/berea_110.raw", "auto", nullptr); }), "needs its dimensions");
  says(error_of([&] { open_volume(kRocks + "/berea_110.raw", "png", nullptr); }), "expected a format");
  says(error_of([&] { open_volume(kRocks + "/README.md", "tiff", nullptr); }), "README.md: expected a readable TIFF");
  says(error_of([&] { open_volume(kRocks + "/README.md", "npy", nullptr); }), "\\x93NUMPY");
  write_npy(temp("c64.npy"), "{'descr': '<f8', 'fortran_order': False, 'shape': (2, 2, 2), }", std::vector<unsigned char>(64));
  says(error_of([&] { open_volume(temp("c64.npy"), "auto", nullptr); }), "dtype '<f8'");
  write_npy(temp("huge.npy"), "{'descr': '|u1', 'fortran_order': False, 'shape': (99999999999999999999, 1), }", {});
  says(error_of([&] { open_volume(temp("huge.npy"), "auto", nullptr); }), "at most 1e12 voxels an axis");
  write_npy(temp("nodescr.npy"), "{'descr': '', 'fortran_order': False, 'shape': (1, 1), }", {0});
  says(error_of([&] { open_volume(temp("nodescr.npy"), "auto", nullptr); }), "dtype ''");
  raw = berea_spec();
  auto berea = open_volume(kRocks + "/berea_110.raw", "raw", &raw);
  PhaseSpec s = pore_is_zero();
  s.crop_lower = {100, 0, 0}, s.crop_upper = {120, 10, 10};
  says(error_of([&] { read_phases(*berea, s); }), "crop within the image's 110 voxels along x");
  s = pore_is_zero();
  s.labels = {{0, 0, 0}};
  s.phases = 1;
  says(error_of([&] { read_phases(*berea, s); }), "label 1 (slice 0) is in no range");
  // A float voxel that is no label.
  std::vector<unsigned char> half(8 * 4, 0);
  const float f = 0.5f;
  std::memcpy(half.data() + 4, &f, 4);
  write_npy(temp("half.npy"), "{'descr': '<f4', 'fortran_order': False, 'shape': (2, 2, 2), }", half);
  says(error_of([&] { all_labels(*open_volume(temp("half.npy"), "auto", nullptr)); }), "expected integer labels");
  // A grey-level image: more than kMaxLabels distinct values.
  std::vector<unsigned char> grey(2 * 100 * 100);
  for (std::size_t k = 0; k < grey.size() / 2; ++k) grey[2 * k] = (unsigned char)(k % 256), grey[2 * k + 1] = (unsigned char)(k / 256 % 32);
  raw.dimensions = {100, 100, 1}, raw.type = VoxelType::U16;
  write_bytes(temp("grey.raw"), "", grey);
  PhaseSpec every;
  every.labels = {{0, 1L << 40, 0}}, every.phases = 1;
  auto g = open_volume(temp("grey.raw"), "raw", &raw);
  says(error_of([&] { read_phases(*g, every); }), "at most 4096 distinct labels");
}

// The real rocks' pore components against an independent labelling (scipy.ndimage.label with
// the 6- and 26-neighbour structures, run once on the same files): Berea 2 components (236,733
// and 31 voxels) at every connectivity; Ketton 2,266 (largest 2,117,726) 6-connected and 124
// (largest 2,127,519) 26-connected. Their largest percolates along every axis.
TEST(Image, TheRocksPoreComponentsAgreeWithAnIndependentLabelling) {
  REQUIRE_ROCKS();
  const RawSpec raw = berea_spec();
  auto berea = open_volume(kRocks + "/berea_110.raw", "raw", &raw);
  const PhaseVolume b = read_phases(*berea, pore_is_zero());
  for (int connectivity : {6, 18, 26}) {
    const PoreComponents c = pore_components(b, 1, connectivity, "berea");
    ASSERT_EQ(c.components.size(), 2u) << connectivity;
    EXPECT_EQ(c.components[0].voxels, 236733);
    EXPECT_EQ(c.components[1].voxels, 31);
    EXPECT_EQ(c.components[0].percolates, (std::array<bool, 3>{true, true, true}));
  }
#ifdef PORESPH_HAVE_TIFF
  auto ketton = open_volume(kRocks + "/ketton_256.tif", "tiff", nullptr);
  const PhaseVolume k = read_phases(*ketton, pore_is_zero());
  const PoreComponents k6 = pore_components(k, 1, 6, "ketton"), k26 = pore_components(k, 1, 26, "ketton");
  EXPECT_EQ(k6.components.size(), 2266u);
  EXPECT_EQ(k6.components[0].voxels, 2117726);
  EXPECT_EQ(k26.components.size(), 124u);
  EXPECT_EQ(k26.components[0].voxels, 2127519);
  EXPECT_EQ(k26.components[0].percolates, (std::array<bool, 3>{true, true, true}));
#endif
}
