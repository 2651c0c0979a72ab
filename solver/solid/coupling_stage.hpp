#pragma once
// The fluid-solid coupling stage (solid/fluid_coupling.hpp): elastic and rigid solids present a
// pressure to the fluid before its force pass, and take the fluid's reaction after their own.
#include "core/pass_profile.hpp"
#include "solid/fluid_coupling.hpp"
#include "solid/solid_options.hpp"
#include "stage/step_context.hpp"

namespace psph {

template <int D, class B>
class CouplingStage {
 public:
  bool active() const { return active_; }

  void setup(StepContext<D, B>& cx, SolidCoupling mode) {
    mode_ = mode;
    active_ = cx.fluid && cx.solids();
    if (!active_) return;
    // Written and read within one force evaluation: not registered.
    ParticleState<D, B>& s = cx.s;
    s.visc_scale.resize(cx.n()), s.fluid_contact.resize(cx.n()), s.p_ambient.resize(cx.n());
    s.visc_scale.zero(), s.fluid_contact.zero(), s.p_ambient.zero();
  }

  // `moduli`: the damaged moduli, if any (damage/damage_stage.hpp).
  void present_solids(StepContext<D, B>& cx, ParticleModuli moduli) const {
    const StageScope scope("coupling");
    if (active_) cx.launch(SolidInterfacePressurePass<D>{cx.pairs(), mode_, moduli});
  }
  // `fo`: the fluid's force options (the reaction is the fluid's pair force, computed again).
  void fluid_on_solids(StepContext<D, B>& cx, const FluidForceOptions& fo) const {
    const StageScope scope("coupling");
    if (!active_) return;
    // The fluid's Laplacian correction of its own force pass, read of fluid neighbours.
    cx.refresh_array(cx.s.visc_scale.data(), cx.s.visc_scale.size(), "visc_scale");
    cx.launch(FluidOnSolidPass<D>{cx.pairs(), fo, mode_ != SolidCoupling::Traction});
  }

 private:
  SolidCoupling mode_ = SolidCoupling::Traction;
  bool active_ = false;
};

}  // namespace psph
