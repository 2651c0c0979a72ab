#pragma once
// Rigid bodies on the device: placing their particles from the bodies' motion, the force and
// torque of their particles (Pazdniakou 2018 eqs. 63, 65), and contact between objects.
// The bodies' Newton-Euler update is rigid/rigid_bodies.hpp. A body's particles are listed by id
// with their offsets q from the centre of mass in the initial orientation (the list survives
// reorderings: index_of_id finds each particle).
#include <cstdint>

#include "core/material.hpp"
#include "neighbours/cell_grid.hpp"
#include "neighbours/neighbour_list.hpp"
#include "state/particles.hpp"
#include "core/pass_fields.hpp"

namespace psph {

// a x b for vectors of D <= 3 components lifted to 3D (zeros beyond D; in 2D only z survives).
template <int D>
PSPH_HD inline void cross_lifted(const Real a[3], const Vec<D>& b_d, Real out[3]) {
  Real b[3] = {0, 0, 0};
  for (int d = 0; d < D; ++d) b[d] = b_d[d];
  out[0] = a[1] * b[2] - a[2] * b[1], out[1] = a[2] * b[0] - a[0] * b[2], out[2] = a[0] * b[1] - a[1] * b[0];
}

template <int D>
struct RigidPose {
  Point<D> centre;
  Vec<D> velocity;
  Mat<D> rotation;
  Real omega[3];  // world frame; in 2D only omega[2]
  PSPH_HD Vec<D> velocity_at(const Vec<D>& arm) const {  // V + omega x arm
    Real w[3];
    cross_lifted<D>(omega, arm, w);
    Vec<D> v = velocity;
    for (int d = 0; d < D; ++d) v[d] += w[d];
    return v;
  }
};

// x_i = X + R q_i, v_i = V + omega x R q_i (eqs. 69a-b with the rotation from the body's start).
template <int D>
struct RigidPlacePass {
  ParticleView<D> s;
  CellGrid<D> grid;
  const std::int32_t* ids;
  const std::int32_t* body_of;
  const Vec<D>* offset;
  const RigidPose<D>* pose;
  PSPH_HD void operator()(int k) const {
    const int i = s.index_of_id[ids[k]];
    if (i < 0) return;  // held by another process
    const RigidPose<D>& p = pose[body_of[k]];
    const Vec<D> arm = p.rotation * offset[k];
    s.x[i] = grid.wrap(p.centre + to_coord(arm));
    s.v[i] = p.velocity_at(arm);
  }
};

// m_i (a_i - g_i) and its moment about the centre of mass (torque: z only in 2D), summed over one
// body in double. The body force g_i is left out of the sum: the body's weight M g, exact in double
// (RigidStage::sum_loads), would otherwise come back with the rounding of g and of every particle's
// share in Real (in mixed precision a free fall's relative error is then ~1e-7; it is 1e-16 so).
struct RigidLoadSum {
  using component_type = double;
  double f[3] = {0, 0, 0}, t[3] = {0, 0, 0};
  PSPH_HD RigidLoadSum& operator+=(const RigidLoadSum& o) {
    for (int k = 0; k < 3; ++k) f[k] += o.f[k], t[k] += o.t[k];
    return *this;
  }
  PSPH_HD friend RigidLoadSum operator+(RigidLoadSum a, const RigidLoadSum& o) { return a += o; }
};
template <int D>
struct RigidLoadOf {
  ParticleView<D> s;
  const std::int32_t* ids;  // the body's entries
  const Vec<D>* offset;
  Mat<D> rotation;
  MaterialTable<D> mats;
  const std::uint8_t* owned;  // this process's particles (null: all): each member counts once
  PSPH_HD RigidLoadSum operator()(int k) const {
    const int i = s.index_of_id[ids[k]];
    if (i < 0 || (owned && !owned[i])) return RigidLoadSum{};
    const Vec<D> f = (s.a[i] - mats.body_force[s.material[i]]) * s.m[i];
    const Vec<D> r = rotation * offset[k];
    Real arm[3] = {0, 0, 0}, t[3];
    for (int d = 0; d < D; ++d) arm[d] = r[d];  // the arm, lifted to 3D
    cross_lifted<D>(arm, f, t);  // r x f: z only in 2D, none in 1D
    RigidLoadSum l;
    for (int d = 0; d < D; ++d) l.f[d] = double(f[d]);
    for (int d = 0; d < 3; ++d) l.t[d] = double(t[d]);
    return l;
  }
};

// Contact between objects: a rigid particle and a particle of another body, a wall or an elastic
// solid, closer than the particle spacing s0, repel each other along the line of centres:
//   m_i a_i = k (s0 - r) e_ij,  k = 2 mu_ij c^2 / s0^2,
// with mu_ij the pair's reduced mass (m_i against a wall, which does not move) and c the larger
// sound speed of the pair's rigid materials. This is eq. 75's conservative repulsion
// f_i = -m_j / (m_i + m_j) B n_i, with B growing with the overlap (the paper leaves B open and
// uses "the repulsive part of the SPH pressure", §5.2.4); no friction, as in the paper. A
// colliding pair then oscillates at sqrt(2) c / s0, within the acoustic step limit; lattice
// neighbours at s0 exert nothing. Sets a rigid particle's acceleration (with its body force, before
// the fluid's reaction, solid/fluid_coupling.hpp) and adds to an elastic particle's.
template <int D>
struct RigidContactPass {
  static constexpr FieldNames neighbour_reads{"position", "material", "rigid_body", "mass"};
  static constexpr FieldNames writes{"acceleration"};
  NeighbourList<D> nb;
  ParticleView<D> s;
  MaterialTable<D> mats;
  Real spacing;
  PSPH_HD void operator()(int i) const {
    const int mi = s.material[i];
    if (!mats.is_solid(mi)) return;
    const bool rigid_i = mats.is_rigid(mi);
    Vec<D> a = Vec<D>::zero();
    nb.for_each(i, [&](int j, const Vec<D>& rij, Real r) PSPH_PAIR {
      const int mj = s.material[j];
      const bool rigid_j = mats.is_rigid(mj);
      if (!(r > Real(0)) || r >= spacing || mats.is_fluid(mj) || !(rigid_i || rigid_j)) return;
      if (rigid_i && rigid_j && s.body[i] == s.body[j]) return;
      const Real c = rigid_i && rigid_j ? fmax(mats[mi].sound_speed, mats[mj].sound_speed)
                                        : mats[rigid_i ? mi : mj].sound_speed;
      const Real share = mats.is_dynamic(mj) ? s.m[j] / (s.m[i] + s.m[j]) : Real(1);  // mu_ij / m_i
      a += rij * (Real(2) * share * c * c * (spacing - r) / (spacing * spacing * r));
    });
    if (rigid_i) s.a[i] = a + mats.body_force[mi];
    else s.a[i] += a;
  }
};

}  // namespace psph
