#pragma once
// The interface stage (two fluids with surface tension): the smoothed colour, the interface normal
// with the walls' wetting, and the curvature that the fluid's force pass turns into the capillary
// force (interface/surface_tension.hpp, interface/wall_wetting.hpp).
#include "core/pass_profile.hpp"
#include "interface/interface_options.hpp"
#include "interface/surface_tension.hpp"
#include "interface/wall_wetting.hpp"
#include "stage/step_context.hpp"

namespace psph {

template <int D, class B>
class InterfaceStage {
 public:
  bool active() const { return o_.surface_tension > 0; }

  void setup(StepContext<D, B>& cx, const InterfaceOptions& o) {
    o_ = o;
    if (!active()) return;
    ParticleState<D, B>& s = cx.s;
    const int n = cx.n();
    s.colour.resize(n), s.colour_gradient.resize(n), s.curvature.resize(n);
    s.colour.zero(), s.colour_gradient.zero(), s.curvature.zero();
    s.add_field(s.colour, 1, "colour", "-", "smoothed colour function, +1 liquid, -1 gas (Pazdniakou eq. 58)");
    s.add_field(s.colour_gradient, D, "colour_gradient", "1/m", "interface normal n = grad c (eq. 59a)");
    s.add_field(s.curvature, 1, "curvature", "1/m", "interface curvature -div n^ (eqs. 7, 60)");
  }

  // Colour, normal (twice more near walls with geometric wetting), curvature.
  void curvature(StepContext<D, B>& cx) const {
    const StageScope scope("interface");
    if (!active()) return;
    const PairContext<D> pc = cx.pairs();
    // Geometric wetting extrapolates the walls' colour; without walls, solids keep cos(theta).
    const bool geometric = o_.geometric_wetting && cx.walls;
    if (geometric) {
      cx.launch(ColourPass<D>{pc, WallColour::FluidOnly});
      cx.launch(NormalPass<D>{pc, WallColour::FluidOnly});
      for (int k = 0; k < 2; ++k) {
        cx.launch(WallWettingPass<D>{pc});
        cx.launch(ColourPass<D>{pc, WallColour::NearWallsAgain});
        cx.launch(NormalPass<D>{pc, WallColour::NearWallsAgain});
      }
    } else {
      cx.launch(ColourPass<D>{pc, WallColour::Constant});
      cx.launch(NormalPass<D>{pc, WallColour::Constant});
    }
    cx.launch(CurvaturePass<D>{pc, Real(o_.normal_threshold / cx.smoothing_length), geometric});
  }

 private:
  InterfaceOptions o_;
};

}  // namespace psph
