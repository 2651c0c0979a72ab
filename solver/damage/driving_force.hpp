#pragma once
// The damage driving force of the thermodynamic models with crack closure (Deptulski 2021 §4.1.3):
// Y = -g'(D) w~, where w~ is the energy that damage can release, eq. 4.18b with
// k(D)/k0 = mu(D)/mu0 = g(D):
//   w~ = k0 (tr eps)^2 / 2 + mu0 eps^d : eps^d   while tr eps >= 0 (open cracks),
//   w~ = mu0 eps^d : eps^d                       while tr eps < 0 (closed: the bulk part is intact).
// eps^d is the 3D deviator in every dimension: 1D and 2D are uniaxial and plane strain, whose
// out-of-plane normal strains are 0 and deviatoric parts -tr(eps)/3 (as solid/constitutive.hpp).
#include "damage/degradation.hpp"

namespace psph {

// eps^d : eps^d of the 3D deviator, with the (3 - D) out-of-plane components -tr(eps)/3.
template <int D>
PSPH_HD inline Real deviator_norm2(const Mat<D>& eps) {
  const Real third = trace(eps) / Real(3);
  Real s = Real(3 - D) * third * third;
  for (int r = 0; r < D; ++r)
    for (int c = 0; c < D; ++c) {
      const Real e = eps.a[r][c] - (r == c ? third : Real(0));
      s += e * e;
    }
  return s;
}

// w~ above; without the unilateral split the bulk part counts in compression too (then
// w~ = eps : C0 : eps / 2).
template <int D>
PSPH_HD inline Real driving_energy(const Mat<D>& eps, Real k0, Real mu0, bool unilateral) {
  const Real tr = trace(eps);
  const Real bulk = (tr >= Real(0) || !unilateral) ? Real(0.5) * k0 * tr * tr : Real(0);
  return bulk + mu0 * deviator_norm2(eps);
}

// Y = -g'(D) w~ (Deptulski eq. 4.18b).
PSPH_HD inline Real damage_driving_force(const ThermodynamicDamage& m, Real damage, Real w) {
  return -degradation_slope(m, damage) * w;
}

}  // namespace psph
