#pragma once
// A case's particles on a grid of one spacing (scene/compressibility.hpp): which cells hold fluid,
// which a wall or a solid, which nothing; the fluid's sections along an axis, its widest pore and
// whether it has a free surface.
#include <array>
#include <cstdint>
#include <vector>

#include "engine/scene.hpp"

namespace psph {

class PoreGrid {
 public:
  explicit PoreGrid(const Scene& sc);
  // The range of the pressure of Stokes flow driven by a unit body force along periodic axis k
  // through the fluid's sections A(z) in series (hydraulic resistance ~ 1/A^2, the pressure
  // periodic): max - min of the integral of (1 - R/<R>) dz, in m; -1 when a section holds no fluid.
  double periodic_head(int k) const;
  // An upper bound of the permeability along periodic axis k (m^2): the sections in series, each
  // one channel of its whole area (Poiseuille conductance A^2 / (8 pi) in 3D, w^3 / 12 in 2D), and
  // no more than a channel as wide as the widest pore at the fluid's porosity; 0 when a section
  // holds no fluid.
  double periodic_permeability(int k) const;
  // Twice the largest distance from a fluid cell to the nearest wall or solid surface (m); the
  // domain's extent across k where there is none.
  double widest(int k) const;
  // Whether the fluid borders empty space inside the domain (a free surface).
  bool free_surface() const { return free_surface_; }

 private:
  enum Cell : std::uint8_t { Empty = 0, Fluid = 1, Solid = 2 };
  long index(const std::array<int, 3>& c) const { return c[0] + long(n_[0]) * (c[1] + long(n_[1]) * c[2]); }
  std::array<int, 3> cell_of(long i) const;
  std::vector<double> section_cells(int k) const;  // fluid cells in each section across axis k
  bool neighbour(std::array<int, 3> c, int axis, int step, std::array<int, 3>& out) const;
  void mark_free_surface(const Scene& sc);
  void solid_distance() const;

  int D_;
  double h_;
  std::array<int, 3> n_{1, 1, 1};
  std::array<bool, 3> periodic_{false, false, false};
  std::array<double, 3> extent_{0, 0, 0};
  std::vector<std::uint8_t> cell_;
  // To the nearest solid cell's centre, in cells: made by the first widest() (only a periodic body
  // force asks), 12 bytes a cell while it is made.
  mutable std::vector<float> distance_;
  bool any_solid_ = false, free_surface_ = false;
};

}  // namespace psph
