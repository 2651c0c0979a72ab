#pragma once
// The open-boundary stage (boundary/open_boundary.hpp): pressure inlet and outlet buffers across
// a periodic axis. Fluid that crosses into the inlet becomes the injected fluid; each step the
// buffers take the velocity of the outgoing characteristic, then their imposed state.
#include "boundary/open_boundary.hpp"
#include "core/open_boundary_zone.hpp"
#include "core/pass_profile.hpp"
#include "stage/step_context.hpp"

namespace psph {

template <int D, class B>
class OpenBoundaryStage {
 public:
  bool active() const { return active_; }

  void setup(StepContext<D, B>& cx, const SceneOpenBoundary& ob, double support_radius, double spacing) {
    active_ = ob.axis >= 0;
    if (!active_) return;
    OpenBoundaryZone<D>& z = cx.mats.open;
    const Coord lo = Coord(ob.lower), hi = Coord(ob.upper), b = Coord(ob.thickness);
    z.axis = ob.axis;
    z.inlet_lower = ob.inlet_at_lower ? lo : hi - b, z.inlet_upper = ob.inlet_at_lower ? lo + b : hi;
    z.outlet_lower = ob.inlet_at_lower ? hi - b : lo, z.outlet_upper = ob.inlet_at_lower ? hi : lo + b;
    z.inlet_pressure = Real(ob.inlet_pressure), z.outlet_pressure = Real(ob.outlet_pressure);
    z.inlet_material = ob.inlet_material;
    z.face_band = Coord(support_radius);
    z.domain_lower = lo;
    z.lattice_volume = Real(1 / cx.kern.lattice_sum(spacing));
  }

  // Before the density pass: fluid come round into the inlet becomes the inlet's.
  void convert_inlet(StepContext<D, B>& cx) const {
    const StageScope scope("open boundary");
    if (active_) cx.launch(ConvertInletFluid<D>{cx.view(), cx.mats});
  }
  // Before the density pass, with the lists built: each buffer particle's mass (BufferMass).
  void buffer_mass(StepContext<D, B>& cx) const {
    const StageScope scope("open boundary");
    if (active_) cx.launch(BufferMass<D>{cx.view(), cx.mats, cx.list(), cx.kern});
  }

  // Each buffer's velocity gets the correction of the outgoing characteristic with its pressure p_b
  // imposed (linear acoustics: u_n - p/(rho c) is carried from the interior into the buffer, u_n the
  // velocity along the buffer's inward normal n): du_n = (p_b - p)/(rho c), with p and rho c the
  // means over the interior band next to the buffer. The pressure difference lets mass in or out
  // until the fluid next to a buffer has the buffer's pressure.
  // Runs after the step is chosen: the buffers' new velocities differ from the last ones by du << c.
  void buffer_velocity(StepContext<D, B>& cx, double dt) const {
    const StageScope scope("open boundary");
    if (!active_) return;
    const ParticleView<D> v = cx.view();
    Real u_band[2] = {0, 0}, du[2] = {0, 0};
    const BandSums sums = cx.template sum_of<BandSums>(BandSum<D>{v, cx.mats});
    for (int b = 0; b < 2; ++b) {
      const Real* q = sums.q[b];
      if (q[0] == 0) continue;
      const BufferZone z = b == 0 ? BufferZone::Inlet : BufferZone::Outlet;
      u_band[b] = q[1] / q[0];
      du[b] = cx.mats.open.inward(z) * (cx.mats.open.pressure(z) - q[2] / q[0]) / (q[3] / q[0]);
    }
    cx.launch(SetBufferVelocity<D>{v, cx.mats, cx.cells(), cx.list(), cx.kern, {u_band[0], u_band[1]},
                                             {du[0], du[1]}, Real(double(kBufferShift) / dt)});
  }

  void buffer_state(StepContext<D, B>& cx) const {
    const StageScope scope("open boundary");
    if (active_) cx.launch(SetBufferState<D>{cx.view(), cx.mats});
  }

 private:
  bool active_ = false;
};

}  // namespace psph
