// Connected pore components (image/pore_components.hpp): one pass of union-find over the voxels,
// each joined to its already visited neighbours of the stencil, then the roots renumbered by size.
#include "image/pore_components.hpp"

#include <algorithm>
#include <numeric>

#include "image/image_error.hpp"

namespace psph {
namespace {

std::int32_t root(std::vector<std::int32_t>& parent, std::int32_t a) {
  while (parent[std::size_t(a)] != a) a = parent[std::size_t(a)] = parent[std::size_t(parent[std::size_t(a)])];
  return a;
}

// The offsets among the 13 visited-before neighbours of the 26 (lower z, or same z and lower y, or
// same z, y and lower x) within the connectivity: 3 faces, 9 with edges, 13 with corners.
std::vector<std::array<int, 3>> backward_stencil(int connectivity) {
  std::vector<std::array<int, 3>> out;
  for (int dz = -1; dz <= 0; ++dz)
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        const bool before = dz < 0 || (dz == 0 && (dy < 0 || (dy == 0 && dx < 0)));
        const int nonzero = (dx != 0) + (dy != 0) + (dz != 0);
        const int reach = connectivity == 6 ? 1 : connectivity == 18 ? 2 : 3;
        if (before && nonzero <= reach) out.push_back({dx, dy, dz});
      }
  return out;
}

}  // namespace

PoreComponents pore_components(const PhaseVolume& v, unsigned pore_phases, int connectivity, const std::string& file) {
  if (connectivity != 6 && connectivity != 18 && connectivity != 26)
    throw ImageError(file, "expected a connectivity of 6, 18 or 26, got " + std::to_string(connectivity));
  const std::array<long, 3> n = v.size;
  if (v.voxels() > 2147483647L) throw ImageError(file, "expected at most 2^31 voxels to label (coarsen it)");
  const auto stencil = backward_stencil(connectivity);
  PoreComponents out;
  std::vector<std::int32_t>& parent = out.label;
  parent.assign(std::size_t(v.voxels()), -1);
  auto index = [&](long x, long y, long z) { return std::size_t((z * n[1] + y) * n[0] + x); };
  for (long z = 0; z < n[2]; ++z)
    for (long y = 0; y < n[1]; ++y)
      for (long x = 0; x < n[0]; ++x) {
        if (!(pore_phases >> v.at(x, y, z) & 1u)) continue;
        const std::size_t i = index(x, y, z);
        std::int32_t r = parent[i] = std::int32_t(i);
        for (const auto& d : stencil) {
          const long a = x + d[0], b = y + d[1], c = z + d[2];
          if (a < 0 || b < 0 || c < 0 || a >= n[0] || b >= n[1]) continue;
          const std::int32_t j = parent[index(a, b, c)];
          if (j < 0) continue;
          const std::int32_t q = root(parent, j);
          if (q != r) parent[std::size_t(std::max(q, r))] = std::min(q, r), r = std::min(q, r);
        }
      }
  // In index order every parent precedes its child (links point to lower indices): each voxel takes
  // its parent's component, coded -(c + 2); a root starts one.
  std::vector<PoreComponent> found;
  std::vector<std::array<bool, 3>> low;
  for (long z = 0; z < n[2]; ++z)
    for (long y = 0; y < n[1]; ++y)
      for (long x = 0; x < n[0]; ++x) {
        const std::size_t i = index(x, y, z);
        const std::int32_t p = parent[i];
        if (p == -1) continue;
        if (std::size_t(p) == i) {
          parent[i] = -(std::int32_t(found.size()) + 2);
          found.emplace_back(), low.push_back({false, false, false});
        } else {
          parent[i] = parent[std::size_t(p)];
        }
        const std::size_t c = std::size_t(-parent[i] - 2);
        ++found[c].voxels;
        const long q[3] = {x, y, z};
        for (int k = 0; k < 3; ++k) {
          if (q[k] == 0) low[c][k] = true;
          if (q[k] == n[k] - 1) found[c].percolates[k] = true;  // high face; both faces below
        }
      }
  for (std::size_t c = 0; c < found.size(); ++c)
    for (int k = 0; k < 3; ++k) found[c].percolates[k] = found[c].percolates[k] && low[c][k];
  std::vector<std::int32_t> order(found.size()), rank(found.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return found[std::size_t(a)].voxels > found[std::size_t(b)].voxels; });
  for (std::size_t r = 0; r < order.size(); ++r) {
    rank[std::size_t(order[r])] = std::int32_t(r);
    out.components.push_back(found[std::size_t(order[r])]);
  }
  for (std::int32_t& l : parent)
    if (l != -1) l = rank[std::size_t(-l - 2)];
  return out;
}

}  // namespace psph
