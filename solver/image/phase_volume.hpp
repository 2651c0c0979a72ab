#pragma once
// A segmented volume as phases: each label mapped to a phase (the case's materials), an optional
// crop, and coarsening by an integer factor per axis with the majority rule, read slice by slice
// so that only the coarse phases are ever held (one byte a coarse voxel). Tie rule (the
// references give none): a tie goes to a pore phase if one is among the tied (the pore space keeps
// its throats), else to the phase listed first.
#include <array>
#include <cstdint>
#include <map>
#include <vector>

#include "image/volume_source.hpp"

namespace psph {

// Labels lo..hi (inclusive) are phase `phase`.
struct LabelRange {
  std::int64_t lo = 0, hi = 0;
  int phase = 0;
};

struct PhaseSpec {
  std::vector<LabelRange> labels;  // the first range holding a label decides; an unmapped label is an error
  int phases = 0;                  // phases 0 .. phases - 1 (at most 255)
  unsigned pore_phases = 0;        // bit p: phase p is pore space (ties go to it)
  // Crop in voxels of the file along x, y, z: [lower, upper), upper 0 for the whole axis.
  std::array<long, 3> crop_lower{0, 0, 0}, crop_upper{0, 0, 0};
  std::array<int, 3> coarsen{1, 1, 1};  // per axis; voxels short of a whole block at the upper end are dropped
};

struct PhaseVolume {
  std::array<long, 3> file_size{0, 0, 0};  // the file's voxels along x, y, z
  std::array<long, 3> size{0, 0, 0};       // coarse voxels along x, y, z
  std::vector<std::uint8_t> phase;          // x fastest, then y, then z
  std::map<std::int64_t, long> label_voxels;  // voxels of each label in the crop's whole blocks (before coarsening)
  std::vector<long> fine_voxels, coarse_voxels;  // of each phase, before (in whole blocks) and after coarsening
  std::uint8_t at(long x, long y, long z) const { return phase[std::size_t((z * size[1] + y) * size[0] + x)]; }
  long voxels() const { return size[0] * size[1] * size[2]; }
};

// The most distinct labels an image may have (more: not a segmented image).
constexpr int kMaxLabels = 4096;

// Reads `src` through `spec` (ImageError on an unmapped label, a crop outside the image or
// smaller than one block, more than kMaxLabels distinct labels).
PhaseVolume read_phases(VolumeSource& src, const PhaseSpec& spec);

// The fraction of voxels in pore phases, before (fine) and after coarsening.
double porosity(const PhaseVolume& v, unsigned pore_phases, bool coarse);

}  // namespace psph
