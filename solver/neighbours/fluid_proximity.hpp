#pragma once
// Which particles have a fluid particle in their neighbourhood. Wall particles far from any fluid
// keep their density and pressure and present nothing to the fluid, so the wall passes skip them:
// in the 3D dam break, 56,560 wall particles against 8,000 water particles, this removes ~85 % of
// the continuity pass.
#include <cstdint>

#include "neighbours/cell_grid.hpp"

namespace psph {

// near[i] = 1 when a fluid particle lies within the list radius of i: a function of i's own
// neighbourhood, hence the same whichever process holds i and whatever lies beyond its halo (a flag
// per cell would look two cells away). A wall farther than the list radius from every fluid
// particle cannot come within the support before the lists expire.
template <int D>
struct NearFluid {
  NeighbourView<D> nb;
  std::uint8_t* near;
  PSPH_HD void operator()(int i) const {
    const Vec<D> xi = nb.x[i];
    bool found = false;
    nb.for_each_cell_in_reach(xi, [&](int key) {
      for (int j = nb.bucket_start[2 * key]; !found && j < nb.bucket_end[2 * key]; ++j)
        found = norm2(nb.grid.separation(xi, nb.x[j])) < nb.support2;
    });
    near[i] = found ? 1 : 0;
  }
};

}  // namespace psph
