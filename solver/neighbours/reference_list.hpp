#pragma once
// Fixed neighbour lists of the reference configuration, for total-Lagrangian solids (Deptulski
// 2021 §2.4.1): each elastic particle's and clamp wall's solid neighbours within the support at
// t = 0, by id, in a row of its own that follows it (a registered field: reorderings, migrations
// between processes and checkpoints carry it); a pass finds them through index_of_id.
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
  const Point<D>* x0;
  const std::int32_t* index_of_id;
  const std::int32_t* ids;    // particle i's row: ids[i * capacity ...]
  const std::int32_t* count;  // per particle
  int capacity;
  Real support2;
  template <class F>
  PSPH_HD PSPH_PAIR void for_each(int i, F&& f) const {
    const Point<D> xi = x0[i];
    for (int k = 0; k < count[i]; ++k) {
      const int j = index_of_id[ids[ListOffset(i) * capacity + k]];
      const Vec<D> d = grid.separation(xi, x0[j]);
      const Real r2 = norm2(d);
      if (r2 < support2) f(j, d, sqrt(r2));
    }
  }
};

// At t = 0 (positions = reference positions), copies a solid particle's or clamp wall's
// non-fluid, non-rigid neighbours within the support from the current lists into its row; the
// count is every such neighbour, also past `capacity` (an error the stage reports); the row's
// unused places hold -1, so that a row is the same whoever recorded it.
template <int D>
struct RecordReferenceNeighbours {
  NeighbourList<D> nb;
  ParticleView<D> s;
  MaterialTable<D> mats;
  CellGrid<D> grid;
  Real support2;
  std::int32_t* ids;
  std::int32_t* count;
  int capacity;
  PSPH_HD void operator()(int i) const {
    int n = 0;
    if (mats.is_elastic(s.material[i]) || (s.mirror && s.mirror[i] >= 0))
      nb.for_each(i, [&](int j, const Vec<D>&, Real) PSPH_PAIR {
        const int mj = s.material[j];
        if (mats.is_fluid(mj) || mats.is_rigid(mj) || !(norm2(grid.separation(s.x0[i], s.x0[j])) < support2)) return;
        if (n < capacity) ids[ListOffset(i) * capacity + n] = s.id[j];
        ++n;
      });
    count[i] = n;
    for (int k = n; k < capacity; ++k) ids[ListOffset(i) * capacity + k] = -1;  // the row's rest: none
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
    std::int32_t* r = ids + ListOffset(i) * capacity;
    int n = 0;
    if (!is_retired_ghost(s.ghost, i))
      for (int k = 0; k < count[i]; ++k)
        if (const int j = s.index_of_id[r[k]]; j < 0 || !is_retired_ghost(s.ghost, j)) r[n++] = r[k];  // (j < 0: a halo copy's partner elsewhere)
    for (int k = n; k < count[i]; ++k) r[k] = -1;
    count[i] = n;
  }
};

// A run shared out over processes: the id of a particle whose reference partner is not on its
// process (beyond the halo), or -1.
template <int D>
struct MissingReferencePartner {
  const std::int32_t* id;
  const std::int32_t* index_of_id;
  const std::int32_t* ids;
  const std::int32_t* count;
  int capacity;
  PSPH_HD int operator()(int i) const {
    for (int k = 0; k < count[i]; ++k)
      if (index_of_id[ids[ListOffset(i) * capacity + k]] < 0) return id[i];
    return -1;
  }
};

// Room for a particle's reference neighbours: the points of the particles' lattice (`spacing`)
// strictly within the support, and half again for particles placed off it.
inline int reference_row_width(int dimension, double support, double spacing) {
  const int reach = int(support / spacing);
  int points = 0;
  for (int a = -reach; a <= reach; ++a)
    for (int b = dimension > 1 ? -reach : 0; b <= (dimension > 1 ? reach : 0); ++b)
      for (int c = dimension > 2 ? -reach : 0; c <= (dimension > 2 ? reach : 0); ++c)
        points += double(a * a + b * b + c * c) * spacing * spacing < support * support;
  return points + points / 2 + 4;
}

}  // namespace psph
