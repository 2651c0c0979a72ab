#pragma once
// Eigen-decomposition of a small symmetric matrix (cyclic Jacobi rotations): principal stresses
// and their directions. Host and device.
#include <cmath>

#include "core/vec.hpp"

namespace psph {

// Cyclic Jacobi rotations (Golub & Van Loan, Algorithm 8.4.1) on m until its off-diagonal part
// is negligible; the rotations accumulate into v where asked for (its columns: eigenvectors).
template <int N, bool Vectors>
PSPH_HD void jacobi_diagonalise(double (&m)[N][N], double (&v)[N][N]) {
  for (int sweep = 0; sweep < 32; ++sweep) {
    double off = 0, scale = 0;
    for (int i = 0; i < N; ++i)
      for (int j = 0; j < N; ++j) (i == j ? scale : off) += m[i][j] * m[i][j];
    if (off <= 1e-30 * scale || off == 0) break;
    for (int p = 0; p < N; ++p)
      for (int q = p + 1; q < N; ++q) {
        if (m[p][q] == 0) continue;
        const double tau = (m[q][q] - m[p][p]) / (2 * m[p][q]);
        const double t = (tau >= 0 ? 1 : -1) / (fabs(tau) + sqrt(1 + tau * tau));
        const double c = 1 / sqrt(1 + t * t), s = t * c;
        for (int k = 0; k < N; ++k) {  // m <- m J
          const double mkp = m[k][p], mkq = m[k][q];
          m[k][p] = c * mkp - s * mkq, m[k][q] = s * mkp + c * mkq;
        }
        for (int k = 0; k < N; ++k) {  // m <- J^T m
          const double mpk = m[p][k], mqk = m[q][k];
          m[p][k] = c * mpk - s * mqk, m[q][k] = s * mpk + c * mqk;
        }
        if (Vectors)
          for (int k = 0; k < N; ++k) {
            const double vkp = v[k][p], vkq = v[k][q];
            v[k][p] = c * vkp - s * vkq, v[k][q] = s * vkp + c * vkq;
          }
      }
  }
}

// The symmetric copy of a's upper triangle.
template <int N>
PSPH_HD void symmetric_copy(const double (&a)[N][N], double (&m)[N][N]) {
  for (int i = 0; i < N; ++i)
    for (int j = 0; j < N; ++j) m[i][j] = i <= j ? a[i][j] : a[j][i];
}

// a: N x N symmetric, row-major (read only the upper triangle). On return `values` holds the
// eigenvalues in descending order and row k of `vectors` the unit eigenvector of values[k].
template <int N>
PSPH_HD void symmetric_eigen(const double (&a)[N][N], double (&values)[N], double (&vectors)[N][N]) {
  double m[N][N], v[N][N];
  symmetric_copy(a, m);
  for (int i = 0; i < N; ++i)
    for (int j = 0; j < N; ++j) v[i][j] = i == j;
  jacobi_diagonalise<N, true>(m, v);
  int order[N];
  for (int i = 0; i < N; ++i) order[i] = i;
  for (int i = 0; i < N; ++i)  // descending by eigenvalue
    for (int j = i + 1; j < N; ++j)
      if (m[order[j]][order[j]] > m[order[i]][order[i]]) {
        const int t = order[i];
        order[i] = order[j], order[j] = t;
      }
  for (int k = 0; k < N; ++k) {
    values[k] = m[order[k]][order[k]];
    for (int i = 0; i < N; ++i) vectors[k][i] = v[i][order[k]];
  }
}

// The eigenvalues only, in descending order: in 2D in closed form, (a + d)/2 +- |((a - d)/2, b)|
// (the damage criteria need no directions); in 3D by the same rotations without the vectors.
template <int N>
PSPH_HD void symmetric_eigenvalues(const double (&a)[N][N], double (&values)[N]) {
  if constexpr (N == 1) {
    values[0] = a[0][0];
  } else if constexpr (N == 2) {
    const double mean = 0.5 * (a[0][0] + a[1][1]), half = 0.5 * (a[0][0] - a[1][1]);
    const double radius = sqrt(half * half + a[0][1] * a[0][1]);  // strains and stresses: no overflow
    values[0] = mean + radius, values[1] = mean - radius;
  } else {
    double m[N][N], unused[N][N];
    symmetric_copy(a, m);
    jacobi_diagonalise<N, false>(m, unused);
    for (int k = 0; k < N; ++k) values[k] = m[k][k];
    for (int i = 0; i < N; ++i)
      for (int j = i + 1; j < N; ++j)
        if (values[j] > values[i]) {
          const double t = values[i];
          values[i] = values[j], values[j] = t;
        }
  }
}

}  // namespace psph
