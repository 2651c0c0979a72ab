#pragma once
// Particle shifting (Lind, Xu, Stansby & Rogers 2012, J. Comput. Phys. 231:1499, eqs. 8-11): each
// step, each fluid particle moves down the gradient of the particle concentration by
//   dr_i = -A h_s^2 sum_j V_j (1 + 0.2 (W_ij / W(dx))^4) grad_i W_ij,
// A dimensionless (per step), which keeps the distribution uniform in flows that would otherwise
// disorder it (flow around obstacles). Without it, the sphere-array flow loses its lattice as particles pass the sphere, the
// summation density scatters by 1-2 %, and the pressure noise (c^2 drho) grows to the size of the
// driving pressure (measured). Particles with a truncated support (free surface: Shepard sum
// below 0.95) are not shifted.
#include "fluid/material.hpp"
#include "kernels/kernel.hpp"
#include "neighbours/neighbour_list.hpp"
#include "state/particles.hpp"

namespace psph {

template <int D>
struct ShiftingPass {
  NeighbourList<D> nb;
  Kernel<D> kern;
  ParticleView<D> s;
  MaterialTable<D> mats;
  Real coefficient;  // A
  Real smoothing_length, spacing;
  Vec<D>* shift;     // output
  PSPH_HD void operator()(int i) const {
    shift[i] = Vec<D>::zero();
    if (!mats.is_fluid(s.material[i])) return;
    const Real w_dx = kern.W(spacing);
    Vec<D> grad = Vec<D>::zero();
    Real shepard = s.m[i] / s.rho[i] * kern.W(Real(0));
    nb.for_each(i, [&](int j, const Vec<D>& rij, Real r) PSPH_PAIR {
      const Real V_j = s.m[j] / s.rho[j];
      const Real w = kern.W(r);
      const Real q = w / w_dx, q2 = q * q;
      grad += kern.grad(rij, r) * (V_j * (Real(1) + Real(0.2) * q2 * q2));
      shepard += V_j * w;
    });
    if (shepard < Real(0.95)) return;
    Vec<D> dr = grad * (-coefficient * smoothing_length * smoothing_length);
    const Real len = norm(dr), cap = Real(0.02) * spacing;  // never more than 2 % of a spacing per step
    if (len > cap) dr *= cap / len;
    shift[i] = dr;
  }
};

template <int D>
struct ApplyShift {
  Vec<D>* x;
  const Vec<D>* shift;
  CellGrid<D> grid;
  PSPH_HD void operator()(int i) const { x[i] = grid.wrap(x[i] + shift[i]); }
};

}  // namespace psph
