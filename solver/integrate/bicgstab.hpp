#pragma once
// Matrix-free BiCGSTAB (van der Vorst 1992) on per-particle vectors, for the implicit viscous step
// (fluid/viscosity.hpp): the operator is not symmetric (the 1/rho_i and trace-normalisation
// factors), so CG does not apply. Backend-neutral: dot products are backend reductions, updates
// are per-particle passes.
#include <cmath>

#include "backend/device_array.hpp"
#include "core/vec.hpp"

namespace psph {

template <int D>
struct DotOf {
  const Vec<D>* a;
  const Vec<D>* b;
  PSPH_HD Real operator()(int i) const { return dot(a[i], b[i]); }
};

// out = ca a + cb b + cc c (out may alias any input).
template <int D>
struct Combine {
  Vec<D>* out;
  const Vec<D>* a;
  Real ca;
  const Vec<D>* b;
  Real cb;
  const Vec<D>* c;
  Real cc;
  PSPH_HD void operator()(int i) const { out[i] = a[i] * ca + b[i] * cb + c[i] * cc; }
};

struct KrylovResult {
  int iterations = 0;
  double relative_residual = 0;
  bool converged = false;
};

template <int D, class B>
class BiCGStab {
 public:
  // Solves A x = b (x holds the initial guess); apply(in, out) computes out = A in, sum(f) the
  // sum of f(i) over the run's particles (a run over several processes: over all of them).
  template <class Apply, class Sum>
  KrylovResult solve(int n, const Apply& apply, const Sum& sum, const Vec<D>* b, Vec<D>* x, double tolerance,
                     int max_iterations) {
    for (auto* a : {&r_, &r0_, &p_, &v_, &s_, &t_}) a->resize(n);
    Vec<D>*r = r_.data(), *r0 = r0_.data(), *p = p_.data(), *v = v_.data(), *s = s_.data(), *t = t_.data();
    auto dot_ = [&](const Vec<D>* a, const Vec<D>* c) { return double(sum(DotOf<D>{a, c})); };
    auto comb = [&](Vec<D>* out, const Vec<D>* a, double ca, const Vec<D>* c, double cc, const Vec<D>* e, double ce) {
      B::for_each(n, Combine<D>{out, a, Real(ca), c, Real(cc), e, Real(ce)});
    };
    KrylovResult res;
    const double b_norm = std::sqrt(dot_(b, b));
    if (b_norm == 0) {
      B::fill_zero(x, sizeof(Vec<D>) * n);
      res.converged = true;
      return res;
    }
    apply(x, t);
    comb(r, b, 1, t, -1, t, 0);  // r = b - A x
    B::copy(r0, r, sizeof(Vec<D>) * n);
    p_.zero(), v_.zero();
    double rho = 1, alpha = 1, omega = 1;
    res.relative_residual = std::sqrt(dot_(r, r)) / b_norm;
    for (; res.iterations < max_iterations && res.relative_residual > tolerance; ++res.iterations) {
      const double rho_new = dot_(r0, r);
      const double beta = (rho_new / rho) * (alpha / omega);
      comb(p, r, 1, p, beta, v, -beta * omega);  // p = r + beta (p - omega v)
      apply(p, v);
      alpha = rho_new / dot_(r0, v);
      comb(s, r, 1, v, -alpha, v, 0);  // s = r - alpha v
      const double s_norm = std::sqrt(dot_(s, s));
      if (s_norm <= tolerance * b_norm) {
        comb(x, x, 1, p, alpha, p, 0);
        res.relative_residual = s_norm / b_norm;
        ++res.iterations;
        break;
      }
      apply(s, t);
      omega = dot_(t, s) / dot_(t, t);
      comb(x, x, 1, p, alpha, s, omega);  // x += alpha p + omega s
      comb(r, s, 1, t, -omega, t, 0);      // r = s - omega t
      res.relative_residual = std::sqrt(dot_(r, r)) / b_norm;
      rho = rho_new;
      if (!std::isfinite(res.relative_residual)) break;
    }
    res.converged = res.relative_residual <= tolerance;
    return res;
  }

 private:
  DeviceArray<Vec<D>, B> r_, r0_, p_, v_, s_, t_;
};

}  // namespace psph
