#pragma once
// Monaghan artificial viscosity and XSPH for elastic solids (Deptulski 2021 eqs. 2.64-2.66, his
// choice for the Dyka bar: alpha = 0.2, beta = 0.4, epsilon = 0.5; `[solid]` keys), over the
// elastic neighbours of the reference configuration with their current separations (a rigid
// rotation is then not damped, also in large strain):
//   a_i += -sum_j m_j Pi_ij grad_i W_ij,  Pi_ij = (alpha c nu_ij + beta nu_ij^2) / rho_ij > 0 for
//   approaching pairs (0 otherwise), nu_ij = -h_s (v_ij . r_ij) / (r_ij^2 + 0.01 h_s^2)   (eqs. 2.64-2.65,
//   written with the sign that makes the force repulsive);
//   v_xsph_i = epsilon sum_j m_j 2 (v_j - v_i) / (rho_i + rho_j) W_ij over the same material (eq. 2.66
//   with Monaghan's kernel factor W_ij, missing there and in Pazdniakou eq. 76): moves the particle only.
// Pair terms are antisymmetric: momentum is kept. The energy they take is not in the monitors'
// dissipated_energy (the damping's only). Runs after the solid's force pass when either is on.
#include "core/material.hpp"
#include "kernels/kernel.hpp"
#include "neighbours/neighbour_list.hpp"
#include "state/particles.hpp"
#include "core/pass_fields.hpp"

namespace psph {

template <int D, class NB = NeighbourList<D>>
struct SolidViscosityPass {
  static constexpr FieldNames neighbour_reads = kSolidPairReads;
  static constexpr FieldNames writes{"acceleration", "xsph_correction"};
  NB nb;  // the solid's pairs
  CellGrid<D> grid;
  Kernel<D> kern;
  ParticleView<D> s;
  MaterialTable<D> mats;
  Real alpha, beta, xsph, smoothing_length;
  PSPH_HD void operator()(int i) const {
    const int mi = s.material[i];
    if (!mats.is_elastic(mi)) return;
    const Real h = smoothing_length, c_i = mats[mi].sound_speed;
    Vec<D> a = Vec<D>::zero(), xs = Vec<D>::zero();
    nb.for_each(i, [&](int j, const Vec<D>&, Real) PSPH_PAIR {
      const int mj = s.material[j];
      const Vec<D> rij = grid.separation(s.x[i], s.x[j]);
      const Real r = norm(rij);
      if (!(r > Real(0)) || r >= kern.support || !mats.is_elastic(mj)) return;
      const Vec<D> vij = s.v[i] - s.v[j];
      const Real vr = dot(vij, rij), rho_ij = Real(0.5) * (s.rho[i] + s.rho[j]);
      if (vr < Real(0)) {
        const Real nu = -h * vr / (r * r + Real(0.01) * h * h);
        const Real pi = (alpha * Real(0.5) * (c_i + mats[mj].sound_speed) * nu + beta * nu * nu) / rho_ij;
        a -= rij * (s.m[j] * pi * kern.F(r));
      }
      if (mj == mi) xs -= vij * (Real(2) * s.m[j] / (s.rho[i] + s.rho[j]) * kern.W(r));
    });
    s.a[i] += a;
    s.v_xsph[i] = xs * xsph;
  }
};

}  // namespace psph
