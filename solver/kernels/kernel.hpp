#pragma once
// Smoothing kernels, written in the normalised distance q = r / R where R is the support radius
// (W = 0 for r >= R). "h" is never used alone: each kernel states its support/h ratio.
#include <cmath>

#include "core/vec.hpp"

namespace psph {

enum class KernelType : int { CubicSpline = 0, WendlandC2 = 1, QuinticSpline = 2 };

// Support radius over smoothing length for each kernel (cubic: 2h, Wendland C2: 2h, quintic: 3h).
PSPH_HD constexpr Real support_per_smoothing_length(KernelType t) {
  return t == KernelType::QuinticSpline ? Real(3) : Real(2);
}

template <int D>
struct Kernel {
  KernelType type = KernelType::CubicSpline;
  Real support = 1;     // R (m)
  Real inv_support = 1; // 1/R
  Real norm = 1;        // sigma_D / R^D

  static Kernel make(KernelType t, Real support_radius) {
    Kernel k;
    k.type = t;
    k.support = support_radius;
    k.inv_support = Real(1) / support_radius;
    k.norm = unit_norm(t) * std::pow(k.inv_support, Real(D));
    return k;
  }

  // Normalisation of the unit-support polynomial, so that the integral of W over R^D is 1.
  static Real unit_norm(KernelType t) {
    const Real pi = Real(M_PI);
    switch (t) {
      case KernelType::CubicSpline:  // M4 spline: 4/(3R), 40/(7 pi R^2), 8/(pi R^3) (Pazdniakou eq. 36)
        return D == 1 ? Real(4) / Real(3) : D == 2 ? Real(40) / (Real(7) * pi) : Real(8) / pi;
      case KernelType::WendlandC2:  // Wendland (1995) C2: 5/(4R), 7/(pi R^2), 21/(2 pi R^3)
        return D == 1 ? Real(1.25) : D == 2 ? Real(7) / pi : Real(21) / (Real(2) * pi);
      case KernelType::QuinticSpline:  // Morris (1997) with h = R/3: 1/(120h), 7/(478 pi h^2), 1/(120 pi h^3)
        return D == 1 ? Real(3) / Real(120)
               : D == 2 ? Real(63) / (Real(478) * pi)
                        : Real(27) / (Real(120) * pi);
    }
    return 1;
  }

  // Unit-support polynomial f(q) and its derivative f'(q), q in [0, 1).
  PSPH_HD PSPH_PAIR static Real f(KernelType t, Real q) {
    if (q >= Real(1)) return 0;
    switch (t) {
      case KernelType::CubicSpline: {  // M4 spline: 1 - 6q^2 + 6q^3 (q<1/2), 2(1-q)^3
        const Real a = Real(1) - q;
        return q < Real(0.5) ? Real(1) - Real(6) * q * q * a : Real(2) * a * a * a;
      }
      case KernelType::WendlandC2: {
        const Real a = Real(1) - q;
        if (D == 1) return a * a * a * (Real(1) + Real(3) * q);
        return a * a * a * a * (Real(1) + Real(4) * q);
      }
      case KernelType::QuinticSpline: {
        const Real s = Real(3) * q;
        const Real a = Real(3) - s, b = Real(2) - s, c = Real(1) - s;
        Real v = a * a * a * a * a;
        if (b > 0) v -= Real(6) * b * b * b * b * b;
        if (c > 0) v += Real(15) * c * c * c * c * c;
        return v;
      }
    }
    return 0;
  }
  PSPH_HD static Real df(KernelType t, Real q) {
    if (q >= Real(1)) return 0;
    switch (t) {
      case KernelType::CubicSpline: {
        const Real a = Real(1) - q;
        return q < Real(0.5) ? q * (Real(18) * q - Real(12)) : Real(-6) * a * a;
      }
      case KernelType::WendlandC2: {
        const Real a = Real(1) - q;
        if (D == 1) return Real(-12) * q * a * a;
        return Real(-20) * q * a * a * a;
      }
      case KernelType::QuinticSpline: {
        const Real s = Real(3) * q;
        const Real a = Real(3) - s, b = Real(2) - s, c = Real(1) - s;
        Real v = a * a * a * a;
        if (b > 0) v -= Real(6) * b * b * b * b;
        if (c > 0) v += Real(15) * c * c * c * c;
        return Real(-15) * v;  // d/dq of (3-3q)^5 is -15 (3-3q)^4
      }
    }
    return 0;
  }

  // f'(q)/q, finite at q = 0, without a division where the polynomial allows it.
  PSPH_HD PSPH_PAIR static Real df_over_q(KernelType t, Real q) {
    if (q >= Real(1)) return 0;
    switch (t) {
      case KernelType::CubicSpline: {
        const Real a = Real(1) - q;
        return q < Real(0.5) ? Real(18) * q - Real(12) : Real(-6) * a * a / q;
      }
      case KernelType::WendlandC2: {
        const Real a = Real(1) - q;
        if (D == 1) return Real(-12) * a * a;
        return Real(-20) * a * a * a;
      }
      case KernelType::QuinticSpline:
        return q > Real(0) ? df(t, q) / q : Real(0);
    }
    return 0;
  }

  PSPH_HD PSPH_PAIR Real W(Real r) const { return norm * f(type, r * inv_support); }
  // dW/dr (<= 0).
  PSPH_HD Real dWdr(Real r) const { return norm * inv_support * df(type, r * inv_support); }
  // F(r) = (1/r) dW/dr, so that grad_i W_ij = r_ij F(r) with r_ij = x_i - x_j (Pazdniakou eq. 46,
  // Deptulski eq. 2.36). The pair passes use it: one division less per pair.
  PSPH_HD PSPH_PAIR Real F(Real r) const { return norm * inv_support * inv_support * df_over_q(type, r * inv_support); }
  PSPH_HD PSPH_PAIR Vec<D> grad(const Vec<D>& rij, Real r) const { return r > Real(0) ? rij * F(r) : Vec<D>::zero(); }

  // sum_j W_ij over a full square (cubic) lattice of the given spacing, self included: the number
  // density summation gives a particle at rest (1 / spacing^D up to the kernel's discretisation).
  double lattice_sum(double spacing) const {
    const int n = static_cast<int>(std::ceil(double(support) / spacing));
    double sum = 0;
    int idx[3] = {-n, -n, -n};
    for (;;) {
      double r2 = 0;
      for (int d = 0; d < D; ++d) r2 += (idx[d] * spacing) * (idx[d] * spacing);
      sum += double(W(Real(std::sqrt(r2))));
      int d = 0;
      while (d < D && ++idx[d] > n) idx[d++] = -n;
      if (d == D) break;
    }
    return sum;
  }
};

}  // namespace psph
