#pragma once
// Fluid pair sums, fused in one neighbour loop: pressure force, viscous force, continuity and XSPH.
// Gather form: each particle writes only its own outputs.
#include "fluid/material.hpp"
#include "kernels/kernel.hpp"
#include "neighbours/cell_grid.hpp"
#include "state/particles.hpp"

namespace psph {

template <int D>
struct FluidForcePass {
  NeighbourView<D> nb;
  Kernel<D> kern;
  ParticleView<D> s;
  MaterialTable<D> mats;
  bool continuity;  // accumulate d rho/dt (eq. 53a)
  Real xsph_eps;    // XSPH epsilon (0 = off)
  bool laplacian_normalised;  // divide the viscous sum by lambda_i (see below)

  PSPH_HD void operator()(int i) const {
    const int mi = s.material[i];
    const bool fluid_i = mats.is_fluid(mi);
    const Vec<D> v_i = s.v[i];
    const Real rho_i = s.rho[i];
    const Real p_rho2_i = s.p[i] / (rho_i * rho_i);
    const Real mu_i = mats[mi].viscosity;
    Vec<D> acc = Vec<D>::zero();
    Vec<D> xs = Vec<D>::zero();
    Vec<D> visc = Vec<D>::zero();
    Real drho = 0;
    // lambda_i = -(1/D) sum_j V_j r_ij^2 F_ij is 1 in the continuum; on a lattice with support = 2
    // spacings it is 1.013 (2D) and 1.020 (3D), the relative error of the Morris Laplacian there.
    // Dividing by it makes the operator exact for quadratic fields on any lattice (a trace form of
    // the second-derivative correction of Fatehi & Manzari 2011).
    Real lambda = 0;

    nb.for_each(i, [&](int j, const Vec<D>& rij, Real r) {
      const int mj = s.material[j];
      const Real rho_j = s.rho[j];
      const Real mj_mass = s.m[j];
      const Real dw_r = kern.dWdr(r) / r;  // F_ij = (1/r) dW/dr, grad_i W_ij = r_ij F_ij
      const Vec<D> vij = v_i - s.v[j];
      if (continuity) drho += mj_mass / rho_j * dot(vij, rij) * dw_r;  // eq. 53a (times rho_i below)
      if (!fluid_i) return;
      const bool fluid_j = mats.is_fluid(mj);
      // Walls present their no-slip velocity to the viscous term (boundary/wall_velocity.hpp).
      const Vec<D> vij_visc = fluid_j ? vij : v_i - s.v_noslip[j];
      // Pressure, symmetric form (Pazdniakou eq. 54b in eq. 57).
      const Real pterm = mj_mass * (p_rho2_i + s.p[j] / (rho_j * rho_j)) * dw_r;
      // Viscosity, Morris form with harmonic-mean viscosity (eqs. 55/56). A wall takes the fluid's
      // viscosity (digest §7 item 16), so fluid-wall pairs reduce to eq. 55.
      const Real mu_j = fluid_j ? mats[mj].viscosity : mu_i;
      const Real mu_sum = mu_i + mu_j;
      const Real mu_pair = mu_sum > Real(0) ? Real(4) * mu_i * mu_j / mu_sum : Real(0);
      const Real vterm = mu_pair * mj_mass / (rho_i * rho_j) * dw_r;
      for (int k = 0; k < D; ++k) acc[k] -= pterm * rij[k];
      visc += vij_visc * vterm;
      lambda -= mj_mass / rho_j * r * r * dw_r;
      // XSPH over the same material, with the kernel factor restored (eq. 76, digest §7 item 2).
      if (xsph_eps > Real(0) && mj == mi) xs -= vij * (Real(2) * mj_mass / (rho_i + rho_j) * kern.W(r));
    });

    if (continuity) s.drho[i] = rho_i * drho;
    if (fluid_i) {
      if (laplacian_normalised && lambda > Real(0)) visc *= Real(D) / lambda;
      s.a[i] = acc + visc + mats.body_force[mi];
      s.lap_v[i] = mu_i > Real(0) ? visc * (rho_i / mu_i) : Vec<D>::zero();
      s.v_xsph[i] = xs * xsph_eps;
    } else {
      s.a[i] = Vec<D>::zero();
      s.v_xsph[i] = Vec<D>::zero();
    }
  }
};

}  // namespace psph
