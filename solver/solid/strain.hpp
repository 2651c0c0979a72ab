#pragma once
// Strain and stress of an elastic solid (the stress form's first pass, and output):
//   eps_i = sym sum_j V_j (u_j - u_i) (x) K_i grad W~_ij   (Deptulski eq. 2.82, printed with positions
//   r for u and unsymmetrised, cf. eq. 1.28; the mixed correction eq. 2.63b, kernels/corrections.hpp)
//   sigma_i = k tr(eps) I + 2 mu dev(eps)                  (eq. 2.84, constitutive.hpp)
// or, with [solid] model = "saint_venant_kirchhoff" (large strain, total Lagrangian, Deptulski
// §2.4.1), F = I + grad u, E = (F^T F - I)/2, S = k tr(E) I + 2 mu dev(E), P = F S (constitutive.hpp),
// over the solid's particles and the walls in reach, which present the mirrored displacement
// (solid/clamp.hpp): linear across a clamp, so the corrected gradient stays exact there, as it is
// at any truncated support (free surfaces need nothing).
#include "kernels/corrections.hpp"
#include "solid/constitutive.hpp"
#include "solid/elastic_force.hpp"
#include "stage/pass_context.hpp"
#include "core/pass_fields.hpp"

namespace psph {

// The solid's neighbours of particle i: elastic and wall particles, not fluids, nor rigid bodies
// (an inclusion meets the solid by contact only, rigid/rigid_body.hpp, Pazdniakou §5.2.4).
template <int D, class NB = NeighbourList<D>>
struct SolidNeighbours {
  NB nb;
  ParticleView<D> s;
  MaterialTable<D> mats;
  template <class F>
  PSPH_HD void for_each(int i, F&& f) const {
    nb.for_each(i, [&](int j, const Vec<D>& rij, Real r) PSPH_PAIR {
      const int mj = s.material[j];
      if (!mats.is_fluid(mj) && !mats.is_rigid(mj)) f(j, rij, r);
    });
  }
};

// Per elastic particle: the gradient correction S_i, G_i, K_i over the solid's neighbours, stored.
template <int D, class NB = NeighbourList<D>>
struct SolidCorrectionPass {
  static constexpr FieldNames neighbour_reads = kSolidPairReads;
  static constexpr FieldNames writes{};
  PairContext<D, NB> c;
  PSPH_HD GradientCorrection<D> correction(int i) const {
    auto volume = [&](int j) { return solid_sum_volume(c.s, j); };
    return gradient_correction(SolidNeighbours<D, NB>{c.nb, c.s, c.mats}, c.kern, i, volume);
  }
  PSPH_HD void operator()(int i) const {
    if (!c.mats.is_elastic(c.s.material[i])) return;
    const GradientCorrection<D> corr = correction(i);
    c.s.shepard[i] = corr.shepard, c.s.shepard_grad[i] = corr.grad_sum, c.s.kcorr[i] = corr.K;
  }
};

// The stored correction of particle i (SolidCorrectionPass).
template <int D>
PSPH_HD inline GradientCorrection<D> stored_correction(const ParticleView<D>& s, int i) {
  GradientCorrection<D> c;
  c.shepard = s.shepard[i], c.grad_sum = s.shepard_grad[i], c.K = s.kcorr[i];
  return c;
}

// Per elastic particle: the strain, the stress, and the gradient correction S_i, G_i, K_i kept for
// the force pass. `corrections_kept`: the stored ones are current (SolidCorrectionPass since the
// last list build), so that only the displacement sum remains.
template <int D, class NB = NeighbourList<D>>
struct StrainStressPass {
  static constexpr FieldNames neighbour_reads = kSolidPairReads;
  static constexpr FieldNames writes{"strain", "stress", "deformation_gradient"};
  PairContext<D, NB> c;  // the solid's neighbours, kernel, particles, materials
  bool corrections_kept = false;
  PSPH_HD void operator()(int i) const {
    const int mi = c.s.material[i];
    if (!c.mats.is_elastic(mi)) return;
    const SolidNeighbours<D, NB> solid{c.nb, c.s, c.mats};
    auto volume = [&](int j) { return solid_sum_volume(c.s, j); };
    const GradientCorrection<D> corr =
        corrections_kept ? stored_correction(c.s, i) : SolidCorrectionPass<D, NB>{c}.correction(i);
    CorrectedGradientSum<D> sum;
    solid.for_each(i, [&](int j, const Vec<D>& rij, Real r) {
      sum.add(to_real(c.s.u[j] - c.s.u[i]), c.kern.W(r), c.kern.grad(rij, r), volume(j));
    });
    const Mat<D> grad_u = sum.corrected(corr);
    if (c.s.grad_u) c.s.grad_u[i] = grad_u;
    const Real k = c.mats[mi].bulk_modulus, mu = c.mats[mi].shear_modulus;
    if (c.s.piola) {  // Saint Venant-Kirchhoff (large strain): Green-Lagrange strain, Piola stress
      const LargeStrain<D> ls = saint_venant_kirchhoff(grad_u, k, mu);
      c.s.strain[i] = ls.green_lagrange, c.s.stress[i] = ls.cauchy, c.s.piola[i] = ls.piola, c.s.defgrad[i] = ls.F;
    } else {
      const Mat<D> eps = symmetric_part(grad_u);
      c.s.strain[i] = eps;
      c.s.stress[i] = small_strain_stress(eps, k, mu);
    }
    if (!corrections_kept) c.s.shepard[i] = corr.shepard, c.s.shepard_grad[i] = corr.grad_sum, c.s.kcorr[i] = corr.K;
  }
};

// g_ij = K_i grad W~_ij from particle i's stored correction (eq. 2.63b with 2.61a).
template <int D>
PSPH_HD PSPH_PAIR inline Vec<D> corrected_gradient(const ParticleView<D>& s, int i, Real W, const Vec<D>& gradW) {
  return stored_correction(s, i).gradient(W, gradW);
}

}  // namespace psph
