#pragma once
// Checks of the SPH operators against exact values: kernel normalisation in 1D/2D/3D, Deptulski
// (2021) Table 2.1 (pair contributions of the corrected gradient, §2.5.1) and the divergence
// tests of his §2.5 (quartic fields, particle density and disorder, 1D to 3D; §2.5.1-2.5.4).
#include <vector>

#include "kernels/kernel.hpp"
#include "validation/validation_cases.hpp"

namespace psph {

std::vector<ValidationRecord> operator_checks();

// Deptulski Table 2.1: V_b (v_b - v_a) . K grad W~_ab for a = point 4 of the 5-point bar and
// b = 2, 3, 4, 5, with v = 20 x. Returns the four pair values.
std::vector<double> deptulski_table_2_1_pairs();

// Relative error of the divergence sum_b V_b (v_b - v_a) . K_a grad W~_ab (Deptulski eqs. 2.42a,
// 2.63b) of the quartic field v_d = q(x_d), q = -4x^4 + 3x^3 + 15x^2 - x + 15 (eq. 2.92c, 2.95), on
// `per_axis` cell-centred points per axis of the unit bar/square/cube at 50 m, support 0.56 m
// (his "h = 2.8 dx" of §2.5 read as the support radius), each point moved by up to `jitter`
// spacings (uniform, fixed seed).
struct DivergenceErrors {
  double max = 0;      // over all points
  double point4 = 0;   // 1D, the fourth point (x = 50.7 m with 5 points)
  int points = 0;
};
DivergenceErrors quartic_divergence(int dimension, int per_axis, double jitter = 0, unsigned seed = 1);

// Riemann sum of W over a lattice of spacing R/`per_support` (~ the kernel's integral, 1).
double kernel_integral(int dimension, KernelType type, int per_support);

}  // namespace psph
