#pragma once
// The memory a segmented image needs, checked before it is read: the bytes the reading holds at
// once (image/phase_volume.cpp says which) against what the machine can give it, so that an image
// too large is refused with the estimate instead of dying half-way (or taking the machine down).
#include <array>
#include <string>

namespace psph {

// The bytes an image may take: PORESPH_IMAGE_MEMORY_LIMIT (bytes) where set, else the kernel's
// MemAvailable (/proc/meminfo), else sysconf's available pages. `source` (optional) says which.
// ImageError naming `file` and the variable when the variable is not a positive number of bytes.
double image_memory_limit(const std::string& file, std::string* source = nullptr);

// ImageError naming `file`, its voxels along x, y, z, the estimate and the limit in GiB (and
// `needs`: what the estimate counts, and how to need less) when `bytes` exceeds the limit.
void check_image_memory(const std::string& file, const std::array<long, 3>& voxels, double bytes,
                        const std::string& needs);

}  // namespace psph
