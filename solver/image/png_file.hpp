#pragma once
// A minimal PNG writer (8-bit RGB, uncompressed deflate blocks): for sections of segmented images
// without any image library (`poresph image slice`).
#include <cstdint>
#include <string>
#include <vector>

namespace psph {

// `rgb`: width x height pixels, rows from the top, 3 bytes each; written whole or not at all
// (ImageError naming `file`).
void write_png(const std::string& file, int width, int height, const std::vector<std::uint8_t>& rgb);

}  // namespace psph
