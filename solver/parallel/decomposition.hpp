#pragma once
// Recursive coordinate bisection of the domain into one box per process, balanced by each
// particle's cost: a node with p processes is cut across its particles' longest extent where the weight
// below the cut is floor(p/2)/p of the node's (found by bisection on the cut with exact global
// sums, so every process finds the very same cuts). The owner of a point is the leaf that holds
// it; the halo of a process is what lies within a width of its box (periodic axes wrap).
#include <array>
#include <vector>

#include "parallel/communicator.hpp"

namespace psph {

struct Box {
  std::array<double, 3> lo{0, 0, 0}, hi{0, 0, 0};
};

class Decomposition {
 public:
  // The domain box and its periodic axes (dimension `dim`).
  Decomposition(int dim, const Box& domain, const std::array<bool, 3>& periodic);

  // Cuts for `parts` processes; points (dim per point) and weights are this process's, the sums
  // are over every process of comm.
  void bisect(const std::vector<double>& points, const std::vector<double>& weights, int parts, Communicator& comm);

  int parts() const { return parts_; }
  int owner(const double* x) const;
  const Box& box(int part) const { return leaf_box_[part]; }
  // The parts other than `self` whose box lies within `width` of x.
  void parts_near(const double* x, double width, int self, std::vector<int>& out) const;
  // The squared distance from x to a box, nearest periodic image.
  double distance2(const double* x, const Box& b) const;

 private:
  struct Node {
    int axis = -1;       // -1 for a leaf
    double cut = 0;      // left: x[axis] < cut
    int left = -1, right = -1;
    int part = -1;       // the leaf's process
    Box box;
  };
  void near(int node, const double* x, double width2, int self, std::vector<int>& out) const;
  std::vector<double> particle_extents(const std::vector<double>& points, const std::vector<int>& at,
                                       Communicator& comm) const;

  int dim_;
  Box domain_;
  std::array<bool, 3> periodic_;
  int parts_ = 1;
  std::vector<Node> nodes_;
  std::vector<Box> leaf_box_;
};

}  // namespace psph
