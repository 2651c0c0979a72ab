// Lattice-Boltzmann Stokes flow through a voxel image (voxel_lbm.hpp). Only the fluid nodes are
// stored (a sparse list in z, y, x order, so OpenMP's static chunks are slabs of z slices), with a
// pull table: for each node and direction, where the population it receives comes from.
#include "voxel_lbm.hpp"

#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

namespace lbmref {
namespace {

constexpr int Q = 19;
// D3Q19 velocities, each odd direction followed by its opposite (opposite(q) = q + 1 for odd q).
constexpr int C[Q][3] = {{0, 0, 0},  {1, 0, 0},  {-1, 0, 0},  {0, 1, 0},  {0, -1, 0}, {0, 0, 1},  {0, 0, -1},
                         {1, 1, 0},  {-1, -1, 0}, {1, -1, 0}, {-1, 1, 0}, {1, 0, 1},  {-1, 0, -1}, {1, 0, -1},
                         {-1, 0, 1}, {0, 1, 1},  {0, -1, -1}, {0, 1, -1}, {0, -1, 1}};
constexpr double W[Q] = {1. / 3,  1. / 18, 1. / 18, 1. / 18, 1. / 18, 1. / 18, 1. / 18, 1. / 36, 1. / 36, 1. / 36,
                         1. / 36, 1. / 36, 1. / 36, 1. / 36, 1. / 36, 1. / 36, 1. / 36, 1. / 36, 1. / 36};
constexpr int opposite(int q) { return q == 0 ? 0 : (q % 2 ? q + 1 : q - 1); }
constexpr double kMagic = 3.0 / 16.0;  // Ginzburg, Verhaeghe & d'Humieres 2008: wall halfway for any tau
constexpr double kSoundSpeed = 0.57735026918962576;  // 1/sqrt(3)
// Below this many fluid nodes a step takes microseconds and a thread team's barrier (milliseconds
// when the cores are shared) would dominate: one thread.
constexpr long kParallelNodes = 32768;

struct Lattice {
  long n = 0;                        // fluid nodes
  std::vector<std::uint32_t> pull;   // [i * 18 + q - 1]: index in f of what streams into node i along q
};

// Nodes are the refine^3 sub-cells of each fluid voxel; a voxel face lies halfway between two nodes,
// where halfway bounce-back puts the wall.
Lattice build(const Voxels& v, int r) {
  const long L[3] = {long(v.nx) * r, long(v.ny) * r, long(v.nz) * r};
  std::vector<std::int32_t> id(std::size_t(L[0] * L[1] * L[2]), -1);
  Lattice lat;
  for (long z = 0; z < L[2]; ++z)
    for (long y = 0; y < L[1]; ++y)
      for (long x = 0; x < L[0]; ++x)
        if (!v.solid[std::size_t(x / r + v.nx * (y / r + long(v.ny) * (z / r)))])
          id[std::size_t(x + L[0] * (y + L[1] * z))] = std::int32_t(lat.n++);
  if (double(lat.n) * Q >= 4294967295.0) throw std::runtime_error("too many fluid nodes for 32-bit pull indices");
  lat.pull.resize(std::size_t(lat.n) * (Q - 1));
#pragma omp parallel for schedule(static)
  for (long z = 0; z < L[2]; ++z)
    for (long y = 0; y < L[1]; ++y)
      for (long x = 0; x < L[0]; ++x) {
        const std::int32_t i = id[std::size_t(x + L[0] * (y + L[1] * z))];
        if (i < 0) continue;
        for (int q = 1; q < Q; ++q) {
          const long p[3] = {x - C[q][0], y - C[q][1], z - C[q][2]};  // upstream node, periodic
          long at = 0;
          for (int d = 2; d >= 0; --d) at = at * L[d] + (p[d] + L[d]) % L[d];
          const std::int32_t m = id[std::size_t(at)];
          // Halfway bounce-back: from a solid neighbour comes this node's own opposite population.
          lat.pull[std::size_t(i) * (Q - 1) + q - 1] =
              m >= 0 ? std::uint32_t(q * lat.n + m) : std::uint32_t(opposite(q) * lat.n + i);
        }
      }
  return lat;
}

struct Relaxation {
  double plus, minus;  // rates omega+ (viscosity) and omega- (set by the magic parameter)
  double force[Q];     // 3 w_q c_q . g
};

// One pull-stream-collide step from fin (post-collision populations, f[q * n + i]) into fout.
// TRT collision with the Stokes (linear) equilibrium e_q = w_q (rho + 3 c_q . j): no inertia.
// Forcing: Guo, Zheng & Shi 2002 (PRE 65 046308) eq. 20 with u = j0 + g/2; for a linear equilibrium
// this is exactly "add 3 w_q c_q . g" with j0 = sum f c in the equilibrium (Ginzburg 2008's form).
// Measure: returns the sum over nodes of j0 along `axis` and the largest |j0 + g/2|^2.
template <bool Measure>
void step(const double* fin, double* fout, const Lattice& lat, const Relaxation& w, int axis, double g,
          double& sum, double& max2) {
  const long n = lat.n;
  const std::uint32_t* pull = lat.pull.data();
  double s = 0, m2 = 0;
#pragma omp parallel for schedule(static) reduction(+ : s) reduction(max : m2) if (n >= kParallelNodes)
  for (long i = 0; i < n; ++i) {
    double f[Q];
    f[0] = fin[i];
    const std::uint32_t* from = pull + std::size_t(i) * (Q - 1);
    for (int q = 1; q < Q; ++q) f[q] = fin[from[q - 1]];
    double rho = 0, j[3] = {0, 0, 0};
    for (int q = 0; q < Q; ++q) {
      rho += f[q];
      for (int d = 0; d < 3; ++d) j[d] += C[q][d] * f[q];
    }
    fout[i] = f[0] - w.plus * (f[0] - W[0] * rho);
    for (int q = 1; q < Q; q += 2) {
      const double cj = C[q][0] * j[0] + C[q][1] * j[1] + C[q][2] * j[2];
      const double dp = w.plus * (0.5 * (f[q] + f[q + 1]) - W[q] * rho);
      const double dm = w.minus * (0.5 * (f[q] - f[q + 1]) - 3 * W[q] * cj);
      fout[q * n + i] = f[q] - dp - dm + w.force[q];
      fout[(q + 1) * n + i] = f[q + 1] - dp + dm - w.force[q];
    }
    if (Measure) {
      s += j[axis];
      j[axis] += 0.5 * g;
      m2 = std::max(m2, j[0] * j[0] + j[1] * j[1] + j[2] * j[2]);
    }
  }
  sum = s;
  max2 = m2;
}

}  // namespace

Result solve(const Voxels& v, const Options& o) {
  if (v.nx < 1 || v.ny < 1 || v.nz < 1 || v.solid.size() != std::size_t(v.nx) * v.ny * v.nz)
    throw std::invalid_argument("voxel_lbm: the image's size does not match its dimensions");
  if (o.refine < 1 || o.axis < 0 || o.axis > 2 || o.tau_plus <= 0.5 || o.check_interval < 1)
    throw std::invalid_argument("voxel_lbm: expected refine >= 1, axis 0..2, tau_plus > 1/2");
  const auto start = std::chrono::steady_clock::now();
  const int r = o.refine;
  Result res;
  res.porosity = double(std::count(v.solid.begin(), v.solid.end(), 0)) / double(v.solid.size());
  const Lattice lat = build(v, r);
  res.fluid_nodes = lat.n;
  const double box_nodes = double(v.nx) * v.ny * v.nz * double(r) * r * r;

  Relaxation w;
  res.nu = (o.tau_plus - 0.5) / 3;
  const double tau_minus = 0.5 + kMagic / (o.tau_plus - 0.5);  // Lambda = (tau+ - 1/2)(tau- - 1/2)
  w.plus = 1 / o.tau_plus;
  w.minus = 1 / tau_minus;
  // Linear in g (Stokes equilibrium), so g only sets the velocity scale: u ~ g (r a)^2 / nu in a pore
  // of a voxels stays the same at any refinement (max Mach 2e-4 on Berea, <= 3e-3 on the spheres).
  const double g = o.force > 0 ? o.force : 1e-5 * res.nu / (double(r) * r);
  res.force = g;
  for (int q = 0; q < Q; ++q) w.force[q] = 3 * W[q] * C[q][o.axis] * g;

  const long n = lat.n;
  std::vector<double> a(std::size_t(n) * Q), b(a.size());
#pragma omp parallel for schedule(static)
  for (long i = 0; i < n; ++i)
    for (int q = 0; q < Q; ++q) a[std::size_t(q * n + i)] = b[std::size_t(q * n + i)] = W[q];

  // K in voxel^2: nu <u> / g in lattice units, over the whole box, divided by r^2.
  auto permeability = [&](double sum) { return res.nu * (sum + 0.5 * g * double(n)) / box_nodes / g / (double(r) * r); };
  double previous = 0, sum = 0, max2 = 0;
  long it = 0;
  int quiet = 0;  // checks in a row under the tolerance
  const auto solve_start = std::chrono::steady_clock::now();
  while (n > 0 && it < o.max_iterations) {
    const bool check = (it + 1) % o.check_interval == 0;
    if (check)
      step<true>(a.data(), b.data(), lat, w, o.axis, g, sum, max2);
    else
      step<false>(a.data(), b.data(), lat, w, o.axis, g, sum, max2);
    std::swap(a, b);
    ++it;
    if (!check) continue;
    const double k = permeability(sum);
    if (!std::isfinite(k)) break;
    res.change = std::abs(k - previous) / std::max(std::abs(k), 1e-300);
    res.permeability = k;
    res.max_mach = std::sqrt(max2) / kSoundSpeed;
    previous = k;
    if (o.progress) o.progress(it, k, res.change);
    quiet = res.change < o.tolerance ? quiet + 1 : 0;
    if (quiet == 2) {
      res.converged = true;
      break;
    }
  }
  res.iterations = it;
  const auto end = std::chrono::steady_clock::now();
  res.seconds = std::chrono::duration<double>(end - start).count();
  const double solving = std::chrono::duration<double>(end - solve_start).count();
  res.mlups = solving > 0 ? double(n) * double(it) / solving / 1e6 : 0;
  return res;
}

}  // namespace lbmref
