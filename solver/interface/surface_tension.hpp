#pragma once
// Continuum surface force between two fluids (Brackbill, Kothe & Zemach 1992) in the SPH form of
// Pazdniakou 2018 §3.1.3, with Morris (2000) reliable normals. Each particle carries a colour:
// +1 liquid, -1 gas, cos(theta) for a wall (eq. 10: theta measured through the liquid, so a wall
// of colour +1 is fully wetted by the liquid). Three passes, run only when a case has two fluids:
//   ColourPass     c_i = sum_j V_j c_j W_ij / sum_j V_j W_ij      (eq. 58, Shepard-normalised:
//                  our choice, the paper is silent); walls keep their constant colour cos(theta), or with
//                  geometric wetting the colour extrapolated from the fluid (wall_wetting.hpp).
//   NormalPass     n_i = sum_j V_j (c_j - c_i) grad_i W_ij        (eq. 59a: points gas -> liquid)
//   CurvaturePass  div n^_i = sum_j N_ij V_j (n^_j - n^_i) . grad_i W_ij / sum_j N_ij V_j W_ij
//                  over pairs whose normals are both reliable (|n| > eps / h_s, N_ij = 1; Morris
//                  2000 eqs. 24-25); walls present a normal only with geometric wetting. The
//                  curvature is then carried from the particle's own level set to the interface
//                  (interface_curvature below).
// The force per unit volume is F_s = 1/2 sigma kappa n with kappa = -div n^ (eqs. 7, 9). The paper's
// eq. 60 expands to +div n^, the opposite sign to its eq. 7; -div n^ is the one for which
// the force on a gas bubble points into the gas, so that p_gas > p_liquid (the Laplace test,
// validation/laplace_bubble.cpp).
#include "core/material.hpp"
#include "kernels/kernel.hpp"
#include "neighbours/neighbour_list.hpp"
#include "state/particles.hpp"
#include "stage/pass_context.hpp"
#include "core/pass_fields.hpp"

namespace psph {

// How the colour and normal passes treat walls. Wall colour (Pazdniakou eq. 10): walls are in every
// sum with their constant colour cos(theta). Geometric wetting (wall_wetting.hpp): the colour and
// the normals are first summed over fluids only; the walls then take the colour extrapolated from
// them, and the colour and normals of fluid particles with walls in reach are summed again with
// the walls (twice: the walls' first colour inherits the one-sided fluid sums; with one round a
// 120 degree drop settled at 113 / 109 degrees from 90 / 135, with two at 115 / 115).
enum class WallColour { Constant, FluidOnly, NearWallsAgain };

template <int D>
PSPH_HD inline bool colour_pass_skips(const NeighbourList<D>& nb, WallColour walls, bool fluid, int i) {
  return walls == WallColour::NearWallsAgain && !(fluid && nb.lists_non_fluid(i));
}

template <int D>
struct ColourPass {
  static constexpr FieldNames neighbour_reads = kFluidPairReads;
  static constexpr FieldNames writes{"colour"};
  PairContext<D> c;  // lists, kernel, particles, materials
  WallColour walls;
  PSPH_HD void operator()(int i) const {
    const int mi = c.s.material[i];
    if (colour_pass_skips(c.nb, walls, c.mats.is_fluid(mi), i)) return;
    if (!c.mats.is_fluid(mi)) {
      if (walls == WallColour::Constant) c.s.colour[i] = c.mats[mi].colour;
      return;
    }
    const Real w0 = c.kern.W(Real(0)) * c.s.m[i] / c.s.rho[i];
    Real num = w0 * c.mats[mi].colour, den = w0;
    auto add = [&](int j, const Vec<D>&, Real r) PSPH_PAIR {
      const Real vw = c.s.m[j] / c.s.rho[j] * c.kern.W(r);
      const int mj = c.s.material[j];  // walls: cos(theta), or their extrapolated colour
      num += vw * (walls == WallColour::NearWallsAgain && !c.mats.is_fluid(mj) ? c.s.colour[j] : c.mats[mj].colour);
      den += vw;
    };
    if (walls == WallColour::FluidOnly) c.nb.for_each_fluid(i, add);
    else c.nb.for_each(i, add);
    c.s.colour[i] = num / den;
  }
};

template <int D>
struct NormalPass {
  static constexpr FieldNames neighbour_reads = kFluidPairReads;
  static constexpr FieldNames writes{"colour_gradient"};
  PairContext<D> c;  // lists, kernel, particles, materials
  WallColour walls;
  PSPH_HD void operator()(int i) const {
    const bool fluid = c.mats.is_fluid(c.s.material[i]);
    if (colour_pass_skips(c.nb, walls, fluid, i)) return;
    Vec<D> n = Vec<D>::zero();
    if (fluid) {
      const Real c_i = c.s.colour[i];
      auto add = [&](int j, const Vec<D>& rij, Real r) PSPH_PAIR {
        if (r > Real(0)) n += rij * (c.s.m[j] / c.s.rho[j] * (c.s.colour[j] - c_i) * c.kern.F(r));
      };
      if (walls == WallColour::FluidOnly) c.nb.for_each_fluid(i, add);
      else c.nb.for_each(i, add);
    }
    c.s.colour_gradient[i] = n;
  }
};

// erf^-1(x) for |x| < 0.9966: the central branch of the single-precision approximation of
// M. Giles, "Approximating the erfinv function", GPU Computing Gems Jade Edition (2011).
PSPH_HD inline Real erfinv_central(Real x) {
  const Real w = -log((Real(1) - x) * (Real(1) + x)) - Real(2.5);
  Real p = Real(2.81022636e-08);
  p = Real(3.43273939e-07) + p * w;
  p = Real(-3.5233877e-06) + p * w;
  p = Real(-4.39150654e-06) + p * w;
  p = Real(0.00021858087) + p * w;
  p = Real(-0.00125372503) + p * w;
  p = Real(-0.00417768164) + p * w;
  p = Real(0.246640727) + p * w;
  p = Real(1.50140941) + p * w;
  return p * x;
}

// The curvature of the interface (c = 0) from the one measured at a particle of the diffuse band.
// Every particle of the band carries the curvature of its own level set, 1/r on a circle of radius
// r, so that the pressure jump, the band integral of 1/2 sigma kappa |grad c|, came out as
// sigma <1/r> ~ (sigma / R) (1 + 3/2 Var / R^2) (2D, Var the band's variance in r: +12 % at
// R = 4 h with the quintic spline). The particle's signed distance d to the interface, positive
// towards the liquid, follows from its smoothed colour: across a plane c = erf(d / sqrt(2 m2))
// (the kernels' profiles are close to Gaussian; m2 = int x^2 W per axis, 0.483 h^2 for the
// quintic spline), and curvature moves that profile by m2 kappa / 2 (a bubble's particles see
// more liquid than a plane's). On a circle or a sphere the curvature of the parallel surface at
// d is kappa = kappa_G / (1 - kappa_G d / (D - 1)), inverted here. (The SPH divergence also
// smooths kappa, by m2/2 lap(kappa) = m2 kappa^3 / 2 on a 2D curve; correcting that too
// measured worse, -0.9 % instead of +0.7 % at R = 4 h and -0.4 % at R = 16 h.)
template <int D>
PSPH_HD inline Real interface_curvature(Real kappa, Real colour, Real m2) {
  const Real cmax = Real(0.99);  // |d| <= 1.82 sqrt(2 m2): the profile's tails carry no signal
  const Real c = colour > cmax ? cmax : colour < -cmax ? -cmax : colour;
  const Real d = sqrt(Real(2) * m2) * erfinv_central(c) + Real(0.5) * m2 * kappa;
  Real den = Real(1) + kappa * d / Real(D > 1 ? D - 1 : 1);  // (1D has no curvature)
  if (den < Real(0.5)) den = Real(0.5);  // only for radii below about 2 h
  return kappa / den;
}

// n^ when the normal is reliable (|n| > threshold), else zero: the flag is |n^| = 1.
template <int D>
PSPH_HD inline Vec<D> reliable_unit_normal(const Vec<D>& n, Real threshold) {
  const Real len = norm(n);
  return len > threshold ? n * (Real(1) / len) : Vec<D>::zero();
}

template <int D>
struct CurvaturePass {
  static constexpr FieldNames neighbour_reads = kFluidPairReads;
  static constexpr FieldNames writes{"curvature"};
  PairContext<D> c;  // lists, kernel, particles, materials
  Real threshold;  // eps / h_s
  bool walls_extend_colour;  // geometric wetting: the colour near walls still measures the distance
  PSPH_HD void operator()(int i) const {
    Real kappa = 0;
    const Vec<D> u_i = reliable_unit_normal(c.s.colour_gradient[i], threshold);
    if (c.mats.is_fluid(c.s.material[i]) && norm2(u_i) > Real(0)) {
      const Real w0 = c.kern.W(Real(0)) * c.s.m[i] / c.s.rho[i];
      Real div = 0, cover = w0, shepard = w0, m2 = 0;
      bool wall = false;
      c.nb.for_each(i, [&](int j, const Vec<D>& rij, Real r) PSPH_PAIR {
        const Real V_j = c.s.m[j] / c.s.rho[j];
        const Real vw = V_j * c.kern.W(r);
        shepard += vw;  // all neighbours, walls included: the kernel's second moment
        m2 += vw * r * r;
        wall |= !c.mats.is_fluid(c.s.material[j]);
        if (!(r > Real(0))) return;
        const Vec<D> u_j = reliable_unit_normal(c.s.colour_gradient[j], threshold);
        if (!(norm2(u_j) > Real(0))) return;
        div += V_j * dot(u_j - u_i, rij) * c.kern.F(r);
        cover += vw;
      });
      // Within a wall's reach a constant wall colour cos(theta) mixes in and the colour no longer
      // measures the distance to the interface: the particle's own curvature is kept there.
      kappa = wall && !walls_extend_colour ? -div / cover
                                           : interface_curvature<D>(-div / cover, c.s.colour[i], m2 / (Real(D) * shepard));
    }
    c.s.curvature[i] = kappa;
  }
};

// Acceleration from the surface force on fluid particle i: F_s / rho_i (eq. 57, last term).
template <int D>
PSPH_HD inline Vec<D> surface_tension_acceleration(const ParticleView<D>& s, int i, Real sigma) {
  return s.colour_gradient[i] * (Real(0.5) * sigma * s.curvature[i] / s.rho[i]);
}

}  // namespace psph
