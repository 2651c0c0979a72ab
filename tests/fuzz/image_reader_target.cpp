// The fuzz target of the segmented-image readers: any bytes, as an image file, go through what
// `poresph image info` does (open, read every slice into phases, the labels and porosity, the
// pore components, the report) as a NumPy .npy, as a TIFF (a multi-page file, and a numbered
// series of two files; refused where the build has no libtiff) and as raw volumes described by the
// input's first bytes (one fitted to the file's length, one as stated: any dimensions, type,
// byte order, axis order and header). An image that reads, or a refusal (ImageError naming the
// file), is a fine outcome; any other exception, a crash, a sanitizer report, a hang or an
// allocation beyond libFuzzer's -malloc_limit_mb is a finding. The images a file may describe are
// bounded by the memory bound (image/image_memory.hpp), set small here. Built with libFuzzer
// (tests/fuzz/CMakeLists.txt, label `fuzz`) and, with a small main, as the replay of the seeds
// and of every input that ever failed (`fuzz_image_replay`, in make test).
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>

#include "image/image_error.hpp"
#include "image/image_report.hpp"
#include "image/phase_volume.hpp"
#include "image/pore_components.hpp"
#include "image/volume_source.hpp"

namespace {

// An image of a few million voxels at most (16 MiB as the memory bound counts it): one input
// stays well under a second, and every allocation of the readers under 256 MiB (run_fuzzer.sh).
constexpr const char* kMemoryLimit = "16777216";

// FUZZ_IMAGE_VERBOSE=1: each outcome and report on stderr (to see what a seed reaches).
bool verbose() {
  static const bool on = std::getenv("FUZZ_IMAGE_VERBOSE") != nullptr;
  return on;
}

// The files the inputs are written to, one set per process (reused).
struct Files {
  std::string stem, single, series_pattern, page_a, page_b;
  Files() {
    stem = (std::filesystem::temp_directory_path() / ("poresph_fuzz_image_" + std::to_string(getpid()))).string();
    single = stem + ".img";
    series_pattern = stem + "_##.tif";  // pages 07 and 08
    page_a = stem + "_07.tif", page_b = stem + "_08.tif";
  }
  ~Files() {
    for (const std::string* p : {&single, &page_a, &page_b}) std::remove(p->c_str());
  }
};

void write_file(const std::string& path, const std::uint8_t* data, std::size_t size) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(data), std::streamsize(size));
  if (!out) {
    std::fprintf(stderr, "fuzz: cannot write %s\n", path.c_str());
    std::abort();
  }
}

// `poresph image info`'s description: label 0 is pore, every other label solid; the input's last
// byte chooses a coarsening (1 or 2 per axis) and a crop of the lowest voxel along x and of 0 to 3
// slices along z (a TIFF then looks its first page up), as --coarsen and --crop would (both
// refused where the image is too small for them).
psph::PhaseSpec info_spec(std::uint8_t control, const std::array<long, 3>& file_size) {
  psph::PhaseSpec s;
  s.labels = {{0, 0, 0}, {std::numeric_limits<std::int64_t>::min(), std::numeric_limits<std::int64_t>::max(), 1}};
  s.phases = 2, s.pore_phases = 1;
  if (control & 0x80)
    for (int k = 0; k < 3; ++k) s.coarsen[k] = 1 + (control >> k & 1);
  if (control & 0x40) s.crop_lower = {1, 0, control >> 4 & 3}, s.crop_upper = {file_size[0], 0, file_size[2]};
  return s;
}

// Opens the file as `format` and does what `poresph image info` does; anything but a refusal
// naming the file aborts.
void image_info(const Files& f, const std::string& file, const std::string& format, const psph::RawSpec* raw,
                long first_page, std::uint8_t control) {
  try {
    auto src = psph::open_volume(file, format, raw, first_page);
    std::array<long, 3> file_size{};
    for (int s = 0; s < 3; ++s) file_size[std::size_t(src->storage_axes()[s])] = src->size()[s];
    const psph::PhaseSpec spec = info_spec(control, file_size);
    const psph::PhaseVolume v = psph::read_phases(*src, spec);
    const int connectivity = control % 3 == 0 ? 6 : control % 3 == 1 ? 18 : 26;
    const psph::PoreComponents pores = psph::pore_components(v, spec.pore_phases, connectivity, file);
    psph::ImageReportInput in;
    in.file = file, in.format = format, in.volume = &v, in.pores = &pores, in.pore_phases = spec.pore_phases;
    in.coarsen = spec.coarsen, in.connectivity = connectivity, in.dimension = v.size[2] == 1 ? 2 : 3;
    const std::string text = psph::image_report_text(psph::image_report(in));
    if (verbose()) std::fprintf(stderr, "%s: read\n%s", format.c_str(), text.c_str());
  } catch (const psph::ImageError& e) {
    if (verbose()) std::fprintf(stderr, "%s: refused: %s\n", format.c_str(), e.what());
    if (std::string(e.what()).find(f.stem) == std::string::npos) {
      std::fprintf(stderr, "fuzz: an image error (%s) that does not name the file: %s\n", format.c_str(), e.what());
      std::abort();
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "fuzz: an exception that is not an image error (%s): %s\n", format.c_str(), e.what());
    std::abort();
  }
}

std::uint32_t u32_at(const std::uint8_t* data, std::size_t size, std::size_t at) {
  std::uint32_t v = 0;
  for (std::size_t k = 0; k < 4; ++k) v |= std::uint32_t(at + k < size ? data[at + k] : 0) << (8 * k);
  return v;
}

const psph::VoxelType kTypes[] = {psph::VoxelType::U8,  psph::VoxelType::I8,  psph::VoxelType::U16, psph::VoxelType::I16,
                                  psph::VoxelType::U32, psph::VoxelType::I32, psph::VoxelType::F32};
const char* const kOrders[] = {"xyz", "xzy", "yxz", "yzx", "zxy", "zyx"};

// A raw volume whose description fits the file's length: type, byte orders, axis order and
// x, y (1 to 16 voxels) from the first bytes, z as many slices as the file holds after a header of
// up to 31 bytes, and the rest of the file added to the header. Nothing if no slice fits.
bool fitted_raw(const std::uint8_t* data, std::size_t size, psph::RawSpec& raw) {
  const std::uint32_t c = u32_at(data, size, 0);
  raw.type = kTypes[(c & 0xff) % 7];
  raw.big_endian = c >> 3 & 1;
  raw.order = kOrders[(c >> 8 & 0xff) % 6];
  const long nx = 1 + long(c >> 16 & 15), ny = 1 + long(c >> 20 & 15), header = long(c >> 24 & 31);
  const long slice = nx * ny * long(psph::voxel_bytes(raw.type));
  if (long(size) < header + slice) return false;
  const long nz = (long(size) - header) / slice;
  raw.header_bytes = long(size) - nz * slice;
  // The dimensions are along x, y, z; the file's storage axes follow `order` (fastest first).
  std::array<long, 3> storage{nx, ny, nz};
  for (int s = 0; s < 3; ++s) raw.dimensions[std::size_t(raw.order[std::size_t(s)] - 'x')] = storage[std::size_t(s)];
  return true;
}

// A raw volume as the input states it: any positive dimensions (bytes 4 to 15), a header of up to
// 65535 bytes (16, 17), the type and orders of the first byte; most are refused by their size.
psph::RawSpec stated_raw(const std::uint8_t* data, std::size_t size) {
  psph::RawSpec raw;
  const std::uint32_t c = u32_at(data, size, 0);
  raw.type = kTypes[(c & 0xff) % 7];
  raw.big_endian = c >> 4 & 1;
  raw.order = kOrders[(c >> 8 & 0xff) % 6];
  for (int k = 0; k < 3; ++k) raw.dimensions[std::size_t(k)] = long(u32_at(data, size, 4 + 4 * std::size_t(k)) & 0x7fffffffu);
  raw.header_bytes = long(u32_at(data, size, 16) & 0xffffu);
  return raw;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const Files f = [] {
    setenv("PORESPH_IMAGE_MEMORY_LIMIT", kMemoryLimit, 0);  // the fuzzer's bound, unless given
    return Files();
  }();
  const std::uint8_t control = size ? data[size - 1] : 0;
  write_file(f.single, data, size);
  image_info(f, f.single, "npy", nullptr, 0, control);
  image_info(f, f.single, "tiff", nullptr, 0, control);
  psph::RawSpec raw;
  if (fitted_raw(data, size, raw)) image_info(f, f.single, "raw", &raw, 0, control);
  raw = stated_raw(data, size);
  image_info(f, f.single, "raw", &raw, 0, control);
  if (psph::tiff_available()) {  // the same page twice as a numbered series
    write_file(f.page_a, data, size);
    write_file(f.page_b, data, size);
    image_info(f, f.series_pattern, "tiff", nullptr, 7, control);
  }
  return 0;
}
