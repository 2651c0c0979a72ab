// The format of a volume file (image/volume_source.hpp).
#include <algorithm>
#include <filesystem>

#include "image/image_error.hpp"
#include "image/volume_source.hpp"

namespace psph {

std::string format_of(const std::string& file) {
  std::string ext = std::filesystem::path(file).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return ext == ".npy" ? "npy" : (ext == ".tif" || ext == ".tiff") ? "tiff" : "raw";
}

std::unique_ptr<VolumeSource> open_volume(const std::string& file, const std::string& format, const RawSpec* raw,
                                          long first_page) {
  const std::string f = format == "auto" ? format_of(file) : format;
  // A FIFO or a device would block or never end; a series is checked file by file.
  std::error_code ec;
  const bool series = f == "tiff" && file.find('#') != std::string::npos;
  if (!series && !std::filesystem::is_regular_file(file, ec))
    throw ImageError(file, std::filesystem::exists(file, ec) ? "expected a regular file" : "no such file");
  if (f == "npy") return open_npy_volume(file);
  if (f == "tiff") return open_tiff_volume(file, first_page);
  if (f != "raw") throw ImageError(file, "expected a format \"raw\", \"npy\", \"tiff\" or \"auto\", got \"" + format + "\"");
  if (!raw) throw ImageError(file, "a raw volume needs its dimensions and voxel type (it has no header)");
  return open_raw_volume(file, *raw);
}

}  // namespace psph
