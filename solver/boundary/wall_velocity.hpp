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
#include "core/pass_fields.hpp"

namespace psph {

enum class WallNoSlip { Prescribed = 0, Mirror = 1, Curved = 2, FreeSlip = 3 };

// The Shepard sums of the modes above over the fluid neighbours f of a wall or solid particle.
template <int D>
struct NoSlipSum {
  Vec<D> normal = Vec<D>::zero();  // the wall normal (curved mode only)
  Vec<D> sum = Vec<D>::zero();
  Real wsum = 0;
  PSPH_HD PSPH_PAIR void add(const ParticleView<D>& s, int j, const Vec<D>& rij, Real w) {
    const Real dn = dot(rij, normal);
    sum += (s.v[j] - s.lap_v[j] * (Real(0.25) * dn * dn)) * w;
    wsum += w;
  }
  PSPH_HD Vec<D> velocity(WallNoSlip mode, const Vec<D>& v_i) const {
    if (!(wsum > Real(0))) return v_i;
    return mode == WallNoSlip::FreeSlip ? sum * (Real(1) / wsum) : v_i * Real(2) - sum * (Real(1) / wsum);
  }
};

// Whether particle i presents its own velocity (no fluid near, or `prescribed`), and the sum to
// fill otherwise.
template <int D>
PSPH_HD inline bool presents_own_velocity(const PairContext<D>& c, WallNoSlip mode, int i, NoSlipSum<D>& sum) {
  if (mode == WallNoSlip::Prescribed || !c.s.near_fluid[i]) return true;
  if (mode == WallNoSlip::Curved) sum.normal = wall_normal_towards_fluid(c.nb, c.kern, i);
  return false;
}

template <int D>
struct WallVelocityPass {
  static constexpr FieldNames neighbour_reads = kFluidPairReads;
  static constexpr FieldNames writes{"wall_noslip_velocity"};
  PairContext<D> c;  // lists, kernel, particles, materials
  WallNoSlip mode;
  bool skip_walls;  // walls done by WallStatePass (boundary/wall_state.hpp): solids only
  PSPH_HD void operator()(int i) const {
    const int mi = c.s.material[i];
    if (c.mats.is_fluid(mi) || (skip_walls && c.mats[mi].kind == MaterialKind::Wall)) return;
    NoSlipSum<D> ns;
    if (presents_own_velocity(c, mode, i, ns)) {
      c.s.v_noslip[i] = c.s.v[i];
      return;
    }
    c.nb.for_each_fluid(i, [&](int j, const Vec<D>& rij, Real r) PSPH_PAIR { ns.add(c.s, j, rij, c.kern.W(r)); });
    c.s.v_noslip[i] = ns.velocity(mode, c.s.v[i]);
  }
};

}  // namespace psph
