// voxel_lbm: the permeability of a segmented image by the lattice-Boltzmann reference
// (voxel_lbm.hpp). Reads raw, NumPy .npy and uncompressed TIFF stacks itself (nothing from
// solver/), with poresph's axis conventions (solver/image/volume_source.hpp):
//   raw   x fastest, then y, slices along z (--order changes it, as the case file's `order`);
//   .npy  index [i][j][k] is voxel (x, y, z), C or Fortran order;
//   .tif  pages along z, x along a page's rows.
#include <omp.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <limits>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "voxel_lbm.hpp"

namespace {

struct Error : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct Volume {
  std::array<long, 3> n{0, 0, 0};  // voxels along x, y, z
  std::vector<std::int64_t> label;   // x + n0 * (y + n1 * z)
};

std::vector<unsigned char> slurp(const std::string& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw Error(file + ": cannot open it for reading");
  return std::vector<unsigned char>(std::istreambuf_iterator<char>(in), {});
}

// An unsigned or signed integer of `bytes` at p in either byte order.
std::int64_t decode(const unsigned char* p, int bytes, bool is_signed, bool big) {
  std::uint64_t u = 0;
  for (int b = 0; b < bytes; ++b) u |= std::uint64_t(p[big ? bytes - 1 - b : b]) << (8 * b);
  if (is_signed && bytes < 8 && (u >> (8 * bytes - 1) & 1)) return std::int64_t(u) - (std::int64_t(1) << (8 * bytes));
  return std::int64_t(u);
}

// `data` holds the volume with storage axes `order` (fastest first, e.g. "zyx").
Volume unpack(const unsigned char* data, std::array<long, 3> n, const std::string& order, int bytes, bool is_signed,
              bool big) {
  Volume v{n, std::vector<std::int64_t>(std::size_t(n[0] * n[1] * n[2]))};
  const int a0 = order[0] - 'x', a1 = order[1] - 'x', a2 = order[2] - 'x';
  std::size_t k = 0;
  std::array<long, 3> p{};
  for (p[a2] = 0; p[a2] < n[a2]; ++p[a2])
    for (p[a1] = 0; p[a1] < n[a1]; ++p[a1])
      for (p[a0] = 0; p[a0] < n[a0]; ++p[a0], ++k)
        v.label[std::size_t(p[0] + n[0] * (p[1] + n[1] * p[2]))] = decode(data + k * bytes, bytes, is_signed, big);
  return v;
}

Volume read_raw(const std::string& file, std::array<long, 3> n, const std::string& order) {
  const auto bytes = slurp(file);
  if (double(bytes.size()) != double(n[0]) * double(n[1]) * double(n[2]))
    throw Error(file + ": expected " + std::to_string(n[0] * n[1] * n[2]) + " bytes of uint8 voxels (--dimensions), got " +
                std::to_string(bytes.size()));
  return unpack(bytes.data(), n, order, 1, false, false);
}

// NumPy .npy, format 1-3: '{'descr': '<u1', 'fortran_order': False, 'shape': (a, b, c), }'.
Volume read_npy(const std::string& file) {
  const auto b = slurp(file);
  if (b.size() < 12 || std::string(b.begin(), b.begin() + 6) != "\x93NUMPY") throw Error(file + ": not a .npy file");
  const bool v1 = b[6] == 1;
  const std::size_t len = v1 ? b[8] | b[9] << 8 : b[8] | b[9] << 8 | b[10] << 16 | std::size_t(b[11]) << 24;
  const std::size_t start = (v1 ? 10 : 12) + len;
  if (start > b.size()) throw Error(file + ": its header is cut short");
  const std::string h(b.begin() + (v1 ? 10 : 12), b.begin() + long(start));
  auto value = [&](const std::string& key) {
    const auto at = h.find("'" + key + "'");
    if (at == std::string::npos) throw Error(file + ": no '" + key + "' in the header");
    return h.substr(h.find(':', at) + 1);
  };
  std::string descr = value("descr");
  descr = descr.substr(descr.find('\'') + 1, 3);
  const char kind = descr[1];
  const int bytes = descr[2] - '0';
  if ((kind != 'u' && kind != 'i' && kind != 'b') || (bytes != 1 && bytes != 2 && bytes != 4 && bytes != 8))
    throw Error(file + ": expected an integer or bool dtype, got '" + descr + "'");
  const bool fortran = value("fortran_order").find("True") < value("fortran_order").find_first_of(",}");
  std::string shape = value("shape");
  shape = shape.substr(shape.find('(') + 1, shape.find(')') - shape.find('(') - 1);
  std::vector<long> dims;
  for (std::size_t i = 0; i < shape.size();)
    if (std::isdigit(static_cast<unsigned char>(shape[i]))) {
      std::size_t used = 0;
      dims.push_back(std::stol(shape.substr(i), &used));
      i += used;
    } else {
      ++i;
    }
  if (dims.size() != 3) throw Error(file + ": expected a 3D array, got shape (" + shape + ")");
  const std::array<long, 3> n{dims[0], dims[1], dims[2]};
  if (double(b.size() - start) < double(n[0]) * n[1] * n[2] * bytes) throw Error(file + ": its data are cut short");
  // [i][j][k] = (x, y, z): C order has z fastest, Fortran order x fastest.
  return unpack(b.data() + start, n, fortran ? "xyz" : "zyx", bytes, kind == 'i', descr[0] == '>');
}

// A multi-page TIFF, uncompressed, 8/16/32-bit grey, strips: x along a row, y the row, z the page.
Volume read_tiff(const std::string& file) {
  const auto b = slurp(file);
  if (b.size() < 8 || !((b[0] == 'I' && b[1] == 'I') || (b[0] == 'M' && b[1] == 'M'))) throw Error(file + ": not a TIFF");
  const bool big = b[0] == 'M';
  auto u = [&](std::size_t at, int bytes) -> std::uint64_t {
    if (at + bytes > b.size()) throw Error(file + ": an offset points past the end of the file");
    return std::uint64_t(decode(b.data() + at, bytes, false, big));
  };
  if (u(2, 2) != 42) throw Error(file + ": not a classic TIFF (BigTIFF is not read)");
  Volume v;
  std::vector<std::vector<std::int64_t>> pages;
  for (std::uint64_t ifd = u(4, 4); ifd != 0; ifd = u(ifd + 2 + 12 * u(ifd, 2), 4)) {
    std::uint64_t width = 0, height = 0, bits = 8, compression = 1, samples = 1, rows_per_strip = ~0ull;
    std::vector<std::uint64_t> offsets;
    for (std::uint64_t e = 0, count = u(ifd, 2); e < count; ++e) {
      const std::size_t at = ifd + 2 + 12 * e;
      const auto tag = u(at, 2), type = u(at + 2, 2), values = u(at + 4, 4);
      const int size = type == 3 ? 2 : 4;  // SHORT or LONG (the tags read here are one or the other)
      const std::size_t data = values * size <= 4 ? at + 8 : u(at + 8, 4);
      auto item = [&](std::uint64_t k) { return u(data + k * size, size); };
      if (tag == 256) width = item(0);
      if (tag == 257) height = item(0);
      if (tag == 258) bits = item(0);
      if (tag == 259) compression = item(0);
      if (tag == 277) samples = item(0);
      if (tag == 278) rows_per_strip = item(0);
      if (tag == 273)
        for (std::uint64_t k = 0; k < values; ++k) offsets.push_back(item(k));
    }
    if (compression != 1 || samples != 1 || (bits != 8 && bits != 16 && bits != 32))
      throw Error(file + ": page " + std::to_string(pages.size()) +
                  ": expected an uncompressed grey image of 8, 16 or 32 bits (no TIFF library here)");
    if (offsets.empty()) throw Error(file + ": page " + std::to_string(pages.size()) + ": expected strips (tiles are not read)");
    if (pages.empty()) v.n = {long(width), long(height), 0};
    if (long(width) != v.n[0] || long(height) != v.n[1]) throw Error(file + ": pages of different sizes");
    const int bytes = int(bits / 8);
    rows_per_strip = std::min(rows_per_strip, height);
    std::vector<std::int64_t> page(width * height);
    for (std::uint64_t y = 0; y < height; ++y) {
      const std::uint64_t row = offsets.at(y / rows_per_strip) + (y % rows_per_strip) * width * bytes;
      u(row + width * bytes - 1, 1);  // bounds check
      for (std::uint64_t x = 0; x < width; ++x) page[y * width + x] = decode(b.data() + row + x * bytes, bytes, false, big);
    }
    pages.push_back(std::move(page));
  }
  v.n[2] = long(pages.size());
  for (auto& p : pages) v.label.insert(v.label.end(), p.begin(), p.end());
  return v;
}

[[noreturn]] void usage(const std::string& why) {
  std::fprintf(stderr,
               "voxel_lbm: %s\n"
               "usage: voxel_lbm IMAGE [--dimensions NX NY NZ] [--order xyz] [--pore LABEL]... [--crop X0 Y0 Z0 X1 Y1 Z1]\n"
               "                 [--axis x|y|z] [--sleeve N] [--refine R] [--tol T] [--max-iter N] [--tau T]\n"
               "                 [--voxel-size S] [--json] [--progress] [--dry-run]\n"
               "IMAGE: raw uint8 (needs --dimensions), .npy, or uncompressed .tif/.tiff stack\n",
               why.c_str());
  std::exit(2);
}

// Whether the fluid (6-connected, inside the crop, closed on the other two axes) joins the inlet
// face to the outlet face of `axis` (face_to_face), and whether it still does when the outlet face
// meets the inlet face as in the periodic box (winds: a path that goes round the periodic axis,
// found by a voxel reached at two unwrapped positions along the axis).
struct Percolation {
  bool face_to_face = false, winds = false;
};

Percolation percolation(const lbmref::Voxels& v, int axis) {
  const long n[3] = {v.nx, v.ny, v.nz};
  const long unseen = std::numeric_limits<long>::min();
  Percolation result;
  for (bool periodic : {false, true}) {
    std::vector<long> at(v.solid.size(), unseen);  // unwrapped coordinate along axis
    std::vector<long> stack;
    for (long start = 0; start < long(v.solid.size()); ++start) {
      const long s0[3] = {start % n[0], start / n[0] % n[1], start / (n[0] * n[1])};
      if (v.solid[std::size_t(start)] || at[std::size_t(start)] != unseen || (!periodic && s0[axis] != 0)) continue;
      at[std::size_t(start)] = s0[axis];
      stack.push_back(start);
      while (!stack.empty()) {
        const long i = stack.back();
        stack.pop_back();
        long p[3] = {i % n[0], i / n[0] % n[1], i / (n[0] * n[1])};
        if (!periodic && p[axis] == n[axis] - 1) result.face_to_face = true;
        for (int d = 0; d < 3; ++d)
          for (int s : {-1, 1}) {
            const long saved = p[d];
            p[d] += s;
            const bool wrap = periodic && d == axis && (p[d] < 0 || p[d] >= n[d]);
            if (wrap) p[d] = (p[d] + n[d]) % n[d];
            if (p[d] >= 0 && p[d] < n[d]) {
              const long j = p[0] + n[0] * (p[1] + n[1] * p[2]);
              const long unwrapped = at[std::size_t(i)] + (d == axis ? s : 0);
              if (!v.solid[std::size_t(j)]) {
                if (at[std::size_t(j)] == unseen) at[std::size_t(j)] = unwrapped, stack.push_back(j);
                else if (at[std::size_t(j)] != unwrapped) result.winds = true;
              }
            }
            p[d] = saved;
          }
      }
    }
  }
  return result;
}

}  // namespace

int main(int argc, char** argv) {
  std::string file, order = "xyz";
  std::array<long, 3> dims{0, 0, 0};
  std::array<long, 6> crop{0, 0, 0, 0, 0, 0};
  bool has_crop = false, json = false, progress = false, dry = false;
  std::set<std::int64_t> pore;
  int sleeve = 0;
  double voxel_size = 0;
  lbmref::Options o;
  const std::vector<std::string> args(argv + 1, argv + argc);
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    auto next = [&](const char* what) -> const std::string& {
      if (i + 1 >= args.size()) usage(a + " expects " + what);
      return args[++i];
    };
    auto number = [&](const char* what) {
      const std::string& s = next(what);
      char* end = nullptr;
      const double x = std::strtod(s.c_str(), &end);
      if (end == s.c_str() || *end) usage(a + " expects " + what + ", got '" + s + "'");
      return x;
    };
    if (a == "--dimensions")
      for (auto& d : dims) d = long(number("three voxel counts"));
    else if (a == "--order") order = next("an axis order such as xyz or zyx");
    else if (a == "--pore") pore.insert(std::int64_t(number("a label")));
    else if (a == "--crop") {
      for (auto& c : crop) c = long(number("six voxel indices"));
      has_crop = true;
    } else if (a == "--axis") {
      const std::string& s = next("x, y or z");
      if (s != "x" && s != "y" && s != "z") usage("--axis expects x, y or z, got '" + s + "'");
      o.axis = s[0] - 'x';
    } else if (a == "--sleeve") sleeve = int(number("a voxel count"));
    else if (a == "--refine") o.refine = int(number("an integer >= 1"));
    else if (a == "--tol") o.tolerance = number("a relative tolerance");
    else if (a == "--max-iter") o.max_iterations = long(number("an iteration count"));
    else if (a == "--tau") o.tau_plus = number("a relaxation time > 1/2");
    else if (a == "--voxel-size") voxel_size = number("metres");
    else if (a == "--json") json = true;
    else if (a == "--progress") progress = true;
    else if (a == "--dry-run") dry = true;
    else if (a.rfind("--", 0) == 0) usage("unknown option " + a);
    else if (file.empty()) file = a;
    else usage("more than one image: " + file + ", " + a);
  }
  if (file.empty()) usage("no image given");
  std::string sorted = order;
  std::sort(sorted.begin(), sorted.end());
  if (sorted != "xyz") usage("--order expects a permutation of xyz, got '" + order + "'");
  if (o.refine < 1 || sleeve < 0 || o.tau_plus <= 0.5) usage("expected --refine >= 1, --sleeve >= 0, --tau > 0.5");
  if (pore.empty()) pore.insert(0);
  try {
    const auto t0 = std::chrono::steady_clock::now();
    const std::string ext = file.substr(file.find_last_of('.') == std::string::npos ? file.size() : file.find_last_of('.'));
    Volume vol;
    if (ext == ".npy") vol = read_npy(file);
    else if (ext == ".tif" || ext == ".tiff") vol = read_tiff(file);
    else if (dims[0] < 1 || dims[1] < 1 || dims[2] < 1) usage("a raw image needs --dimensions NX NY NZ");
    else vol = read_raw(file, dims, order);
    if (!has_crop) crop = {0, 0, 0, vol.n[0], vol.n[1], vol.n[2]};
    for (int d = 0; d < 3; ++d)
      if (crop[d] < 0 || crop[d + 3] > vol.n[d] || crop[d] >= crop[d + 3])
        throw Error("--crop: expected 0 <= lower < upper <= the image's size (" + std::to_string(vol.n[0]) + " " +
                    std::to_string(vol.n[1]) + " " + std::to_string(vol.n[2]) + ") on each axis");
    // The crop, then `sleeve` solid voxels on the four faces normal to the other two axes.
    const long c[3] = {crop[3] - crop[0], crop[4] - crop[1], crop[5] - crop[2]};
    long pad[3] = {sleeve, sleeve, sleeve};
    pad[o.axis] = 0;
    lbmref::Voxels cropped{int(c[0]), int(c[1]), int(c[2]), {}}, box{int(c[0] + 2 * pad[0]), int(c[1] + 2 * pad[1]), int(c[2] + 2 * pad[2]), {}};
    cropped.solid.resize(std::size_t(c[0] * c[1] * c[2]));
    box.solid.assign(std::size_t(box.nx) * box.ny * box.nz, 1);
    long fluid = 0;
    for (long z = 0; z < c[2]; ++z)
      for (long y = 0; y < c[1]; ++y)
        for (long x = 0; x < c[0]; ++x) {
          const auto label = vol.label[std::size_t(x + crop[0] + vol.n[0] * (y + crop[1] + vol.n[1] * (z + crop[2])))];
          const std::uint8_t s = pore.count(label) ? 0 : 1;
          fluid += !s;
          cropped.solid[std::size_t(x + c[0] * (y + c[1] * z))] = s;
          box.solid[std::size_t(x + pad[0] + box.nx * (y + pad[1] + long(box.ny) * (z + pad[2])))] = s;
        }
    vol = Volume();
    const double porosity = double(fluid) / double(cropped.solid.size());
    const Percolation connected = percolation(cropped, o.axis);
    // The crop's cross-section (sleeve excluded) over the box's: poresph's superficial velocity.
    const double area_ratio = double(box.nx) * box.ny * box.nz / (double(c[0]) * c[1] * c[2]);
    lbmref::Result r;
    if (!dry) {
      if (progress)
        o.progress = [](long it, double k, double change) {
          if (it % 1000 == 0) std::fprintf(stderr, "  iteration %ld  K %.6e voxel^2 (box)  change %.2e\n", it, k, change);
        };
      r = lbmref::solve(box, o);
    }
    const double k_crop = r.permeability * area_ratio;
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const char* axes = "xyz";
    if (json) {
      char m2[32] = "null";
      if (voxel_size > 0) std::snprintf(m2, sizeof m2, "%.6e", k_crop * voxel_size * voxel_size);
      std::printf("{\"image\": \"%s\", \"crop\": [%ld, %ld, %ld, %ld, %ld, %ld], \"axis\": \"%c\", \"sleeve\": %d, "
                  "\"refine\": %d, \"porosity\": %.6f, \"percolates\": %s, \"percolates_periodic\": %s, \"permeability_voxel2\": %.8e, "
                  "\"permeability_box_voxel2\": %.8e, \"permeability_m2\": %s, \"iterations\": %ld, \"change\": %.3e, "
                  "\"converged\": %s, \"tau_plus\": %g, \"max_mach\": %.3e, \"fluid_nodes\": %ld, \"mlups\": %.2f, "
                  "\"threads\": %d, \"seconds\": %.2f}\n",
                  file.c_str(), crop[0], crop[1], crop[2], crop[3], crop[4], crop[5], axes[o.axis], sleeve, o.refine, porosity,
                  connected.face_to_face ? "true" : "false", connected.winds ? "true" : "false", k_crop, r.permeability,
                  m2, r.iterations, r.change,
                  r.converged ? "true" : "false", o.tau_plus, r.max_mach, r.fluid_nodes, r.mlups, omp_get_max_threads(), wall);
    } else {
      std::printf("image %s, crop [%ld %ld %ld]-[%ld %ld %ld], flow along %c, sleeve %d, refinement %d\n", file.c_str(),
                  crop[0], crop[1], crop[2], crop[3], crop[4], crop[5], axes[o.axis], sleeve, o.refine);
      std::printf("porosity %.6f (crop); pore space (6-connected) %s face to face along %c, %s through the periodic join\n",
                  porosity, connected.face_to_face ? "percolates" : "does NOT percolate", axes[o.axis],
                  connected.winds ? "percolates" : "does NOT percolate");
      if (!dry) {
        std::printf("K %.6e voxel^2 (superficial velocity over the crop's cross-section; %.6e over the box's)\n", k_crop,
                    r.permeability);
        if (voxel_size > 0) std::printf("K %.6e m^2 (voxel %g m)\n", k_crop * voxel_size * voxel_size, voxel_size);
        std::printf("%s after %ld iterations (relative change %.2e over %d), max Mach %.2e, %ld fluid nodes, %.1f MLUPS "
                    "on %d threads, wall %.2f s\n",
                    r.converged ? "converged" : "NOT converged", r.iterations, r.change, o.check_interval, r.max_mach,
                    r.fluid_nodes, r.mlups, omp_get_max_threads(), wall);
      }
    }
    return dry || r.converged ? 0 : 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "voxel_lbm: %s\n", e.what());
    return 2;
  }
}
