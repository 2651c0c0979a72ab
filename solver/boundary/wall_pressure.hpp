#pragma once
// Pressure that wall particles present to the fluid.
//   summation:    the wall's own density by summation (or continuity) through the EOS, with the
//                 initial summed density as reference (Pazdniakou §3.3, eq. 74; the summed value is
//                 our choice, so that walls start at zero pressure). Soft:
//                 under a sustained body force the fluid creeps into the wall (measured: in the
//                 sphere array the first fluid layer compresses against the sphere and the
//                 permeability drifts from -1 % at 0.3 s to -35 % at 2.3 s).
//   extrapolated: p_w = [sum_f p_f W_wf + (g_f - a_w) . sum_f rho_f r_wf W_wf] / sum_f W_wf over
//                 fluid neighbours f, r_wf = x_w - x_f (Adami, Hu & Adams 2012, J. Comput. Phys.
//                 231:7057, eq. 27), and rho_w from the EOS inverted at p_w: the wall carries the
//                 fluid's pressure plus the body-force head, so it holds any sustained load.
//                 Walls here are fixed or move at constant velocity (a_w = 0); elastic solids
//                 present the same (solid/fluid_coupling.hpp).
#include "core/equation_of_state.hpp"
#include "core/fluid_table.hpp"
#include "kernels/kernel.hpp"
#include "neighbours/neighbour_list.hpp"
#include "state/particles.hpp"
#include "stage/pass_context.hpp"

namespace psph {

enum class WallPressure { Summation = 0, Extrapolated = 1 };

// The sums of Adami, Hu & Adams (2012) eq. 27 at a particle that accelerates at a_i (0 for walls
// and solids here, solid/fluid_coupling.hpp), over its fluid neighbours f.
template <int D>
struct FluidPressureSum {
  Vec<D> a_i = Vec<D>::zero();
  Real psum = 0, wsum = 0;
  PSPH_HD PSPH_PAIR void add(const ParticleView<D>& s, const FluidTable<D>& mats, int j, const Vec<D>& rij, Real w) {
    psum += (s.p[j] + s.rho[j] * dot(mats.body_force_at(s.material[j], s.x[j]) - a_i, rij)) * w;
    wsum += w;
  }
  // The extrapolated pressure into p; false (p untouched) without fluid within the support.
  PSPH_HD bool pressure(Real& p) const {
    if (!(wsum > Real(0))) return false;
    p = psum / wsum;
    return true;
  }
};

template <int D>
PSPH_HD inline bool extrapolate_fluid_pressure(const NeighbourList<D>& nb, const Kernel<D>& kern,
                                               const ParticleView<D>& s, const FluidTable<D>& mats, int i,
                                               const Vec<D>& a_i, Real& p) {
  FluidPressureSum<D> sum;
  sum.a_i = a_i;
  nb.for_each_fluid(i, [&](int j, const Vec<D>& rij, Real r) PSPH_PAIR { sum.add(s, mats, j, rij, kern.W(r)); });
  return sum.pressure(p);
}

}  // namespace psph
