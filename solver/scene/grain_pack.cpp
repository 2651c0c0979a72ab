#include "scene/grain_pack.hpp"

#include "scene/shape.hpp"

#include <cmath>
#include <random>
#include <stdexcept>
#include <string>

namespace psph {
namespace {

// Uniform in [0, 1) from 53 random bits: the same sequence with every standard library.
double unit(std::mt19937_64& rng) { return double(rng() >> 11) * 0x1.0p-53; }

bool in_box(const GrainPackSpec& s, const double* x, int D) {
  for (int k = 0; k < D; ++k)
    if (x[k] < s.lower[k] || x[k] > s.upper[k]) return false;
  return true;
}

// Fraction of a grain inside the box, by a fixed-point quadrature on its bounding cube.
double inside_fraction(const GrainPackSpec& s, const Grain& g, int D) {
  const int n = 24;
  long in = 0, all = 0;
  int idx[3] = {0, 0, 0};
  for (;;) {
    double x[3], r2 = 0;
    for (int k = 0; k < D; ++k) {
      x[k] = g.centre[k] + g.radius * (-1 + (2 * idx[k] + 1.0) / n);
      r2 += (x[k] - g.centre[k]) * (x[k] - g.centre[k]);
    }
    if (r2 <= g.radius * g.radius) ++all, in += in_box(s, x, D);
    int k = 0;
    while (k < D && ++idx[k] >= n) idx[k++] = 0;
    if (k == D) break;
  }
  return all ? double(in) / all : 0.0;
}

}  // namespace

GrainPack generate_grain_pack(const GrainPackSpec& s, int D) {
  double box = 1;
  for (int k = 0; k < D; ++k) box *= s.upper[k] - s.lower[k];
  const double unit_ball = unit_ball_volume(D);
  std::mt19937_64 rng(s.seed);
  GrainPack pack;
  double solid = 0;
  const long max_attempts = 200000;
  for (long attempt = 0; attempt < max_attempts && solid < s.solid_fraction * box; ++attempt) {
    Grain g;
    for (int k = 0; k < D; ++k) g.centre[k] = s.lower[k] + unit(rng) * (s.upper[k] - s.lower[k]);
    g.radius = s.grain_radius * (1 + s.radius_spread * (2 * unit(rng) - 1));
    bool free = true;
    for (const Grain& o : pack.grains) {
      double d2 = 0;
      for (int k = 0; k < D; ++k) d2 += (g.centre[k] - o.centre[k]) * (g.centre[k] - o.centre[k]);
      const double reach = g.radius + o.radius + s.min_gap;
      if (d2 < reach * reach) {
        free = false;
        break;
      }
    }
    if (!free) continue;
    pack.grains.push_back(g);
    solid += unit_ball * std::pow(g.radius, D) * inside_fraction(s, g, D);
  }
  pack.solid_fraction = solid / box;
  if (solid < s.solid_fraction * box)
    throw std::invalid_argument("the grains reach a solid fraction of only " + std::to_string(pack.solid_fraction) +
                                " after " + std::to_string(max_attempts) + " placements (" +
                                std::to_string(pack.grains.size()) +
                                " grains); lower solid_fraction or min_gap, or use smaller grains");
  return pack;
}

bool in_grain_pack(const GrainPackSpec& s, const std::vector<Grain>& grains, const double* x, int D) {
  if (!in_box(s, x, D)) return false;
  for (const Grain& g : grains) {
    double r2 = 0;
    for (int k = 0; k < D; ++k) r2 += (x[k] - g.centre[k]) * (x[k] - g.centre[k]);
    if (r2 <= g.radius * g.radius) return true;
  }
  return false;
}

}  // namespace psph
