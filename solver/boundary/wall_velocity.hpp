#pragma once
// Velocity that wall particles present to the viscous term.
//   prescribed: the wall's own velocity: the plain extended summation of Pazdniakou §3.3. On a
//               lattice the no-slip plane then sits ~0.4 spacing inside the wall (measured: a 10 %
//               error on plane Poiseuille flow at support = 2 spacings).
//   mirror:     v_w = 2 v_wall - sum_f v_f W_wf / sum_f W_wf over fluid neighbours f (Adami, Hu &
//               Adams 2012, J. Comput. Phys. 231:7057, eq. 23): the fluid velocity mirrored through
//               the wall, which puts the no-slip plane on the wall surface. Exact for a linear
//               profile; for a curved one the mirror misses v'' d^2 (d: distance to the surface),
//               which is 0.6 % of the peak in Pazdniakou's Poiseuille-Couette case.
//   curved:     the mirror plus that term: each fluid neighbour f contributes
//               v_f - (lap v)_f (n . r_wf)^2 / 4, with n the wall normal (direction to the fluid)
//               and lap v the fluid's velocity Laplacian from the previous force pass. Exact for a
//               quadratic profile normal to a flat wall (our choice; references silent).
//   free_slip:  v_w = sum_f v_f W_wf / sum_f W_wf: the walls present the fluid's own velocity, so
//               they exert no shear (Adami, Hu & Adams 2012 §2.3's slip condition).
#include "boundary/wall_normal.hpp"
#include "core/material.hpp"
#include "kernels/kernel.hpp"
#include "neighbours/neighbour_list.hpp"
#include "state/particles.hpp"
#include "stage/pass_context.hpp"

namespace psph {

enum class WallNoSlip { Prescribed = 0, Mirror = 1, Curved = 2, FreeSlip = 3 };

template <int D>
struct WallVelocityPass {
  PairContext<D> c;  // lists, kernel, particles, materials
  WallNoSlip mode;
  PSPH_HD void operator()(int i) const {
    if (c.mats.is_fluid(c.s.material[i])) return;
    if (mode == WallNoSlip::Prescribed || !c.s.near_fluid[i]) {
      c.s.v_noslip[i] = c.s.v[i];
      return;
    }
    const Vec<D> normal = mode == WallNoSlip::Curved ? wall_normal_towards_fluid(c.nb, c.kern, i) : Vec<D>::zero();
    Vec<D> sum = Vec<D>::zero();
    Real wsum = 0;
    c.nb.for_each_fluid(i, [&](int j, const Vec<D>& rij, Real r) PSPH_PAIR {
      const Real w = c.kern.W(r);
      const Real dn = dot(rij, normal);
      sum += (c.s.v[j] - c.s.lap_v[j] * (Real(0.25) * dn * dn)) * w;
      wsum += w;
    });
    if (!(wsum > Real(0))) c.s.v_noslip[i] = c.s.v[i];
    else if (mode == WallNoSlip::FreeSlip) c.s.v_noslip[i] = sum * (Real(1) / wsum);
    else c.s.v_noslip[i] = c.s.v[i] * Real(2) - sum * (Real(1) / wsum);
  }
};

}  // namespace psph
