#pragma once
// Newton-Euler motion of rigid bodies (Pazdniakou 2018 eqs. 25, 62-69), on the host in double
// precision: a case has few bodies, and their sums over particles come from the backend
// (rigid/rigid_body.hpp). Each body keeps its centre of mass X, velocity V, rotation R from its
// initial orientation and angular momentum L about X; its particles sit at X + R q_i, q_i their
// initial offsets from X.
//
// Choices where the paper is silent or loose:
// - eq. 25c is integrated as dL/dt = T with omega = I^-1 L, I = R I_0 R^T: the same equation,
//   and a torque-free body keeps L exactly.
// - The rotation of a step is exact for the step's angular velocity (Rodrigues' formula) instead
//   of the first-order product of eq. 70, with omega taken at the half-rotated orientation (a
//   fixed point, two iterations): second order also for a body whose omega is not a principal axis.
// - In 2D a body turns about z only (omega_z = L_z / I_zz); in 1D it only translates.
#include <array>
#include <vector>

#include "core/length_unit.hpp"

namespace psph {

using Vec3d = std::array<double, 3>;
using Mat3d = std::array<double, 9>;  // row-major

struct RigidBodyState {
  double mass = 0;
  Mat3d inertia0{};  // about the centre of mass, in the initial orientation (eq. 64)
  Vec3d centre{}, velocity{}, angular_momentum{};
  Mat3d rotation{1, 0, 0, 0, 1, 0, 0, 0, 1};
};

// Force and torque about the centre of mass (eqs. 63, 65).
struct RigidLoad {
  Vec3d force{}, torque{};
};

class RigidBodies {
 public:
  RigidBodies() = default;
  RigidBodies(int dimension, std::vector<RigidBodyState> bodies);

  int count() const { return static_cast<int>(bodies_.size()); }
  const RigidBodyState& body(int b) const { return bodies_[b]; }
  const std::vector<RigidBodyState>& all() const { return bodies_; }
  void set_all(const std::vector<RigidBodyState>& b) { bodies_ = b; }

  // World-frame angular velocity I^-1 L.
  Vec3d angular_velocity(int b) const;
  // V += h F / M, L += h T (eqs. 66a, 67: a half kick of velocity Verlet or a leapfrog kick).
  void kick(const std::vector<RigidLoad>& load, double h);
  // X += dt V (eq. 68), R <- exp(dt [omega]) R (eqs. 69b-70).
  void drift(double dt);

  // The state as a flat list of doubles (checkpoints) and back.
  std::vector<double> pack() const;
  void unpack(const std::vector<double>& values);

 private:
  int dimension_ = 3;
  std::vector<RigidBodyState> bodies_;
};

// States as a flat list of doubles (checkpoints) and back; throws std::invalid_argument when the
// list holds other than `bodies` states.
constexpr std::size_t kPackedRigidState = 1 + 9 + 18;  // doubles per body
std::vector<double> pack_states(const std::vector<RigidBodyState>& states);
std::vector<RigidBodyState> unpack_states(const std::vector<double>& values, std::size_t bodies);
// A state in another length unit (core/length_unit.hpp): from SI into `u`, or back (`to_si`).
RigidBodyState in_unit(RigidBodyState s, const LengthUnit& u, bool to_si);

// The bodies of a scene at t = 0 (engine/rigid_scene.hpp builds them from the particles).
struct SceneRigidBodies {
  std::vector<RigidBodyState> state;          // at t = 0
  std::vector<std::vector<int>> members;      // particle indices (= ids) of each body
  std::vector<std::vector<Vec3d>> offsets;    // each member's position relative to the centre of mass
  std::vector<Vec3d> weight;                  // each body's mass times its material's body force (N)
};

// Mass, centre of mass (eq. 62) and inertia (eq. 64) of point masses m at positions x (3 per
// point), with the velocity V and angular momentum L of a body moving at v_cm and omega.
RigidBodyState rigid_body_from_points(const std::vector<double>& m, const std::vector<Vec3d>& x, const Vec3d& v_cm,
                                      const Vec3d& omega, int dimension);

// World-frame angular velocity I^-1 L, I = R I0 R^T (2D: L_z / I_zz; 1D: none).
Vec3d angular_velocity_of(const RigidBodyState& b, int dimension);

Vec3d cross(const Vec3d& a, const Vec3d& b);
Vec3d mat_vec(const Mat3d& m, const Vec3d& v);
Mat3d mat_mul(const Mat3d& a, const Mat3d& b);
// Rotation by the vector theta (axis theta / |theta|, angle |theta|): Rodrigues' formula.
Mat3d rotation_of(const Vec3d& theta);

}  // namespace psph
