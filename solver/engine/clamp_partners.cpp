#include "engine/clamp_partners.hpp"

#include <algorithm>
#include <cmath>

#include "neighbours/host_neighbours.hpp"

namespace psph {

namespace {

template <int D>
std::vector<std::int32_t> partners(const Scene& sc) {
  const int n = sc.count();
  std::vector<std::int32_t> mirror(n, -1);
  auto kind = [&](int i) { return sc.materials[sc.material[i]].props.kind; };
  std::vector<Point<D>> solid;
  std::vector<int> solid_index;
  for (int i = 0; i < n; ++i)
    if (kind(i) == MaterialKind::Elastic) {
      Point<D> x;
      for (int k = 0; k < D; ++k) x[k] = Coord(sc.x[i * D + k]);
      solid.push_back(x), solid_index.push_back(i);
    }
  if (solid.empty()) return mirror;
  Coord lo[D], hi[D];
  bool per[D];
  for (int k = 0; k < D; ++k) lo[k] = Coord(sc.lower[k]), hi[k] = Coord(sc.upper[k]), per[k] = sc.periodic[k];
  const HostNeighbours<D> cells(solid, lo, hi, per, Coord(sc.options.support_radius));
  const NeighbourView<D> view = cells.view();
  const Real dx = Real(sc.options.spacing);
  // The elastic particle nearest to p within the support (ties to the lowest index): scene index,
  // separation p - x_s and distance.
  struct Nearest {
    int index = -1;
    Vec<D> sep{};
    Real r = 0;
  };
  auto nearest = [&](const Point<D>& p) {
    Nearest best;
    view.for_each_fluid_near(p, [&](int k, const Vec<D>& d, Real r) {
      const int idx = solid_index[cells.order[k]];
      if (best.index < 0 || r < best.r || (r == best.r && idx < best.index)) best = {idx, d, r};
    });
    return best;
  };
  struct Candidate {
    Real r;
    int wall, partner;
  };
  std::vector<Candidate> found;
  for (int w = 0; w < n; ++w) {
    if (kind(w) != MaterialKind::Wall) continue;
    Point<D> xw;
    for (int k = 0; k < D; ++k) xw[k] = Coord(sc.x[w * D + k]);
    const Nearest first = nearest(xw);
    if (first.index < 0 || !(first.r > Real(0.5) * dx)) continue;
    const Vec<D> normal = first.sep * (Real(-1) / first.r);  // from the wall towards the solid
    const Point<D> image = cells.grid.wrap(xw + to_coord(normal * (Real(2) * first.r - dx)));
    const Nearest p = nearest(image);
    if (p.index >= 0 && p.r < Real(0.25) * dx) found.push_back({first.r, w, p.index});
  }
  std::stable_sort(found.begin(), found.end(), [](const Candidate& a, const Candidate& b) { return a.r < b.r; });
  for (const Candidate& c : found)
    if (mirror[c.partner] < 0) mirror[c.wall] = c.partner, mirror[c.partner] = c.wall;
  return mirror;
}

}  // namespace

std::vector<std::int32_t> clamp_mirror_partners(const Scene& sc) {
  switch (sc.dimension) {
    case 1: return partners<1>(sc);
    case 2: return partners<2>(sc);
    default: return partners<3>(sc);
  }
}

}  // namespace psph
