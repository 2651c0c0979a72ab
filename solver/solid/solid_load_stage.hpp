#pragma once
// The solid-load stage (`[[solid_load]]`, solid/solid_load.hpp): tractions and imposed velocities
// on groups of elastic particles, applied after every other force.
#include <cmath>
#include <cstdint>
#include <vector>

#include "core/pass_profile.hpp"
#include "solid/solid_load.hpp"
#include "stage/ramp.hpp"
#include "stage/step_context.hpp"

namespace psph {

template <int D, class B>
class SolidLoadStage {
 public:
  bool active() const { return !loads_.empty(); }

  // `mask`: each particle's loads, bit g for load g.
  void setup(StepContext<D, B>& cx, const std::vector<SceneSolidLoad>& loads, const std::vector<int>& mask) {
    loads_ = loads;
    if (!active()) return;
    cx.s.load_mask.upload(std::vector<std::int32_t>(mask.begin(), mask.end()));
    cx.s.add_field(cx.s.load_mask, 1, "solid_load_mask", "-", "the [[solid_load]]s a particle belongs to: bit g for load g");
  }

  void apply(StepContext<D, B>& cx) const {
    const StageScope scope("solid loads");
    if (active()) cx.launch(SolidLoadPass<D>{cx.view(), at(cx.force_time, cx.spacing)});
  }

 private:
  // The loads at time t: tractions as forces on each particle's share of the surface
  // (spacing^(D-1)), ramped; imposed velocities until their duration ends.
  SolidLoads<D> at(double t, double spacing) const {
    SolidLoads<D> l;
    l.count = static_cast<int>(loads_.size());
    const double area = std::pow(spacing, D - 1);
    for (int g = 0; g < l.count; ++g) {
      const SceneSolidLoad& sl = loads_[g];
      l.kind[g] = sl.velocity ? SolidLoadKind::Velocity : SolidLoadKind::Traction;
      l.axes[g] = sl.axes;
      const double f = sl.velocity ? (sl.duration > 0 && t > sl.duration ? 0.0 : 1.0)
                                   : area * ramp_factor(t, sl.ramp_time);
      for (int d = 0; d < D; ++d) l.value[g][d] = Real(f * sl.value[d]);
    }
    return l;
  }

  std::vector<SceneSolidLoad> loads_;
};

}  // namespace psph
