#pragma once
// What the stages of a step share (engine/simulation.hpp orders them): the particle state, the
// cell grid and the lists, the kernel, the material table and which kinds of particle the case
// holds. Each stage owns the rest: its options, fields, scratch arrays, launches, time-step
// inputs, monitors and checkpoint data.
// Every global reduction goes through sum_of/max_of: the one place where a reduction over
// several processes (an allreduce) will go.
#include "core/fluid_table.hpp"
#include "kernels/kernel.hpp"
#include "neighbours/neighbour_stage.hpp"
#include "stage/pass_context.hpp"
#include "state/particles.hpp"

namespace psph {

template <int D, class B>
struct StepContext {
  ParticleState<D, B> s;
  CellGrid<D> grid{};
  Kernel<D> kern{};
  FluidTable<D> mats{};  // materials, body-force regions, open-boundary buffers
  NeighbourStage<D, B> neighbours;
  double spacing = 0, smoothing_length = 0;
  // What the case holds, and what the lists must serve.
  bool walls = false, fluid = false, elastic = false, rigid = false;
  bool continuity = false;  // density integrated: walls need no wall neighbours
  bool follow_ids = false;  // some stage finds particles by id after reorderings (index_of_id)
  double force_time = 0;    // the time at which the forces being evaluated act

  int n() const { return s.size(); }
  ListNeeds list_needs() const { return ListNeeds{walls, fluid, !continuity, elastic && walls, follow_ids}; }
  bool solids() const { return elastic || rigid; }
  ParticleView<D> view() { return s.view(); }
  // The lists at the current positions, and at the solids' reference positions (small strain).
  NeighbourList<D> list() const { return neighbours.list(grid, s.x.data(), kern.support); }
  NeighbourList<D> reference_list() const { return neighbours.list(grid, s.x0.data(), kern.support); }
  NeighbourView<D> cells() const { return neighbours.cells(grid, s.x.data()); }
  // What a pair pass reads (stage/pass_context.hpp): over the lists, or over neighbours nb.
  PairContext<D> pairs() { return PairContext<D>{list(), kern, view(), mats}; }
  template <class NB>
  PairContext<D, NB> pairs(const NB& nb) { return PairContext<D, NB>{nb, kern, view(), mats}; }

  template <class T, class F>
  T sum_of(const F& f) const { return B::template sum_of<T>(n(), f); }
  template <class T, class F>
  T max_of(const F& f) const { return B::template max_of<T>(n(), f); }
  // A reduction over `count` entries of a stage's own list (e.g. a rigid body's particles).
  template <class T, class F>
  T sum_over(int count, const F& f) const { return B::template sum_of<T>(count, f); }
};

}  // namespace psph
