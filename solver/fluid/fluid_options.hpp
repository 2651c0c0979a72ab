#pragma once
// The fluid stage's options ([solver] keys of the case file that only fluids read).
#include "boundary/wall_pressure.hpp"
#include "boundary/wall_velocity.hpp"
#include "kernels/laplacian_correction.hpp"

namespace psph {

enum class DensityMethod { Summation, NormalisedSummation, NumberSummation, Continuity };

struct FluidOptions {
  DensityMethod density = DensityMethod::Summation;
  double xsph = 0;                  // XSPH epsilon
  double artificial_viscosity = 0;  // Monaghan alpha
  double density_diffusion = 0;     // delta-SPH delta (continuity only)
  WallNoSlip wall_noslip = WallNoSlip::Curved;
  WallPressure wall_pressure = WallPressure::Extrapolated;
  LaplacianCorrection laplacian_correction = LaplacianCorrection::Trace;  // kernels/laplacian_correction.hpp
  // Backward-Euler viscous step solved by BiCGSTAB (fluid/viscosity.hpp, integrate/bicgstab.hpp):
  // no viscous time-step limit.
  bool implicit_viscosity = false;
  double implicit_tolerance = 1e-6;  // relative residual of the viscous solve
  // Pa/s: the background pressure grows at this rate from its value at t = 0 (a closed pore's
  // water pressurised quasi-statically; the fluid's own dynamics do not see a uniform pressure).
  double background_pressure_rate = 0;
};

}  // namespace psph
