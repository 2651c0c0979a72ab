// Deep voxels (image/deep_voxels.hpp): the mask of "near another phase" grown by `reach` along each
// axis in turn, a running count over a window of 2 reach + 1 voxels of each line.
#include "image/deep_voxels.hpp"

#include <vector>

namespace psph {
namespace {

// near[i] = 1 where a voxel within `r` along `axis` (or the volume's face) is near.
void grow_along(std::vector<std::uint8_t>& near, const std::array<long, 3>& n, int axis, long r) {
  const long len = n[std::size_t(axis)];
  const long stride = axis == 0 ? 1 : axis == 1 ? n[0] : n[0] * n[1];
  std::vector<std::uint8_t> line(std::size_t(len), 0);
  std::vector<long> count(std::size_t(len) + 1, 0);
  for (long z = 0; z < (axis == 2 ? 1 : n[2]); ++z)
    for (long y = 0; y < (axis == 1 ? 1 : n[1]); ++y)
      for (long x = 0; x < (axis == 0 ? 1 : n[0]); ++x) {
        const long base = (z * n[1] + y) * n[0] + x;
        for (long i = 0; i < len; ++i) count[std::size_t(i + 1)] = count[std::size_t(i)] + near[std::size_t(base + i * stride)];
        for (long i = 0; i < len; ++i) {
          const long lo = i - r, hi = i + r + 1;
          line[std::size_t(i)] = lo < 0 || hi > len || count[std::size_t(hi)] > count[std::size_t(lo)];
        }
        for (long i = 0; i < len; ++i) near[std::size_t(base + i * stride)] = line[std::size_t(i)];
      }
}

}  // namespace

long replace_deep_voxels(PhaseVolume& v, unsigned phases, const std::array<long, 3>& reach, int axes, std::uint8_t to) {
  std::vector<std::uint8_t> near(v.phase.size());
  for (std::size_t i = 0; i < near.size(); ++i) near[i] = !(phases >> v.phase[i] & 1u);
  for (int k = 0; k < axes; ++k) grow_along(near, v.size, k, reach[std::size_t(k)]);
  long replaced = 0;
  for (std::size_t i = 0; i < near.size(); ++i)
    if (!near[i]) v.phase[i] = to, ++replaced;
  return replaced;
}

}  // namespace psph
