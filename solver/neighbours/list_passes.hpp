#pragma once
// Small per-particle passes of the neighbour stage (neighbours/neighbour_stage.hpp): sort keys and
// neighbour counts.
#include <cstdint>

#include "core/material.hpp"
#include "neighbours/cell_grid.hpp"
#include "neighbours/neighbour_list.hpp"

namespace psph {

// Sort key: two buckets per cell, fluid particles first (neighbours/cell_grid.hpp).
template <int D>
struct CellKeyPass {
  CellGrid<D> grid;
  const Point<D>* x;
  const std::uint8_t* material;
  MaterialTable<D> mats;
  int* key;
  PSPH_HD void operator()(int i) const { key[i] = 2 * grid.cell_of(x[i]) + (mats.is_fluid(material[i]) ? 0 : 1); }
};

// Neighbours within the support radius of a fluid or solid particle (0 for walls).
template <int D>
struct NeighbourCount {
  NeighbourList<D> nb;
  const std::uint8_t* material;
  MaterialTable<D> mats;
  PSPH_HD Real operator()(int i) const {
    if (!mats.is_dynamic(material[i])) return Real(0);
    int n = 0;
    nb.for_each(i, [&](int, const Vec<D>&, Real) { ++n; });
    return Real(n);
  }
};
template <int D>
struct IsDynamic {
  const std::uint8_t* material;
  MaterialTable<D> mats;
  PSPH_HD Real operator()(int i) const { return mats.is_dynamic(material[i]) ? Real(1) : Real(0); }
};

}  // namespace psph
