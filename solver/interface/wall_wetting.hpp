#pragma once
// Wetting by extrapolation of the colour into the walls: the geometric wetting condition of Ding &
// Spelt (2007, Phys. Rev. E 75:046708) carried to SPH (our choice; the references only give the
// constant wall colour cos(theta) of Pazdniakou eq. 10, which measured 113 degrees for 120 and
// 48 for 30: VALIDATION.md). Each wall particle w near fluid takes the colour the fluid's would
// have there if the interface met the wall at the contact angle theta:
//   c_w = sum_f W_wf (c_f + (x_w - x_f) . g_f) / sum_f W_wf,   g_f = t_f - n_w |t_f| cot(theta),
// with n_w the wall normal (towards the fluid) and t_f the part of the fluid's grad c along the
// wall. The interface normal n = grad c / |grad c| (gas -> liquid) then satisfies
// cos(theta) = -n . n_w at the wall. Where no interface reaches the wall (t_f = 0) the wall
// continues the fluid's own colour, so a liquid or gas at rest on a wall feels no force from it.
// The walls also present g (their smoothed value) to the curvature pass. The fluid's c_f and grad c
// here are summed over fluids only (surface_tension.hpp, WallColour::FluidOnly), so that the walls'
// colour does not feed back into itself.
#include "boundary/wall_normal.hpp"
#include "core/material.hpp"
#include "kernels/kernel.hpp"
#include "neighbours/neighbour_list.hpp"
#include "state/particles.hpp"
#include "stage/pass_context.hpp"
#include "core/pass_fields.hpp"

namespace psph {

template <int D>
struct WallWettingPass {
  static constexpr FieldNames neighbour_reads = kFluidPairReads;
  static constexpr FieldNames writes{"colour", "colour_gradient"};
  PairContext<D> c;  // lists, kernel, particles, materials
  PSPH_HD void operator()(int i) const {
    const int mi = c.s.material[i];
    if (c.mats.is_fluid(mi) || !c.s.near_fluid[i]) return;
    const Vec<D> n_w = wall_normal_towards_fluid(c.nb, c.kern, i);
    const Real cos_t = c.mats[mi].colour;
    const Real sin_t = sqrt(Real(1) - cos_t * cos_t);
    const Real cot_t = cos_t / (sin_t > Real(1e-3) ? sin_t : Real(1e-3));  // 0 and 180 degrees: the clamp below decides
    Real colour = 0, wsum = 0;
    Vec<D> g_sum = Vec<D>::zero();
    c.nb.for_each_fluid(i, [&](int j, const Vec<D>& rij, Real r) PSPH_PAIR {
      const Real w = c.kern.W(r);
      const Vec<D> n_f = c.s.colour_gradient[j];
      const Vec<D> t_f = n_f - n_w * dot(n_f, n_w);
      const Vec<D> g = t_f - n_w * (norm(t_f) * cot_t);
      colour += (c.s.colour[j] + dot(rij, g)) * w;  // rij = x_w - x_f
      g_sum += g * w;
      wsum += w;
    });
    if (!(wsum > Real(0))) return;
    colour /= wsum;
    c.s.colour[i] = colour > Real(1) ? Real(1) : colour < Real(-1) ? Real(-1) : colour;
    c.s.colour_gradient[i] = g_sum * (Real(1) / wsum);
  }
};

}  // namespace psph
