// A build without libtiff (image/volume_source.hpp): TIFF images are refused with the reason.
#include "image/image_error.hpp"
#include "image/volume_source.hpp"

namespace psph {

std::unique_ptr<VolumeSource> open_tiff_volume(const std::string& file, long) {
  throw ImageError(file, "this build of poresph reads no TIFF (libtiff was not found when it was built; "
                         "scripts/install-deps.sh installs libtiff-dev); convert the stack to raw or .npy");
}
bool tiff_available() { return false; }

}  // namespace psph
