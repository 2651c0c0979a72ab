#pragma once
// Each particle class's cost in a shared run's initial force evaluation (after its last list
// build; parallel/particle_cost.hpp), measured where the time goes: every pass launched through the
// step context runs once per class, on that class's owned particles only (a pass gathers into its
// own particle's outputs, so splitting a launch changes no number), each launch timed; a launch on
// no particle times the skipping of the others, which is taken off. The time outside these passes
// (halo refreshes, reductions) is shared equally by the owned particles. The class costs are then
// summed over the processes, so every process weighs a class alike.
#include <algorithm>
#include <chrono>
#include <cstdint>
#include <vector>

#include "backend/device_array.hpp"
#include "core/pass_profile.hpp"
#include "parallel/communicator.hpp"
#include "parallel/owned_terms.hpp"
#include "parallel/particle_cost.hpp"

namespace psph {

template <class B>
class CostCalibration {
 public:
  // The current particle order's classes (kCostClasses: a halo copy), after every sort.
  void classify(const std::vector<std::uint8_t>& klass) {
    std::vector<std::uint8_t> m(klass.size());
    for (int c = 0; c < kCostClasses; ++c) {
      present_[c] = 0;
      for (std::size_t i = 0; i < klass.size(); ++i) m[i] = klass[i] == c, present_[c] += m[i];
      mask_[c].upload(m);
    }
    none_.upload(std::vector<std::uint8_t>(klass.size(), 0));
  }

  // Whether the classes are those of these `n` particles (a run that creates or removes particles
  // meanwhile is measured no further).
  bool fits(int n) const { return std::size_t(n) == none_.size(); }

  // The pass once per class present, each launch timed (outside the run's profile, which gets the
  // launches' total as one call).
  template <class F>
  void run(int n, const F& pass) {
    const ProfileFocus focus = profile_focus();
    const ProfilePause pause;
    B::for_each(n, OwnedPass<F>{pass, none_.data()});  // a first launch loads the kernel: untimed
    const double empty = timed([&] { B::for_each(n, OwnedPass<F>{pass, none_.data()}); });
    double total = empty;
    for (int c = 0; c < kCostClasses; ++c) {
      if (!present_[c]) continue;
      const double t = timed([&] { B::for_each(n, OwnedPass<F>{pass, mask_[c].data()}); });
      work_[c] += std::max(0.0, t - empty), total += t;
    }
    in_passes_ += total;
    if (focus.profile) focus.profile->add(focus.stage, pass_name_of<F>(), total);
  }

  // Seconds per particle and evaluation of each class, over every process. A class that no process held
  // (walls that the fluid has yet to reach) keeps its static weight relative to the fluid's.
  // `busy`: the seconds measured, less the time waiting for other processes.
  ClassCosts costs(Communicator& comm, double busy) const {
    constexpr int K = kCostClasses;
    ExactSum acc[2 * K + 1];
    for (int c = 0; c < K; ++c) acc[c].add(work_[c]), acc[K + c].add(double(present_[c]));
    acc[2 * K].add(std::max(0.0, busy - in_passes_));
    comm.sum(acc, 2 * K + 1);
    double particles = 0;
    for (int c = 0; c < K; ++c) particles += acc[K + c].value();
    const double outside = particles > 0 ? acc[2 * K].value() / particles : 0;
    const ClassCosts guess;
    ClassCosts out;
    double scale = 0;  // seconds per unit of static weight
    for (int c = K - 1; c >= 0; --c) {
      const double count = acc[K + c].value();
      if (count > 0) out.per_particle[c] = acc[c].value() / count + outside, scale = out.per_particle[c] / guess.per_particle[c];
    }
    for (int c = 0; c < K; ++c)
      if (!(acc[K + c].value() > 0)) out.per_particle[c] = guess.per_particle[c] * scale;
    out.measured = scale > 0;
    return out;
  }

 private:
  template <class G>
  static double timed(const G& launch) {
    B::synchronize();
    const auto t0 = std::chrono::steady_clock::now();
    launch();
    B::synchronize();
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  }

  DeviceArray<std::uint8_t, B> mask_[kCostClasses], none_;
  long long present_[kCostClasses] = {};
  double work_[kCostClasses] = {};
  double in_passes_ = 0;
};

}  // namespace psph
