#pragma once
// Small-strain elasticity in stress form with the mixed kernel and gradient correction (Deptulski
// 2021 §2.4.2, eqs. 2.82-2.87):
//   a_i = 1/rho_i sum_j V_j (sigma_i g_ij - sigma_j g_ji),   g_ij = K_i grad W~_ij   (eq. 2.86)
// with the strain and stress of solid/strain.hpp. g_ij != -g_ji once corrected, hence two terms;
// the forces are -dE/du of the elastic energy E = sum_i V_i sigma_i : eps_i / 2 (the solid's
// particles only: walls carry no stress, and clamps add the chain rule of their mirror,
// solid/clamp.hpp), so kinetic + E is conserved. Unlike the displacement form's central pair
// forces (elastic_force.hpp), it holds for any Poisson ratio, leaves rigid rotations free at free
// surfaces, and takes a per-particle stress law (damage).
#include "solid/clamp.hpp"
#include "solid/hourglass.hpp"
#include "solid/strain.hpp"
#include "stage/pass_context.hpp"
#include "core/pass_fields.hpp"

namespace psph {

template <int D, class NB = NeighbourList<D>>
struct StressForcePass {
  static constexpr FieldNames neighbour_reads = kSolidPairReads;
  static constexpr FieldNames writes{"acceleration"};
  PairContext<D, NB> c;  // the solid's neighbours, kernel, particles, materials
  Real damping = 0;  // zeta (1/s): a -= zeta v
  // The fluid's traction P_i b_i, b_i = sum_j V_j (g_ij - g_ji) over the solid's neighbours j, P_i
  // the ambient pressure (solid/fluid_coupling.hpp): the stresses taken relative to -P_i I. A wall
  // j (a clamp) counts as the body's continuation, g_ji = -grad_i W_ij (walls have no correction):
  // b_i then loads the faces the fluid wets and not the face on a plate, where a traction fed by
  // the pore water's pressure grew into an instability (VALIDATION.md, the wider crop).
  bool traction = false;
  Real hourglass = 0;  // alpha of the hourglass control (solid/hourglass.hpp), 0 for none
  PSPH_HD void operator()(int i) const {
    const int mi = c.s.material[i];
    if (!c.mats.is_elastic(mi)) return;
    // Small strain: the Cauchy stress; large strain: the first Piola-Kirchhoff stress (the same
    // sum in the reference configuration), and the fluid's pressure on the current surface,
    // J F^-T N dA (Nanson), so that a solid at uniform Cauchy stress -p I stays in equilibrium.
    const Mat<D> sigma_i = c.s.piola ? c.s.piola[i] : c.s.stress[i];
    const Real p_i = traction ? c.s.p_ambient[i] : Real(0);
    const Mat<D> area = c.s.defgrad ? cofactor(c.s.defgrad[i]) : Mat<D>::identity();
    Vec<D> f = Vec<D>::zero(), f_hg = Vec<D>::zero();
    const Real young_i = hourglass > Real(0) ? young_of(c.s, c.mats, i) : Real(0);
    SolidNeighbours<D, NB>{c.nb, c.s, c.mats}.for_each(i, [&](int j, const Vec<D>& rij, Real r) {
      if (r <= Real(0)) return;
      const Real W = c.kern.W(r);
      const Vec<D> gradW = c.kern.grad(rij, r);  // grad_i W_ij; grad_j W_ji = -grad_i W_ij
      const Vec<D> g_ij = corrected_gradient(c.s, i, W, gradW);
      Vec<D> t = sigma_i * g_ij;
      if (c.mats.is_elastic(c.s.material[j])) {
        const Vec<D> g_ji = corrected_gradient(c.s, j, W, gradW * Real(-1));
        t -= (c.s.piola ? c.s.piola[j] : c.s.stress[j]) * g_ji;
        if (traction) t += area * (g_ij - g_ji) * p_i;
        if (hourglass > Real(0))
          f_hg += hourglass_share(c.s, c.mats, c.kern, young_i, i, j, rij, r, solid_sum_volume(c.s, j));
      } else if (traction) {
        t += area * (g_ij + gradW) * p_i;
      }
      f += t * solid_sum_volume(c.s, j);
    });
    Vec<D> a = f * (Real(1) / c.s.rho[i]) + f_hg * (hourglass / c.s.rho0[i]);  // alpha V_i / m_i = alpha / rho0_i
    const int w = c.s.mirror[i] >= 0 ? c.s.index_of_id[c.s.mirror[i]] : -1;  // -1 also: a halo copy's far wall
    if (w >= 0) a += clamp_reaction(c.nb, c.kern, c.s, c.mats, w) * (Real(1) / c.s.m[i]);
    c.s.a[i] = a + c.mats.body_force[mi] - c.s.v[i] * damping;
  }
};

// Elastic energy V_i S : E_i / 2 of the stress form, S from the stress the forces read (degraded
// where [damage] applies; small strain: S = sigma, E = eps; large strain: S from sigma and F).
template <int D>
struct StrainEnergyOf {
  ParticleView<D> s;
  MaterialTable<D> mats;
  PSPH_HD Real operator()(int i) const {
    const int mi = s.material[i];
    if (!mats.is_elastic(mi)) return Real(0);
    return s.m[i] / s.rho[i] * half_contraction(s.piola ? second_piola(s.stress[i], s.defgrad[i]) : s.stress[i], s.strain[i]);
  }
};

}  // namespace psph
