#pragma once
// Small per-particle passes the simulation orders (engine/simulation.hpp): sort keys, counts,
// the walls' initial state, and the vector updates of the implicit viscous step.
#include <cstdint>

#include "fluid/material.hpp"
#include "neighbours/cell_grid.hpp"
#include "neighbours/neighbour_list.hpp"
#include "state/particles.hpp"

namespace psph {

// Sort key: two buckets per cell, fluid particles first (neighbours/cell_grid.hpp).
template <int D>
struct CellKeyPass {
  CellGrid<D> grid;
  const Vec<D>* x;
  const std::uint8_t* material;
  MaterialTable<D> mats;
  int* key;
  PSPH_HD void operator()(int i) const { key[i] = 2 * grid.cell_of(x[i]) + (mats.is_fluid(material[i]) ? 0 : 1); }
};

// Neighbours within the support radius of a fluid particle (0 for others).
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

template <int D>
struct SetWallRestDensity {
  ParticleView<D> s;
  MaterialTable<D> mats;
  PSPH_HD void operator()(int i) const {
    if (!mats.is_fluid(s.material[i])) {
      s.rho0[i] = s.rho[i];
      s.p[i] = mats[s.material[i]].background_pressure;
    }
  }
};

// out = a - b on freely moving fluid particles, 0 on walls and open-boundary buffers (the rows of
// the implicit viscous system).
template <int D>
struct FluidDifference {
  Vec<D>* out;
  const Vec<D>* a;
  const Vec<D>* b;
  ParticleView<D> s;
  MaterialTable<D> mats;
  PSPH_HD void operator()(int i) const {
    out[i] = mats.moves_freely(s.material[i], s.x[i]) ? a[i] - b[i] : Vec<D>::zero();
  }
};
template <int D>
struct SetFluidVelocity {
  const Vec<D>* from;
  ParticleView<D> s;
  MaterialTable<D> mats;
  PSPH_HD void operator()(int i) const {
    if (mats.moves_freely(s.material[i], s.x[i])) s.v[i] = from[i];
  }
};

}  // namespace psph
