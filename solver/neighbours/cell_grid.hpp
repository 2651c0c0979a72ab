#pragma once
// Uniform cell grid for the cell-linked neighbour list. Cells are at least one support radius wide,
// so a particle's neighbours lie in its own cell and the 3^D cells around it. Periodic axes wrap
// (minimum image); they need at least 3 cells so that the 3 visited cells are distinct.
#include <cmath>

#include "core/vec.hpp"

namespace psph {

template <int D>
struct CellGrid {
  Coord lower[D];
  Coord length[D];     // domain length per axis (the period on periodic axes)
  Coord inv_cell[D];   // 1 / cell width
  int ncell[D];
  bool periodic[D];
  int total = 1;

  // Build the grid for a box [lo, hi] and a support radius. Returns false when a periodic axis is
  // shorter than 3 support radii (the caller reports that as a case-file error).
  static bool make(const Coord* lo, const Coord* hi, const bool* per, Coord support, CellGrid& g) {
    g.total = 1;
    bool ok = true;
    for (int k = 0; k < D; ++k) {
      g.lower[k] = lo[k];
      g.length[k] = hi[k] - lo[k];
      g.periodic[k] = per[k];
      int n = static_cast<int>(std::floor(g.length[k] / support));
      if (n < 1) n = 1;
      if (per[k] && n < 3) ok = false;
      g.ncell[k] = n;
      g.inv_cell[k] = Coord(n) / g.length[k];
      g.total *= n;
    }
    return ok;
  }

  PSPH_HD int axis_cell(int k, Coord x) const {
    int c = static_cast<int>(floor((x - lower[k]) * inv_cell[k]));
    return c < 0 ? 0 : (c >= ncell[k] ? ncell[k] - 1 : c);
  }

  PSPH_HD int cell_of(const Point<D>& x) const {
    int key = 0;
    for (int k = D - 1; k >= 0; --k) key = key * ncell[k] + axis_cell(k, x[k]);
    return key;
  }

  // x_i - x_j with the minimum-image convention on periodic axes, in Coord.
  PSPH_HD PSPH_PAIR Point<D> offset(const Point<D>& xi, const Point<D>& xj) const {
    Point<D> d = xi - xj;
    for (int k = 0; k < D; ++k)
      if (periodic[k]) {
        if (d[k] > Coord(0.5) * length[k]) d[k] -= length[k];
        else if (d[k] < Coord(-0.5) * length[k]) d[k] += length[k];
      }
    return d;
  }
  // The same handed to the pair code: the one place where positions become Real (a difference of
  // neighbours keeps its digits; the positions themselves would not, far from the origin).
  PSPH_HD PSPH_PAIR Vec<D> separation(const Point<D>& xi, const Point<D>& xj) const { return to_real(offset(xi, xj)); }

  // Wraps a position back into the box on periodic axes.
  PSPH_HD Point<D> wrap(Point<D> x) const {
    for (int k = 0; k < D; ++k)
      if (periodic[k]) {
        if (x[k] < lower[k]) x[k] += length[k];
        else if (x[k] >= lower[k] + length[k]) x[k] -= length[k];
      }
    return x;
  }

  PSPH_HD bool inside(const Point<D>& x) const {
    for (int k = 0; k < D; ++k)
      if (!periodic[k] && !(x[k] >= lower[k] && x[k] <= lower[k] + length[k])) return false;
    return true;
  }
};

// Read-only view of the sorted cell list. Particles are stored in cell order and, within a cell,
// fluid particles first: bucket 2c holds the fluid particles of cell c and bucket 2c+1 the others
// (walls), each as [bucket_start, bucket_end). Passes that only need fluid neighbours (wall
// boundary conditions) then never visit wall-wall candidates.
template <int D>
struct NeighbourView {
  CellGrid<D> grid;
  const Point<D>* x;
  const int* bucket_start;
  const int* bucket_end;
  Real support2;

  PSPH_HD bool cell_has_fluid(int key) const { return bucket_end[2 * key] > bucket_start[2 * key]; }

  // Calls f(key) for each distinct cell of the 3^D stencil around position xi.
  template <class F>
  PSPH_HD void for_each_cell(const Point<D>& xi, F&& f) const {
    for_each_stencil_cell(xi, [&](int, int key) { f(key); });
  }
  // The same with the stencil index s (offset (s % 3 - 1) on the first axis, and so on).
  template <class F>
  PSPH_HD void for_each_stencil_cell(const Point<D>& xi, F&& f) const {
    int ci[D];
    for (int k = 0; k < D; ++k) ci[k] = grid.axis_cell(k, xi[k]);
    constexpr int nstencil = D == 1 ? 3 : D == 2 ? 9 : 27;
    for (int s = 0; s < nstencil; ++s) {
      int key = 0, rem = s;
      bool skip = false;
      int off[D];
      for (int k = 0; k < D; ++k) { off[k] = rem % 3 - 1; rem /= 3; }
      for (int k = D - 1; k >= 0; --k) {
        int c = ci[k] + off[k];
        if (c < 0 || c >= grid.ncell[k]) {
          if (!grid.periodic[k]) { skip = true; break; }
          c = c < 0 ? c + grid.ncell[k] : c - grid.ncell[k];
        }
        key = key * grid.ncell[k] + c;
      }
      if (!skip) f(s, key);
    }
  }

  // Calls f(key) for the stencil cells around xi that may hold a point within the radius
  // (sqrt(support2)): a cell whose nearest face is farther from xi is skipped. With cells one radius
  // wide that skips about a quarter of the 27 cells in 3D (each corner cell is in reach with
  // probability pi/6, each edge cell pi/4) and leaves the visiting order, hence every sum, unchanged.
  template <class F>
  PSPH_HD void for_each_cell_in_reach(const Point<D>& xi, F&& f) const {
    Real below[D], above[D];  // squared gaps from xi to its cell's lower and upper faces
    for (int k = 0; k < D; ++k) {
      const Coord width = Coord(1) / grid.inv_cell[k];
      const Coord face = grid.lower[k] + Coord(grid.axis_cell(k, xi[k])) * width;
      const Real lo = Real(xi[k] - face), hi = Real(face + width - xi[k]);
      below[k] = lo > Real(0) ? lo * lo : Real(0);
      above[k] = hi > Real(0) ? hi * hi : Real(0);
    }
    const Real reach2 = support2 * Real(1.000001);  // a margin for the faces' rounding: never skip a neighbour
    for_each_stencil_cell(xi, [&](int s, int key) {
      Real gap2 = 0;
      for (int k = 0; k < D; ++k, s /= 3) gap2 += s % 3 == 0 ? below[k] : s % 3 == 2 ? above[k] : Real(0);
      if (gap2 < reach2) f(key);
    });
  }

  // Calls f(j, x_i - x_j, r) for every particle j != i with r < support (gather order is fixed by
  // the cell order, so sums are reproducible).
  template <class F>
  PSPH_HD void for_each(int i, F&& f) const {
    visit(i, 0, 2, f);
  }
  // The same over fluid neighbours only, and over the others only.
  template <class F>
  PSPH_HD void for_each_fluid(int i, F&& f) const {
    visit(i, 0, 1, f);
  }
  template <class F>
  PSPH_HD void for_each_non_fluid(int i, F&& f) const {
    visit(i, 1, 2, f);
  }

  // Calls f(j, p - x_j, r) for every fluid particle j within the list radius of a point p (callers
  // weigh by the kernel, zero beyond the support). The cells must be current to within half the
  // lists' skin, as for the particles' own lists.
  template <class F>
  PSPH_HD void for_each_fluid_near(const Point<D>& p, F&& f) const {
    for_each_cell_in_reach(p, [&](int key) {
      const int end = bucket_end[2 * key];
      for (int j = bucket_start[2 * key]; j < end; ++j) {
        const Vec<D> d = grid.separation(p, x[j]);
        const Real r2 = norm2(d);
        if (r2 < support2) f(j, d, sqrt(r2));
      }
    });
  }

 private:
  template <class F>
  PSPH_HD void visit(int i, int first, int last, F& f) const {
    const Point<D> xi = x[i];
    for_each_cell_in_reach(xi, [&](int key) {
      for (int b = 2 * key + first; b < 2 * key + last; ++b) {
        const int end = bucket_end[b];
        for (int j = bucket_start[b]; j < end; ++j) {
          if (j == i) continue;
          const Vec<D> d = grid.separation(xi, x[j]);
          const Real r2 = norm2(d);
          if (r2 < support2) f(j, d, sqrt(r2));
        }
      }
    });
  }
};

}  // namespace psph
