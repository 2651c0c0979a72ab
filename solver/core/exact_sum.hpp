#pragma once
// Exact sums of doubles: a long fixed-point accumulator covering the whole double range
// (Kulisch's long accumulator, in 32-bit digits held in 64-bit words). Integer additions are
// associative, so a sum does not depend on the order of its terms: the same on any thread count,
// any particle order and any number of processes (each process's digits add exactly). Rounded
// once, to the double nearest the exact sum.
#include <cstdint>
#include <cstring>
#include <type_traits>

#include "core/config.hpp"
#include "core/vec.hpp"

namespace psph {

class ExactSum {
 public:
  // Bit k of the fixed-point number weighs 2^(k - 1074); the top digits leave room for carries.
  static constexpr int kDigits = 68;
  static constexpr int kBits = 32;

  PSPH_HD ExactSum() {
    for (int k = 0; k < kDigits; ++k) d_[k] = 0;
  }

  PSPH_HD void add(double x) {
    std::uint64_t bits;
    std::memcpy(&bits, &x, sizeof bits);
    const int e = int((bits >> 52) & 0x7ff);
    std::uint64_t mant = bits & ((std::uint64_t(1) << 52) - 1);
    const bool negative = (bits >> 63) != 0;
    if (e == 0x7ff) {  // inf or NaN: kept apart, rounded as IEEE addition would
      special_ |= mant ? kNaN : negative ? kMinusInf : kPlusInf;
      return;
    }
    if (mant == 0 && e == 0) return;
    int p = e - 1;  // the position of the mantissa's lowest bit (subnormals sit at the normals' lowest)
    if (e == 0) p = 0;
    else mant |= std::uint64_t(1) << 52;
    const int digit = p / kBits, shift = p % kBits;
    const std::uint64_t lo = mant << shift, hi = shift ? mant >> (64 - shift) : 0;  // 53 bits moved up by < 32
    const std::int64_t parts[3] = {std::int64_t(lo & kMask), std::int64_t(lo >> kBits), std::int64_t(hi)};
    for (int k = 0; k < 3; ++k) d_[digit + k] += negative ? -parts[k] : parts[k];
    if (++adds_ == kAddsBeforeCarry) carry();
  }

  PSPH_HD void merge(const ExactSum& o) {
    ExactSum b = o;
    b.carry();
    carry();
    for (int k = 0; k < kDigits; ++k) d_[k] += b.d_[k];
    special_ |= o.special_;
  }

  // The double nearest to the exact sum (ties to even).
  PSPH_HD double value() const {
    if (special_ & kNaN || (special_ & kPlusInf && special_ & kMinusInf)) return nan_value();
    if (special_) return special_ & kPlusInf ? inf_value() : -inf_value();
    ExactSum t = *this;
    t.carry();
    const bool negative = t.d_[kDigits - 1] < 0;
    if (negative) {
      for (int k = 0; k < kDigits; ++k) t.d_[k] = -t.d_[k];
      t.carry();
    }
    int top = kDigits - 1;
    while (top >= 0 && t.d_[top] == 0) --top;
    if (top < 0) return 0.0;
    // The top 64 significant bits, with a sticky bit for everything below them, round correctly in
    // one conversion.
    const std::uint64_t t2 = std::uint64_t(t.d_[top]), t1 = top >= 1 ? std::uint64_t(t.d_[top - 1]) : 0,
                        t0 = top >= 2 ? std::uint64_t(t.d_[top - 2]) : 0;
    int lz = 0;
    while (!(t2 << lz & (std::uint64_t(1) << 31))) ++lz;
    std::uint64_t m = ((t2 << 32 | t1) << lz) | (lz ? t0 >> (kBits - lz) : 0);
    bool sticky = (t0 & ((std::uint64_t(1) << (kBits - lz)) - 1)) != 0;
    for (int k = top - 3; k >= 0; --k) sticky |= t.d_[k] != 0;
    if (sticky) m |= 1;
    const double r = scale(static_cast<double>(m), (top - 2) * kBits + kBits - lz - 1074);
    return negative ? -r : r;
  }

  // Digits in canonical form (each in [0, 2^32), the top one signed); the raw words for a
  // reduction over processes, which adds them as integers.
  PSPH_HD void carry() {
    for (int k = 0; k + 1 < kDigits; ++k) {
      const std::int64_t c = d_[k] >> kBits;  // arithmetic shift: floor division
      d_[k] -= c * (std::int64_t(1) << kBits);
      d_[k + 1] += c;
    }
    adds_ = 0;
  }
  PSPH_HD std::int64_t* words() { return d_; }
  PSPH_HD int& special() { return special_; }

 private:
  static constexpr std::uint64_t kMask = (std::uint64_t(1) << kBits) - 1;
  static constexpr int kAddsBeforeCarry = 1 << 29;  // each add moves a digit by under 2^32
  static constexpr int kNaN = 1, kPlusInf = 2, kMinusInf = 4;

  PSPH_HD static double scale(double x, int e) {
    // x * 2^e by exact halvings/doublings (ldexp is not available on every device).
    while (e > 0) { const int s = e > 60 ? 60 : e; x *= double(std::uint64_t(1) << s); e -= s; }
    while (e < 0) { const int s = -e > 60 ? 60 : -e; x /= double(std::uint64_t(1) << s); e += s; }
    return x;
  }
  PSPH_HD static double inf_value() { return 1e308 * 10.0; }
  PSPH_HD static double nan_value() { const double i = inf_value(); return i - i; }

  std::int64_t d_[kDigits];
  int adds_ = 0;
  int special_ = 0;
};

// What a reduction's value type is made of: its scalar (core/vec.hpp: a floating-point type
// itself, a vector's or matrix's components); a struct its `component_type` where it names one
// (RigidLoadSum: double), otherwise Real (BandSums).
template <class T, class = void>
struct ComponentOf { using type = std::conditional_t<std::is_floating_point_v<ScalarOf<T>>, ScalarOf<T>, Real>; };
template <class T>
struct ComponentOf<T, std::void_t<typename T::component_type>> { using type = typename T::component_type; };

// A reduction's value type seen as its components.
template <class T>
struct RealComponents {
  using C = typename ComponentOf<T>::type;
  static_assert(std::is_trivially_copyable_v<T> && sizeof(T) % sizeof(C) == 0,
                "an exact sum needs a type made of one floating-point type");
  static constexpr int count = int(sizeof(T) / sizeof(C));
  PSPH_HD static C get(const T& v, int k) {
    C r;
    std::memcpy(&r, reinterpret_cast<const char*>(&v) + k * sizeof(C), sizeof(C));
    return r;
  }
  PSPH_HD static void set(T& v, int k, C r) { std::memcpy(reinterpret_cast<char*>(&v) + k * sizeof(C), &r, sizeof(C)); }
};

// T from one rounded exact sum per component.
template <class T>
PSPH_HD T rounded(const ExactSum* acc) {
  T out{};
  using C = typename RealComponents<T>::C;
  for (int k = 0; k < RealComponents<T>::count; ++k) RealComponents<T>::set(out, k, C(acc[k].value()));
  return out;
}

// The sum of f(0), ..., f(n - 1) through a backend's exact accumulation.
template <class T, class B, class F>
T exact_sum_of(int n, const F& f) {
  ExactSum acc[RealComponents<T>::count];
  B::template accumulate<T>(n, f, acc);
  return rounded<T>(acc);
}

}  // namespace psph
