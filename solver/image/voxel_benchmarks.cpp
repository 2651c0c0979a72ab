#include "image/voxel_benchmarks.hpp"

#include <cmath>
#include <functional>
#include <stdexcept>

namespace psph {
namespace {

constexpr std::uint8_t kPore = 0, kSolid = 1;

// A volume of nx x ny x nz whose voxel (x, y, z) is pore where `pore` says so.
LabelVolume fill(long nx, long ny, long nz, const std::function<bool(long, long, long)>& pore) {
  LabelVolume v;
  v.size = {nx, ny, nz};
  v.label.resize(std::size_t(nx * ny * nz));
  for (long z = 0; z < nz; ++z)
    for (long y = 0; y < ny; ++y)
      for (long x = 0; x < nx; ++x) v.label[std::size_t(x + nx * (y + ny * z))] = pore(x, y, z) ? kPore : kSolid;
  return v;
}

bool in(long a, long lo, long hi) { return a >= lo && a < hi; }

void require(bool ok, const std::string& what) {
  if (!ok) throw std::invalid_argument(what);
}

}  // namespace

const char* const* voxel_benchmark_kinds() {
  static const char* const kinds[] = {"duct", "twin_ducts", "tilted_slit", "sphere_array", "dead_ends", "zigzag", nullptr};
  return kinds;
}

LabelVolume make_voxel_benchmark(const VoxelBenchmark& s) {
  const long w = s.width;
  require(w >= 1 && w <= 512, "width: expected 1 to 512 voxels");
  require(s.length >= 1 && s.length <= 4096, "length: expected 1 to 4096 voxels");
  if (s.kind == "duct")
    return fill(w + 2, w + 2, s.length, [&](long x, long y, long) { return in(x, 1, w + 1) && in(y, 1, w + 1); });
  if (s.kind == "twin_ducts")
    return fill(2 * w + 3, w + 2, s.length, [&](long x, long y, long) {
      return in(y, 1, w + 1) && (in(x, 1, w + 1) || in(x, w + 2, 2 * w + 2));
    });
  if (s.kind == "tilted_slit") {
    // Mid-plane x - 2 y = n/2 (mod n) at the voxels' centres: one slit that winds once around the
    // periodic section, its windings n / sqrt(5) apart.
    const long n = s.size;
    require(n >= 4 && double(w) <= double(n) / std::sqrt(5.0) - 2, "size: expected the slit's windings (size / sqrt 5) two voxels wider than its width");
    return fill(n, n, s.length, [&](long x, long y, long) {
      double f = std::fmod((x + 0.5) - 2 * (y + 0.5) - 0.5 * n, double(n));
      if (f < -0.5 * n) f += n;
      if (f >= 0.5 * n) f -= n;
      return std::fabs(f) / std::sqrt(5.0) < 0.5 * double(w);
    });
  }
  if (s.kind == "sphere_array") {
    const long n = s.size;
    require(n >= 4 && n <= 1024, "size: expected 4 to 1024 voxels");
    require(s.radius > 0 && s.radius <= 0.5 * std::sqrt(2.0) * n, "radius: expected (0, size / sqrt 2]");
    const double c = 0.5 * n;
    return fill(n, n, n, [&](long x, long y, long z) {
      const double dx = x + 0.5 - c, dy = y + 0.5 - c, dz = z + 0.5 - c;
      return dx * dx + dy * dy + dz * dz >= s.radius * s.radius;
    });
  }
  if (s.kind == "dead_ends")  // branches 2 w deep along +x at z in [w/2, 3w/2) and [5w/2, 7w/2) of 4 w
    return fill(3 * w + 2, w + 2, 4 * w, [&](long x, long y, long z) {
      const long zz = z % (2 * w);
      const bool branch = in(2 * zz, w, 3 * w) && in(x, 1, 3 * w + 1);
      return in(y, 1, w + 1) && (in(x, 1, w + 1) || branch);
    });
  if (s.kind == "zigzag")  // up the left column, across, up the right one, across back (period 4 w)
    return fill(3 * w + 2, w + 2, 4 * w, [&](long x, long y, long z) {
      const long leg = z / w;  // 0: left column, 1: across, 2: right column, 3: across
      const bool left = in(x, 1, w + 1), right = in(x, 2 * w + 1, 3 * w + 1), across = in(x, 1, 3 * w + 1);
      return in(y, 1, w + 1) && (leg == 0 ? left : leg == 2 ? right : across);
    });
  throw std::invalid_argument("kind: expected duct, twin_ducts, tilted_slit, sphere_array, dead_ends or zigzag");
}

}  // namespace psph
