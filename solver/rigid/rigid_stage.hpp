#pragma once
// The rigid-body stage: the bodies' particle lists on the device, their motion on the host
// (rigid/rigid_bodies.hpp), and the passes between the two (rigid/rigid_body.hpp). Each step: kick
// and drift the bodies with the particles and place the bodies' particles; in the force
// evaluation, contact between objects, then each body's load; kick again.
#include <cmath>
#include <string>
#include <vector>

#include "backend/device_array.hpp"
#include "core/pass_profile.hpp"
#include "rigid/rigid_bodies.hpp"
#include "rigid/rigid_body.hpp"
#include "stage/monitor_value.hpp"
#include "stage/step_context.hpp"
#include "state/checkpoint.hpp"

namespace psph {

template <int D, class B>
class RigidStage {
 public:
  bool active() const { return bodies_.count() > 0; }

  // Lists each body's particles by id with their offsets and registers the particles' bodies.
  // `body`: each particle's body (-1 if none); `lower`, `periodic_length`: the domain per axis.
  void setup(StepContext<D, B>& cx, const SceneRigidBodies& rb, const std::vector<int>& body, const double lower[],
             const double periodic_length[]) {
    if (rb.state.empty()) return;
    bodies_ = RigidBodies(D, rb.state);
    weight_ = rb.weight;
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
    cx.s.body.upload(std::vector<std::int32_t>(body.begin(), body.end()));
    cx.s.index_of_id.resize(cx.n());
    cx.s.add_field(cx.s.body, 1, "rigid_body", "-", "the rigid body a particle belongs to, -1 if none");
    for (int k = 0; k < D; ++k) lower_[k] = lower[k], length_[k] = periodic_length[k];
    cx.rigid = true;
    cx.follow_ids = true;  // a body's particles are found by id
  }

  // With the particles' kick and drift: the bodies move, their particles take their motion.
  void kick(StepContext<D, B>& cx, double h) {
    const StageScope scope("rigid");
    if (!active()) return;
    bodies_.kick(load_, h);
    place(cx);
  }
  void drift(StepContext<D, B>& cx, double dt) {
    const StageScope scope("rigid");
    if (!active()) return;
    bodies_.drift(dt);
    place(cx);
  }

  void contact(StepContext<D, B>& cx) const {
    const StageScope scope("rigid");
    if (active()) cx.launch(RigidContactPass<D>{cx.list(), cx.view(), cx.mats, Real(cx.spacing)});
  }

  // Each body's force and torque from its particles' accelerations (eqs. 63, 65).
  void sum_loads(StepContext<D, B>& cx) {
    const StageScope scope("rigid");
    if (!active()) return;
    load_.assign(bodies_.count(), RigidLoad{});
    for (int b = 0; b < bodies_.count(); ++b) {
      Mat<D> R;
      for (int k = 0; k < D; ++k)
        for (int l = 0; l < D; ++l) R.a[k][l] = Real(bodies_.body(b).rotation[3 * k + l]);
      const RigidLoadSum sum = cx.template sum_over<RigidLoadSum>(
          begin_[b + 1] - begin_[b], RigidLoadOf<D>{cx.view(), ids_.data() + begin_[b], offset_.data() + begin_[b], R, cx.mats, cx.owned()});
      for (int k = 0; k < 3; ++k) load_[b].force[k] = sum.f[k] + weight_[b][k], load_[b].torque[k] = sum.t[k];
    }
  }

  const RigidBodies& bodies() const { return bodies_; }

  // Per body b: its centre of mass (unwrapped across periodic sides), velocity and angular
  // velocity (z in 2D), in the case's order of its geometries.
  void monitors(std::vector<MonitorValue>& out) const {
    const char* axis = "xyz";
    for (int b = 0; b < bodies_.count(); ++b) {
      const RigidBodyState& st = bodies_.body(b);
      const std::string p = "body" + std::to_string(b) + "_";
      for (int k = 0; k < D; ++k) out.push_back({p + axis[k], st.centre[k], "m"});
      for (int k = 0; k < D; ++k) out.push_back({p + "v" + axis[k], st.velocity[k], "m/s"});
      const Vec3d w = angular_velocity_of(st, D);
      if (D == 2) out.push_back({p + "omega", w[2], "rad/s"});
      if (D == 3)
        for (int k = 0; k < 3; ++k) out.push_back({p + "omega_" + axis[k], w[k], "rad/s"});
    }
  }

  void save(Checkpoint& c) const { c.rigid_bodies = bodies_.pack(); }
  // Empty when the checkpoint matches; else what differs.
  std::string mismatch(const Checkpoint& c) const {
    const std::size_t ours = bodies_.pack().size();
    if (c.rigid_bodies.size() == ours) return "";
    return "rigid bodies' state (" + std::to_string(c.rigid_bodies.size()) + " values) differs from the case's (" +
           std::to_string(ours) + " values)";
  }
  void load(const Checkpoint& c) {
    if (active()) bodies_.unpack(c.rigid_bodies);
  }

 private:
  // Places every body's particles at its current motion (index_of_id must be current).
  void place(StepContext<D, B>& cx) {
    std::vector<RigidPose<D>> pose(bodies_.count());
    for (int b = 0; b < bodies_.count(); ++b) {
      const RigidBodyState& st = bodies_.body(b);
      const Vec3d w = bodies_.angular_velocity(b);
      RigidPose<D>& p = pose[b];
      for (int k = 0; k < D; ++k) {
        double c = st.centre[k];  // into the domain on periodic axes; the particles wrap after
        if (length_[k] > 0) c -= length_[k] * std::floor((c - lower_[k]) / length_[k]);
        p.centre[k] = Coord(c), p.velocity[k] = Real(st.velocity[k]);
        for (int l = 0; l < D; ++l) p.rotation.a[k][l] = Real(st.rotation[3 * k + l]);
      }
      for (int k = 0; k < 3; ++k) p.omega[k] = Real(w[k]);
    }
    pose_.upload(pose);
    // Every process places the members it holds, halo copies too, from the same motion.
    B::for_each(static_cast<int>(ids_.size()),
                RigidPlacePass<D>{cx.view(), cx.grid, ids_.data(), body_of_.data(), offset_.data(), pose_.data()});
    cx.written("position"), cx.written("velocity");
  }

  RigidBodies bodies_;
  std::vector<int> begin_;  // body b's entries: [begin_[b], begin_[b + 1])
  DeviceArray<std::int32_t, B> ids_, body_of_;
  DeviceArray<Vec<D>, B> offset_;
  DeviceArray<RigidPose<D>, B> pose_;
  std::vector<RigidLoad> load_;
  std::vector<Vec3d> weight_;  // M g of each body, exact (rigid/rigid_body.hpp RigidLoadSum)
  double lower_[D] = {}, length_[D] = {};
};

}  // namespace psph
