#pragma once
// Adaptive time step from every active limit (Pazdniakou eqs. 50-52 plus the acoustic limit,
// which the paper omits), written with the smoothing length h_s (R/2 for the cubic spline) as in
// Morris et al. (1997). Read with h = support radius, as printed in Pazdniakou, eq. 52 allows a
// step 4x larger, and the Poiseuille cases blow up with it (measured).
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "core/material.hpp"

namespace psph {

// What the limits need from the materials, computed here only (the case reader checks a fixed
// step against them, the engine steps with them): the largest sound speed of any material, the
// largest kinematic viscosity mu/rho of a fluid (0 with implicit viscosity, which has no viscous
// limit), the smallest fluid density over the surface tension (0 without surface tension).
struct TimeStepInputs {
  double c_max = 0, nu_max = 0, rho_over_sigma = 0;
  // The elastic solids' Monaghan artificial viscosity (solid/artificial_viscosity.hpp): alpha times
  // their largest sound speed, beta, and the dimension.
  double solid_alpha_c = 0, solid_beta = 0;
  int dimension = 3;
};
// `solid_alpha`, `solid_beta`: the elastic solids' artificial viscosity, in `dimension`.
inline TimeStepInputs time_step_inputs(const Material* m, int count, bool implicit_viscosity, double surface_tension,
                                       double solid_alpha = 0, double solid_beta = 0, int dimension = 3) {
  TimeStepInputs in;
  double c_solid = 0;
  for (int k = 0; k < count; ++k) {
    in.c_max = std::max(in.c_max, double(m[k].sound_speed));
    if (m[k].kind == MaterialKind::Elastic) c_solid = std::max(c_solid, double(m[k].sound_speed));
    if (m[k].kind != MaterialKind::Fluid) continue;
    if (!implicit_viscosity && m[k].viscosity > 0) in.nu_max = std::max(in.nu_max, double(m[k].viscosity / m[k].rest_density));
    if (surface_tension > 0) {
      const double r = double(m[k].rest_density) / surface_tension;
      in.rho_over_sigma = in.rho_over_sigma > 0 ? std::min(in.rho_over_sigma, r) : r;
    }
  }
  in.solid_alpha_c = solid_alpha * c_solid, in.solid_beta = solid_beta, in.dimension = dimension;
  return in;
}

// The kinematic viscosity that Monaghan's artificial viscosity amounts to, nu = alpha h_s c / (2 (d + 2))
// (alpha h c / 8 in 2D, / 10 in 3D: Monaghan 2005, Rep. Prog. Phys. 68:1703, §4.2), with the
// quadratic term's beta h_s |v_ij|, |v_ij| <= 2 v_max, beside alpha c. Its viscous limit is
// h_s / (alpha c) in 2D: at alpha = 10 (Deptulski's softening bar) 2.5 times below the acoustic one.
inline double solid_artificial_viscosity_nu(const TimeStepInputs& in, double h_s, double v_max) {
  return h_s * (in.solid_alpha_c + 2 * in.solid_beta * v_max) / (2 * (in.dimension + 2));
}

struct TimeStepLimits {
  double acoustic = std::numeric_limits<double>::infinity();      // 0.25 h_s / (c_max + v_max)  eq. 50
  double acceleration = std::numeric_limits<double>::infinity();  // 0.25 sqrt(h_s / a_max)      eq. 51
  double viscous = std::numeric_limits<double>::infinity();       // 0.125 h_s^2 / nu_max        eq. 52
  double capillary = std::numeric_limits<double>::infinity();     // 0.25 sqrt(rho_min h_s^3 / (2 pi sigma))

  double min() const { return std::min({acoustic, acceleration, viscous, capillary}); }
  const char* limiting() const {
    const double m = min();
    return m == acoustic ? "acoustic" : m == acceleration ? "acceleration" : m == viscous ? "viscous" : "capillary";
  }
};

// `nu_max` is the largest kinematic viscosity mu/rho of any fluid; `rho_over_sigma` the smallest
// fluid density over the surface tension (0 without surface tension), for the capillary-wave
// limit of Morris (2000; not in Pazdniakou 2018); `factor` scales every limit.
inline TimeStepLimits time_step_limits(double h_s, double c_max, double v_max, double a_max, double nu_max,
                                       double factor, double rho_over_sigma = 0) {
  TimeStepLimits l;
  l.acoustic = factor * 0.25 * h_s / (c_max + v_max);
  if (a_max > 0) l.acceleration = factor * 0.25 * std::sqrt(h_s / a_max);
  if (nu_max > 0) l.viscous = factor * 0.125 * h_s * h_s / nu_max;
  if (rho_over_sigma > 0) l.capillary = factor * 0.25 * std::sqrt(rho_over_sigma * h_s * h_s * h_s / (2 * M_PI));
  return l;
}
inline TimeStepLimits time_step_limits(double h_s, const TimeStepInputs& in, double v_max, double a_max, double factor) {
  const double nu = std::max(in.nu_max, solid_artificial_viscosity_nu(in, h_s, v_max));
  return time_step_limits(h_s, in.c_max, v_max, a_max, nu, factor, in.rho_over_sigma);
}

}  // namespace psph
