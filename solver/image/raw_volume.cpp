// Raw volumes (image/volume_source.hpp): a header to skip, then voxels in the stated order.
#include <algorithm>
#include <filesystem>
#include <fstream>

#include "image/image_error.hpp"
#include "image/volume_source.hpp"

namespace psph {
namespace {

constexpr double kMaxVoxels = 1e13;  // beyond any disk, and far from overflowing a 64-bit offset

class RawVolume final : public VolumeSource {
 public:
  RawVolume(const std::string& file, const RawSpec& spec, std::array<int, 3> axes)
      : file_(file), spec_(spec), axes_(axes), in_(file, std::ios::binary) {
    if (!in_) throw ImageError(file, "cannot open it for reading");
    for (int s = 0; s < 3; ++s) size_[s] = spec.dimensions[axes[s]];
  }
  std::array<long, 3> size() const override { return size_; }
  std::array<int, 3> storage_axes() const override { return axes_; }
  std::string file() const override { return file_; }

  void read_slice(long s, std::vector<std::int64_t>& labels) override {
    const std::size_t count = std::size_t(size_[0]) * std::size_t(size_[1]), bytes = voxel_bytes(spec_.type);
    buffer_.resize(count * bytes);
    in_.seekg(std::streamoff(spec_.header_bytes) + std::streamoff(s) * std::streamoff(count * bytes));
    if (!in_.read(reinterpret_cast<char*>(buffer_.data()), std::streamsize(buffer_.size())))
      throw ImageError(file_, "could not read slice " + std::to_string(s));
    std::size_t bad = 0;
    if (!decode_labels(buffer_.data(), count, spec_.type, spec_.big_endian, labels, bad))
      throw ImageError(file_, "expected integer labels in a segmented image; voxel " + std::to_string(bad) +
                                  " of slice " + std::to_string(s) + " is not one");
  }

 private:
  std::string file_;
  RawSpec spec_;
  std::array<int, 3> axes_;
  std::array<long, 3> size_{};
  std::ifstream in_;
  std::vector<unsigned char> buffer_;
};

// "xyz" -> {0, 1, 2}; false unless a permutation of x, y, z.
bool parse_order(const std::string& order, std::array<int, 3>& axes) {
  if (order.size() != 3) return false;
  for (int s = 0; s < 3; ++s) {
    if (order[s] < 'x' || order[s] > 'z') return false;
    axes[s] = order[s] - 'x';
  }
  std::array<int, 3> sorted = axes;
  std::sort(sorted.begin(), sorted.end());
  return sorted == std::array<int, 3>{0, 1, 2};
}

}  // namespace

std::unique_ptr<VolumeSource> open_raw_volume(const std::string& file, const RawSpec& spec) {
  std::array<int, 3> axes{};
  if (!parse_order(spec.order, axes))
    throw ImageError(file, "expected an axis order of x, y and z, fastest first (\"xyz\", \"zyx\", ...), got \"" +
                               spec.order + "\"");
  double voxels = 1;
  for (long n : spec.dimensions) {
    if (n < 1) throw ImageError(file, "expected dimensions of at least 1 voxel along each axis", "dimensions");
    voxels *= double(n);
  }
  if (voxels > kMaxVoxels) throw ImageError(file, "expected at most 1e13 voxels", "dimensions");
  std::error_code ec;
  const auto length = std::filesystem::file_size(file, ec);
  if (ec) throw ImageError(file, "cannot read its size: " + ec.message());
  const double expected = double(spec.header_bytes) + voxels * double(voxel_bytes(spec.type));
  if (double(length) != expected)
    throw ImageError(file, "expected " + std::to_string(std::int64_t(expected)) + " bytes (" + std::to_string(spec.header_bytes) +
                               " of header + " + std::to_string(spec.dimensions[0]) + " x " +
                               std::to_string(spec.dimensions[1]) + " x " + std::to_string(spec.dimensions[2]) +
                               " voxels of " + voxel_type_name(spec.type) + "), the file has " +
                               std::to_string(length));
  return std::make_unique<RawVolume>(file, spec, axes);
}

}  // namespace psph
