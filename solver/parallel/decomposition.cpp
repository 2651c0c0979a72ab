#include "parallel/decomposition.hpp"

#include <algorithm>
#include <cmath>

namespace psph {
namespace {

// Bisection steps for each cut: the cut is then known to 2^-48 of its node's extent.
constexpr int kCutSteps = 48;

struct Pending {
  int node, first_part, parts;
  double lo, hi, target;  // the cut's bracket and the weight wanted below it
};

}  // namespace

Decomposition::Decomposition(int dim, const Box& domain, const std::array<bool, 3>& periodic)
    : dim_(dim), domain_(domain), periodic_(periodic) {
  nodes_.push_back(Node{});
  nodes_[0].box = domain;
  nodes_[0].part = 0;
  leaf_box_ = {domain};
}

void Decomposition::bisect(const std::vector<double>& points, const std::vector<double>& weights, int parts,
                           Communicator& comm) {
  parts_ = parts;
  nodes_.assign(1, Node{});
  nodes_[0].box = domain_;
  leaf_box_.assign(parts, domain_);
  const std::size_t n = weights.size();
  std::vector<int> at(n, 0);  // each point's node at the current level
  // The level's nodes to cut: (node, its processes [first, first + p)).
  std::vector<std::array<int, 3>> level{{0, 0, parts}};
  while (!level.empty()) {
    std::vector<Pending> cuts;
    const std::vector<double> extent = particle_extents(points, at, comm);
    for (const auto& [node, first, p] : level) {
      Node& nd = nodes_[node];
      if (p == 1) {
        nd.part = first;
        leaf_box_[first] = nd.box;
        continue;
      }
      // Across the longest extent of the node's particles (of its box where it has none): a box
      // cut across its longest side may hold a slab of particles that cannot be halved.
      const double* e = &extent[std::size_t(node) * 3];
      const bool empty = e[0] < 0;
      int axis = 0;
      for (int k = 1; k < dim_; ++k)
        if ((empty ? nd.box.hi[k] - nd.box.lo[k] : e[k]) > (empty ? nd.box.hi[axis] - nd.box.lo[axis] : e[axis])) axis = k;
      nd.axis = axis;
      cuts.push_back(Pending{node, first, p, nd.box.lo[axis], nd.box.hi[axis], 0});
    }
    if (cuts.empty()) break;
    // Each node's total weight, then the bisection of every cut of the level at once.
    std::vector<int> slot(nodes_.size(), -1);
    for (std::size_t c = 0; c < cuts.size(); ++c) slot[cuts[c].node] = int(c);
    auto weigh = [&](bool below_only) {
      std::vector<ExactSum> w(cuts.size());
      for (std::size_t i = 0; i < n; ++i) {
        const int c = slot[at[i]];
        if (c < 0) continue;
        const Pending& q = cuts[c];
        const double mid = 0.5 * (q.lo + q.hi);
        if (!below_only || points[i * dim_ + nodes_[q.node].axis] < mid) w[c].add(weights[i]);
      }
      comm.sum(w.data(), int(w.size()));
      return w;
    };
    const std::vector<ExactSum> total = weigh(false);
    for (std::size_t c = 0; c < cuts.size(); ++c) cuts[c].target = total[c].value() * (cuts[c].parts / 2) / cuts[c].parts;
    for (int step = 0; step < kCutSteps; ++step) {
      const std::vector<ExactSum> below = weigh(true);
      for (std::size_t c = 0; c < cuts.size(); ++c) {
        const double mid = 0.5 * (cuts[c].lo + cuts[c].hi);
        (below[c].value() < cuts[c].target ? cuts[c].lo : cuts[c].hi) = mid;
      }
    }
    // Children, and each point's child.
    std::vector<std::array<int, 3>> next;
    for (const Pending& q : cuts) {
      const int left = int(nodes_.size()), right = left + 1;
      Node& nd = nodes_[q.node];
      nd.cut = q.hi;
      nd.left = left, nd.right = right;
      Node l, r;
      l.box = r.box = nd.box;
      l.box.hi[nd.axis] = r.box.lo[nd.axis] = nd.cut;
      nodes_.push_back(l), nodes_.push_back(r);
      next.push_back({left, q.first_part, q.parts / 2});
      next.push_back({right, q.first_part + q.parts / 2, q.parts - q.parts / 2});
    }
    for (std::size_t i = 0; i < n; ++i) {
      const Node& nd = nodes_[at[i]];
      if (nd.axis >= 0) at[i] = points[i * dim_ + nd.axis] < nd.cut ? nd.left : nd.right;
    }
    level = std::move(next);
  }
}

// Each node's particles' extent along each axis over every process (-1 where it has none).
std::vector<double> Decomposition::particle_extents(const std::vector<double>& points, const std::vector<int>& at,
                                                    Communicator& comm) const {
  const std::size_t nodes = nodes_.size();
  std::vector<double> span(nodes * 6, -HUGE_VAL);  // per node and axis: -min, max
  for (std::size_t i = 0; i < at.size(); ++i)
    for (int k = 0; k < dim_; ++k) {
      const double x = points[i * dim_ + k];
      double* s = &span[std::size_t(at[i]) * 6 + 2 * k];
      s[0] = std::max(s[0], -x), s[1] = std::max(s[1], x);
    }
  comm.max(span.data(), int(span.size()));
  std::vector<double> extent(nodes * 3, -1);
  for (std::size_t c = 0; c < nodes; ++c)
    for (int k = 0; k < dim_; ++k)
      if (span[c * 6 + 2 * k + 1] > -HUGE_VAL) extent[c * 3 + k] = span[c * 6 + 2 * k + 1] + span[c * 6 + 2 * k];
  return extent;
}

int Decomposition::owner(const double* x) const {
  int node = 0;
  while (nodes_[node].axis >= 0) node = x[nodes_[node].axis] < nodes_[node].cut ? nodes_[node].left : nodes_[node].right;
  return nodes_[node].part;
}

double Decomposition::distance2(const double* x, const Box& b) const {
  double d2 = 0;
  for (int k = 0; k < dim_; ++k) {
    auto gap = [&](double y) { return std::max({b.lo[k] - y, 0.0, y - b.hi[k]}); };
    double g = gap(x[k]);
    if (periodic_[k]) {
      const double length = domain_.hi[k] - domain_.lo[k];
      g = std::min({g, gap(x[k] + length), gap(x[k] - length)});
    }
    d2 += g * g;
  }
  return d2;
}

void Decomposition::parts_near(const double* x, double width, int self, std::vector<int>& out) const {
  out.clear();
  near(0, x, width * width, self, out);
}

void Decomposition::near(int node, const double* x, double width2, int self, std::vector<int>& out) const {
  const Node& nd = nodes_[node];
  if (distance2(x, nd.box) >= width2) return;
  if (nd.axis < 0) {
    if (nd.part != self) out.push_back(nd.part);
    return;
  }
  near(nd.left, x, width2, self, out);
  near(nd.right, x, width2, self, out);
}

}  // namespace psph
