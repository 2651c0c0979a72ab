#pragma once
// Fluid-solid coupling by extended summation (Pazdniakou 2018 §3.3, Antoci et al. 2007): the
// fluid's pressure and viscous sums run over elastic neighbours as over walls (fluid/momentum.hpp),
// each elastic particle presenting a pressure and its no-slip velocity (boundary/wall_velocity.hpp).
// The solid takes, by `[solid] coupling`:
//   traction (default, stress form): the reaction of the viscous pair forces, and for the pressure
//             the traction P_i b_i / rho_i, with b_i = sum_j V_j (g_ij - g_ji) over its elastic
//             neighbours, the boundary sum of the stress form (solid/stress_form.hpp), and P_i the
//             fluid's pressure carried into the body's surface layer (b_i reaches a support deeper
//             than the fluid: AmbientPressurePass). A fluid at rest at pressure p and a solid at
//             stress -p I are then in exact equilibrium, particle by particle; momentum is
//             exchanged exactly at rest, to O(h/L) of the pressure force in motion. The reaction
//             of the pressure pairs instead loads a body's surface with p (1 - O(h/L)) (measured:
//             an elastic cube of 10 spacings 7 % too stiff inside), the fluid's uncorrected pair
//             sums missing a strip along the solid's edges that its corrected gradients count.
//   pair:     the reaction of every pair force (action and reaction, exact momentum exchange),
//             with the extrapolated pressure;
//   pair_eos: the same with the solid's own pressure c_solid^2 (rho - rho0) = -k tr(eps)
//             (Pazdniakou eq. 74 with the density change of the strain), k the damaged bulk
//             modulus where the damage stage degrades it.
// Rigid bodies (rigid/) present the extrapolated pressure and take the reaction of every pair force.
// The extrapolated pressure is Adami, Hu & Adams (2012) eq. 27 without the particle's own
// acceleration: with it, the traction feeds the last step's acceleration back into the next one
// (an added-mass loop: the elastic cube of VALIDATION.md blew up in 54 steps).
#include "boundary/wall_pressure.hpp"
#include "fluid/momentum.hpp"
#include "solid/constitutive.hpp"
#include "solid/elastic_force.hpp"
#include "solid/solid_options.hpp"
#include "solid/strain.hpp"
#include "stage/pass_context.hpp"
#include "core/pass_fields.hpp"

namespace psph {

template <int D>
struct SolidInterfacePressurePass {
  static constexpr FieldNames neighbour_reads = kFluidPairReads;
  static constexpr FieldNames writes{"pressure"};
  PairContext<D> c;  // lists, kernel, particles, materials
  SolidCoupling mode;
  ParticleModuli moduli;  // the damaged moduli, if any
  PSPH_HD void operator()(int i) const {
    const int mi = c.s.material[i];
    if (!c.mats.is_solid(mi)) return;
    Real p = 0;  // without fluid neighbours no fluid sees it
    c.s.fluid_contact[i] = extrapolate_fluid_pressure(c.nb, c.kern, c.s, c.mats, i, Vec<D>::zero(), p);
    const bool eos = mode == SolidCoupling::PairEos && c.mats.is_elastic(mi);
    const Real k = moduli.bulk ? moduli.bulk[i] : c.mats[mi].bulk_modulus;
    c.s.p[i] = eos ? small_strain_pressure(c.s.strain[i], k) : p;
  }
};

// P_i = sum_j p_j W_ij / sum_j W_ij - p_ref over the elastic particles j (i included) in contact with
// the fluid: the fluid's pressure over the solid's surface layer, 0 deeper. p_ref ([solid]
// reference_pressure) lets a fluid carry a background pressure (fluid/density.hpp) that orders its
// particles without loading the solid.
template <int D>
struct AmbientPressurePass {
  static constexpr FieldNames neighbour_reads = kFluidPairReads;
  static constexpr FieldNames writes{};
  PairContext<D> c;  // lists, kernel, particles, materials
  Real reference = 0;  // p_ref (Pa)
  PSPH_HD void operator()(int i) const {
    if (!c.mats.is_elastic(c.s.material[i])) return;
    const Real w0 = c.s.fluid_contact[i] ? c.kern.W(Real(0)) : Real(0);
    Real psum = c.s.p[i] * w0, wsum = w0;
    SolidNeighbours<D>{c.nb, c.s, c.mats}.for_each(i, [&](int j, const Vec<D>&, Real r) PSPH_PAIR {
      if (!c.mats.is_elastic(c.s.material[j]) || !c.s.fluid_contact[j]) return;
      const Real w = c.kern.W(r);
      psum += c.s.p[j] * w, wsum += w;
    });
    c.s.p_ambient[i] = wsum > Real(0) ? psum / wsum - reference : Real(0);
  }
};

// a_i += -(m_f / m_i) a_f(i) over the fluid neighbours f of solid particle i, a_f(i) the
// acceleration fluid particle f took from i in FluidForcePass (the same function, with f's
// Laplacian correction): its pressure part only with `pressure` (pair coupling) or on a rigid
// body (which has no traction). Runs after the solid's own force pass, which sets a_i.
template <int D>
struct FluidOnSolidPass {
  static constexpr FieldNames neighbour_reads = kFluidPairReads;
  static constexpr FieldNames writes{"acceleration"};
  PairContext<D> c;  // lists, kernel, particles, materials
  FluidForceOptions opt;
  bool pressure;
  PSPH_HD void operator()(int i) const {
    const int mi = c.s.material[i];
    if (!c.mats.is_solid(mi)) return;
    const bool with_pressure = pressure || c.mats.is_rigid(mi);
    const Real V_i = c.mats.volume_of(c.s, i);
    Vec<D> f = Vec<D>::zero();
    c.nb.for_each_fluid(i, [&](int j, const Vec<D>& rij, Real r) PSPH_PAIR {
      if (!(r > Real(0)) || !c.mats.moves_freely(c.s.material[j], c.s.x[j])) return;
      const FluidParticle<D> fj(c.s, c.mats, j);
      const FluidPairTerms<D> t = fluid_pair_terms(fj, c.s, c.mats, opt, i, rij * Real(-1), r, c.kern.F(r), V_i);
      const Vec<D> a_j = t.artificial + t.viscous * (opt.viscosity ? c.s.visc_scale[j] : Real(0));
      f -= (with_pressure ? a_j + t.pressure : a_j) * c.s.m[j];
    });
    c.s.a[i] += f * (Real(1) / c.s.m[i]);
  }
};

}  // namespace psph
