#pragma once
// The viscous term of the momentum equation, shared by the explicit force pass (fluid/momentum.hpp)
// and the implicit (backward Euler) operator below.
#include "core/fluid_table.hpp"
#include "kernels/kernel.hpp"
#include "kernels/laplacian_correction.hpp"
#include "neighbours/neighbour_list.hpp"
#include "state/particles.hpp"
#include "stage/pass_context.hpp"
#include "core/pass_fields.hpp"

namespace psph {

// Coefficient of (v_i - v_j) in the viscous acceleration of i: Morris form with the harmonic-mean
// viscosity (Pazdniakou eqs. 55-57), 4 mu_i mu_j / (mu_i + mu_j) V_j / rho_i F_ij. A wall takes
// the fluid's viscosity (our choice: §3.3 gives solids none), so fluid-wall pairs reduce to eq. 55.
PSPH_HD inline Real viscous_pair_coefficient(Real mu_i, Real mu_j, Real V_j, Real inv_rho_i, Real F_ij) {
  const Real mu_sum = mu_i + mu_j;
  return mu_sum > Real(0) ? Real(4) * mu_i * mu_j / mu_sum * V_j * inv_rho_i * F_ij : Real(0);
}

// out = (I - dt L) in over the freely moving fluid particles (0 on walls and open-boundary
// buffers), L the viscous operator of the force pass with the trace-normalised Laplacian (or none):
// the matrix of a backward-Euler viscous step (Ghaitanellis 2017 §3, implicit viscosity). `walls`:
// wall and buffer neighbours present their imposed velocity (the inhomogeneous part); without it
// they present zero, which makes the map linear.
template <int D>
struct ImplicitViscosityOperator {
  static constexpr FieldNames neighbour_reads = kFluidPairReads;  // and the input vector (fluid/fluid_stage.hpp)
  static constexpr FieldNames writes{};
  PairContext<D> c;  // lists, kernel, particles, materials
  bool normalise;  // trace-normalised Laplacian (kernels/laplacian_correction.hpp)
  Real dt;
  const Vec<D>* in;
  Vec<D>* out;
  bool walls;
  PSPH_HD void operator()(int i) const {
    const int mi = c.s.material[i];
    if (!c.mats.moves_freely(mi, c.s.x[i])) {
      out[i] = Vec<D>::zero();
      return;
    }
    const Real mu_i = c.mats[mi].viscosity, inv_rho_i = Real(1) / c.s.rho[i];
    const Vec<D> u_i = in[i];
    Vec<D> lap = Vec<D>::zero();
    Real lambda = 0;
    c.nb.for_each(i, [&](int j, const Vec<D>&, Real r) PSPH_PAIR {
      if (!(r > Real(0))) return;
      const int mj = c.s.material[j];
      const bool fluid_j = c.mats.is_fluid(mj);
      const Real V_j = c.s.m[j] / c.s.rho[j], F = c.kern.F(r);
      // Walls present their no-slip velocity, open-boundary buffers their imposed one.
      const Vec<D> u_j = c.mats.moves_freely(mj, c.s.x[j]) ? in[j]
                         : !walls                      ? Vec<D>::zero()
                         : fluid_j                     ? c.s.v[j]
                                                       : c.s.v_noslip[j];
      lap += (u_i - u_j) * viscous_pair_coefficient(mu_i, fluid_j ? c.mats[mj].viscosity : mu_i, V_j, inv_rho_i, F);
      lambda -= V_j * r * r * F;
    });
    if (normalise && lambda > Real(0)) lap *= Real(D) / lambda;
    out[i] = u_i - lap * dt;
  }
};

// out = a - b on freely moving fluid particles, 0 on walls and open-boundary buffers (the rows of
// the implicit viscous system).
template <int D>
struct FluidDifference {
  Vec<D>* out;
  const Vec<D>* a;
  const Vec<D>* b;
  ParticleView<D> s;
  FluidTable<D> mats;
  PSPH_HD void operator()(int i) const {
    out[i] = mats.moves_freely(s.material[i], s.x[i]) ? a[i] - b[i] : Vec<D>::zero();
  }
};
template <int D>
struct SetFluidVelocity {
  const Vec<D>* from;
  ParticleView<D> s;
  FluidTable<D> mats;
  PSPH_HD void operator()(int i) const {
    if (mats.moves_freely(s.material[i], s.x[i])) s.v[i] = from[i];
  }
};

}  // namespace psph
