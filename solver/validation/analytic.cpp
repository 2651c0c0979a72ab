#include "validation/analytic.hpp"

#include <cmath>

namespace psph {

double poiseuille_couette_velocity(double x, double t, double L, double g, double V, double nu, int terms) {
  const double pi = M_PI;
  double v = g / (2 * nu) * x * (L - x) + V * x / L;
  for (int n = 1; n <= terms; ++n) {
    const double npi = n * pi;
    const double sgn = (n % 2 == 0) ? 1.0 : -1.0;  // (-1)^n
    const double coef = g / nu * L * L * 2 * (sgn - 1) / (npi * npi * npi) - 2 * V * (-sgn) / npi;
    const double decay = std::exp(-npi * npi * nu * t / (L * L));
    if (decay < 1e-300) break;
    v += coef * decay * std::sin(npi * x / L);
  }
  return v;
}

double two_phase_poiseuille_velocity(double x, double l, double F, double mu_gas, double mu_liquid) {
  const double mu = x < 0 ? mu_gas : mu_liquid, s = mu_gas + mu_liquid;
  return -F * l * l / (2 * mu) * (x * x / (l * l) - x / l * (mu_gas - mu_liquid) / s - 2 * mu / s);
}

}  // namespace psph
