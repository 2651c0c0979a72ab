#include "scene/pore_grid.hpp"

#include <algorithm>
#include <cmath>
#include <deque>

namespace psph {

PoreGrid::PoreGrid(const Scene& sc) : D_(sc.dimension), h_(sc.options.spacing) {
  for (int k = 0; k < D_; ++k) {
    extent_[k] = sc.upper[k] - sc.lower[k];
    n_[k] = std::max(1, int(std::ceil(extent_[k] / h_ - 1e-9)));
    periodic_[k] = sc.periodic[k];
  }
  cell_.assign(std::size_t(n_[0]) * n_[1] * n_[2], Empty);
  for (int i = 0; i < sc.count(); ++i) {
    std::array<int, 3> c{0, 0, 0};
    for (int k = 0; k < D_; ++k) c[k] = std::clamp(int((sc.x[i * D_ + k] - sc.lower[k]) / h_), 0, n_[k] - 1);
    std::uint8_t& cell = cell_[index(c)];
    const bool fluid = sc.materials[sc.material[i]].props.kind == MaterialKind::Fluid;
    cell = fluid ? Fluid : cell == Fluid ? Fluid : Solid;  // a cell with any fluid counts as the fluid's
  }
  any_solid_ = std::count(cell_.begin(), cell_.end(), Solid) > 0;
  mark_free_surface(sc);
}

std::array<int, 3> PoreGrid::cell_of(long i) const {
  return {int(i % n_[0]), int((i / n_[0]) % n_[1]), int(i / (long(n_[0]) * n_[1]))};
}

// The cell `step` cells from c along `axis` (wrapped across a periodic side); false past a closed one.
bool PoreGrid::neighbour(std::array<int, 3> c, int axis, int step, std::array<int, 3>& out) const {
  c[axis] += step;
  if (c[axis] < 0 || c[axis] >= n_[axis]) {
    if (!periodic_[axis]) return false;
    c[axis] = (c[axis] + n_[axis]) % n_[axis];
  }
  out = c;
  return true;
}

// On cells of two spacings, so that a disordered start leaves no cell of the fluid empty.
void PoreGrid::mark_free_surface(const Scene& sc) {
  std::array<int, 3> m{1, 1, 1};
  for (int k = 0; k < D_; ++k) m[k] = std::max(1, n_[k] / 2);
  std::vector<std::uint8_t> coarse(std::size_t(m[0]) * m[1] * m[2], Empty);
  auto at = [&](const std::array<int, 3>& c) -> std::uint8_t& { return coarse[c[0] + std::size_t(m[0]) * (c[1] + std::size_t(m[1]) * c[2])]; };
  for (int i = 0; i < sc.count(); ++i) {
    std::array<int, 3> c{0, 0, 0};
    for (int k = 0; k < D_; ++k) c[k] = std::clamp(int((sc.x[i * D_ + k] - sc.lower[k]) / (extent_[k] / m[k])), 0, m[k] - 1);
    std::uint8_t& cell = at(c);
    cell = std::max<std::uint8_t>(cell, sc.materials[sc.material[i]].props.kind == MaterialKind::Fluid ? Fluid : Solid);
  }
  for (int z = 0; z < m[2]; ++z)
    for (int y = 0; y < m[1]; ++y)
      for (int x = 0; x < m[0]; ++x) {
        if (at({x, y, z}) != Fluid) continue;
        for (int k = 0; k < D_; ++k)
          for (int s : {-1, 1}) {
            std::array<int, 3> c{x, y, z};
            c[k] += s;
            if (c[k] < 0 || c[k] >= m[k]) {
              if (!periodic_[k]) continue;
              c[k] = (c[k] + m[k]) % m[k];
            }
            if (at(c) == Empty) free_surface_ = true;
          }
      }
}

// A breadth-first sweep from every solid cell that carries each cell's nearest solid cell along
// (exact enough for a width: within a cell of the Euclidean distance).
void PoreGrid::solid_distance() const {
  distance_.assign(cell_.size(), -1.f);
  if (!any_solid_) return;
  std::vector<long> seed(cell_.size(), -1);
  std::deque<long> queue;
  for (long i = 0; i < long(cell_.size()); ++i)
    if (cell_[i] == Solid) seed[i] = i, distance_[i] = 0, queue.push_back(i);
  auto dist = [&](long a, long b) {
    const std::array<int, 3> ca = cell_of(a), cb = cell_of(b);
    double s = 0;
    for (int k = 0; k < D_; ++k) {
      double d = std::abs(ca[k] - cb[k]);
      if (periodic_[k]) d = std::min(d, n_[k] - d);
      s += d * d;
    }
    return float(std::sqrt(s));
  };
  while (!queue.empty()) {
    const long i = queue.front();
    queue.pop_front();
    const std::array<int, 3> c = cell_of(i);
    for (int k = 0; k < D_; ++k)
      for (int s : {-1, 1}) {
        std::array<int, 3> nb;
        if (!neighbour(c, k, s, nb)) continue;
        const long j = index(nb);
        if (cell_[j] == Solid) continue;
        const float d = dist(j, seed[i]);
        if (distance_[j] >= 0 && distance_[j] <= d) continue;
        distance_[j] = d, seed[j] = seed[i];
        queue.push_back(j);
      }
  }
}

std::vector<double> PoreGrid::section_cells(int k) const {
  std::vector<double> cells(n_[k], 0.0);
  for (long i = 0; i < long(cell_.size()); ++i)
    if (cell_[i] == Fluid) cells[cell_of(i)[k]] += 1;
  return cells;
}

double PoreGrid::periodic_head(int k) const {
  const std::vector<double> area = section_cells(k);
  double mean_r = 0;
  for (double a : area) {
    if (a == 0) return -1;
    mean_r += 1 / (a * a) / n_[k];
  }
  double p = 0, lo = 0, hi = 0;
  for (double a : area) {
    p += (1 - 1 / (a * a) / mean_r) * h_;
    lo = std::min(lo, p), hi = std::max(hi, p);
  }
  return hi - lo;
}

double PoreGrid::periodic_permeability(int k) const {
  const std::vector<double> area = section_cells(k);
  double fluid = 0;
  for (double a : area) fluid += a;
  const double cell_area = std::pow(h_, D_ - 1), box = double(cell_.size()) / n_[k] * cell_area;
  double resistance = 0;  // <1 / C> over the sections
  for (double a : area) {
    if (a == 0) return 0;
    const double A = a * cell_area, C = D_ == 3 ? A * A / (8 * M_PI) : A * A * A / 12;
    resistance += 1 / C / n_[k];
  }
  const double porosity = fluid / double(cell_.size()), w = widest(k);
  return std::min(1 / (box * resistance), porosity * w * w / (D_ == 3 ? 32.0 : 12.0));
}

double PoreGrid::widest(int k) const {
  if (!any_solid_) {
    double w = 0;
    for (int j = 0; j < D_; ++j)
      if (j != k) w = std::max(w, extent_[j]);
    return w;
  }
  if (distance_.empty()) solid_distance();
  float far = 0;
  for (long i = 0; i < long(cell_.size()); ++i)
    if (cell_[i] == Fluid) far = std::max(far, distance_[i]);
  // The wall's surface lies half a spacing before its first particle, the middle of the pore half a
  // spacing past the farthest fluid particle: the two halves cancel.
  return 2 * double(far) * h_;
}

}  // namespace psph
