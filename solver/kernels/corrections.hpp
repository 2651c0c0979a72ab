#pragma once
// Kernel and gradient corrections as reusable per-particle operators (Deptulski 2021, Sec. 2.3.1).
//   Shepard kernel            W~_ab = W_ab / S_a,  S_a = sum_b V_b W_ab                (eq. 2.58)
//   its exact gradient        grad W~_ab = (grad W_ab S_a - G_a W_ab) / S_a^2,
//                             G_a = sum_b V_b grad W_ab                                (eq. 2.61a)
//   corrective matrix         K_a = (sum_b V_b grad W~_ab (x) r_ba)^-1                 (eq. 2.62a)
//   mixed corrected gradient  K_a grad W~_ab                                           (eq. 2.63b)
// With it, sum_b V_b (f_b - f_a) (x) K_a grad W~_ab is exact for linear f.
#include "core/vec.hpp"
#include "kernels/kernel.hpp"
#include "neighbours/cell_grid.hpp"

namespace psph {

template <int D>
struct GradientCorrection {
  Real shepard = 1;              // S_a (self term included)
  Vec<D> grad_sum = Vec<D>::zero();  // G_a
  Mat<D> K = Mat<D>::identity();
  bool regular = true;           // false where sum V grad W~ (x) r_ba was singular (K = I then)

  // Shepard-normalised kernel value.
  PSPH_HD Real kernel(Real W) const { return W / shepard; }
  // Exact gradient of the Shepard kernel (eq. 2.61a).
  PSPH_HD PSPH_PAIR Vec<D> shepard_gradient(Real W, const Vec<D>& gradW) const {
    return (gradW * shepard - grad_sum * W) * (Real(1) / (shepard * shepard));
  }
  // Mixed kernel and gradient correction (eq. 2.63b).
  PSPH_HD PSPH_PAIR Vec<D> gradient(Real W, const Vec<D>& gradW) const { return K * shepard_gradient(W, gradW); }
};

// sum_j w_j f_j (x) K_a grad W~_aj, summed per pair without the correction and corrected once:
// K grad W~ = K (grad W S - G W) / S^2 (eq. 2.61a), so the sum is (S A - b (x) G) K^T / S^2 with
// A = sum w f (x) grad W and b = sum w W f (no division or matrix product per pair).
template <int D>
struct CorrectedGradientSum {
  Mat<D> A = Mat<D>::zero();
  Vec<D> b = Vec<D>::zero();
  PSPH_HD PSPH_PAIR void add(const Vec<D>& f, Real W, const Vec<D>& gradW, Real w) {
    add_outer(A, f, gradW, w);
    b += f * (w * W);
  }
  PSPH_HD Mat<D> corrected(const GradientCorrection<D>& c) const {
    const Real inv = Real(1) / (c.shepard * c.shepard);
    Mat<D> out;
    for (int r = 0; r < D; ++r)
      for (int s = 0; s < D; ++s) {
        Real sum = 0;
        for (int k = 0; k < D; ++k) sum += (c.shepard * A.a[r][k] - b.c[r] * c.grad_sum.c[k]) * c.K.a[s][k];
        out.a[r][s] = sum * inv;
      }
    return out;
  }
};

// NB is any neighbour provider with for_each(i, f(j, r_ij, r)) (cell view or list).
// Shepard sum S_a = sum_b V_b W_ab including the particle itself. `volume(j)` returns V_j.
template <int D, class NB, class Volume>
PSPH_HD Real shepard_sum(const NB& nb, const Kernel<D>& kern, int i, const Volume& volume) {
  Real s = volume(i) * kern.W(Real(0));
  nb.for_each(i, [&](int j, const Vec<D>&, Real r) { s += volume(j) * kern.W(r); });
  return s;
}

template <int D, class NB, class Volume>
PSPH_HD GradientCorrection<D> gradient_correction(const NB& nb, const Kernel<D>& kern, int i,
                                                  const Volume& volume) {
  GradientCorrection<D> c;
  c.shepard = volume(i) * kern.W(Real(0));
  nb.for_each(i, [&](int j, const Vec<D>& rij, Real r) {
    c.shepard += volume(j) * kern.W(r);
    c.grad_sum += kern.grad(rij, r) * volume(j);
  });
  Mat<D> A = Mat<D>::zero();
  nb.for_each(i, [&](int j, const Vec<D>& rij, Real r) {
    const Vec<D> g = c.shepard_gradient(kern.W(r), kern.grad(rij, r));
    add_outer(A, g, rij * Real(-1), volume(j));  // r_ba = x_b - x_a = -r_ab
  });
  // Scale-aware singularity guard: A is dimensionless (~identity) for a full support.
  c.regular = invert(A, c.K, Real(1e-6));
  return c;
}

}  // namespace psph
