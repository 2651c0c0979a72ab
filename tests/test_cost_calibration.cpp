// The particle classes' measured costs (parallel/cost_calibration.hpp): a pass split by class gives
// every particle exactly what one launch gives, and a class whose particles work longer costs more.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "backend/cpu_backend.hpp"
#include "parallel/cost_calibration.hpp"

using namespace psph;

namespace {

// A per-particle pass whose work depends on the particle's class: `rounds[klass]` iterations.
struct UnevenPass {
  const std::uint8_t* klass;
  const int* rounds;
  double* out;
  void operator()(int i) const {
    double v = 1 + i;
    for (int r = 0; r < rounds[klass[i]]; ++r) v = std::sqrt(v + r);
    out[i] = v;
  }
};

}  // namespace

TEST(CostCalibration, SplitLaunchesGiveTheSameNumbersAndRankTheClasses) {
  const int n = 6000;
  std::vector<std::uint8_t> klass(n);
  for (int i = 0; i < n; ++i) klass[i] = i % 3 == 0 ? kFluidCost : i % 3 == 1 ? kWallNearFluidCost : kWallFarCost;
  klass[5] = kCostClasses;  // a halo copy: no pass runs on it
  const int rounds[kCostClasses + 1] = {2000, 0, 0, 200, 0, 0};
  std::vector<double> whole(n, -1), split(n, -1);
  for (int i = 0; i < n; ++i)
    if (klass[i] < kCostClasses) UnevenPass{klass.data(), rounds, whole.data()}(i);

  CostCalibration<CpuBackend> cal;
  cal.classify(klass);
  ASSERT_TRUE(cal.fits(n));
  for (int k = 0; k < 5; ++k) cal.run(n, UnevenPass{klass.data(), rounds, split.data()});  // timings summed
  EXPECT_EQ(split, whole);  // the halo copy untouched, every other particle as one launch gives it

  Communicator one;
  const ClassCosts c = cal.costs(one, 0.0);
  ASSERT_TRUE(c.measured);
  EXPECT_GT(c.per_particle[kFluidCost], 2 * c.per_particle[kWallNearFluidCost]);  // 10 x the work
  EXPECT_GT(c.per_particle[kWallNearFluidCost], c.per_particle[kWallFarCost]);
  // Classes the particles do not hold: their static weight against the fluid's measured cost.
  EXPECT_DOUBLE_EQ(c.per_particle[kSolidCost], c.per_particle[kFluidCost]);
}
