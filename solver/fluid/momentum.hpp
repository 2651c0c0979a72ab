#pragma once
// Fluid pair sums, fused in one neighbour loop: pressure force, viscous force, artificial
// viscosity and XSPH. Gather form: each particle writes only its own outputs.
#include "fluid/material.hpp"
#include "fluid/viscosity.hpp"
#include "interface/contact_line.hpp"
#include "interface/surface_tension.hpp"
#include "kernels/kernel.hpp"
#include "kernels/laplacian_correction.hpp"
#include "neighbours/neighbour_list.hpp"
#include "state/particles.hpp"

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

template <int D>
struct FluidForcePass {
  NeighbourList<D> nb;
  Kernel<D> kern;
  ParticleView<D> s;
  MaterialTable<D> mats;
  FluidForceOptions opt;

  PSPH_HD void operator()(int i) const {
    const int mi = s.material[i];
    const Vec<D> v_i = s.v[i];
    const Real rho_i = s.rho[i];
    const Real inv_rho_i = Real(1) / rho_i;
    const Real p_rho2_i = s.p[i] * inv_rho_i * inv_rho_i;
    const Real inv_m_i = Real(1) / s.m[i];
    const Real p_V2_i = s.p[i] * s.m[i] * inv_rho_i * s.m[i] * inv_rho_i;
    const Real mu_i = mats[mi].viscosity;
    const Real c_i = mats[mi].sound_speed;
    const Real hs = opt.smoothing_length;
    Vec<D> acc = Vec<D>::zero(), visc = Vec<D>::zero(), xs = Vec<D>::zero();
    // lambda_i = -sum_j V_j r_ij^2 F_ij is D in the continuum; on a lattice with support = 2
    // spacings it is 1.013 D (2D) and 1.020 D (3D), the relative error of the Morris Laplacian
    // there. Dividing by lambda_i / D (the trace form) makes the operator exact for quadratic
    // fields on cubic lattices; the tensor form also on sheared ones (kernels/laplacian_correction.hpp).
    Real lambda = 0;
    ContactLineSum<D> contact;
    const bool contact_line = opt.surface_tension > Real(0) && opt.contact_line_force && nb.lists_non_fluid(i);
    const Real colour_i = contact_line ? s.colour[i] : Real(0);

    if (!mats.moves_freely(mi, s.x[i])) {  // walls and open-boundary buffers
      s.a[i] = Vec<D>::zero();
      s.v_xsph[i] = Vec<D>::zero();
      s.lap_v[i] = Vec<D>::zero();  // none for walls and buffers (a recycled one kept the outlet's)
      return;
    }
    Mat<D> A = Mat<D>::identity();
    bool tensor = opt.laplacian == LaplacianCorrection::Tensor;
    if (tensor) {
      LaplacianTensor<D> lt;
      nb.for_each(i, [&](int j, const Vec<D>& rij, Real r) {
        if (r > Real(0)) lt.add(s.m[j] / s.rho[j], kern.F(r), rij);
      });
      tensor = lt.solve(A);  // a degenerate neighbourhood falls back to the trace form
    }
    nb.for_each(i, [&](int j, const Vec<D>& rij, Real r) PSPH_PAIR {
      if (!(r > Real(0))) return;  // coincident particles exert no pair force (avoids 0/0)
      const int mj = s.material[j];
      const Real rho_j = s.rho[j];
      const Real m_j = s.m[j];
      const Real inv_rho_j = Real(1) / rho_j;
      const Real V_j = m_j * inv_rho_j;
      const Real dw_r = kern.F(r);  // grad_i W_ij = r_ij F_ij
      const Vec<D> vij = v_i - s.v[j];
      const bool fluid_j = mats.is_fluid(mj);
      // Pressure, symmetric form (Pazdniakou eq. 54b in eq. 57). With number density the particle
      // masses differ by the density ratio, and eq. 54b would weigh a gas particle's own pressure by
      // its liquid neighbour's mass; the volume form of Hu & Adams (2006, J. Comput. Phys. 213:844),
      // (p_i V_i^2 + p_j V_j^2) / m_i, is the same for equal masses and stays consistent.
      Real pterm = opt.number_density ? (p_V2_i + s.p[j] * V_j * V_j) * inv_m_i
                                      : m_j * (p_rho2_i + s.p[j] * inv_rho_j * inv_rho_j);
      // Artificial viscosity for approaching pairs (Monaghan 1992; Deptulski eq. 2.64 with the
      // sign that makes it repulsive).
      const Real vr = dot(vij, rij);
      if (opt.artificial_viscosity > Real(0) && vr < Real(0)) {
        // Pi_ij = -alpha c_mean mu_ij / rho_mean, mu_ij = h vr / (r^2 + 0.01 h^2): one division.
        const Real c_j = fluid_j ? mats[mj].sound_speed : c_i;
        pterm -= m_j * opt.artificial_viscosity * (c_i + c_j) * hs * vr /
                 ((r * r + Real(0.01) * hs * hs) * (rho_i + rho_j));
      }
      acc -= rij * (pterm * dw_r);
      // Viscosity (fluid/viscosity.hpp); a wall presents its no-slip velocity (boundary/wall_velocity.hpp).
      const Vec<D> vij_visc = fluid_j ? vij : v_i - s.v_noslip[j];
      const Real w = tensor ? LaplacianTensor<D>::weight(A, rij) : Real(1);
      visc += vij_visc * (viscous_pair_coefficient(mu_i, fluid_j ? mats[mj].viscosity : mu_i, V_j, inv_rho_i, dw_r) * w);
      lambda -= V_j * r * r * dw_r;
      // XSPH over the same material, with the kernel factor restored (eq. 76, digest §7 item 2).
      if (opt.xsph > Real(0) && mj == mi) xs -= vij * (Real(2) * m_j / (rho_i + rho_j) * kern.W(r));
      if (contact_line && !fluid_j) contact.add(V_j, rij, dw_r, kern.W(r), mats[mj].colour);
      if (contact_line && fluid_j) contact.add_fluid(V_j, rij, dw_r, s.colour[j] - colour_i);
    });

    if (!tensor && opt.laplacian != LaplacianCorrection::None && lambda > Real(0)) visc *= Real(D) / lambda;
    if (opt.surface_tension > Real(0)) acc += surface_tension_acceleration(s, i, opt.surface_tension);
    if (contact_line) acc += contact.acceleration(s.colour_gradient[i], opt.surface_tension, rho_i);
    s.a[i] = acc + (opt.viscosity ? visc : Vec<D>::zero()) + mats.body_force_at(mi, s.x[i]);
    s.lap_v[i] = mu_i > Real(0) ? visc * (rho_i / mu_i) : Vec<D>::zero();
    s.v_xsph[i] = xs * opt.xsph;
  }
};

}  // namespace psph
