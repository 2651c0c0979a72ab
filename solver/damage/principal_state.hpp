#pragma once
// Principal strains and intact stresses of a point, as the damage criteria need them: three values,
// tension positive, in descending order. In 1D and 2D the point is in uniaxial and plane strain,
// so the out-of-plane normal strains (0) are principal too, with their stresses lambda tr(eps).
#include "core/symmetric_eigen.hpp"

namespace psph {

struct PrincipalState {
  Real strain[3], stress[3];  // eps_1 >= eps_2 >= eps_3, and sigma_i = 2 mu0 eps_i + lambda0 tr(eps)
};

template <int D>
PSPH_HD inline PrincipalState principal_state(const Mat<D>& eps, Real k0, Real mu0) {
  double a[D][D], values[D];
  for (int r = 0; r < D; ++r)
    for (int c = 0; c < D; ++c) a[r][c] = eps.a[r][c];
  symmetric_eigenvalues<D>(a, values);
  PrincipalState p;
  for (int k = 0; k < 3; ++k) p.strain[k] = k < D ? Real(values[k]) : Real(0);
  for (int i = 0; i < 3; ++i)  // the zeros among the descending values
    for (int j = i + 1; j < 3; ++j)
      if (p.strain[j] > p.strain[i]) {
        const Real t = p.strain[i];
        p.strain[i] = p.strain[j], p.strain[j] = t;
      }
  const Real tr = trace(eps);
  for (int k = 0; k < 3; ++k) p.stress[k] = Real(2) * mu0 * p.strain[k] + (k0 - Real(2) * mu0 / Real(3)) * tr;
  return p;
}

}  // namespace psph
