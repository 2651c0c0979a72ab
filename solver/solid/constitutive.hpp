#pragma once
// Small-strain isotropic elasticity with a damage variable that degrades the moduli and a
// unilateral (crack-closure) effect (Deptulski 2021 eq. 2.84 and §4.1.3, eq. 4.18a):
//   sigma = k_eff tr(eps) I + 2 mu (1 - d) dev(eps),   k_eff = k (1 - d) if tr(eps) > 0, else k,
// so a damaged particle carries no tension but recovers its bulk stiffness when its crack closes
// under compression. dev(eps) = eps - tr(eps)/3 I is the 3D deviator in every dimension: in 2D the
// solid is in plane strain with 3D moduli (the thesis never says which; its 3D deviator implies it).
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

// Saint Venant-Kirchhoff (Deptulski 2021 §2.4.1, eqs. 2.67-2.74): from H = grad u in the reference
// configuration, F = I + H, the Green-Lagrange strain E = (H + H^T + H^T H) / 2, the second
// Piola-Kirchhoff stress S = k tr(E) I + 2 mu dev(E) (the small-strain law applied to E, with its
// damage argument), the first P = F S, and the Cauchy stress sigma = P F^T / det F (for output and
// damage criteria).
template <int D>
struct LargeStrain {
  Mat<D> F, green_lagrange, piola, cauchy;
};
template <int D>
PSPH_HD inline LargeStrain<D> saint_venant_kirchhoff(const Mat<D>& H, Real k, Real mu, Real damage = 0) {
  LargeStrain<D> r;
  r.F = H;
  for (int a = 0; a < D; ++a) r.F.a[a][a] += Real(1);
  for (int a = 0; a < D; ++a)
    for (int b = 0; b < D; ++b) {
      Real hh = 0;
      for (int c = 0; c < D; ++c) hh += H.a[c][a] * H.a[c][b];
      r.green_lagrange.a[a][b] = Real(0.5) * (H.a[a][b] + H.a[b][a] + hh);
    }
  const Mat<D> S = small_strain_stress(r.green_lagrange, k, mu, damage);
  const Real inv_J = Real(1) / determinant(r.F);
  for (int a = 0; a < D; ++a)
    for (int b = 0; b < D; ++b) {
      Real p = 0;
      for (int c = 0; c < D; ++c) p += r.F.a[a][c] * S.a[c][b];
      r.piola.a[a][b] = p;
    }
  for (int a = 0; a < D; ++a)
    for (int b = 0; b < D; ++b) {
      Real c = 0;
      for (int e = 0; e < D; ++e) c += r.piola.a[a][e] * r.F.a[b][e];
      r.cauchy.a[a][b] = c * inv_J;
    }
  return r;
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
