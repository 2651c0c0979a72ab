#pragma once
// Checks of the SPH operators against exact values: kernel normalisation in 1D/2D/3D and
// Deptulski (2021) Table 2.1 (pair contributions of the corrected gradient, digest §4.2).
#include <vector>

#include "kernels/kernel.hpp"
#include "validation/validation_cases.hpp"

namespace psph {

std::vector<ValidationRecord> operator_checks();

// Deptulski Table 2.1: V_b (v_b - v_a) . K grad W~_ab for a = point 4 of the 5-point bar and
// b = 2, 3, 4, 5, with v = 20 x. Returns the four pair values.
std::vector<double> deptulski_table_2_1_pairs();

// Riemann sum of W over a lattice of spacing R/`per_support` (~ the kernel's integral, 1).
double kernel_integral(int dimension, KernelType type, int per_support);

}  // namespace psph
