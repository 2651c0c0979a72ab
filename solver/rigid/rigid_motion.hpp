#pragma once
// The rigid bodies of a simulation on backend B: their particle lists on the device, their
// motion on the host (rigid/rigid_bodies.hpp), and the passes between the two
// (rigid/rigid_body.hpp). Each step: kick and drift the bodies with the particles, place the
// bodies' particles, evaluate the forces, sum each body's load, kick again.
#include <cmath>
#include <vector>

#include "backend/device_array.hpp"
#include "neighbours/cell_grid.hpp"
#include "rigid/rigid_body.hpp"
#include "rigid/rigid_scene.hpp"
#include "state/particles.hpp"

namespace psph {

template <int D, class B>
class RigidMotion {
 public:
  bool active() const { return bodies_.count() > 0; }

  // Lists each body's particles by id with their offsets and registers the particles' bodies.
  void setup(const Scene& sc, ParticleState<D, B>& s) {
    const SceneRigidBodies rb = rigid_bodies_of(sc);
    if (rb.state.empty()) return;
    bodies_ = RigidBodies(D, rb.state);
    std::vector<std::int32_t> ids, body_of;
    std::vector<Vec<D>> off;
    for (std::size_t b = 0; b < rb.members.size(); ++b) {
      begin_.push_back(static_cast<int>(ids.size()));
      for (std::size_t q = 0; q < rb.members[b].size(); ++q) {
        ids.push_back(rb.members[b][q]), body_of.push_back(static_cast<std::int32_t>(b));
        Vec<D> o;
        for (int k = 0; k < D; ++k) o[k] = Real(rb.offsets[b][q][k]);
        off.push_back(o);
      }
    }
    begin_.push_back(static_cast<int>(ids.size()));
    ids_.upload(ids), body_of_.upload(body_of), offset_.upload(off);
    std::vector<std::int32_t> body(sc.count(), -1);
    for (int i = 0; i < sc.count(); ++i) body[i] = sc.body[i];
    s.enable_rigid(body);
    for (int k = 0; k < D; ++k) lower_[k] = sc.lower[k], length_[k] = sc.periodic[k] ? sc.upper[k] - sc.lower[k] : 0;
  }

  // Places every body's particles at its current motion (index_of_id must be current).
  void place(const ParticleView<D>& s, const CellGrid<D>& grid) {
    std::vector<RigidPose<D>> pose(bodies_.count());
    for (int b = 0; b < bodies_.count(); ++b) {
      const RigidBodyState& st = bodies_.body(b);
      const Vec3d w = bodies_.angular_velocity(b);
      RigidPose<D>& p = pose[b];
      for (int k = 0; k < D; ++k) {
        double c = st.centre[k];  // into the domain on periodic axes; the particles wrap after
        if (length_[k] > 0) c -= length_[k] * std::floor((c - lower_[k]) / length_[k]);
        p.centre[k] = Real(c), p.velocity[k] = Real(st.velocity[k]);
        for (int l = 0; l < D; ++l) p.rotation.a[k][l] = Real(st.rotation[3 * k + l]);
      }
      for (int k = 0; k < 3; ++k) p.omega[k] = Real(w[k]);
    }
    pose_.upload(pose);
    B::for_each(static_cast<int>(ids_.size()),
                RigidPlacePass<D>{s, grid, ids_.data(), body_of_.data(), offset_.data(), pose_.data()});
  }

  // Each body's force and torque from its particles' accelerations (eqs. 63, 65).
  void sum_loads(const ParticleView<D>& s) {
    load_.assign(bodies_.count(), RigidLoad{});
    for (int b = 0; b < bodies_.count(); ++b) {
      Mat<D> R;
      for (int k = 0; k < D; ++k)
        for (int l = 0; l < D; ++l) R.a[k][l] = Real(bodies_.body(b).rotation[3 * k + l]);
      const RigidLoadSum sum = B::template sum_of<RigidLoadSum>(
          begin_[b + 1] - begin_[b], RigidLoadOf<D>{s, ids_.data() + begin_[b], offset_.data() + begin_[b], R});
      for (int k = 0; k < 3; ++k) load_[b].force[k] = double(sum.f[k]), load_[b].torque[k] = double(sum.t[k]);
    }
  }

  void kick(double h) { bodies_.kick(load_, h); }
  void drift(double dt) { bodies_.drift(dt); }
  const RigidBodies& bodies() const { return bodies_; }
  std::vector<double> pack() const { return bodies_.pack(); }
  void unpack(const std::vector<double>& v) { bodies_.unpack(v); }

 private:
  RigidBodies bodies_;
  std::vector<int> begin_;  // body b's entries: [begin_[b], begin_[b + 1])
  DeviceArray<std::int32_t, B> ids_, body_of_;
  DeviceArray<Vec<D>, B> offset_;
  DeviceArray<RigidPose<D>, B> pose_;
  std::vector<RigidLoad> load_;
  double lower_[D] = {}, length_[D] = {};
};

}  // namespace psph
