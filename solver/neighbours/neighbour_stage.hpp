#pragma once
// The neighbour stage: cell keys, the sort by cell (ties by id) that reorders every registered field,
// the Verlet lists (neighbours/neighbour_list.hpp) and when they expire. The physics stages read
// the lists through the step context (stage/step_context.hpp).
#include <algorithm>
#include <stdexcept>
#include <vector>

#include "backend/device_array.hpp"
#include "core/pass_profile.hpp"
#include "neighbours/list_passes.hpp"
#include "neighbours/cell_grid.hpp"
#include "neighbours/fluid_proximity.hpp"
#include "neighbours/neighbour_list.hpp"
#include "state/particles.hpp"

namespace psph {

// What the lists must serve in this case (the step context says: stage/step_context.hpp).
struct ListNeeds {
  bool walls = false, fluid = false;
  bool walls_need_walls = false;  // wall density by summation: walls near the fluid list their wall neighbours
  bool clamps = false;            // clamp walls list every neighbour (solid/clamp.hpp)
  bool follow_ids = false;        // some stage finds particles by id after reorderings (index_of_id)
};

inline constexpr const char* kListPositionsField = "list_positions";

template <int D, class B>
class NeighbourStage {
 public:
  // The list radius R (1 + skin), reduced where a periodic axis needs it to keep 3 cells; the grid
  // of cells of at least R.
  CellGrid<D> setup(const double lower[], const double upper[], const bool periodic[], double support, double skin) {
    support_ = support;
    radius_ = support * (1 + skin);
    Coord lo[D], hi[D];
    bool per[D];
    for (int k = 0; k < D; ++k) {
      lo[k] = Coord(lower[k]), hi[k] = Coord(upper[k]), per[k] = periodic[k];
      if (per[k]) radius_ = std::min(radius_, (upper[k] - lower[k]) / 3);
    }
    radius_ = std::max(radius_, support);
    CellGrid<D> grid{};
    if (!CellGrid<D>::make(lo, hi, per, Coord(radius_), grid))
      throw std::invalid_argument("a periodic axis is shorter than 3 support radii");
    bucket_start_.resize(2 * grid.total), bucket_end_.resize(2 * grid.total);
    fluid_lo_.resize(grid.total), fluid_hi_.resize(grid.total), cell_near_.resize(grid.total);
    return grid;
  }

  // The positions of the last build are a particle field: a checkpoint carries them, so that a
  // restart rebuilds the very lists of the run it continues (build_as_saved) and a checkpoint
  // changes nothing in the run.
  void resize(ParticleState<D, B>& s, int n) {
    keys_.resize(n), perm_.resize(n), count_.resize(n), fluid_count_.resize(n), x_build_.resize(n);
    s.add_field(x_build_, D, kListPositionsField, "m", "positions at the last neighbour-list build");
  }

  // The cell ranges of the last sort, for searches beyond the lists (open-boundary buffers).
  NeighbourView<D> cells(const CellGrid<D>& grid, const Point<D>* x) const {
    return NeighbourView<D>{grid, x, bucket_start_.data(), bucket_end_.data(), Real(radius_ * radius_)};
  }
  // The lists, visited with positions x (the current ones, or a solid's reference positions).
  NeighbourList<D> list(const CellGrid<D>& grid, const Point<D>* x, Real support) const {
    return NeighbourList<D>{grid, x, index_.data(), count_.data(), fluid_count_.data(), stride_i(), stride_k(),
                            support * support};
  }
  int capacity() const { return capacity_; }

  // Cell keys, sort by cell (fluid first in each cell), reorder every registered field, ranges, lists.
  // `every_particle`: full lists for every particle (the initial density, which must see every
  // wall's whole neighbourhood to set its rest density); otherwise walls far from the fluid get none.
  void build(ParticleState<D, B>& s, const CellGrid<D>& grid, const MaterialTable<D>& mats, const ListNeeds& needs,
             bool every_particle) {
    const StageScope scope("neighbours");
    sort_and_list(s, grid, mats, needs, every_particle);
    B::copy(x_build_.data(), s.x.data(), sizeof(Point<D>) * s.size());
  }

  // After a restore: the lists of the saved build positions (the state is in their cell order
  // already, so the sort keeps it), then the current positions back.
  void build_as_saved(ParticleState<D, B>& s, const CellGrid<D>& grid, const MaterialTable<D>& mats,
                      const ListNeeds& needs) {
    const StageScope scope("neighbours");
    s.x.swap(x_build_);  // the field "list_positions" is permuted with the state meanwhile
    sort_and_list(s, grid, mats, needs, false);
    s.x.swap(x_build_);
  }

  // The lists hold every pair within R as long as no particle moved by half the skin: they have
  // expired when the largest `displacement` (a reduction over the run) reaches half_skin().
  double half_skin() const { return 0.5 * (radius_ - support_); }
  DisplacementSinceBuild<D> displacement(const ParticleState<D, B>& s, const CellGrid<D>& grid) const {
    return DisplacementSinceBuild<D>{grid, s.x.data(), x_build_.data()};
  }
  double radius() const { return radius_; }

 private:
  void sort_and_list(ParticleState<D, B>& s, const CellGrid<D>& grid, const MaterialTable<D>& mats,
                     const ListNeeds& needs, bool every_particle) {
    const int n = s.size();
    if (keys_.size() != std::size_t(n))  // a process's share of a run changed (parallel/)
      keys_.fit(n), perm_.fit(n), count_.fit(n), fluid_count_.fit(n);
    B::for_each(n, CellKeyPass<D>{grid, s.x.data(), s.material.data(), mats, keys_.data()});
    B::sort_by_cell(keys_.data(), n, 2 * grid.total, perm_.data(), bucket_start_.data(), bucket_end_.data(), s.id.data());
    s.permute(perm_.data());
    if (needs.follow_ids) {
      B::for_each(static_cast<int>(s.index_of_id.size()), ClearIndexOfId{s.index_of_id.data()});
      B::for_each(n, IndexOfIdPass<D>{s.view()});
    }
    if (!every_particle && needs.walls && needs.fluid) {
      const NeighbourView<D> nb = cells(grid, s.x.data());
      B::for_each(grid.total, CellFluidBox<D>{nb, fluid_lo_.data(), fluid_hi_.data()});
      B::for_each(grid.total, CellNearFluid<D>{nb, fluid_lo_.data(), fluid_hi_.data(), cell_near_.data()});
      B::for_each(n, NearFluid<D>{nb, fluid_lo_.data(), fluid_hi_.data(), cell_near_.data(), s.near_fluid.data()});
    }
    else  // without fluids every wall lists all its neighbours
      s.near_fluid.upload(std::vector<std::uint8_t>(n, 1));
    build_lists(s, grid, mats, needs);
  }

  ListOffset stride_i() const { return B::list_rows_contiguous ? capacity_ : 1; }
  ListOffset stride_k() const { return B::list_rows_contiguous ? 1 : ListOffset(count_.size()); }

  // Lists from the cell list; grows the capacity when a particle has more neighbours.
  void build_lists(ParticleState<D, B>& s, const CellGrid<D>& grid, const MaterialTable<D>& mats, const ListNeeds& needs) {
    const int n = s.size();
    for (;;) {
      if (index_.size() < std::size_t(capacity_) * n) index_.resize(std::size_t(capacity_) * n);
      B::for_each(n, BuildNeighbourList<D>{cells(grid, s.x.data()), s.material.data(), mats, s.near_fluid.data(),
                                           needs.clamps ? s.mirror.data() : nullptr, s.ghost.data(), needs.walls_need_walls,
                                           !needs.fluid, index_.data(), count_.data(), fluid_count_.data(), capacity_,
                                           stride_i(), stride_k()});
      const int most = n ? B::template max_of<int>(n, ListCount<D>{count_.data()}) : 0;
      if (most <= capacity_) return;
      capacity_ = most + most / 4 + 4;
    }
  }

  double support_ = 0, radius_ = 0;
  int capacity_ = 32;
  DeviceArray<int, B> keys_, perm_, bucket_start_, bucket_end_;
  DeviceArray<int, B> index_, count_, fluid_count_;
  DeviceArray<Point<D>, B> x_build_;  // positions at the last list build
  DeviceArray<Point<D>, B> fluid_lo_, fluid_hi_;  // each cell's fluid box (neighbours/fluid_proximity.hpp)
  DeviceArray<std::uint8_t, B> cell_near_;     // fluid in a cell's stencil
};

}  // namespace psph
