#pragma once
// The fluid stage: density (summation, or the continuity equation and the equation of state), the
// pressure and no-slip velocity that walls present to the fluid, the fluid's pair forces, the
// implicit viscous step, the ramped body-force regions and background pressure.
#include <string>
#include <vector>

#include "boundary/wall_state.hpp"
#include "core/instability.hpp"
#include "core/pass_profile.hpp"
#include "fluid/body_force_region.hpp"
#include "fluid/continuity.hpp"
#include "fluid/density.hpp"
#include "fluid/fluid_options.hpp"
#include "fluid/momentum.hpp"
#include "integrate/bicgstab.hpp"
#include "interface/interface_options.hpp"
#include "stage/ramp.hpp"
#include "stage/step_context.hpp"

namespace psph {

template <int D, class B>
class FluidStage {
 public:
  void setup(StepContext<D, B>& cx, const FluidOptions& o, const InterfaceOptions& io,
             const std::vector<SceneForceRegion>& regions) {
    o_ = o;
    for (int m = 0; m < cx.mats.count; ++m) background_pressure_[m] = cx.mats.m[m].background_pressure;
    regions_ = regions;
    cx.mats.region_count = static_cast<int>(regions_.size());
    for (int r = 0; r < cx.mats.region_count; ++r) {
      cx.mats.region[r].material = regions_[r].material;
      for (int d = 0; d < D; ++d)
        cx.mats.region[r].lower[d] = Coord(regions_[r].lower[d]), cx.mats.region[r].upper[d] = Coord(regions_[r].upper[d]);
    }
    fo_.xsph = Real(o.xsph);
    fo_.laplacian = o.laplacian_correction;
    fo_.artificial_viscosity = Real(o.artificial_viscosity);
    fo_.smoothing_length = Real(cx.smoothing_length);
    fo_.number_density = o.density == DensityMethod::NumberSummation;
    fo_.viscosity = !o.implicit_viscosity;
    fo_.surface_tension = Real(io.surface_tension);
    fo_.contact_line_force = io.contact_line_force && cx.walls;
  }
  const FluidForceOptions& force_options() const { return fo_; }
  int linear_iterations() const { return linear_iterations_; }

  // Each material's background pressure at time t.
  void ramp_pressure(StepContext<D, B>& cx, double t) const {
    if (o_.background_pressure_rate == 0) return;
    for (int m = 0; m < cx.mats.count; ++m)
      cx.mats.m[m].background_pressure = Real(background_pressure_[m] + o_.background_pressure_rate * t);
  }

  // Body-force regions at time t, each scaled by its ramp factor.
  void ramp_regions(StepContext<D, B>& cx, double t) const {
    for (int r = 0; r < cx.mats.region_count; ++r) {
      const double f = ramp_factor(t, regions_[r].ramp_time);
      for (int d = 0; d < D; ++d) cx.mats.region[r].acceleration[d] = Real(f * regions_[r].acceleration[d]);
    }
  }

  // The walls' reference density: their initial summed density (lists of every particle built).
  void wall_rest_density(StepContext<D, B>& cx) const {
    const StageScope scope("fluid");
    density(cx, true);
    cx.launch(SetWallRestDensity<D>{cx.view(), cx.mats});
  }
  // Density by summation, or the pressure of the integrated density.
  void density(StepContext<D, B>& cx, bool all_particles = false) const {
    const StageScope scope("fluid");
    if (cx.continuity) return cx.launch(EquationOfStatePass<D>{cx.view(), cx.mats});
    const bool normalised = o_.density == DensityMethod::NormalisedSummation;
    const bool number = o_.density == DensityMethod::NumberSummation;
    if (normalised) cx.launch(NumberDensityPass<D>{cx.list(), cx.kern, cx.view(), all_particles});
    cx.launch(DensitySummationPass<D>{cx.pairs(), normalised, number,
                                                all_particles, cx.solids()});
  }
  // d rho/dt with the velocity that drifts the particles (fluid/continuity.hpp).
  void density_rate(StepContext<D, B>& cx) const {
    const StageScope scope("fluid");
    if (!cx.continuity) return;
    cx.launch(ContinuityPass<D>{cx.pairs(), Real(o_.density_diffusion),
                                          Real(cx.smoothing_length), o_.wall_pressure == WallPressure::Summation});
  }

  // Walls and solids present a pressure and a no-slip velocity (boundary/, solid/fluid_coupling.hpp).
  void present_walls(StepContext<D, B>& cx) const {
    const StageScope scope("fluid");
    const bool extrapolated = cx.walls && o_.wall_pressure == WallPressure::Extrapolated;
    if (extrapolated) cx.launch(WallStatePass<D>{cx.pairs(), o_.wall_noslip});
    if ((cx.walls && !extrapolated) || cx.solids())
      cx.launch(WallVelocityPass<D>{cx.pairs(), o_.wall_noslip, extrapolated});
  }
  void forces(StepContext<D, B>& cx) const {
    const StageScope scope("fluid");
    cx.launch(FluidForcePass<D>{cx.pairs(), fo_});
  }

  // v <- (I - dt L)^-1 v on the fluid (fluid/viscosity.hpp), L at the current positions with the
  // walls' no-slip velocities of the last force pass; those move to the right-hand side.
  // `when()` says when, for the message of a solve that fails (built only then).
  template <class When>
  void viscous_step(StepContext<D, B>& cx, double dt, const When& when) {
    const StageScope scope("fluid");
    if (!o_.implicit_viscosity || !cx.fluid) return;
    const int n = cx.n();
    const ParticleView<D> v = cx.view();
    for (auto* a : {&visc_b_, &visc_x_}) a->resize(n);
    const bool normalise = o_.laplacian_correction != LaplacianCorrection::None;
    // Over several processes: the operator's input from the owners of the halo, at each product.
    auto op = [&](Vec<D>* in, Vec<D>* out, bool walls) {
      cx.refresh_array(in, std::size_t(n), "the implicit viscous solve's vector");
      B::for_each(n, ImplicitViscosityOperator<D>{cx.pairs(), normalise, Real(dt), in, out, walls});
    };
    cx.template refresh_reads<ImplicitViscosityOperator<D>>();
    visc_x_.zero();
    op(visc_x_.data(), visc_b_.data(), true);  // A(0): the walls' part
    B::for_each(n, FluidDifference<D>{visc_b_.data(), v.v, visc_b_.data(), v, cx.mats});
    B::for_each(n, FluidDifference<D>{visc_x_.data(), v.v, visc_x_.data(), v, cx.mats});  // guess: v
    const KrylovResult r = krylov_.solve(
        n, [&](Vec<D>* in, Vec<D>* out) { op(in, out, false); },
        [&](const DotOf<D>& dot) { return cx.template sum_of<Real>(dot); }, visc_b_.data(), visc_x_.data(),
        o_.implicit_tolerance, 1000);
    linear_iterations_ = r.iterations;
    if (!r.converged)
      throw InstabilityError("the implicit viscous solve did not converge (relative residual " +
                             std::to_string(r.relative_residual) + " after " + std::to_string(r.iterations) +
                             " BiCGSTAB iterations)" + when());
    B::for_each(n, SetFluidVelocity<D>{visc_x_.data(), v, cx.mats});
    cx.written("velocity");
  }

 private:
  FluidOptions o_;
  FluidForceOptions fo_;
  double background_pressure_[kMaxMaterials] = {};  // Pa, each material's at t = 0
  std::vector<SceneForceRegion> regions_;  // full body forces of the regions (cx.mats holds them ramped)
  BiCGStab<D, B> krylov_;
  DeviceArray<Vec<D>, B> visc_b_, visc_x_;  // implicit viscous step: right-hand side, solution
  int linear_iterations_ = 0;
};

}  // namespace psph
