// Cell-linked list against brute force: random, clustered and periodic clouds in 1D, 2D and 3D.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <set>

#include "neighbours/host_neighbours.hpp"
#include "neighbours/neighbour_list.hpp"

using namespace psph;

enum class Cloud { Random, Clustered };

template <int D>
void compare_with_brute_force(Cloud cloud, bool periodic, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0, 1);
  std::normal_distribution<double> g(0, 0.04);
  const int n = D == 1 ? 300 : D == 2 ? 1500 : 3000;
  const Real L[3] = {1.0, 0.8, 0.6};
  std::vector<Point<D>> pts(n);
  for (int i = 0; i < n; ++i)
    for (int k = 0; k < D; ++k) {
      double x = cloud == Cloud::Random ? u(rng) * L[k] : (i % 3) * 0.3 * L[k] + 0.1 * L[k] + g(rng);
      x = std::clamp(x, 0.0, double(L[k]) * (1 - 1e-9));
      pts[i][k] = Coord(x);
    }
  Coord lo[D], hi[D];
  bool per[D];
  for (int k = 0; k < D; ++k) lo[k] = 0, hi[k] = L[k], per[k] = periodic && (k % 2 == 0 || D == 1);
  const Real R = Real(0.09);
  HostNeighbours<D> nb(pts, lo, hi, per, R);
  const NeighbourView<D> view = nb.view();
  long total = 0;
  for (int a = 0; a < n; ++a) {
    std::set<int> cell_list, brute;
    view.for_each(a, [&](int b, const Vec<D>& rab, Real r) {
      EXPECT_TRUE(cell_list.insert(nb.order[b]).second) << "neighbour visited twice";
      EXPECT_NEAR(norm(rab), r, 1e-12);
    });
    for (int b = 0; b < n; ++b) {
      if (b == a) continue;
      Real r2 = 0;
      for (int k = 0; k < D; ++k) {
        Real d = nb.x[a][k] - nb.x[b][k];
        if (per[k]) d -= L[k] * std::round(d / L[k]);
        r2 += d * d;
      }
      if (r2 < R * R) brute.insert(nb.order[b]);
    }
    ASSERT_EQ(cell_list, brute) << D << "D particle " << a;
    total += static_cast<long>(brute.size());
  }
  EXPECT_GT(total, n);  // the configurations do have neighbours
}

TEST(Neighbours, Random1D) { compare_with_brute_force<1>(Cloud::Random, false, 1); }
TEST(Neighbours, Random2D) { compare_with_brute_force<2>(Cloud::Random, false, 2); }
TEST(Neighbours, Random3D) { compare_with_brute_force<3>(Cloud::Random, false, 3); }
TEST(Neighbours, Clustered1D) { compare_with_brute_force<1>(Cloud::Clustered, false, 4); }
TEST(Neighbours, Clustered2D) { compare_with_brute_force<2>(Cloud::Clustered, false, 5); }
TEST(Neighbours, Clustered3D) { compare_with_brute_force<3>(Cloud::Clustered, false, 6); }
TEST(Neighbours, Periodic1D) { compare_with_brute_force<1>(Cloud::Random, true, 7); }
TEST(Neighbours, Periodic2D) { compare_with_brute_force<2>(Cloud::Random, true, 8); }
TEST(Neighbours, Periodic3D) { compare_with_brute_force<3>(Cloud::Random, true, 9); }
TEST(Neighbours, PeriodicClustered3D) { compare_with_brute_force<3>(Cloud::Clustered, true, 10); }

TEST(Neighbours, SortIsStableAndCellsAreContiguous) {
  std::vector<int> keys{3, 1, 3, 0, 1, 3};
  std::vector<int> perm(6), start(4), end(4);
  CpuBackend::sort_by_cell(keys.data(), 6, 4, perm.data(), start.data(), end.data());
  EXPECT_EQ(perm, (std::vector<int>{3, 1, 4, 0, 2, 5}));
  EXPECT_EQ(start, (std::vector<int>{0, 1, 3, 3}));
  EXPECT_EQ(end, (std::vector<int>{1, 3, 3, 6}));
}

// With ids, a cell's particles come in id order whatever their order before (or which process
// holds them): the neighbours' visiting order, hence every sum, is a function of the particles.
TEST(Neighbours, SortBreaksTiesById) {
  std::vector<int> keys{3, 1, 3, 0, 1, 3};
  const std::vector<std::int32_t> ids{40, 7, 12, 5, 3, 20};
  std::vector<int> perm(6), start(4), end(4);
  CpuBackend::sort_by_cell(keys.data(), 6, 4, perm.data(), start.data(), end.data(), ids.data());
  EXPECT_EQ(perm, (std::vector<int>{3, 4, 1, 2, 5, 0}));
  EXPECT_EQ(start, (std::vector<int>{0, 1, 3, 3}));
}

TEST(Neighbours, ShortPeriodicAxisIsRejected) {
  CellGrid<2> g;
  const Coord lo[2] = {0, 0}, hi[2] = {1, Coord(Real(0.25))};
  const bool per[2] = {true, true};
  EXPECT_FALSE(CellGrid<2>::make(lo, hi, per, Real(0.1), g));
}

// The lists leave out the retired damage ghosts (core/damage_ghost.hpp): a retired ghost lists
// no one and no list holds it; a pending ghost is still listed until it retires.
TEST(Neighbours, RetiredGhostsAreInNoList) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(0, 1);
  const int n = 800, capacity = 256;
  std::vector<Point<2>> pts(n);
  for (auto& p : pts) p[0] = Coord(Real(u(rng))), p[1] = Coord(Real(u(rng)));
  const Coord lo[2] = {0, 0}, hi[2] = {1, 1};
  const bool per[2] = {false, false};
  HostNeighbours<2> nb(pts, lo, hi, per, Real(0.08));
  MaterialTable<2> mats;
  mats.count = 1, mats.m[0].kind = MaterialKind::Elastic;
  std::vector<std::uint8_t> material(n, 0), near_fluid(n, 1), ghost(n, 0);
  for (int i = 0; i < n; i += 7) ghost[i] = kGhostRetired;
  for (int i = 3; i < n; i += 11) ghost[i] = kGhostPending;
  std::vector<int> index(std::size_t(capacity) * n), count(n), fluid_count(n);
  const BuildNeighbourList<2> build{nb.view(), material.data(), mats, near_fluid.data(), nullptr, ghost.data(),
                                    false, false, index.data(), count.data(), fluid_count.data(), capacity,
                                    capacity, 1};
  int pending_listed = 0;
  for (int i = 0; i < n; ++i) {
    build(i);
    std::set<int> listed(index.begin() + std::size_t(i) * capacity, index.begin() + std::size_t(i) * capacity + count[i]);
    std::set<int> expected;
    if (ghost[i] != kGhostRetired)
      nb.view().for_each(i, [&](int j, const Vec<2>&, Real) {
        if (ghost[j] != kGhostRetired) expected.insert(j);
      });
    ASSERT_LE(count[i], capacity);
    EXPECT_EQ(listed, expected) << "particle " << i;
    for (int j : listed) pending_listed += ghost[j] == kGhostPending;
  }
  EXPECT_GT(pending_listed, 0);
}

// The pruned stencil (cells whose nearest face is beyond the radius are skipped): with cells one
// radius wide, a corner cell is in reach with probability pi/6 and an edge cell pi/4, so a random
// point visits 7 + 12 pi/4 + 8 pi/6 = 20.6 of the 27 cells on average. Brute force above checks
// that no neighbour is lost.
TEST(Neighbours, StencilSkipsCellsOutOfReach) {
  std::mt19937 rng(12);
  std::uniform_real_distribution<double> u(0, 1);
  const Coord lo[3] = {0, 0, 0}, hi[3] = {1, 1, 1};
  const bool per[3] = {true, true, true};
  const HostNeighbours<3> nb(std::vector<Point<3>>{}, lo, hi, per, Real(0.1));
  const NeighbourView<3> view = nb.view();
  const int points = 20000;
  long visited = 0;
  for (int i = 0; i < points; ++i) {
    const Point<3> p{Coord(u(rng)), Coord(u(rng)), Coord(u(rng))};
    view.for_each_cell_in_reach(p, [&](int) { ++visited; });
  }
  EXPECT_NEAR(double(visited) / points, 7 + 3.14159265 * (3.0 + 4.0 / 3.0), 0.15);
}
