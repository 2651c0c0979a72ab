#pragma once
// Adaptive time step from every active limit (Pazdniakou eqs. 50-52 plus the acoustic limit,
// digest §7 item 20), written with the smoothing length h_s (R/2 for the cubic spline) as in
// Morris et al. (1997). Read with h = support radius, as printed in Pazdniakou, eq. 52 allows a
// step 4x larger, and the Poiseuille cases blow up with it (measured).
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace psph {

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
// limit of Morris (2000, digest §7 item 20); `factor` scales every limit.
inline TimeStepLimits time_step_limits(double h_s, double c_max, double v_max, double a_max, double nu_max,
                                       double factor, double rho_over_sigma = 0) {
  TimeStepLimits l;
  l.acoustic = factor * 0.25 * h_s / (c_max + v_max);
  if (a_max > 0) l.acceleration = factor * 0.25 * std::sqrt(h_s / a_max);
  if (nu_max > 0) l.viscous = factor * 0.125 * h_s * h_s / nu_max;
  if (rho_over_sigma > 0) l.capillary = factor * 0.25 * std::sqrt(rho_over_sigma * h_s * h_s * h_s / (2 * M_PI));
  return l;
}

}  // namespace psph
