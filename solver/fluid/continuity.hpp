#pragma once
// Density rate for the continuity form (Pazdniakou eq. 53a) with optional delta-SPH diffusion.
// Run after the kick, with the velocity that also moves the particles (v at t + dt/2; the XSPH
// correction, off by default, is left out), so that positions and densities advance together: evaluated with the velocity of the previous step
// instead, the density lags the motion and a resting tank gains energy (measured: a closed 2D
// tank reached 1.4 m/s in 3 s).
#include "core/material.hpp"
#include "kernels/kernel.hpp"
#include "neighbours/neighbour_list.hpp"
#include "state/particles.hpp"
#include "stage/pass_context.hpp"
#include "core/pass_fields.hpp"

namespace psph {

template <int D>
struct ContinuityPass {
  static constexpr FieldNames neighbour_reads = kFluidPairReads;
  static constexpr FieldNames writes{"density_rate"};
  PairContext<D> c;  // lists, kernel, particles, materials
  Real density_diffusion;  // delta (0 = off)
  Real smoothing_length;
  bool walls;              // integrate wall densities too (false when walls take the fluid's pressure)
  PSPH_HD void operator()(int i) const {
    const int mi = c.s.material[i];
    const bool fluid_i = c.mats.is_fluid(mi);
    const Vec<D> v_i = c.s.v[i];
    const Real rho_i = c.s.rho[i];
    if (!fluid_i && (!walls || !c.s.near_fluid[i] || c.mats.is_solid(mi))) {
      c.s.drho[i] = Real(0);
      return;
    }
    Real div = 0, diffusion = 0;
    auto pair = [&](int j, const Vec<D>& rij, Real r) PSPH_PAIR {
      if (!(r > Real(0))) return;
      const Real F = c.kern.F(r);
      const Real V_j = c.mats.volume_of(c.s, j);
      div += V_j * dot(v_i - c.s.v[j], rij) * F;  // eq. 53a
      // delta-SPH: 2 delta h_s c sum_j V_j (rho_j - rho_i) (r_ji . grad_i W_ij) / r^2 over fluid
      // pairs (Molteni & Colagrossi 2009, Comput. Phys. Commun. 180:861, eq. 7).
      if (density_diffusion > Real(0) && fluid_i && c.mats.is_fluid(c.s.material[j]))
        diffusion -= Real(2) * V_j * (c.s.rho[j] - rho_i) * F;
    };
    if (fluid_i) c.nb.for_each(i, pair);
    else c.nb.for_each_fluid(i, pair);  // a wall's density answers the fluid only
    c.s.drho[i] = rho_i * div + density_diffusion * smoothing_length * c.mats[mi].sound_speed * diffusion;
  }
};

}  // namespace psph
