#pragma once
// Small-strain linear elasticity in displacement form (Navier-Cauchy, Pazdniakou eqs. 16-17):
//   rho a = mu lap(u) + (k + mu/3) grad(div u)
// with the second derivatives of Pazdniakou eq. 61 (r^2 in its first denominator, misprinted as r) /
// Deptulski eq. 2.89 (his eq. 2.90 misprints the cross terms on u_x, and the sign; fixed here):
//   D_ag(f)_i = sum_j V_j (c e_a e_g - delta_ag) (f_i - f_j) F_ij,   c = d + 2,  e = r_ij / r,
// F_ij = (dW/dr)/r. Summed over the components this gives, per pair,
//   mu sum_g D_gg(u_a) + (k + mu/3) sum_g D_ag(u_g)
//     = V_j F_ij [ (mu (c - d) - (k + mu/3)) du + (k + mu/3) c e (e . du) ],   du = u_i - u_j,
// a central, antisymmetric pair force: momentum is conserved and the stiffness is symmetric, so
// the elastic energy is -1/2 sum_i m_i u_i . a_i. In 1D it is (k + 4 mu/3) u''; in 2D, plane strain.
// A pair's stiffness across e is mu (c - d) - (k + mu/3) = 5 mu/3 - k, negative above nu = 1/4 (the
// Cauchy relation of central-force lattices): such solids go unstable, and the case reader refuses
// them in 2D and 3D. The same transverse term resists rigid rotations where the support is
// truncated (free surfaces): a bending plate comes out far too stiff (VALIDATION.md).
// Walls in reach clamp the solid through the displacement they present (solid/clamp.hpp).
// Pair moduli are harmonic means (as in Deptulski eq. 2.45; his eq. 2.90 assumes uniform moduli, so
// this is our choice, the digest's recommendation for damage too): of the materials' moduli, or of
// per-particle ones where the damage stage degrades them (a pair is as weak as its weaker particle:
// the harmonic mean is below twice the smaller modulus).
#include "core/material.hpp"
#include "kernels/kernel.hpp"
#include "neighbours/neighbour_list.hpp"
#include "state/particles.hpp"
#include "stage/pass_context.hpp"
#include "core/pass_fields.hpp"

namespace psph {

// The volume a solid neighbour j (elastic or wall) has in the solid's sums: its rest volume
// m_j / rho0_j. An elastic particle's density does not change; a wall's does near a fluid (it
// follows the fluid's summed density, and with it the fluid's disorder), but the wall's share of
// the solid's sums is its place on the lattice: with rest volumes the corrections depend on the
// reference positions alone and are kept from one list build to the next, fluid or not.
template <int D>
PSPH_HD PSPH_PAIR inline Real solid_sum_volume(const ParticleView<D>& s, int j) {
  return s.m[j] / s.rho0[j];
}

PSPH_HD inline Real harmonic_mean(Real a, Real b) { return a + b > Real(0) ? Real(2) * a * b / (a + b) : Real(0); }

// u = x - x0, minimum image on periodic axes; stored for output and the elastic energy.
template <int D>
struct DisplacementPass {
  static constexpr FieldNames neighbour_reads{};
  static constexpr FieldNames writes{"displacement"};
  ParticleView<D> s;
  CellGrid<D> grid;
  PSPH_HD void operator()(int i) const { s.u[i] = grid.offset(s.x[i], s.x0[i]); }
};

// One pair's bracket of the sum above: times V_j F_ij it is pair j's part of rho a_i.
template <int D>
PSPH_HD inline Vec<D> navier_pair(const Vec<D>& du, const Vec<D>& e, Real k, Real mu) {
  const Real c = Real(D + 2), lambda_mu = k + mu / Real(3);  // lambda + mu
  return du * (mu * (c - Real(D)) - lambda_mu) + e * (lambda_mu * c * dot(e, du));
}

// Per-particle moduli of the elastic particles that replace their materials' (null: none).
struct ParticleModuli {
  const Real* bulk = nullptr;
  const Real* shear = nullptr;
};

template <int D>
struct ElasticForcePass {
  static constexpr FieldNames neighbour_reads = kSolidPairReads;
  static constexpr FieldNames writes{"acceleration"};
  PairContext<D> c;  // lists, kernel, particles, materials
  Real damping = 0;  // zeta (1/s): a -= zeta v
  ParticleModuli moduli;
  PSPH_HD Real bulk(int i, int m) const { return moduli.bulk ? moduli.bulk[i] : c.mats[m].bulk_modulus; }
  PSPH_HD Real shear(int i, int m) const { return moduli.shear ? moduli.shear[i] : c.mats[m].shear_modulus; }
  // The elastic acceleration (eq. 17) of elastic particle i.
  PSPH_HD Vec<D> elastic_acceleration(int i) const {
    const int mi = c.s.material[i];
    const Real k_i = bulk(i, mi), mu_i = shear(i, mi);
    const Point<D> u_i = c.s.u[i];
    Vec<D> f = Vec<D>::zero();
    c.nb.for_each(i, [&](int j, const Vec<D>& rij, Real r) PSPH_PAIR {
      const int mj = c.s.material[j];
      if (r <= Real(0) || c.mats.is_fluid(mj) || c.mats.is_rigid(mj)) return;  // rigid: contact only
      Real k = k_i, mu = mu_i;  // walls (clamps) present the particle's own moduli
      if (c.mats.is_elastic(mj) && (mj != mi || moduli.bulk))
        k = harmonic_mean(k_i, bulk(j, mj)), mu = harmonic_mean(mu_i, shear(j, mj));
      f += navier_pair<D>(to_real(u_i - c.s.u[j]), rij * (Real(1) / r), k, mu) * (solid_sum_volume(c.s, j) * c.kern.F(r));
    });
    return f * (Real(1) / c.s.rho[i]);
  }
  PSPH_HD void operator()(int i) const {
    const int mi = c.s.material[i];
    if (!c.mats.is_elastic(mi)) return;
    c.s.a[i] = elastic_acceleration(i) + c.mats.body_force[mi] - c.s.v[i] * damping;
  }
};

// Elastic energy of a linear solid, -1/2 m u . a_elastic (its own sum again: a also holds body,
// damping and fluid forces).
template <int D>
struct ElasticEnergyOf {
  static constexpr FieldNames neighbour_reads{"position", "reference_position", "material", "displacement", "mass",
                                              "rest_density", "damaged_bulk_modulus", "damaged_shear_modulus"};
  ElasticForcePass<D> pass;
  PSPH_HD Real operator()(int i) const {
    if (!pass.c.mats.is_elastic(pass.c.s.material[i])) return Real(0);
    return Real(-0.5) * pass.c.s.m[i] * dot(to_real(pass.c.s.u[i]), pass.elastic_acceleration(i));
  }
};

}  // namespace psph
