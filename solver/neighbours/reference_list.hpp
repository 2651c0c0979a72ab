#pragma once
// Fixed neighbour lists of the reference configuration, for total-Lagrangian solids (Deptulski
// 2021 §2.4.1): each elastic particle's and clamp wall's solid neighbours within the support at
// t = 0, kept by id for the whole run; a pass finds them after reorderings through index_of_id.
// (The small-strain solids use the current lists with the reference positions instead: their
// pairs stay listed while strains stay below the lists' skin.)
#include <cstdint>

#include "core/damage_ghost.hpp"
#include "core/material.hpp"
#include "neighbours/neighbour_list.hpp"
#include "state/particles.hpp"

namespace psph {

template <int D>
struct ReferenceNeighbours {
  CellGrid<D> grid;
  const Vec<D>* x0;
  const std::int32_t* id;
  const std::int32_t* index_of_id;
  const std::int32_t* ids;    // row id * capacity: the neighbours' ids
  const std::int32_t* count;  // per id
  int capacity;
  Real support2;
  template <class F>
  PSPH_HD PSPH_PAIR void for_each(int i, F&& f) const {
    const int row = id[i];
    const Vec<D> xi = x0[i];
    for (int k = 0; k < count[row]; ++k) {
      const int j = index_of_id[ids[ListOffset(row) * capacity + k]];
      const Vec<D> d = grid.separation(xi, x0[j]);
      const Real r2 = norm2(d);
      if (r2 < support2) f(j, d, sqrt(r2));
    }
  }
};

// At t = 0 (positions = reference positions), copies a solid particle's or clamp wall's
// non-fluid, non-rigid neighbours from the current lists into its row.
template <int D>
struct RecordReferenceNeighbours {
  NeighbourList<D> nb;
  ParticleView<D> s;
  MaterialTable<D> mats;
  std::int32_t* ids;
  std::int32_t* count;
  int capacity;
  PSPH_HD void operator()(int i) const {
    const int row = s.id[i];
    int n = 0;
    if (mats.is_elastic(s.material[i]) || (s.mirror && s.mirror[i] >= 0))
      nb.for_each(i, [&](int j, const Vec<D>&, Real) PSPH_PAIR {
        const int mj = s.material[j];
        if (!mats.is_fluid(mj) && !mats.is_rigid(mj) && n < capacity) ids[ListOffset(row) * capacity + n++] = s.id[j];
      });
    count[row] = n;
  }
};

// After each list build: the rows lose their retired damage ghosts (core/damage_ghost.hpp), the
// rest in order, and a ghost's own row empties, so that a ghost leaves the solid for good.
template <int D>
struct PruneGhostReferences {
  ParticleView<D> s;
  std::int32_t* ids;
  std::int32_t* count;
  int capacity;
  PSPH_HD void operator()(int i) const {
    const int row = s.id[i];
    std::int32_t* r = ids + ListOffset(row) * capacity;
    int n = 0;
    if (!is_retired_ghost(s.ghost, i))
      for (int k = 0; k < count[row]; ++k)
        if (!is_retired_ghost(s.ghost, s.index_of_id[r[k]])) r[n++] = r[k];
    count[row] = n;
  }
};

}  // namespace psph
