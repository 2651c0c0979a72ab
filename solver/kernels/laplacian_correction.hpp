#pragma once
// Tensor correction of the Morris Laplacian. The Morris sum L u_i = sum_j V_j 2 (u_i - u_j) F_ij
// (F = (1/r) dW/dr) gives H : M for a quadratic field with Hessian H, where
// M = -sum_j V_j F_ij r r^T is I in the continuum but not on a sheared lattice. Weighting each pair
// by w_ij = r^T A_i r / r^2, with the symmetric A_i that solves
//     -sum_j V_j F_ij r r^T (r^T A_i r) / r^2 = I,
// makes the sum exact for every quadratic field on any centrally symmetric neighbourhood
// (the second-derivative consistency condition of Fatehi & Manzari 2011, Comput. Math. Appl.
// 61:482, written for the Morris pair form). D(D+1)/2 unknowns: 1, 3 or 6.
#include "core/vec.hpp"

namespace psph {

// none: the Morris sum as printed; trace: divided by tr(M)/D (exact on a cubic lattice, the
// default); tensor: LaplacianTensor below (exact on sheared lattices too; one more neighbour loop).
enum class LaplacianCorrection { None, Trace, Tensor };

template <int D>
struct LaplacianTensor {
  static constexpr int N = D * (D + 1) / 2;
  // G[p][q] = -sum_j V_j F_ij (r_a r_b)(r_c r_d) / r^2 for the pairs p = (a, b), q = (c, d), a <= b.
  // The system is sum_q G[p][q] (2 - delta_cd) A_q = delta_ab (G is symmetric: q >= p accumulated).
  Real G[N][N] = {};

  PSPH_HD static void pair_of(int p, int& a, int& b) {
    int k = 0;
    for (int i = 0; i < D; ++i)
      for (int j = i; j < D; ++j, ++k)
        if (k == p) a = i, b = j;
  }

  // Adds neighbour j: V_j, F_ij and r_ij.
  PSPH_HD void add(Real V, Real F, const Vec<D>& r) {
    Real u[N];
    int k = 0;
    for (int a = 0; a < D; ++a)
      for (int b = a; b < D; ++b) u[k++] = r[a] * r[b];
    const Real w = -V * F / norm2(r);
    for (int p = 0; p < N; ++p) {
      const Real wp = w * u[p];
      for (int q = p; q < N; ++q) G[p][q] += wp * u[q];
    }
  }

  // A_i by Gaussian elimination with partial pivoting; false for a degenerate neighbourhood.
  PSPH_HD bool solve(Mat<D>& A) const {
    Real m[N][N + 1];
    for (int p = 0; p < N; ++p) {
      int a = 0, b = 0;
      pair_of(p, a, b);
      for (int q = 0; q < N; ++q) {
        int c = 0, d = 0;
        pair_of(q, c, d);
        m[p][q] = (q >= p ? G[p][q] : G[q][p]) * (c == d ? Real(1) : Real(2));
      }
      m[p][N] = a == b ? Real(1) : Real(0);
    }
    Real scale = 0;
    for (int p = 0; p < N; ++p) scale = fmax(scale, fabs(m[p][p]));
    for (int col = 0; col < N; ++col) {
      int piv = col;
      for (int row = col + 1; row < N; ++row)
        if (fabs(m[row][col]) > fabs(m[piv][col])) piv = row;
      if (!(fabs(m[piv][col]) > Real(1e-8) * scale)) return false;
      for (int k = 0; k <= N; ++k) {
        const Real t = m[col][k];
        m[col][k] = m[piv][k], m[piv][k] = t;
      }
      for (int row = 0; row < N; ++row) {
        if (row == col) continue;
        const Real f = m[row][col] / m[col][col];
        for (int k = col; k <= N; ++k) m[row][k] -= f * m[col][k];
      }
    }
    for (int p = 0; p < N; ++p) {
      int a = 0, b = 0;
      pair_of(p, a, b);
      A.a[a][b] = A.a[b][a] = m[p][N] / m[p][p];
    }
    return true;
  }

  // The pair weight r^T A r / r^2.
  PSPH_HD static Real weight(const Mat<D>& A, const Vec<D>& r) { return dot(r, A * r) / norm2(r); }
};

}  // namespace psph
