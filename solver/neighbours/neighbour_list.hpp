#pragma once
// Verlet neighbour lists built from the cell list with a radius R (1 + skin) and kept until some
// particle has moved by half the skin. The cell search tests the cells of the 27 in reach (~21 of
// them, ~20 R^3 of space for a 4/3 pi R^3 sphere: ~20 % of the candidates are neighbours); the
// passes then visit only listed pairs, each still tested against R. Fluid neighbours come first
// in each list, so wall passes can stop after them.
// Layout: neighbour k of particle i is at i * stride_i + k * stride_k: row-major on the CPU,
// column-major on the GPU (coalesced loads across a warp). Offsets are 64-bit: capacity x count
// passes 2^31 near 50 million particles, below what one GPU holds.
#include <cstdint>

#include "core/damage_ghost.hpp"
#include "core/material.hpp"
#include "neighbours/cell_grid.hpp"

namespace psph {

using ListOffset = std::int64_t;

template <int D>
struct NeighbourList {
  CellGrid<D> grid;
  const Point<D>* x;
  const int* index;
  const int* count;        // neighbours of i
  const int* fluid_count;  // of which fluid (listed first)
  ListOffset stride_i, stride_k;
  Real support2;           // R^2: listed pairs beyond the support are skipped

  template <class F>
  PSPH_HD PSPH_PAIR void for_each(int i, F&& f) const {
    visit(i, 0, count[i], f);
  }
  template <class F>
  PSPH_HD PSPH_PAIR void for_each_fluid(int i, F&& f) const {
    visit(i, 0, fluid_count[i], f);
  }
  PSPH_HD bool lists_non_fluid(int i) const { return count[i] > fluid_count[i]; }

 private:
  template <class F>
  PSPH_HD PSPH_PAIR void visit(int i, int begin, int end, F& f) const {
    const Point<D> xi = x[i];
    const int* row = index + ListOffset(i) * stride_i;
    for (int k = begin; k < end; ++k) {
      const int j = row[ListOffset(k) * stride_k];
      const Vec<D> d = grid.separation(xi, x[j]);
      const Real r2 = norm2(d);
      if (r2 < support2) f(j, d, sqrt(r2));
    }
  }
};

// Fills the lists from the cell list; count[i] may exceed capacity, in which case the caller
// grows the capacity and builds again. Walls need no list far from the fluid, and near it only
// their fluid neighbours unless `walls_need_walls` (wall density by summation). Without fluids
// (`no_fluid`: walls only clamp elastic solids) every wall lists all its neighbours, and so does a
// clamp wall (`mirror` >= 0, solid/clamp.hpp) in any case: its partner takes a reaction through
// its elastic neighbours. A retired damage ghost (core/damage_ghost.hpp) lists none and is listed by none.
template <int D>
struct BuildNeighbourList {
  NeighbourView<D> cells;
  const std::uint8_t* material;
  MaterialTable<D> mats;
  const std::uint8_t* near_fluid;  // per particle (neighbours/fluid_proximity.hpp)
  const std::int32_t* mirror;      // clamp partners (null without elastic solids and walls)
  const std::uint8_t* ghost;       // damage ghosts (null without them)
  bool walls_need_walls;
  bool no_fluid;
  int* index;
  int* count;
  int* fluid_count;
  int capacity;
  ListOffset stride_i, stride_k;
  PSPH_HD void operator()(int i) const {
    if (is_retired_ghost(ghost, i)) {
      count[i] = fluid_count[i] = 0;
      return;
    }
    int* row = index + ListOffset(i) * stride_i;
    const bool full = no_fluid || mats.is_dynamic(material[i]) || (mirror && mirror[i] >= 0);
    int n = full || near_fluid[i] ? collect(i, 0, 0, row) : 0;
    fluid_count[i] = n;
    if (full || (near_fluid[i] && walls_need_walls)) n = collect(i, 1, n, row);
    count[i] = n;
  }

 private:
  // Appends the particles of bucket `b` (0 fluid, 1 the others) of each cell in reach that lie
  // within the list radius; returns the new count (entries past `capacity` are counted, not
  // written). On the CPU the candidate loop does not branch on the distance: most candidates are
  // rejected, unpredictably, and without that branch the 3D dam break's build takes a quarter less
  // time. On the GPU only kept pairs are written (not measured there yet).
  PSPH_HD int collect(int i, int b, int n, int* row) const {
    const Point<D> xi = cells.x[i];
    const Point<D>* x = cells.x;
    const Coord radius2 = cells.support2;  // the test in Coord: no conversion per candidate
    const int room = capacity;
    const ListOffset step = stride_k;
    const std::uint8_t* ghosts = ghost;
    cells.for_each_cell_in_reach(xi, [&](int key) {
      const int end = cells.bucket_end[2 * key + b];
      for (int j = cells.bucket_start[2 * key + b]; j < end; ++j) {
        const int in = int(norm2(cells.grid.offset(xi, x[j])) < radius2) & int(j != i) &
                       int(!is_retired_ghost(ghosts, j));
#ifdef __CUDA_ARCH__
        if (in && n < room) row[ListOffset(n) * step] = j;  // a warp diverges; global writes cost more
#else
        if (n < room) row[ListOffset(n) * step] = j;  // kept only where `in`
#endif
        n += in;
      }
    });
    return n;
  }
};

// Distance moved since the lists were built (minimum image on periodic axes).
template <int D>
struct DisplacementSinceBuild {
  CellGrid<D> grid;
  const Point<D>* x;
  const Point<D>* x_build;
  PSPH_HD Real operator()(int i) const { return Real(norm(grid.offset(x[i], x_build[i]))); }
};

template <int D>
struct ListCount {
  const int* count;
  PSPH_HD int operator()(int i) const { return count[i]; }
};

}  // namespace psph
