// Derived fields: principal stresses by Jacobi rotations, and the phase code of each material.
#include <cmath>

#include <gtest/gtest.h>

#include "core/symmetric_eigen.hpp"
#include "state/derived_fields.hpp"

using namespace psph;

TEST(DerivedFields, PrincipalStressesOfARotatedTensor) {
  // R diag(30, -10, 5) R^T with R a rotation by 0.7 rad about z then 0.4 rad about x.
  const double c1 = std::cos(0.7), s1 = std::sin(0.7), c2 = std::cos(0.4), s2 = std::sin(0.4);
  const double Rz[3][3] = {{c1, -s1, 0}, {s1, c1, 0}, {0, 0, 1}}, Rx[3][3] = {{1, 0, 0}, {0, c2, -s2}, {0, s2, c2}};
  double R[3][3] = {}, a[3][3] = {};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) R[i][j] += Rx[i][k] * Rz[k][j];
  const double d[3] = {30, -10, 5};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) a[i][j] += R[i][k] * d[k] * R[j][k];
  double values[3], vectors[3][3];
  symmetric_eigen<3>(a, values, vectors);
  EXPECT_NEAR(values[0], 30, 1e-12);
  EXPECT_NEAR(values[1], 5, 1e-12);
  EXPECT_NEAR(values[2], -10, 1e-12);
  // The sigma_1 direction is R's first column (up to sign).
  const double dot = vectors[0][0] * R[0][0] + vectors[0][1] * R[1][0] + vectors[0][2] * R[2][0];
  EXPECT_NEAR(std::fabs(dot), 1, 1e-12);
}

// The eigenvalues alone (the damage criteria's principal strains): the 2D closed form and the 3D
// rotations without vectors agree with the full decomposition, also with repeated eigenvalues.
TEST(DerivedFields, EigenvaluesAloneAgreeWithTheDecomposition) {
  const double twos[][2][2] = {{{3, 4}, {4, -3}}, {{1e-3, 0}, {0, 1e-3}}, {{-2e-4, 7e-5}, {7e-5, 5e-4}}, {{0, 0}, {0, 0}}};
  for (const auto& a : twos) {
    double full[2], vectors[2][2], alone[2];
    symmetric_eigen<2>(a, full, vectors);
    symmetric_eigenvalues<2>(a, alone);
    for (int k = 0; k < 2; ++k) EXPECT_NEAR(alone[k], full[k], 1e-15 * (1 + std::fabs(full[0]))) << k;
  }
  const double threes[][3][3] = {{{30, 2, -1}, {2, -10, 0.5}, {-1, 0.5, 5}}, {{1, 0, 0}, {0, 1, 0}, {0, 0, -2}},
                                 {{1e-3, 2e-4, 0}, {2e-4, 1e-3, 2e-4}, {0, 2e-4, 1e-3}}};
  for (const auto& a : threes) {
    double full[3], vectors[3][3], alone[3];
    symmetric_eigen<3>(a, full, vectors);
    symmetric_eigenvalues<3>(a, alone);
    for (int k = 0; k < 3; ++k) EXPECT_EQ(alone[k], full[k]) << k;  // the same rotations
  }
}

TEST(DerivedFields, PrincipalFieldsFromAStressField2D) {
  const std::vector<double> stress = {3, 4, 4, -3};  // eigenvalues +-5
  auto src = [&](const std::string&) { return stress; };
  const auto p = compute_derived_field("principal_stress", 2, {}, src);
  ASSERT_EQ(p.size(), 3u);
  EXPECT_NEAR(p[0], 5, 1e-12);
  EXPECT_NEAR(p[1], -5, 1e-12);
  EXPECT_EQ(p[2], 0);
  const auto dir = compute_derived_field("principal_direction", 2, {}, src);
  EXPECT_NEAR(std::fabs(dir[0] * 2 + dir[1] * 1) / std::sqrt(5.0), 1, 1e-12);  // (2, 1)/sqrt 5
}

TEST(DerivedFields, PhaseFollowsTheMaterialKind) {
  Material water, wall;
  wall.kind = MaterialKind::Wall;
  auto src = [](const std::string& name) {
    EXPECT_EQ(name, "material");
    return std::vector<double>{1, 0, 1};
  };
  const auto ph = compute_derived_field("phase", 3, {water, wall}, src);
  EXPECT_EQ(ph, (std::vector<double>{0, 1, 0}));
  EXPECT_THROW(compute_derived_field("no_such_field", 3, {}, src), std::invalid_argument);
}
