#pragma once
// Contact-line force: the unbalanced Young force sigma (cos theta_s - cos theta_d) along the wall at
// the contact line (Huber et al. 2016, J. Comput. Phys. 310:459, eq. 21; the references have none).
// The CSF force of a diffuse interface that ends on a wall carries the wall's adhesion only as far
// as the discrete sums near the wall resolve it: without this force a 120-degree drop settled at
// 115 degrees and a slit with theta = 0 let gas in at 0.8 x the entry pressure (VALIDATION.md).
// At a fluid particle i with walls in reach:
//   f_i = -sigma (cos theta_s - cos theta_d) |grad phi_w| t_i,   t_i = grad c_i - n_w (grad c_i . n_w),
// n_w the wall normal towards the fluid, phi_w = sum_w V_w W_iw the walls' volume fraction, theta_s
// the walls' angle (their colour cos theta_s, kernel-weighted), and cos theta_d = -g^ . n_w with g
// the colour gradient over the fluid alone, first-order corrected (Deptulski eq. 2.62a without the
// Shepard step): the particle's own grad c mixes in the walls' extrapolated colour and read 6 degrees
// low on an ideal 120-degree cap, which the force then pushed 6 degrees too high. The weight
// |grad phi_w| |t_i| is the contact line's delta function: across the wall band |grad phi_w|
// integrates to phi_w at the wall (1/2), along the wall |t_i| = |dc/ds| integrates to 2, so the force
// per unit length of contact line is sigma (cos theta_s - cos theta_d), towards the gas (-t) when
// the liquid should spread (tests/test_contact_line.cpp).
#include "kernels/kernel.hpp"

namespace psph {

template <int D>
struct ContactLineSum {
  Vec<D> grad_wall = Vec<D>::zero();  // grad phi_w, pointing into the wall
  Real cos_sum = 0, weight = 0;       // kernel-weighted mean of the walls' cos(theta_s)
  Vec<D> colour_sum = Vec<D>::zero();  // sum_f V_f (c_f - c_i) grad_i W_if over fluid neighbours
  Mat<D> moment = Mat<D>::zero();      // sum_f V_f grad_i W_if (x) (x_f - x_i)

  // A wall neighbour j of volume V_j: grad_i W_ij = r_ij F_ij (r_ij = x_i - x_j).
  PSPH_HD void add(Real V_j, const Vec<D>& rij, Real F_ij, Real W_ij, Real cos_theta_j) {
    grad_wall += rij * (V_j * F_ij);
    cos_sum += V_j * W_ij * cos_theta_j;
    weight += V_j * W_ij;
  }

  // A fluid neighbour j: the first-order consistent colour gradient over the fluid alone.
  PSPH_HD void add_fluid(Real V_j, const Vec<D>& rij, Real F_ij, Real dc) {
    colour_sum += rij * (V_j * F_ij * dc);
    add_outer(moment, rij * F_ij, rij, -V_j);
  }

  // Acceleration of a fluid particle of density rho with colour gradient grad_c.
  PSPH_HD Vec<D> acceleration(const Vec<D>& grad_c, Real sigma, Real rho) const {
    const Real g = norm(grad_wall), len_c = norm(grad_c);
    if (!(g > Real(0)) || !(len_c > Real(0)) || !(weight > Real(0))) return Vec<D>::zero();
    const Vec<D> n_w = grad_wall * (Real(-1) / g);
    const Real along_normal = dot(grad_c, n_w);
    const Vec<D> t = grad_c - n_w * along_normal;
    Mat<D> K;
    const Vec<D> grad_d = invert(moment, K, Real(1e-6)) ? K * colour_sum : grad_c;
    const Real len_d = norm(grad_d);
    const Real cos_d = len_d > Real(0) ? -dot(grad_d, n_w) / len_d : -along_normal / len_c;
    const Real cos_s = cos_sum / weight;
    return t * (-sigma * (cos_s - cos_d) * g / rho);
  }
};

}  // namespace psph
