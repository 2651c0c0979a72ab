#pragma once
// A cell list built on the host for a fixed set of points (operator checks, unit tests). Points are
// stored in cell order; `order[k]` is the input index of stored point k.
#include <vector>

#include "backend/cpu_backend.hpp"
#include "neighbours/cell_grid.hpp"

namespace psph {

template <int D>
struct HostNeighbours {
  CellGrid<D> grid{};
  std::vector<Vec<D>> x;
  std::vector<int> order, cell_start, cell_end;
  Real support = 0;

  HostNeighbours(const std::vector<Vec<D>>& points, const Real* lo, const Real* hi, const bool* periodic,
                 Real support_radius)
      : support(support_radius) {
    CellGrid<D>::make(lo, hi, periodic, support_radius, grid);
    const int n = static_cast<int>(points.size());
    std::vector<int> keys(n);
    for (int i = 0; i < n; ++i) keys[i] = grid.cell_of(points[i]);
    order.resize(n), cell_start.resize(grid.total), cell_end.resize(grid.total);
    CpuBackend::sort_by_cell(keys.data(), n, grid.total, order.data(), cell_start.data(), cell_end.data());
    x.resize(n);
    for (int k = 0; k < n; ++k) x[k] = points[order[k]];
  }
  NeighbourView<D> view() const {
    return NeighbourView<D>{grid, x.data(), cell_start.data(), cell_end.data(), support * support};
  }
};

}  // namespace psph
