#pragma once
// Fluid pair sums, fused in one neighbour loop: pressure force, viscous force, artificial
// viscosity and XSPH. Gather form: each particle writes only its own outputs.
#include "core/fluid_table.hpp"
#include "fluid/viscosity.hpp"
#include "interface/contact_line.hpp"
#include "interface/surface_tension.hpp"
#include "kernels/kernel.hpp"
#include "kernels/laplacian_correction.hpp"
#include "neighbours/neighbour_list.hpp"
#include "state/particles.hpp"
#include "stage/pass_context.hpp"
#include "core/pass_fields.hpp"

namespace psph {

struct FluidForceOptions {
  Real xsph = 0;                     // XSPH epsilon (eq. 76), 0 = off
  LaplacianCorrection laplacian = LaplacianCorrection::Trace;  // of the viscous sum (see below)
  Real artificial_viscosity = 0;     // Monaghan alpha (Deptulski eq. 2.64), 0 = off
  Real smoothing_length = 0;         // h_s, for the artificial viscosity
  Real surface_tension = 0;          // sigma; > 0: the interface passes ran (interface/surface_tension.hpp)
  bool number_density = false;       // pressure in the Hu & Adams (2006) volume form (see below)
  bool contact_line_force = false;   // the unbalanced Young force at contact lines (interface/contact_line.hpp)
  bool viscosity = true;  // false: integrated implicitly instead (the sum still gives lap_v for the walls)
};

// What fluid particle i brings to its pair sums.
template <int D>
struct FluidParticle {
  Vec<D> v;
  Real rho, inv_rho, inv_m, p_rho2, p_V2, mu, c;
  PSPH_HD FluidParticle(const ParticleView<D>& s, const FluidTable<D>& mats, int i)
      : v(s.v[i]), rho(s.rho[i]), inv_rho(Real(1) / s.rho[i]), inv_m(Real(1) / s.m[i]),
        p_rho2(s.p[i] * inv_rho * inv_rho), p_V2(s.p[i] * s.m[i] * inv_rho * s.m[i] * inv_rho),
        mu(mats[s.material[i]].viscosity), c(mats[s.material[i]].sound_speed) {}
};

// The accelerations of fluid particle i from neighbour j: pressure, artificial viscosity and
// viscous, the last before the Laplacian correction. dw_r = F_ij (grad_i W_ij = r_ij F_ij); V_j
// = mats.volume_of(s, j).
template <int D>
struct FluidPairTerms {
  Vec<D> pressure, artificial, viscous;
};
template <int D>
PSPH_HD PSPH_PAIR inline FluidPairTerms<D> fluid_pair_terms(const FluidParticle<D>& fi, const ParticleView<D>& s,
                                                  const FluidTable<D>& mats, const FluidForceOptions& opt, int j,
                                                  const Vec<D>& rij, Real r, Real dw_r, Real V_j) {
  const int mj = s.material[j];
  const Real rho_j = s.rho[j];
  const Real m_j = s.m[j];
  const Real inv_rho_j = Real(1) / rho_j;
  const bool fluid_j = mats.is_fluid(mj);
  // Against a wall or solid, the velocity it presents (boundary/wall_velocity.hpp) in both viscous
  // terms: its own with `prescribed`, the fluid's with `free_slip` (no artificial wall friction).
  const Vec<D> vij = fi.v - (fluid_j ? s.v[j] : s.v_noslip[j]);
  // Pressure, symmetric form (Pazdniakou eq. 54b in eq. 57). With number density the particle
  // masses differ by the density ratio, and eq. 54b would weigh a gas particle's own pressure by
  // its liquid neighbour's mass; the volume form of Hu & Adams (2006, J. Comput. Phys. 213:844),
  // (p_i V_i^2 + p_j V_j^2) / m_i, is the same for equal masses and stays consistent. An elastic
  // or rigid neighbour (its own density and mass) also takes the volume form.
  const Real pterm = opt.number_density || mats.is_solid(mj) ? (fi.p_V2 + s.p[j] * V_j * V_j) * fi.inv_m
                                                                : m_j * (fi.p_rho2 + s.p[j] * inv_rho_j * inv_rho_j);
  // Artificial viscosity for approaching pairs (Monaghan 1992; Deptulski eq. 2.64 with the sign
  // that makes it repulsive).
  const Real vr = dot(vij, rij);
  Real pi_ij = 0;
  if (opt.artificial_viscosity > Real(0) && vr < Real(0)) {
    // Pi_ij = -alpha c_mean mu_ij / rho_mean, mu_ij = h vr / (r^2 + 0.01 h^2): one division.
    const Real hs = opt.smoothing_length;
    const Real c_j = fluid_j ? mats[mj].sound_speed : fi.c;
    pi_ij = -m_j * opt.artificial_viscosity * (fi.c + c_j) * hs * vr / ((r * r + Real(0.01) * hs * hs) * (fi.rho + rho_j));
  }
  // Viscosity (fluid/viscosity.hpp); a wall or solid presents its no-slip velocity
  // (boundary/wall_velocity.hpp).
  const Real coef = viscous_pair_coefficient(fi.mu, fluid_j ? mats[mj].viscosity : fi.mu, V_j, fi.inv_rho, dw_r);
  return FluidPairTerms<D>{rij * (-pterm * dw_r), rij * (-pi_ij * dw_r), vij * coef};
}

template <int D>
struct FluidForcePass {
  static constexpr FieldNames neighbour_reads = kFluidPairReads;
  static constexpr FieldNames writes{"acceleration", "xsph_correction", "velocity_laplacian"};
  PairContext<D> c;  // lists, kernel, particles, materials
  FluidForceOptions opt;

  PSPH_HD void operator()(int i) const {
    const int mi = c.s.material[i];
    if (!c.mats.moves_freely(mi, c.s.x[i])) {  // walls, open-boundary buffers and solids
      if (!c.mats.is_elastic(mi)) c.s.a[i] = Vec<D>::zero();  // an elastic solid's comes from solid/
      c.s.v_xsph[i] = Vec<D>::zero();
      c.s.lap_v[i] = Vec<D>::zero();  // none for walls and buffers (a recycled one kept the outlet's)
      return;
    }
    const FluidParticle<D> fi(c.s, c.mats, i);
    Vec<D> acc = Vec<D>::zero(), visc = Vec<D>::zero(), xs = Vec<D>::zero();
    // lambda_i = -sum_j V_j r_ij^2 F_ij is D in the continuum; on a lattice with support = 2
    // spacings it is 1.013 D (2D) and 1.020 D (3D), the relative error of the Morris Laplacian
    // there. Dividing by lambda_i / D (the trace form) makes the operator exact for quadratic
    // fields on cubic lattices; the tensor form also on sheared ones (kernels/laplacian_correction.hpp).
    Real lambda = 0;
    ContactLineSum<D> contact;
    const bool contact_line = opt.surface_tension > Real(0) && opt.contact_line_force && c.nb.lists_non_fluid(i);
    const Real colour_i = contact_line ? c.s.colour[i] : Real(0);

    Mat<D> A = Mat<D>::identity();
    bool tensor = opt.laplacian == LaplacianCorrection::Tensor;
    if (tensor) {
      LaplacianTensor<D> lt;
      c.nb.for_each(i, [&](int j, const Vec<D>& rij, Real r) {
        if (r > Real(0)) lt.add(c.s.m[j] / c.s.rho[j], c.kern.F(r), rij);
      });
      tensor = lt.solve(A);  // a degenerate neighbourhood falls back to the trace form
    }
    c.nb.for_each(i, [&](int j, const Vec<D>& rij, Real r) PSPH_PAIR {
      if (!(r > Real(0))) return;  // coincident particles exert no pair force (avoids 0/0)
      const int mj = c.s.material[j];
      const Real V_j = c.mats.volume_of(c.s, j);
      const Real dw_r = c.kern.F(r);  // grad_i W_ij = r_ij F_ij
      const bool fluid_j = c.mats.is_fluid(mj);
      const FluidPairTerms<D> t = fluid_pair_terms(fi, c.s, c.mats, opt, j, rij, r, dw_r, V_j);
      acc += t.pressure + t.artificial;
      visc += tensor ? t.viscous * LaplacianTensor<D>::weight(A, rij) : t.viscous;
      lambda -= V_j * r * r * dw_r;
      // XSPH over the same material, with the kernel factor W_ij that eq. 76 misses.
      if (opt.xsph > Real(0) && mj == mi) xs -= (fi.v - c.s.v[j]) * (Real(2) * c.s.m[j] / (fi.rho + c.s.rho[j]) * c.kern.W(r));
      if (contact_line && !fluid_j) contact.add(V_j, rij, dw_r, c.kern.W(r), c.mats[mj].colour);
      if (contact_line && fluid_j) contact.add_fluid(V_j, rij, dw_r, c.s.colour[j] - colour_i);
    });

    const Real scale = !tensor && opt.laplacian != LaplacianCorrection::None && lambda > Real(0) ? Real(D) / lambda : Real(1);
    visc *= scale;
    if (c.s.visc_scale) c.s.visc_scale[i] = scale;
    if (opt.surface_tension > Real(0)) acc += surface_tension_acceleration(c.s, i, opt.surface_tension);
    if (contact_line) acc += contact.acceleration(c.s.colour_gradient[i], opt.surface_tension, fi.rho);
    c.s.a[i] = acc + (opt.viscosity ? visc : Vec<D>::zero()) + c.mats.body_force_at(mi, c.s.x[i]);
    c.s.lap_v[i] = fi.mu > Real(0) ? visc * (fi.rho / fi.mu) : Vec<D>::zero();
    c.s.v_xsph[i] = xs * opt.xsph;
  }
};

}  // namespace psph
