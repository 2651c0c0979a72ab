#pragma once
// Which particles have a fluid particle in their neighbourhood. Wall particles far from any fluid
// keep their density and pressure and present nothing to the fluid, so the wall passes skip them:
// in the 3D dam break, 56,560 wall particles against 8,000 water particles, this removes ~85 % of
// the continuity pass.
#include <cstdint>

#include "neighbours/cell_grid.hpp"

namespace psph {

// near[c] = 1 when a cell of c's stencil holds a fluid particle (computed per cell: far fewer
// cells than particles).
template <int D>
struct CellNearFluid {
  NeighbourView<D> nb;
  std::uint8_t* cell_near;
  PSPH_HD void operator()(int c) const {
    Vec<D> centre;
    int rem = c;
    for (int k = 0; k < D; ++k) {
      centre[k] = nb.grid.lower[k] + (Real(rem % nb.grid.ncell[k]) + Real(0.5)) / nb.grid.inv_cell[k];
      rem /= nb.grid.ncell[k];
    }
    std::uint8_t f = 0;
    nb.for_each_cell(centre, [&](int key) { f |= nb.cell_has_fluid(key) ? 1 : 0; });
    cell_near[c] = f;
  }
};

// near[i] = near flag of i's cell.
template <int D>
struct NearFluid {
  CellGrid<D> grid;
  const Vec<D>* x;
  const std::uint8_t* cell_near;
  std::uint8_t* near;
  PSPH_HD void operator()(int i) const { near[i] = cell_near[grid.cell_of(x[i])]; }
};

}  // namespace psph
