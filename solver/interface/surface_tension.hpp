#pragma once
// Continuum surface force between two fluids (Brackbill, Kothe & Zemach 1992) in the SPH form of
// Pazdniakou 2018 §3.1.3, with Morris (2000) reliable normals. Each particle carries a colour:
// +1 liquid, -1 gas, cos(theta) for a wall (eq. 10: theta measured through the liquid, so a wall
// of colour +1 is fully wetted by the liquid). Three passes, run only when a case has two fluids:
//   ColourPass     c_i = sum_j V_j c_j W_ij / sum_j V_j W_ij      (eq. 58, Shepard-normalised,
//                  digest §7 item 8); walls keep their constant colour cos(theta).
//   NormalPass     n_i = sum_j V_j (c_j - c_i) grad_i W_ij        (eq. 59a: points gas -> liquid)
//   CurvaturePass  div n^_i = sum_j N_ij V_j (n^_j - n^_i) . grad_i W_ij / sum_j N_ij V_j W_ij
//                  over pairs whose normals are both reliable (|n| > eps / h_s, N_ij = 1; Morris
//                  2000 eqs. 24-25); walls present no normal.
// The force per unit volume is F_s = 1/2 sigma kappa n with kappa = -div n^ (eqs. 7, 9). The paper's
// eq. 60 expands to +div n^, the opposite sign (digest §7 item 5); -div n^ is the one for which
// the force on a gas bubble points into the gas, so that p_gas > p_liquid (the Laplace test,
// validation/laplace_bubble.cpp).
#include "fluid/material.hpp"
#include "kernels/kernel.hpp"
#include "neighbours/neighbour_list.hpp"
#include "state/particles.hpp"

namespace psph {

template <int D>
struct ColourPass {
  NeighbourList<D> nb;
  Kernel<D> kern;
  ParticleView<D> s;
  MaterialTable<D> mats;
  PSPH_HD void operator()(int i) const {
    const int mi = s.material[i];
    if (!mats.is_fluid(mi)) {
      s.colour[i] = mats[mi].colour;
      return;
    }
    const Real w0 = kern.W(Real(0)) * s.m[i] / s.rho[i];
    Real num = w0 * mats[mi].colour, den = w0;
    nb.for_each(i, [&](int j, const Vec<D>&, Real r) PSPH_PAIR {
      const Real vw = s.m[j] / s.rho[j] * kern.W(r);
      num += vw * mats[s.material[j]].colour;
      den += vw;
    });
    s.colour[i] = num / den;
  }
};

template <int D>
struct NormalPass {
  NeighbourList<D> nb;
  Kernel<D> kern;
  ParticleView<D> s;
  MaterialTable<D> mats;
  PSPH_HD void operator()(int i) const {
    Vec<D> n = Vec<D>::zero();
    if (mats.is_fluid(s.material[i])) {
      const Real c_i = s.colour[i];
      nb.for_each(i, [&](int j, const Vec<D>& rij, Real r) PSPH_PAIR {
        if (r > Real(0)) n += rij * (s.m[j] / s.rho[j] * (s.colour[j] - c_i) * kern.F(r));
      });
    }
    s.colour_gradient[i] = n;
  }
};

// n^ when the normal is reliable (|n| > threshold), else zero: the flag is |n^| = 1.
template <int D>
PSPH_HD inline Vec<D> reliable_unit_normal(const Vec<D>& n, Real threshold) {
  const Real len = norm(n);
  return len > threshold ? n * (Real(1) / len) : Vec<D>::zero();
}

template <int D>
struct CurvaturePass {
  NeighbourList<D> nb;
  Kernel<D> kern;
  ParticleView<D> s;
  MaterialTable<D> mats;
  Real threshold;  // eps / h_s
  PSPH_HD void operator()(int i) const {
    Real kappa = 0;
    const Vec<D> u_i = reliable_unit_normal(s.colour_gradient[i], threshold);
    if (mats.is_fluid(s.material[i]) && norm2(u_i) > Real(0)) {
      Real div = 0, cover = kern.W(Real(0)) * s.m[i] / s.rho[i];
      nb.for_each(i, [&](int j, const Vec<D>& rij, Real r) PSPH_PAIR {
        if (!mats.is_fluid(s.material[j]) || !(r > Real(0))) return;
        const Vec<D> u_j = reliable_unit_normal(s.colour_gradient[j], threshold);
        if (!(norm2(u_j) > Real(0))) return;
        const Real V_j = s.m[j] / s.rho[j];
        div += V_j * dot(u_j - u_i, rij) * kern.F(r);
        cover += V_j * kern.W(r);
      });
      kappa = -div / cover;
    }
    s.curvature[i] = kappa;
  }
};

// Acceleration from the surface force on fluid particle i: F_s / rho_i (eq. 57, last term).
template <int D>
PSPH_HD inline Vec<D> surface_tension_acceleration(const ParticleView<D>& s, int i, Real sigma) {
  return s.colour_gradient[i] * (Real(0.5) * sigma * s.curvature[i] / s.rho[i]);
}

}  // namespace psph
