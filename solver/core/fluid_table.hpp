#pragma once
// The material table with what only the fluid's passes read: the body-force regions, ramped by the
// fluid stage (fluid/fluid_stage.hpp), and the open boundary's buffers (boundary/open_boundary.hpp).
// Passed by value to those passes; the others take the MaterialTable it derives from.
#include "core/material.hpp"
#include "core/open_boundary_zone.hpp"

namespace psph {

constexpr int kMaxForceRegions = 4;

// A body force on one fluid inside a box only: e.g. the gas of a reservoir that drives a
// drainage through a periodic cell (Pazdniakou 2018 §5.2).
template <int D>
struct ForceRegion {
  int material = 0;
  Point<D> lower, upper;
  Vec<D> acceleration;
};

template <int D>
struct FluidTable : MaterialTable<D> {
  int region_count = 0;
  ForceRegion<D> region[kMaxForceRegions];
  OpenBoundaryZone<D> open;  // pressure inlet and outlet buffers (boundary/open_boundary.hpp)

  // A fluid particle that the forces move: not in an open boundary's buffer (whose state is imposed).
  PSPH_HD bool moves_freely(int k, const Point<D>& x) const {
    return this->is_fluid(k) && open.zone(x) == BufferZone::None;
  }
  // Body force (m/s^2) on a particle of material k at x: the material's plus its regions'.
  PSPH_HD Vec<D> body_force_at(int k, const Point<D>& x) const {
    Vec<D> g = this->body_force[k];
    for (int r = 0; r < region_count; ++r) {
      bool in = region[r].material == k;
      for (int d = 0; d < D; ++d) in = in && x[d] >= region[r].lower[d] && x[d] < region[r].upper[d];
      if (in) g += region[r].acceleration;
    }
    return g;
  }
};

}  // namespace psph
