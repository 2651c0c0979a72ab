#pragma once
// An image geometry's volume (scene/read_image.cpp): its `file` found along the image search path
// (scene/image_path.hpp), its format and the raw keys read and checked against it. Every failure
// is a CaseError naming the key.
#include <memory>
#include <string>

#include "image/volume_source.hpp"
#include "scene/case_reader.hpp"

namespace psph {

// `format` and `file` get the format read and the path found (absolute).
std::unique_ptr<VolumeSource> open_image(CaseReader& r, const std::string& case_file, std::string& format, std::string& file);

}  // namespace psph
