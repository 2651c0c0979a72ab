#pragma once
// What a pair pass reads besides its own options: its neighbours (the lists, or the solids'
// reference neighbours NB), the kernel, the particles and the material table. One aggregate, so
// that a pass declares it once and a stage builds it once (StepContext::pairs()).
#include "core/fluid_table.hpp"
#include "kernels/kernel.hpp"
#include "neighbours/neighbour_list.hpp"
#include "state/particles.hpp"

namespace psph {

template <int D, class NB = NeighbourList<D>>
struct PairContext {
  NB nb;
  Kernel<D> kern;
  ParticleView<D> s;
  FluidTable<D> mats;
};

}  // namespace psph
