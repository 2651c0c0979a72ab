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
  std::vector<Point<D>> x;
  std::vector<int> order, bucket_start, bucket_end;
  Coord support = 0;

  HostNeighbours(const std::vector<Point<D>>& points, const Coord* lo, const Coord* hi, const bool* periodic,
                 Coord support_radius)
      : support(support_radius) {
    CellGrid<D>::make(lo, hi, periodic, support_radius, grid);
    const int n = static_cast<int>(points.size());
    std::vector<int> keys(n);
    for (int i = 0; i < n; ++i) keys[i] = 2 * grid.cell_of(points[i]);  // every point in a "fluid" bucket
    order.resize(n), bucket_start.resize(2 * grid.total), bucket_end.resize(2 * grid.total);
    CpuBackend::sort_by_cell(keys.data(), n, 2 * grid.total, order.data(), bucket_start.data(), bucket_end.data());
    x.resize(n);
    for (int k = 0; k < n; ++k) x[k] = points[order[k]];
  }
  NeighbourView<D> view() const {
    return NeighbourView<D>{grid, x.data(), bucket_start.data(), bucket_end.data(), Real(support * support)};
  }
};

}  // namespace psph
