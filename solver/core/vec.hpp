#pragma once
// Small fixed-size vector and matrix for 1D/2D/3D particle maths, usable on host and device.
#include <cmath>

#include "core/config.hpp"
#include "core/real_math.hpp"

namespace psph {

// True for a finite number (false for NaN and +-Inf), on host and device alike.
template <class T>
PSPH_HD inline bool is_finite(T x) { return x - x == T(0); }

// A D-vector of T: `Vec<D>` holds Real (velocities, forces, pair differences), `Point<D>` holds
// Coord (positions, displacements: double also in mixed precision, core/config.hpp).
template <class T, int D>
struct VecT {
  T c[D];
  PSPH_HD T& operator[](int k) { return c[k]; }
  PSPH_HD const T& operator[](int k) const { return c[k]; }
  static PSPH_HD VecT zero() {
    VecT v;
    for (int k = 0; k < D; ++k) v.c[k] = T(0);
    return v;
  }
  PSPH_HD VecT& operator+=(const VecT& o) {
    for (int k = 0; k < D; ++k) c[k] += o.c[k];
    return *this;
  }
  PSPH_HD VecT& operator-=(const VecT& o) {
    for (int k = 0; k < D; ++k) c[k] -= o.c[k];
    return *this;
  }
  PSPH_HD VecT& operator*=(T s) {
    for (int k = 0; k < D; ++k) c[k] *= s;
    return *this;
  }
};
template <int D>
using Vec = VecT<Real, D>;
template <int D>
using Point = VecT<Coord, D>;

// Explicit conversions between the two (the identity where Real is Coord).
template <class To, class From, int D>
PSPH_HD PSPH_PAIR inline VecT<To, D> vec_cast(const VecT<From, D>& a) {
  VecT<To, D> out;
  for (int k = 0; k < D; ++k) out.c[k] = static_cast<To>(a.c[k]);
  return out;
}
template <int D>
PSPH_HD PSPH_PAIR inline Vec<D> to_real(const Point<D>& a) { return vec_cast<Real>(a); }
template <int D>
PSPH_HD inline Point<D> to_coord(const Vec<D>& a) { return vec_cast<Coord>(a); }

// The scalar's type is not deduced: `v * 2` and `v * Real(x)` both take the vector's type.
template <class T>
struct Same { using type = T; };

template <class T, int D>
PSPH_HD inline VecT<T, D> operator+(VecT<T, D> a, const VecT<T, D>& b) { return a += b; }
template <class T, int D>
PSPH_HD inline VecT<T, D> operator-(VecT<T, D> a, const VecT<T, D>& b) { return a -= b; }
template <class T, int D>
PSPH_HD inline VecT<T, D> operator*(VecT<T, D> a, typename Same<T>::type s) { return a *= s; }
template <class T, int D>
PSPH_HD inline VecT<T, D> operator*(typename Same<T>::type s, VecT<T, D> a) { return a *= s; }
template <class T, int D>
PSPH_HD inline T dot(const VecT<T, D>& a, const VecT<T, D>& b) {
  T s = 0;
  for (int k = 0; k < D; ++k) s += a.c[k] * b.c[k];
  return s;
}
template <class T, int D>
PSPH_HD inline T norm2(const VecT<T, D>& a) { return dot(a, a); }
template <class T, int D>
PSPH_HD inline T norm(const VecT<T, D>& a) { return sqrt(dot(a, a)); }

// Row-major D×D matrix.
template <int D>
struct Mat {
  Real a[D][D];
  static PSPH_HD Mat zero() {
    Mat m;
    for (int r = 0; r < D; ++r)
      for (int s = 0; s < D; ++s) m.a[r][s] = Real(0);
    return m;
  }
  static PSPH_HD Mat identity() {
    Mat m = zero();
    for (int r = 0; r < D; ++r) m.a[r][r] = Real(1);
    return m;
  }
};

template <int D>
PSPH_HD inline Vec<D> operator*(const Mat<D>& m, const Vec<D>& v) {
  Vec<D> out;
  for (int r = 0; r < D; ++r) {
    Real s = 0;
    for (int k = 0; k < D; ++k) s += m.a[r][k] * v.c[k];
    out.c[r] = s;
  }
  return out;
}

// m += a ⊗ b, i.e. m_rs += a_r b_s.
template <int D>
PSPH_HD inline void add_outer(Mat<D>& m, const Vec<D>& a, const Vec<D>& b, Real w) {
  for (int r = 0; r < D; ++r)
    for (int s = 0; s < D; ++s) m.a[r][s] += w * a.c[r] * b.c[s];
}

template <int D>
PSPH_HD inline Real trace(const Mat<D>& m) {
  Real t = 0;
  for (int r = 0; r < D; ++r) t += m.a[r][r];
  return t;
}

template <int D>
PSPH_HD inline Real determinant(const Mat<D>& m) {
  if constexpr (D == 1) {
    return m.a[0][0];
  } else if constexpr (D == 2) {
    return m.a[0][0] * m.a[1][1] - m.a[0][1] * m.a[1][0];
  } else {
    return m.a[0][0] * (m.a[1][1] * m.a[2][2] - m.a[1][2] * m.a[2][1]) -
           m.a[0][1] * (m.a[1][0] * m.a[2][2] - m.a[1][2] * m.a[2][0]) +
           m.a[0][2] * (m.a[1][0] * m.a[2][1] - m.a[1][1] * m.a[2][0]);
  }
}

// Cofactor matrix det(m) m^-T (defined also where m is singular): it maps an area vector of the
// reference configuration to the current one (Nanson's formula, n da = cof(F) N dA).
template <int D>
PSPH_HD inline Mat<D> cofactor(const Mat<D>& m) {
  Mat<D> c = Mat<D>::identity();
  if constexpr (D == 2) {
    c.a[0][0] = m.a[1][1], c.a[0][1] = -m.a[1][0], c.a[1][0] = -m.a[0][1], c.a[1][1] = m.a[0][0];
  } else if constexpr (D == 3) {
    for (int r = 0; r < 3; ++r)
      for (int s = 0; s < 3; ++s) {
        const int r1 = (r + 1) % 3, r2 = (r + 2) % 3, c1 = (s + 1) % 3, c2 = (s + 2) % 3;
        c.a[r][s] = m.a[r1][c1] * m.a[r2][c2] - m.a[r1][c2] * m.a[r2][c1];
      }
  }
  return c;
}

// Inverse by cofactors; returns false (and leaves `out` as identity) when |det| <= tiny.
template <int D>
PSPH_HD inline bool invert(const Mat<D>& m, Mat<D>& out, Real tiny) {
  const Real det = determinant(m);
  out = Mat<D>::identity();
  if (!(fabs(det) > tiny)) return false;
  const Real inv = Real(1) / det;
  if constexpr (D == 1) {
    out.a[0][0] = inv;
  } else if constexpr (D == 2) {
    out.a[0][0] = m.a[1][1] * inv;
    out.a[0][1] = -m.a[0][1] * inv;
    out.a[1][0] = -m.a[1][0] * inv;
    out.a[1][1] = m.a[0][0] * inv;
  } else {
    const Mat<D> c = cofactor(m);  // m^-1 = cof(m)^T / det
    for (int r = 0; r < 3; ++r)
      for (int s = 0; s < 3; ++s) out.a[r][s] = c.a[s][r] * inv;
  }
  return true;
}

// The scalar a field's values are made of (a vector's or matrix's components).
template <class T>
struct Scalar { using type = T; };
template <class T, int D>
struct Scalar<VecT<T, D>> { using type = T; };
template <int D>
struct Scalar<Mat<D>> { using type = Real; };
template <class T>
using ScalarOf = typename Scalar<T>::type;

}  // namespace psph
