// Phases of a segmented volume (image/phase_volume.hpp), coarsened one block of slices at a time.
#include "image/phase_volume.hpp"

#include <algorithm>
#include <string>

#include "image/image_error.hpp"
#include "image/image_memory.hpp"

namespace psph {
namespace {

// Label -> phase: a table for 0..65535, the ranges beyond.
class LabelMap {
 public:
  explicit LabelMap(const PhaseSpec& spec) : spec_(spec), table_(65536, kNone) {
    for (std::int64_t l = 0; l < 65536; ++l) table_[std::size_t(l)] = lookup(l);
  }
  int operator()(std::int64_t label) const { return label >= 0 && label < 65536 ? table_[std::size_t(label)] : lookup(label); }
  static constexpr int kNone = -1;

 private:
  int lookup(std::int64_t label) const {
    for (const LabelRange& r : spec_.labels)
      if (label >= r.lo && label <= r.hi) return r.phase;
    return kNone;
  }
  const PhaseSpec& spec_;
  std::vector<int> table_;
};

// The majority phase of a block's counts; ties to a pore phase, then to the lower phase.
int majority(const std::uint32_t* counts, int phases, unsigned pore) {
  int best = 0;
  for (int p = 1; p < phases; ++p) {
    const bool better = counts[p] > counts[best] ||
                        (counts[p] == counts[best] && (pore >> p & 1u) && !(pore >> best & 1u));
    if (better) best = p;
  }
  return best;
}

constexpr std::int64_t kTable = 65536;

struct Extent {
  std::array<long, 3> lower, fine, coarse;  // per physical axis: crop start, cropped voxels, coarse voxels
};

Extent extent_of(const VolumeSource& src, const PhaseSpec& spec, std::array<long, 3>& file_size) {
  const std::array<long, 3> n = src.size();
  const std::array<int, 3> axes = src.storage_axes();
  for (int s = 0; s < 3; ++s) file_size[axes[s]] = n[s];
  Extent e;
  const char* name = "xyz";
  for (int k = 0; k < 3; ++k) {
    const long lo = spec.crop_lower[k], hi = spec.crop_upper[k] == 0 ? file_size[k] : spec.crop_upper[k];
    if (lo < 0 || hi > file_size[k] || hi <= lo)
      throw ImageError(src.file(), std::string("expected a crop within the image's ") + std::to_string(file_size[k]) +
                                       " voxels along " + name[k] + ", got [" + std::to_string(lo) + ", " +
                                       std::to_string(hi) + ")", "crop");
    if (spec.coarsen[k] < 1)
      throw ImageError(src.file(), std::string("expected a coarsening factor >= 1 along ") + name[k], "coarsen");
    e.lower[k] = lo, e.fine[k] = hi - lo, e.coarse[k] = (hi - lo) / spec.coarsen[k];
    if (e.coarse[k] == 0)
      throw ImageError(src.file(), std::string("expected at least one whole block of ") + std::to_string(spec.coarsen[k]) +
                                       " voxels along " + name[k] + " in the crop", "coarsen");
  }
  return e;
}

// What reading holds at once, checked before anything large is allocated: each coarse voxel's
// phase (1 byte) and, while its pore components are labelled, their label (4 bytes); a slice of
// the file as read (at most 4 bytes a voxel) and decoded (8); a coarse slice's counts per phase;
// the label tables.
void check_memory(const VolumeSource& src, const Extent& e, const std::array<long, 3>& file_size, int phases) {
  const std::array<long, 3> n = src.size();
  const std::array<int, 3> axes = src.storage_axes();
  const double coarse = double(e.coarse[0]) * double(e.coarse[1]) * double(e.coarse[2]);
  const double slice = double(n[0]) * double(n[1]);
  const double counts = double(e.coarse[axes[0]]) * double(e.coarse[axes[1]]) * phases;
  const double bytes = 5 * coarse + 12 * slice + 4 * counts + 12.0 * kTable;
  auto times = [](const std::array<long, 3>& v) {
    return std::to_string(v[0]) + " x " + std::to_string(v[1]) + " x " + std::to_string(v[2]);
  };
  check_image_memory(src.file(), file_size, bytes,
                     times(e.coarse) + " coarse voxels at 5 bytes each, slices of " + std::to_string(n[0]) + " x " +
                         std::to_string(n[1]) + " voxels at 12 bytes each; coarsen or crop it");
}

}  // namespace

PhaseVolume read_phases(VolumeSource& src, const PhaseSpec& spec) {
  if (spec.phases < 1 || spec.phases > 255) throw ImageError(src.file(), "expected 1 to 255 phases", "labels");
  PhaseVolume v;
  const Extent e = extent_of(src, spec, v.file_size);
  check_memory(src, e, v.file_size, spec.phases);
  const std::array<int, 3> axes = src.storage_axes();
  const std::array<long, 3> n = src.size();
  v.size = e.coarse;
  v.phase.assign(std::size_t(v.voxels()), 0);
  v.fine_voxels.assign(spec.phases, 0), v.coarse_voxels.assign(spec.phases, 0);
  const LabelMap map(spec);
  const int a0 = axes[0], a1 = axes[1], a2 = axes[2];
  const long c0 = e.coarse[a0], c1 = e.coarse[a1];
  std::vector<std::uint32_t> counts(std::size_t(c0 * c1 * spec.phases));
  std::vector<std::int64_t> labels;
  std::vector<long> small(kTable, 0);  // voxels of each label 0..65535, and of the others
  std::map<std::int64_t, long> big;
  long distinct = 0;  // labels seen: a grey-level image is refused at its 4097th
  for (long b = 0; b < e.coarse[a2]; ++b) {
    std::fill(counts.begin(), counts.end(), 0u);
    for (int f = 0; f < spec.coarsen[a2]; ++f) {
      const long s = e.lower[a2] + b * spec.coarsen[a2] + f;
      src.read_slice(s, labels);
      for (long j = 0; j < c1 * spec.coarsen[a1]; ++j)
        for (long i = 0; i < c0 * spec.coarsen[a0]; ++i) {
          const std::int64_t label = labels[std::size_t((e.lower[a1] + j) * n[0] + e.lower[a0] + i)];
          const int p = map(label);
          if (p == LabelMap::kNone)
            throw ImageError(src.file(), "label " + std::to_string(label) + " (slice " + std::to_string(s) +
                                             ") is in no range of the label map", "labels");
          const bool fresh = (label >= 0 && label < kTable) ? small[std::size_t(label)]++ == 0 : big[label]++ == 0;
          if (fresh && ++distinct > kMaxLabels)
            throw ImageError(src.file(), "expected a segmented image of at most " + std::to_string(kMaxLabels) +
                                             " distinct labels (a grey-level image has more)", "labels");
          ++v.fine_voxels[p];
          ++counts[std::size_t(((j / spec.coarsen[a1]) * c0 + i / spec.coarsen[a0]) * spec.phases + p)];
        }
    }
    for (long j = 0; j < c1; ++j)
      for (long i = 0; i < c0; ++i) {
        const int p = majority(&counts[std::size_t((j * c0 + i) * spec.phases)], spec.phases, spec.pore_phases);
        std::array<long, 3> q{};
        q[a0] = i, q[a1] = j, q[a2] = b;
        v.phase[std::size_t((q[2] * v.size[1] + q[1]) * v.size[0] + q[0])] = std::uint8_t(p);
        ++v.coarse_voxels[p];
      }
  }
  for (std::size_t l = 0; l < small.size(); ++l)
    if (small[l]) v.label_voxels[std::int64_t(l)] = small[l];
  v.label_voxels.insert(big.begin(), big.end());
  return v;
}

double porosity(const PhaseVolume& v, unsigned pore_phases, bool coarse) {
  const std::vector<long>& n = coarse ? v.coarse_voxels : v.fine_voxels;
  long pore = 0, all = 0;
  for (std::size_t p = 0; p < n.size(); ++p) all += n[p], pore += (pore_phases >> p & 1u) ? n[p] : 0;
  return all ? double(pore) / double(all) : 0.0;
}

}  // namespace psph
