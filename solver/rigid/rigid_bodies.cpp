#include "rigid/rigid_bodies.hpp"

#include <cmath>
#include <stdexcept>

// Host-side 3x3 algebra in double precision (the bodies' motion is integrated in double whatever
// the particles' precision; core/vec.hpp's Mat works in Real).
namespace psph {

Vec3d cross(const Vec3d& a, const Vec3d& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

Vec3d mat_vec(const Mat3d& m, const Vec3d& v) {
  Vec3d r{};
  for (int i = 0; i < 3; ++i) r[i] = m[3 * i] * v[0] + m[3 * i + 1] * v[1] + m[3 * i + 2] * v[2];
  return r;
}

Mat3d mat_mul(const Mat3d& a, const Mat3d& b) {
  Mat3d r{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) r[3 * i + j] += a[3 * i + k] * b[3 * k + j];
  return r;
}

namespace {

Mat3d transpose(const Mat3d& a) {
  Mat3d r{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) r[3 * i + j] = a[3 * j + i];
  return r;
}

// Solves m x = b (m symmetric positive definite: an inertia tensor) by Cramer's rule.
Vec3d solve(const Mat3d& m, const Vec3d& b) {
  auto det = [](const Mat3d& a) {
    return a[0] * (a[4] * a[8] - a[5] * a[7]) - a[1] * (a[3] * a[8] - a[5] * a[6]) + a[2] * (a[3] * a[7] - a[4] * a[6]);
  };
  const double d = det(m);
  if (!(std::fabs(d) > 0)) throw std::runtime_error("a rigid body has a singular inertia tensor");
  Vec3d x{};
  for (int c = 0; c < 3; ++c) {
    Mat3d mc = m;
    for (int r = 0; r < 3; ++r) mc[3 * r + c] = b[r];
    x[c] = det(mc) / d;
  }
  return x;
}

}  // namespace

Mat3d rotation_of(const Vec3d& theta) {
  const double a = std::sqrt(theta[0] * theta[0] + theta[1] * theta[1] + theta[2] * theta[2]);
  Mat3d r{1, 0, 0, 0, 1, 0, 0, 0, 1};
  if (a == 0) return r;
  const Vec3d k{theta[0] / a, theta[1] / a, theta[2] / a};
  const double s = std::sin(a), c1 = 1 - std::cos(a);
  const Mat3d K{0, -k[2], k[1], k[2], 0, -k[0], -k[1], k[0], 0};
  const Mat3d K2 = mat_mul(K, K);
  for (int i = 0; i < 9; ++i) r[i] += s * K[i] + c1 * K2[i];
  return r;
}

namespace {

Vec3d omega_at(const RigidBodyState& b, const Mat3d& R, int dimension) {
  if (dimension == 1) return {0, 0, 0};
  if (dimension == 2) return {0, 0, b.angular_momentum[2] / b.inertia0[8]};
  // omega = R I0^-1 R^T L
  return mat_vec(R, solve(b.inertia0, mat_vec(transpose(R), b.angular_momentum)));
}

}  // namespace

Vec3d angular_velocity_of(const RigidBodyState& b, int dimension) { return omega_at(b, b.rotation, dimension); }

RigidBodies::RigidBodies(int dimension, std::vector<RigidBodyState> bodies)
    : dimension_(dimension), bodies_(std::move(bodies)) {}

Vec3d RigidBodies::angular_velocity(int b) const { return angular_velocity_of(bodies_[b], dimension_); }

void RigidBodies::kick(const std::vector<RigidLoad>& load, double h) {
  for (std::size_t b = 0; b < bodies_.size(); ++b) {
    RigidBodyState& s = bodies_[b];
    for (int k = 0; k < 3; ++k) {
      s.velocity[k] += h * load[b].force[k] / s.mass;
      s.angular_momentum[k] += h * load[b].torque[k];
    }
  }
}

void RigidBodies::drift(double dt) {
  for (RigidBodyState& s : bodies_) {
    for (int k = 0; k < 3; ++k) s.centre[k] += dt * s.velocity[k];
    if (dimension_ == 1) continue;
    Vec3d w = omega_at(s, s.rotation, dimension_);
    for (int it = 0; it < 2; ++it) {  // omega at the half-rotated orientation
      const Mat3d half = mat_mul(rotation_of({0.5 * dt * w[0], 0.5 * dt * w[1], 0.5 * dt * w[2]}), s.rotation);
      w = omega_at(s, half, dimension_);
    }
    s.rotation = mat_mul(rotation_of({dt * w[0], dt * w[1], dt * w[2]}), s.rotation);
  }
}

std::vector<double> pack_states(const std::vector<RigidBodyState>& states) {
  std::vector<double> out;
  for (const RigidBodyState& s : states) {
    out.push_back(s.mass);
    for (const auto* a : {&s.centre, &s.velocity, &s.angular_momentum}) out.insert(out.end(), a->begin(), a->end());
    for (const auto* m : {&s.inertia0, &s.rotation}) out.insert(out.end(), m->begin(), m->end());
  }
  return out;
}

std::vector<RigidBodyState> unpack_states(const std::vector<double>& v, std::size_t bodies) {
  constexpr std::size_t per = kPackedRigidState;
  if (v.size() != per * bodies)
    throw std::invalid_argument("the checkpoint holds " + std::to_string(v.size() / per) + " rigid bodies, the case " +
                                std::to_string(bodies));
  std::vector<RigidBodyState> out(bodies);
  std::size_t k = 0;
  for (RigidBodyState& s : out) {
    s.mass = v[k++];
    for (auto* a : {&s.centre, &s.velocity, &s.angular_momentum})
      for (double& x : *a) x = v[k++];
    for (auto* m : {&s.inertia0, &s.rotation})
      for (double& x : *m) x = v[k++];
  }
  return out;
}

std::vector<double> RigidBodies::pack() const { return pack_states(bodies_); }
void RigidBodies::unpack(const std::vector<double>& v) { bodies_ = unpack_states(v, bodies_.size()); }

// Mass ~ L^D, inertia ~ M L^2, angular momentum ~ inertia / time; velocity and rotation unchanged.
RigidBodyState in_unit(RigidBodyState s, const LengthUnit& u, bool to_si) {
  const int D = u.dimension;
  auto f = [&](double& v, int k) { v = u.convert(v, k, to_si); };
  f(s.mass, D);
  for (double& v : s.inertia0) f(v, D + 2);
  for (double& v : s.centre) f(v, 1);
  for (double& v : s.angular_momentum) f(v, D + 1);
  return s;
}

RigidBodyState rigid_body_from_points(const std::vector<double>& m, const std::vector<Vec3d>& x, const Vec3d& v_cm,
                                      const Vec3d& omega, int dimension) {
  RigidBodyState s;
  for (std::size_t i = 0; i < m.size(); ++i) {
    s.mass += m[i];
    for (int k = 0; k < 3; ++k) s.centre[k] += m[i] * x[i][k];
  }
  for (double& c : s.centre) c /= s.mass;
  for (std::size_t i = 0; i < m.size(); ++i) {
    const Vec3d r{x[i][0] - s.centre[0], x[i][1] - s.centre[1], x[i][2] - s.centre[2]};
    const double r2 = r[0] * r[0] + r[1] * r[1] + r[2] * r[2];
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) s.inertia0[3 * a + b] += m[i] * ((a == b ? r2 : 0.0) - r[a] * r[b]);  // eq. 64
  }
  s.velocity = v_cm;
  if (dimension == 2) s.angular_momentum = {0, 0, s.inertia0[8] * omega[2]};
  else if (dimension == 3) s.angular_momentum = mat_vec(s.inertia0, omega);
  return s;
}

}  // namespace psph
