#pragma once
// What the stages of a step share (engine/simulation.hpp orders them): the particle state, the
// cell grid and the lists, the kernel, the material table and which kinds of particle the case
// holds. Each stage owns the rest: its options, fields, scratch arrays, launches, time-step
// inputs, monitors and checkpoint data.
// Every global reduction goes through sum_of/max_of, which reduce over the processes of a shared
// run too (parallel/).
#include <algorithm>
#include <string>
#include <type_traits>
#include <vector>

#include "core/exact_sum.hpp"
#include "core/fluid_table.hpp"
#include "kernels/kernel.hpp"
#include "neighbours/neighbour_stage.hpp"
#include "parallel/cost_calibration.hpp"
#include "parallel/owned_terms.hpp"
#include "parallel/particle_domain.hpp"
#include "stage/pass_context.hpp"
#include "core/pass_fields.hpp"
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

  // Reductions over the particles of the run: this process's own ones, then over every process
  // (exact sums: core/exact_sum.hpp).
  template <class T, class F>
  T sum_of(const F& f) {
    refresh_reads<F>();
    ExactSum acc[RealComponents<T>::count];
    B::template accumulate<T>(n(), OwnedTerm<T, F>{f, owned()}, acc);
    return reduced<T>(acc);
  }
  template <class T, class F>
  T max_of(const F& f) {
    refresh_reads<F>();
    const T m = B::template max_of<T>(n(), OwnedMax<T, F>{f, owned()});
    if (!domain) return m;
    if constexpr (std::is_integral_v<T>) return T(domain->comm().max(static_cast<long long>(m)));
    else return T(domain->comm().max(double(m)));
  }
  // A sum over `count` entries of a stage's own list (e.g. a rigid body's particles), over every
  // process.
  template <class T, class F>
  T sum_over(int count, const F& f) const {
    ExactSum acc[RealComponents<T>::count];
    B::template accumulate<T>(count, f, acc);
    return reduced<T>(acc);
  }
  template <class T>
  T reduced(ExactSum* acc) const {
    if (domain) domain->comm().sum(acc, RealComponents<T>::count);
    return rounded<T>(acc);
  }

  // The lists expire when a particle of the run moved by half their skin.
  bool lists_expired() {
    const double half_skin = neighbours.half_skin();
    return half_skin <= 0 || double(max_of<Real>(neighbours.displacement(s, grid))) >= half_skin;
  }

  // Launches a per-particle pass on every particle here. A run shared out over processes runs it
  // on the particles this process owns, after bringing the halo's values of the fields the pass
  // reads of its neighbours where a pass wrote them since they were last brought
  // (core/pass_fields.hpp); the fields it writes are then stale in the halo.
  template <class F>
  void launch(const F& pass) {
    if (!domain) return B::for_each(n(), pass);
    if constexpr (DeclaresFields<F>::value) {
      refresh_reads<F>();
      run_owned(pass);
      for (int k = 0; k < F::writes.count; ++k) written(F::writes.names[k]);
    } else {
      for (const auto& f : s.fields().all()) refresh(f.info.name.c_str());
      run_owned(pass);
      for (const auto& f : s.fields().all()) written(f.info.name.c_str());
    }
  }

  // A pass on the owned particles; while the particle classes' costs are measured, once per class.
  template <class F>
  void run_owned(const F& pass) {
    if (calibration && calibration->fits(n())) calibration->run(n(), pass);
    else B::for_each(n(), OwnedPass<F>{pass, domain->owned()});
  }

  // The fields that F (a pass or a reduction) declares it reads of its neighbours.
  template <class F>
  void refresh_reads() {
    if constexpr (DeclaresReads<F>::value)
      for (int k = 0; k < F::neighbour_reads.count; ++k) refresh(F::neighbour_reads.names[k]);
  }

  // A run shared out over processes: the halo's values of the named field from their owners
  // (parallel/particle_domain.hpp), if a pass wrote it since they were last brought.
  void refresh(const char* field) {
    if (!domain) return;
    const auto stale = std::find(stale_.begin(), stale_.end(), field);
    if (stale == stale_.end()) return;
    stale_.erase(stale);
    domain->refresh(s.fields().get(field));
  }
  // The halo's values of an unregistered per-particle array (`n` values from `data`), which a pass
  // about to run reads of its neighbours: brought from their owners every time.
  template <class T>
  void refresh_array(T* data, std::size_t n, const char* what) {
    if (domain && n) domain->refresh(data, n, what);
  }
  // A field that a pass or the host wrote: its halo values are stale.
  void written(const char* field) {
    if (domain && s.fields().has(field) && std::find(stale_.begin(), stale_.end(), field) == stale_.end())
      stale_.push_back(field);
  }
  // The halo was gathered again (parallel/particle_domain.hpp): every value is its owner's.
  void halo_fresh() { stale_.clear(); }
  const std::uint8_t* owned() const { return domain ? domain->owned() : nullptr; }
  ParticleDomain<D, B>* domain = nullptr;  // null on one process
  CostCalibration<B>* calibration = nullptr;  // a shared run's first steps only
  std::vector<std::string> stale_;          // fields whose halo values are not their owners'
};

}  // namespace psph
