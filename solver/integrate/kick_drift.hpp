#pragma once
// Kick and drift updates shared by the leapfrog (Pazdniakou eq. 48) and velocity-Verlet
// (eq. 49, kick-drift-kick form) integrators. Fluids and elastic solids are kicked; walls are
// not: they drift with their prescribed velocity (fixed walls have v = 0); rigid particles are
// placed by their body's motion after the drift (rigid/rigid_stage.hpp).
#include <cmath>

#include "core/material.hpp"
#include "neighbours/cell_grid.hpp"
#include "state/particles.hpp"
#include "core/pass_fields.hpp"

namespace psph {

template <int D>
struct KickPass {
  static constexpr FieldNames neighbour_reads{};
  static constexpr FieldNames writes{"velocity"};
  ParticleView<D> s;
  MaterialTable<D> mats;
  Real dt;
  PSPH_HD void operator()(int i) const {
    if (mats.is_kicked(s.material[i])) s.v[i] += s.a[i] * dt;
  }
};

// x += dt (v + v_xsph) (eq. 48b with the XSPH velocity of eq. 76); with continuity,
// rho += dt d rho/dt.
template <int D>
struct DriftPass {
  static constexpr FieldNames neighbour_reads{};
  static constexpr FieldNames writes{"position", "density"};
  ParticleView<D> s;
  CellGrid<D> grid;
  Real dt;
  bool continuity;
  PSPH_HD void operator()(int i) const {
    s.x[i] = grid.wrap(s.x[i] + to_coord(s.v[i] + s.v_xsph[i]) * Coord(dt));  // in Coord: mixed keeps the digits
    if (continuity) s.rho[i] += s.drho[i] * dt;
  }
};

// 4: state not finite; 3: left the domain through a closed side; 2: an elastic particle faster
// than its P-wave speed (strains of order one: an unstable solid grows its energy for long before
// it overflows); 1: a fluid density off its reference by more than `max_density_deviation` (no
// longer weakly compressible); 0: healthy.
template <int D>
struct BadParticle {
  ParticleView<D> s;
  CellGrid<D> grid;
  MaterialTable<D> mats;
  Real max_density_deviation;
  PSPH_HD int operator()(int i) const {
    Real sum = s.rho[i];
    for (int k = 0; k < D; ++k) sum += Real(s.x[i][k]) + s.v[i][k] + s.a[i][k];
    if (!is_finite(sum)) return 4;
    if (!grid.inside(s.x[i])) return 3;
    const int m = s.material[i];
    if (mats.is_elastic(m) && norm2(s.v[i]) > mats[m].sound_speed * mats[m].sound_speed) return 2;
    return mats.is_fluid(m) && fabs(s.rho[i] / s.rho0[i] - Real(1)) > max_density_deviation ? 1 : 0;
  }
};

// |rho/rho0 - 1| of fluid particles (weak-compressibility monitor).
template <int D>
struct DensityDeviationOf {
  ParticleView<D> s;
  MaterialTable<D> mats;
  PSPH_HD Real operator()(int i) const {
    return mats.is_fluid(s.material[i]) ? fabs(s.rho[i] / s.rho0[i] - Real(1)) : Real(0);
  }
};

// BadParticle's code and the fluid's density deviation in one reduction: 16 code + min(|rho/rho0 - 1|,
// 15), whose maximum is the worst code and, where every particle is healthy, the largest deviation.
template <int D>
struct HealthOf {
  BadParticle<D> bad;
  PSPH_HD Real operator()(int i) const {
    const int code = bad(i);
    if (code) return Real(16 * code);  // the deviation of a broken particle may be NaN
    const Real dev = DensityDeviationOf<D>{bad.s, bad.mats}(i);
    return dev < Real(15) ? dev : Real(15);
  }
};

// The id of a particle for which BadParticle returns `code` (-1: none; the failure path only).
template <int D>
struct BadParticleId {
  BadParticle<D> bad;
  int code;
  PSPH_HD int operator()(int i) const { return bad(i) == code ? int(bad.s.id[i]) : -1; }
};

template <int D>
struct SpeedOf {
  ParticleView<D> s;
  PSPH_HD Real operator()(int i) const { return norm(s.v[i]); }
};
template <int D>
struct AccelerationOf {
  ParticleView<D> s;
  PSPH_HD Real operator()(int i) const { return norm(s.a[i]); }
};
template <int D>
struct KineticEnergyOf {
  ParticleView<D> s;
  MaterialTable<D> mats;
  PSPH_HD Real operator()(int i) const {
    return mats.is_dynamic(s.material[i]) ? Real(0.5) * s.m[i] * norm2(s.v[i]) : Real(0);
  }
};
}  // namespace psph
