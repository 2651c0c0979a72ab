#pragma once
// A segmented volume read one slice at a time (never whole): raw files, NumPy .npy files
// (image/raw_volume.cpp) and TIFF stacks (image/tiff_volume.cpp). Voxels are stored with one axis
// fastest, then another, slices along the third: `storage_axes` says which physical axis (0 = x,
// 1 = y, 2 = z) each storage axis is, fastest first.
#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "image/voxel_type.hpp"

namespace psph {

class VolumeSource {
 public:
  virtual ~VolumeSource() = default;
  // Voxels along each storage axis, fastest first.
  virtual std::array<long, 3> size() const = 0;
  virtual std::array<int, 3> storage_axes() const = 0;
  // The labels of slice `s` (size()[0] x size()[1] voxels, the fastest axis first).
  virtual void read_slice(long s, std::vector<std::int64_t>& labels) = 0;
  virtual std::string file() const = 0;
};

// How to read a raw volume: its voxels along x, y, z, their type and byte order, the bytes of
// header to skip, and the order of the axes in the file, fastest first ("xyz": x fastest, then y,
// slices along z, as most CT exports; "zyx": the C order of an array indexed [x][y][z]).
struct RawSpec {
  std::array<long, 3> dimensions{0, 0, 0};
  VoxelType type = VoxelType::U8;
  bool big_endian = false;
  long header_bytes = 0;
  std::string order = "xyz";
};

// The file must hold header + voxels x type bytes exactly (ImageError otherwise).
std::unique_ptr<VolumeSource> open_raw_volume(const std::string& file, const RawSpec& spec);
// Type, byte order, shape and order from the file's own header (format versions 1 to 3); a 2D
// array is one slice. The array's index [i][j][k] is voxel (x, y, z) = (i, j, k).
std::unique_ptr<VolumeSource> open_npy_volume(const std::string& file);
// A multi-page TIFF (pages along z, x along a page's rows), or a numbered series of files: a run
// of '#' in `file` is the page's number, zero-padded to its length, from `first` until a number
// has no file. 1-, 8-, 16- or 32-bit unsigned integer samples, one per pixel, strips or tiles,
// either byte order, BlackIsZero or WhiteIsZero (the labels are the stored values either way).
// Without libtiff in the build: ImageError.
std::unique_ptr<VolumeSource> open_tiff_volume(const std::string& file, long first = 0);

// By `format` ("raw", "npy", "tiff"), or "auto": by the file's extension (.npy; .tif, .tiff; else
// raw). A raw file needs `raw` (ImageError without).
std::unique_ptr<VolumeSource> open_volume(const std::string& file, const std::string& format, const RawSpec* raw,
                                          long first_page = 0);
// The format "auto" picks for a file.
std::string format_of(const std::string& file);

// Whether this build reads TIFF (libtiff was found).
bool tiff_available();

}  // namespace psph
