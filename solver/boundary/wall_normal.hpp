#pragma once
// Unit normal of a wall particle, pointing towards the fluid: the kernel-weighted direction of its
// fluid neighbours, -sum_f r_wf W_wf (r_wf = x_w - x_f); zero without fluid neighbours.
#include "kernels/kernel.hpp"
#include "neighbours/neighbour_list.hpp"

namespace psph {

template <int D>
PSPH_HD inline Vec<D> wall_normal_towards_fluid(const NeighbourList<D>& nb, const Kernel<D>& kern, int i) {
  Vec<D> normal = Vec<D>::zero();
  nb.for_each_fluid(i, [&](int, const Vec<D>& rij, Real r) PSPH_PAIR { normal -= rij * kern.W(r); });
  const Real len = norm(normal);
  return len > Real(0) ? normal * (Real(1) / len) : normal;
}

}  // namespace psph
