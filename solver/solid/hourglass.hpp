#pragma once
// Hourglass control of the stress form (Ganzenmüller 2015, Comput. Methods Appl. Mech. Engrg. 286;
// the penalty of O'Connor & Rogers 2021's total-Lagrangian SPH). The collocated strain
// sum (solid/strain.hpp) is blind to a displacement that alternates from one particle to the next:
// with u_j - u_i = -2a on both sides, the two neighbours' terms cancel, so that mode has no elastic
// energy and nothing holds it (a zero-energy mode; Deptulski 2021 §2.3 lists them among SPH's
// drawbacks). The penalty acts on the part of a pair's separation that the pair's own displacement
// gradients H = grad u do not predict,
//   e_ij = (H_i + H_j) X_ij / 2 - u_ij,        X_ij = x_ij - u_ij (the pair in the reference state)
//   f_i += alpha E_ij V_i V_j W(|X_ij|) / |X_ij|^2 (e_ij . x^_ij) x^_ij       (f_ji = -f_ij),
// zero for any linear displacement (a rigid rotation included), so the patch test still holds. E_ij
// is the pair's mean undamaged Young modulus: the control belongs to the discretisation, not to
// the material, and leaves a damaged particle's affine deformation free.
#include "core/material.hpp"
#include "core/vec.hpp"
#include "kernels/kernel.hpp"
#include "state/particles.hpp"

namespace psph {

// Young's modulus of particle i's material (E_i, taken once per particle by the force pass).
template <int D>
PSPH_HD inline Real young_of(const ParticleView<D>& s, const MaterialTable<D>& mats, int i) {
  const auto& m = mats[s.material[i]];
  return young_modulus(m.bulk_modulus, m.shear_modulus);
}

// Elastic neighbour j's share of the penalty force on i, less alpha V_i (x_ij = x_i - x_j at
// distance r > 0, V_j its volume): the force pass scales the sum once.
template <int D>
PSPH_HD PSPH_PAIR inline Vec<D> hourglass_share(const ParticleView<D>& s, const MaterialTable<D>& mats,
                                                const Kernel<D>& kern, Real young_i, int i, int j,
                                                const Vec<D>& x_ij, Real r, Real v_j) {
  const Vec<D> u_ij = to_real(s.u[i] - s.u[j]);
  const Vec<D> X_ij = x_ij - u_ij;
  const Real R2 = dot(X_ij, X_ij);
  if (R2 <= Real(0)) return Vec<D>::zero();
  const Vec<D> e = (s.grad_u[i] * X_ij + s.grad_u[j] * X_ij) * Real(0.5) - u_ij;
  const Vec<D> n = x_ij * (Real(1) / r);
  const Real E = Real(0.5) * (young_i + young_of(s, mats, j));
  return n * (E * v_j * kern.W(std::sqrt(R2)) / R2 * dot(e, n));
}

}  // namespace psph
