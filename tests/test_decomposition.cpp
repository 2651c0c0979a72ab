// The recursive coordinate bisection (parallel/decomposition.hpp): balanced parts, owners that are
// the boxes', cuts across the particles' longest extent, and parts without particles.
#include <gtest/gtest.h>

#include <random>

#include "parallel/decomposition.hpp"

using namespace psph;

namespace {

std::vector<double> weight_per_part(const Decomposition& d, const std::vector<double>& x, const std::vector<double>& w,
                                    int dim) {
  std::vector<double> out(d.parts(), 0);
  for (std::size_t i = 0; i < w.size(); ++i) out[d.owner(&x[i * dim])] += w[i];
  return out;
}

}  // namespace

TEST(Decomposition, PartsBalanceTheirWeightAndOwnTheirBoxes) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<double> x, w;
  for (int i = 0; i < 20000; ++i) x.push_back(u(rng)), x.push_back(u(rng) * 0.5), w.push_back(i % 4 ? 1.0 : 0.25);
  Box box;
  box.hi = {1, 0.5, 0};
  Communicator one;
  for (int parts : {2, 3, 4, 7}) {
    Decomposition d(2, box, {false, false, false});
    d.bisect(x, w, parts, one);
    const std::vector<double> per = weight_per_part(d, x, w, 2);
    double total = 0;
    for (double v : per) total += v;
    for (int p = 0; p < parts; ++p) {
      EXPECT_NEAR(per[p], total / parts, 0.01 * total / parts) << parts << " parts, part " << p;
      const Box& b = d.box(p);
      const double centre[2] = {(b.lo[0] + b.hi[0]) / 2, (b.lo[1] + b.hi[1]) / 2};
      EXPECT_EQ(d.owner(centre), p);
    }
  }
}

// A flat layer of particles spread along y in a box longest along x: the cut goes across y, where
// the particles are, not across the box's longest side (which a slab one lattice plane thick,
// like SPHERIC test 2's, cannot balance).
TEST(Decomposition, CutsAcrossTheParticlesLongestExtent) {
  std::vector<double> x, w;
  for (int i = 0; i < 1000; ++i) x.push_back(0.5), x.push_back(i * 1e-3), w.push_back(1);
  Box box;
  box.hi = {10, 1, 0};
  Communicator one;
  Decomposition d(2, box, {false, false, false});
  d.bisect(x, w, 2, one);
  EXPECT_EQ(d.box(0).hi[0], 10);
  EXPECT_NEAR(d.box(0).hi[1], 0.5, 1e-3);
  const std::vector<double> per = weight_per_part(d, x, w, 2);
  EXPECT_EQ(per[0], 500);
  EXPECT_EQ(per[1], 500);
}

TEST(Decomposition, MorePartsThanParticles) {
  const std::vector<double> x{0.1, 0.2, 0.7, 0.8}, w{1, 1};
  Box box;
  box.hi = {1, 1, 0};
  Communicator one;
  Decomposition d(2, box, {false, false, false});
  d.bisect(x, w, 5, one);
  const std::vector<double> per = weight_per_part(d, x, w, 2);
  int empty = 0;
  for (double v : per) empty += v == 0;
  EXPECT_EQ(empty, 3);
  EXPECT_NE(d.owner(&x[0]), d.owner(&x[2]));
}
