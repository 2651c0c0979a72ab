#pragma once
// What a wall presents to the fluid, its extrapolated pressure (boundary/wall_pressure.hpp) and its
// no-slip velocity (boundary/wall_velocity.hpp), from one loop over its fluid neighbours: the two
// passes apart walked the same pairs twice (9 % of the 3D dam break's step).
#include "boundary/wall_pressure.hpp"
#include "core/equation_of_state.hpp"
#include "boundary/wall_velocity.hpp"
#include "core/pass_fields.hpp"

namespace psph {

template <int D>
struct WallStatePass {
  static constexpr FieldNames neighbour_reads = kFluidPairReads;
  static constexpr FieldNames writes{"pressure", "density", "wall_noslip_velocity"};
  PairContext<D> c;  // lists, kernel, particles, materials
  WallNoSlip mode;
  PSPH_HD void operator()(int i) const {
    const int mi = c.s.material[i];
    if (c.mats[mi].kind != MaterialKind::Wall) return;
    Real p = c.mats[mi].background_pressure;
    NoSlipSum<D> ns;
    const bool own_velocity = presents_own_velocity(c, mode, i, ns);
    if (c.s.near_fluid[i]) {
      FluidPressureSum<D> ps;
      c.nb.for_each_fluid(i, [&](int j, const Vec<D>& rij, Real r) PSPH_PAIR {
        const Real w = c.kern.W(r);
        ps.add(c.s, c.mats, j, rij, w);
        if (!own_velocity) ns.add(c.s, j, rij, w);
      });
      ps.pressure(p);
    }
    c.s.p[i] = p;
    c.s.rho[i] = density_from_pressure(c.mats[mi], p, c.s.rho0[i]);  // the EOS inverted at p
    c.s.v_noslip[i] = own_velocity ? c.s.v[i] : ns.velocity(mode, c.s.v[i]);
  }
};

}  // namespace psph
