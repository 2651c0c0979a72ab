// The synthetic claystone (image/claystone_sample.hpp). Random numbers from the 64-bit Mersenne
// twister's raw output (not a std distribution, whose algorithm the standard leaves open), so that
// a seed gives the same sample with any standard library.
#include "image/claystone_sample.hpp"

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>

#include "image/image_error.hpp"
#include "io/durable_file.hpp"

namespace psph {
namespace {

class Random {
 public:
  explicit Random(std::uint64_t seed) : g_(seed) {}
  double uniform(double lo, double hi) { return lo + (hi - lo) * double(g_() >> 11) * 0x1.0p-53; }

 private:
  std::mt19937_64 g_;
};

constexpr std::uint8_t kPore = 0, kClay = 1, kGrain = 2;

struct Fracture {
  double n = 50;
  double phase_z = 0, phase_y = 0, wander = 0;
  // The fracture's half-aperture at (y, z) about its mid-surface x_c(y, z) (0: outside it).
  double half_aperture(double y, double z) const {
    const double s = z / n;                                            // 0 at the bottom, 1 at the top
    const double aperture = n * (0.05 + 0.15 * std::pow(s, 1.5));     // 2.5 voxels at the outlet, 10 at the entry
    const double half_width = n * (0.15 + 0.25 * s);                   // across y
    const double yc = n / 2 + wander * std::sin(2 * M_PI * s + phase_y);
    const double u = (y - yc) / half_width;
    return u * u < 1 ? 0.5 * aperture * std::sqrt(1 - u * u) : 0;   // a lens across: sharp tips along y
  }
  double mid_surface(double y, double z) const {
    return n / 2 + 0.08 * n * std::sin(1.4 * M_PI * z / n + phase_z) + 0.04 * n * std::sin(2 * M_PI * y / n + phase_y);
  }
};

struct Grid {
  long n;
  std::vector<std::uint8_t>& v;
  std::uint8_t& at(long x, long y, long z) { return v[std::size_t((z * n + y) * n + x)]; }
  bool inside(long x, long y, long z) const { return x >= 0 && y >= 0 && z >= 0 && x < n && y < n && z < n; }
};

// The fracture (one pore), or its part above z0 closed downwards to a tip and that part's
// reflection through the centre (two pores, each open to one face).
void carve_fractures(Grid& g, const Fracture& f, bool two_pores) {
  const double n = double(g.n), tip = 0.5 * n + 3, taper = 0.25 * n;
  for (long z = 0; z < g.n; ++z)
    for (long y = 0; y < g.n; ++y)
      for (long x = 0; x < g.n; ++x) {
        auto in_pore = [&](double px, double py, double pz) {
          double a = f.half_aperture(py, pz);
          if (two_pores) a *= pz > tip ? std::sqrt(std::min(1.0, (pz - tip) / taper)) : 0;
          // the closing part bends towards +x: its tip points to that side
          const double bend = two_pores ? 0.12 * n * std::max(0.0, 1 - (pz - tip) / taper) : 0;
          return a >= 0.5 && std::fabs(px - f.mid_surface(py, pz) - bend) <= a;
        };
        const double px = double(x) + 0.5, py = double(y) + 0.5, pz = double(z) + 0.5;
        if (in_pore(px, py, pz) || (two_pores && in_pore(n - px, n - py, n - pz))) g.at(x, y, z) = kPore;
      }
}

// Ellipsoids of `to` with semi-axes in [r0, r1] (one of them halved: flat, as clay pores and
// grains are), each kept `gap` voxels clear of everything that is not clay, until `count` voxels
// are `to` (or the attempts run out).
void scatter(Grid& g, Random& rnd, std::uint8_t to, long count, double r0, double r1, long gap) {
  long placed = 0;
  for (long attempt = 0; attempt < 1000000 && placed < count; ++attempt) {
    std::array<double, 3> c{}, r{};
    for (int k = 0; k < 3; ++k) c[k] = rnd.uniform(0, double(g.n)), r[k] = rnd.uniform(r0, r1);
    r[std::size_t(std::min(2.0, rnd.uniform(0, 3)))] *= 0.5;
    std::array<long, 3> lo{}, hi{};
    for (int k = 0; k < 3; ++k) lo[k] = long(std::floor(c[k] - r[k])) - gap - 1, hi[k] = long(std::ceil(c[k] + r[k])) + gap + 1;
    auto inside = [&](long x, long y, long z, double grow) {
      const double dx = (double(x) + 0.5 - c[0]) / (r[0] + grow), dy = (double(y) + 0.5 - c[1]) / (r[1] + grow),
                   dz = (double(z) + 0.5 - c[2]) / (r[2] + grow);
      return dx * dx + dy * dy + dz * dz <= 1;
    };
    bool clear = true;
    std::vector<std::array<long, 3>> voxels;
    for (long z = lo[2]; z <= hi[2] && clear; ++z)
      for (long y = lo[1]; y <= hi[1] && clear; ++y)
        for (long x = lo[0]; x <= hi[0] && clear; ++x) {
          if (!g.inside(x, y, z)) continue;
          if (inside(x, y, z, double(gap) + 0.75) && g.at(x, y, z) != kClay) clear = false;
          else if (inside(x, y, z, 0)) voxels.push_back({x, y, z});
        }
    if (!clear) continue;
    for (const auto& p : voxels) g.at(p[0], p[1], p[2]) = to;
    placed += long(voxels.size());
  }
}

}  // namespace

ClaystoneSample make_claystone(const ClaystoneSpec& spec) {
  if (spec.size < 16 || spec.size > 1024) throw std::invalid_argument("expected a size from 16 to 1024 voxels");
  if (!(spec.porosity > 0 && spec.porosity < 0.5)) throw std::invalid_argument("expected a porosity in (0, 0.5)");
  if (!(spec.grains >= 0 && spec.grains < 0.4)) throw std::invalid_argument("expected a grain fraction in [0, 0.4)");
  ClaystoneSample s;
  s.size = {spec.size, spec.size, spec.size};
  s.label.assign(std::size_t(spec.size * spec.size * spec.size), kClay);
  Grid g{spec.size, s.label};
  Random rnd(spec.seed);
  Fracture f;
  f.n = double(spec.size);
  f.phase_z = rnd.uniform(0, 2 * M_PI), f.phase_y = rnd.uniform(0, 2 * M_PI), f.wander = rnd.uniform(0, 0.05 * f.n);
  carve_fractures(g, f, spec.two_pores);
  const long voxels = long(s.label.size());
  const long pores = long(std::count(s.label.begin(), s.label.end(), kPore));
  const double scale = double(spec.size) / 50;  // the pores' and grains' sizes follow the cube's
  // A voxel of clay between any two pores: disconnected even with 26-connectivity.
  scatter(g, rnd, kPore, long(spec.porosity * double(voxels)) - pores, 1.5 * scale, 3.5 * scale, 1);
  scatter(g, rnd, kGrain, long(spec.grains * double(voxels)), 1.5 * scale, 4.0 * scale, 1);
  return s;
}

void write_npy(const std::string& file, const LabelVolume& s) {
  std::string header = "{'descr': '|u1', 'fortran_order': True, 'shape': (" + std::to_string(s.size[0]) + ", " +
                       std::to_string(s.size[1]) + ", " + std::to_string(s.size[2]) + "), }";
  // NumPy format 1.0: magic, version, header length; the header padded with spaces to a multiple of
  // 64 bytes with the preamble, ending in a newline.
  const std::size_t preamble = 10;
  header.append(63 - (preamble + header.size()) % 64, ' ');
  header += '\n';
  std::string out = "\x93NUMPY";
  out += char(1), out += char(0);
  out += char(header.size() & 0xff), out += char(header.size() >> 8);
  out += header;
  out.append(reinterpret_cast<const char*>(s.label.data()), s.label.size());
  try {
    write_file_atomically(file, out);
  } catch (const WriteError& e) {
    throw ImageError(file, e.what());
  }
}

}  // namespace psph
