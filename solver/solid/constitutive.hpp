#pragma once
// Small-strain isotropic elasticity (Deptulski 2021 eq. 2.84):
//   sigma = k tr(eps) I + 2 mu dev(eps),
// dev(eps) = eps - tr(eps)/3 I the 3D deviator in every dimension: in 2D the solid is in plane
// strain with 3D moduli (the thesis never says which; its 3D deviator implies it). A damaged
// point takes degraded moduli from damage/degraded_stress.hpp.
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

template <int D>
PSPH_HD inline Mat<D> small_strain_stress(const Mat<D>& eps, Real k, Real mu) {
  const Real tr = trace(eps);
  Mat<D> s;
  for (int r = 0; r < D; ++r)
    for (int c = 0; c < D; ++c) s.a[r][c] = Real(2) * mu * eps.a[r][c];
  for (int r = 0; r < D; ++r) s.a[r][r] += (k - Real(2) * mu / Real(3)) * tr;
  return s;
}

// Saint Venant-Kirchhoff (Deptulski 2021 §2.4.1, eqs. 2.67-2.74): from H = grad u in the reference
// configuration, F = I + H, the Green-Lagrange strain E = (H + H^T + H^T H) / 2, the second
// Piola-Kirchhoff stress S = k tr(E) I + 2 mu dev(E) (the small-strain law applied to E), the
// first P = F S, and the Cauchy stress sigma = P F^T / det F (for output and damage criteria).
template <int D>
struct LargeStrain {
  Mat<D> F, green_lagrange, piola, cauchy;
};
// P = F S and sigma = P F^T / det F, given F and S.
template <int D>
PSPH_HD inline void piola_and_cauchy(LargeStrain<D>& r, const Mat<D>& S) {
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
}
template <int D>
PSPH_HD inline LargeStrain<D> saint_venant_kirchhoff(const Mat<D>& H, Real k, Real mu) {
  LargeStrain<D> r;
  r.F = H;
  for (int a = 0; a < D; ++a) r.F.a[a][a] += Real(1);
  for (int a = 0; a < D; ++a)
    for (int b = 0; b < D; ++b) {
      Real hh = 0;
      for (int c = 0; c < D; ++c) hh += H.a[c][a] * H.a[c][b];
      r.green_lagrange.a[a][b] = Real(0.5) * (H.a[a][b] + H.a[b][a] + hh);
    }
  piola_and_cauchy(r, small_strain_stress(r.green_lagrange, k, mu));
  return r;
}

// The solid's pressure -k tr(eps) (compression positive; in 2D plane strain tr(eps) is also the
// volume change): Pazdniakou eq. 74's c_solid^2 (rho - rho0) with rho = rho0 (1 - tr eps).
template <int D>
PSPH_HD inline Real small_strain_pressure(const Mat<D>& eps, Real k) {
  return -k * trace(eps);
}

// The second Piola-Kirchhoff stress of a Cauchy stress: S = J F^-1 sigma F^-T = cof(F)^T sigma cof(F) / J.
template <int D>
PSPH_HD inline Mat<D> second_piola(const Mat<D>& sigma, const Mat<D>& F) {
  const Mat<D> cof = cofactor(F);
  const Real inv_J = Real(1) / determinant(F);
  Mat<D> S = Mat<D>::zero();
  for (int a = 0; a < D; ++a)
    for (int b = 0; b < D; ++b)
      for (int c = 0; c < D; ++c)
        for (int e = 0; e < D; ++e) S.a[a][b] += cof.a[c][a] * sigma.a[c][e] * cof.a[e][b] * inv_J;
  return S;
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
