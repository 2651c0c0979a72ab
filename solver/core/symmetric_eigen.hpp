#pragma once
// Eigen-decomposition of a small symmetric matrix (cyclic Jacobi rotations): principal stresses
// and their directions. Host and device.
#include <cmath>

#include "core/vec.hpp"

namespace psph {

// a: N x N symmetric, row-major (read only the upper triangle). On return `values` holds the
// eigenvalues in descending order and row k of `vectors` the unit eigenvector of values[k].
template <int N>
PSPH_HD void symmetric_eigen(const double (&a)[N][N], double (&values)[N], double (&vectors)[N][N]) {
  double m[N][N], v[N][N];
  for (int i = 0; i < N; ++i)
    for (int j = 0; j < N; ++j) m[i][j] = i <= j ? a[i][j] : a[j][i], v[i][j] = i == j;
  for (int sweep = 0; sweep < 32; ++sweep) {
    double off = 0, scale = 0;
    for (int i = 0; i < N; ++i)
      for (int j = 0; j < N; ++j) (i == j ? scale : off) += m[i][j] * m[i][j];
    if (off <= 1e-30 * scale || off == 0) break;
    for (int p = 0; p < N; ++p)
      for (int q = p + 1; q < N; ++q) {
        if (m[p][q] == 0) continue;
        // Rotation that zeroes m[p][q] (Golub & Van Loan, Algorithm 8.4.1).
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
        for (int k = 0; k < N; ++k) {  // columns of v are the eigenvectors
          const double vkp = v[k][p], vkq = v[k][q];
          v[k][p] = c * vkp - s * vkq, v[k][q] = s * vkp + c * vkq;
        }
      }
  }
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

}  // namespace psph
