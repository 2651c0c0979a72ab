// Exact sums (core/exact_sum.hpp): the correctly rounded sum, whatever the order of the terms, the
// split into parts and the thread count.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

#include "backend/cpu_backend.hpp"
#include "core/exact_sum.hpp"

using namespace psph;

namespace {

double exact(const std::vector<double>& xs) {
  ExactSum s;
  for (double x : xs) s.add(x);
  return s.value();
}
std::uint64_t bits(double x) {
  std::uint64_t b;
  std::memcpy(&b, &x, sizeof b);
  return b;
}
// Values over 600 binades, both signs, with cancellations.
std::vector<double> wide_values(int n, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> mant(-1, 1);
  std::uniform_int_distribution<int> ex(-300, 300);
  std::vector<double> xs(n);
  for (auto& x : xs) x = std::ldexp(mant(rng), ex(rng));
  return xs;
}

}  // namespace

TEST(ExactSum, RoundsTheExactSumOnce) {
  EXPECT_EQ(exact({1e100, 1.0, -1e100}), 1.0);
  EXPECT_EQ(exact(std::vector<double>(10, 0.1)), 1.0);  // a running double sum gives 0.9999999999999999
  EXPECT_EQ(exact({0.1, 0.2}), 0.1 + 0.2);              // one term each side: IEEE's own rounding
  EXPECT_EQ(exact({-3.5, 1.25}), -2.25);
  EXPECT_EQ(exact({}), 0.0);
  const double tiny = std::numeric_limits<double>::denorm_min();
  EXPECT_EQ(exact({tiny, tiny, tiny}), 3 * tiny);
  const double big = std::numeric_limits<double>::max();
  EXPECT_EQ(exact({big, big, -big}), big);  // no overflow in between
  EXPECT_EQ(exact({1.0, std::ldexp(1.0, -53)}), 1.0);                                   // a tie: to even
  EXPECT_EQ(exact({1.0, std::ldexp(1.0, -53), std::ldexp(1.0, -200)}), 1.0 + std::ldexp(1.0, -52));  // sticky
}

TEST(ExactSum, IntegersSumExactly) {
  std::mt19937_64 rng(3);
  std::uniform_int_distribution<std::int64_t> u(-(std::int64_t(1) << 50), std::int64_t(1) << 50);
  std::vector<double> xs(5000);
  std::int64_t total = 0;
  for (auto& x : xs) {
    const std::int64_t k = u(rng);
    total += k;
    x = double(k);
  }
  EXPECT_EQ(exact(xs), double(total));
}

TEST(ExactSum, InfinitiesAndNaN) {
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_EQ(exact({1.0, inf}), inf);
  EXPECT_EQ(exact({-inf, 2.0}), -inf);
  EXPECT_TRUE(std::isnan(exact({inf, -inf})));
  EXPECT_TRUE(std::isnan(exact({1.0, std::nan("")})));
}

TEST(ExactSum, OrderAndSplitDoNotMatter) {
  std::vector<double> xs = wide_values(20000, 5);
  const double whole = exact(xs);
  std::mt19937 rng(9);
  for (int trial = 0; trial < 5; ++trial) {
    std::shuffle(xs.begin(), xs.end(), rng);
    const std::size_t cut = xs.size() * (trial + 1) / 7;
    ExactSum a, b;
    for (std::size_t i = 0; i < cut; ++i) a.add(xs[i]);
    for (std::size_t i = cut; i < xs.size(); ++i) b.add(xs[i]);
    b.merge(a);
    EXPECT_EQ(bits(b.value()), bits(whole));
  }
}

TEST(ExactSum, BackendSumsOfStructsAreExact) {
  struct Pair {
    Real a, b;
  };
  const std::vector<double> xs = wide_values(10000, 7);
  const Pair p = CpuBackend::sum_of<Pair>(int(xs.size()), [&](int i) { return Pair{Real(xs[i]), Real(-2 * xs[i])}; });
  EXPECT_EQ(double(p.a), exact(xs));
  EXPECT_EQ(double(p.b), -2 * exact(xs));
}
