#pragma once
// Small-strain isotropic elasticity with a damage variable that degrades the moduli and a
// unilateral (crack-closure) effect (Deptulski 2021 eq. 2.84 and §4.1.3, digest §3.3):
//   sigma = k_eff tr(eps) I + 2 mu (1 - d) dev(eps),   k_eff = k (1 - d) if tr(eps) > 0, else k,
// so a damaged particle carries no tension but recovers its bulk stiffness when its crack closes
// under compression. dev(eps) = eps - tr(eps)/3 I is the 3D deviator in every dimension: in 2D the
// solid is in plane strain with 3D moduli (digest O-S4).
#include "core/vec.hpp"

namespace psph {

// (g + g^T) / 2.
template <int D>
PSPH_HD inline Mat<D> symmetric_part(const Mat<D>& g) {
  Mat<D> e;
  for (int r = 0; r < D; ++r)
    for (int c = 0; c < D; ++c) e.a[r][c] = Real(0.5) * (g.a[r][c] + g.a[c][r]);
  return e;
}

// The bulk modulus with crack closure: damaged in tension only.
PSPH_HD inline Real effective_bulk_modulus(Real tr_eps, Real k, Real damage) {
  return tr_eps > Real(0) ? k * (Real(1) - damage) : k;
}

template <int D>
PSPH_HD inline Mat<D> small_strain_stress(const Mat<D>& eps, Real k, Real mu, Real damage = 0) {
  const Real tr = trace(eps);
  const Real k_eff = effective_bulk_modulus(tr, k, damage), mu_eff = mu * (Real(1) - damage);
  Mat<D> s;
  for (int r = 0; r < D; ++r)
    for (int c = 0; c < D; ++c) s.a[r][c] = Real(2) * mu_eff * eps.a[r][c];
  for (int r = 0; r < D; ++r) s.a[r][r] += (k_eff - Real(2) * mu_eff / Real(3)) * tr;
  return s;
}

// The solid's pressure -k tr(eps) (compression positive; in 2D plane strain tr(eps) is also the
// volume change): Pazdniakou eq. 74's c_solid^2 (rho - rho0) with rho = rho0 (1 - tr eps).
template <int D>
PSPH_HD inline Real small_strain_pressure(const Mat<D>& eps, Real k, Real damage = 0) {
  const Real tr = trace(eps);
  return -effective_bulk_modulus(tr, k, damage) * tr;
}

// Elastic energy density sigma : eps / 2.
template <int D>
PSPH_HD inline Real half_contraction(const Mat<D>& sigma, const Mat<D>& eps) {
  Real w = 0;
  for (int r = 0; r < D; ++r)
    for (int c = 0; c < D; ++c) w += sigma.a[r][c] * eps.a[r][c];
  return Real(0.5) * w;
}

}  // namespace psph
