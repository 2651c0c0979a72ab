#pragma once
// The simulation's bookkeeping around the step order of engine/simulation.hpp: the shared context
// from the scene, the time step, the health check, statistics and checkpoints.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <stdexcept>

#include "engine/simulation.hpp"

namespace psph {

template <int D, class B>
void Simulation<D, B>::setup_context(const Scene& sc) {
  StepContext<D, B>& cx = cx_;
  bool periodic[D];
  double lower[D], upper[D];
  for (int k = 0; k < D; ++k) lower[k] = sc.lower[k], upper[k] = sc.upper[k], periodic[k] = sc.periodic[k];
  cx.grid = cx.neighbours.setup(lower, upper, periodic, opt_.support_radius, opt_.neighbour_skin);
  cx.kern = Kernel<D>::make(opt_.kernel, Real(opt_.support_radius));
  cx.spacing = opt_.spacing;
  cx.smoothing_length = opt_.support_radius / support_per_smoothing_length(opt_.kernel);
  cx.continuity = opt_.density == DensityMethod::Continuity;
  cx.mats.count = static_cast<int>(sc.materials.size());
  for (int k = 0; k < cx.mats.count; ++k) {
    cx.mats.m[k] = sc.materials[k].props;
    for (int d = 0; d < D; ++d) cx.mats.body_force[k][d] = Real(sc.materials[k].body_force[d]);
    cx.walls |= cx.mats.m[k].kind == MaterialKind::Wall;
    cx.fluid |= cx.mats.m[k].kind == MaterialKind::Fluid;
    cx.elastic |= cx.mats.m[k].kind == MaterialKind::Elastic;
  }
  // The particles, with every material's rest density.
  const int n = sc.count();
  cx.s.resize(n);
  std::vector<Vec<D>> x(n), v(n);
  std::vector<Real> m(n), rho(n);
  std::vector<std::uint8_t> mat(n);
  std::vector<std::int32_t> id(n);
  for (int i = 0; i < n; ++i) {
    for (int k = 0; k < D; ++k) x[i][k] = Real(sc.x[i * D + k]), v[i][k] = Real(sc.v[i * D + k]);
    m[i] = Real(sc.mass[i]);
    mat[i] = static_cast<std::uint8_t>(sc.material[i]);
    rho[i] = cx.mats.m[sc.material[i]].rest_density;
    id[i] = i;
  }
  cx.s.x.upload(x), cx.s.v.upload(v), cx.s.m.upload(m), cx.s.rho.upload(rho), cx.s.rho0.upload(rho);
  cx.s.material.upload(mat), cx.s.id.upload(id);
  cx.s.near_fluid.upload(std::vector<std::uint8_t>(n, 1));  // recomputed per step when there are walls
  cx.neighbours.resize(cx.s, n);
}

template <int D, class B>
void Simulation<D, B>::setup_rigid(const Scene& sc) {
  double lower[D], length[D];
  for (int k = 0; k < D; ++k) lower[k] = sc.lower[k], length[k] = sc.periodic[k] ? sc.upper[k] - sc.lower[k] : 0;
  rigid_.setup(cx_, rigid_bodies_of(sc), sc.body, lower, length);
}

// The adaptive step from every limit (integrate/timestep.hpp), landing exactly on t_stop.
template <int D, class B>
double Simulation<D, B>::next_dt(double t_stop) {
  const StageScope scope("time step");
  double dt = opt_.fixed_dt;
  dt_limit_ = "fixed";
  if (!(dt > 0)) {
    const ParticleView<D> v = cx_.view();
    const double vmax = cx_.template max_of<Real>(SpeedOf<D>{v});
    const double amax = cx_.template max_of<Real>(AccelerationOf<D>{v});
    const TimeStepLimits lim = time_step_limits(cx_.smoothing_length, dt_inputs_, vmax, amax, opt_.dt_factor);
    dt_limit_ = lim.limiting();
    dt = lim.min();
    if (dt_first_ == 0) dt_first_ = dt;
    if (!(dt >= opt_.min_dt_ratio * dt_first_))
      throw InstabilityError("time step collapsed to " + std::to_string(dt) + " s (" + dt_limit_ + " limit)" + when() +
                             "; first step was " + std::to_string(dt_first_) + " s");
  }
  if (t_ + dt > t_stop) dt = t_stop - t_;
  if (t_ + dt >= t_stop * (1 - 1e-12)) dt = t_stop - t_;  // land exactly on output times
  if (!(t_ + dt > t_)) {
    char b[32];
    std::snprintf(b, sizeof b, "%.3g", dt);
    throw InstabilityError(std::string("the time step (") + b + " s) makes no progress" + when() +
                           ": the clock no longer advances in double precision");
  }
  return dt;
}

// Summation density of a disordered start can be 20 % off for a few steps and recover, so the
// density stops a run only when asked (solver.on_density_deviation = "stop"); otherwise it is
// watched, from the same reduction.
template <int D, class B>
void Simulation<D, B>::check_health() {
  const StageScope scope("health check");
  if (cx_.n() == 0) return;  // the reduction of nothing is the lowest Real
  const bool stop = opt_.stop_on_density_deviation && opt_.max_density_deviation > 0;
  const BadParticle<D> check{cx_.view(), cx_.grid, cx_.mats, Real(stop ? opt_.max_density_deviation : 1e30)};
  const double health = cx_.template max_of<Real>(HealthOf<D>{check});
  const int bad = int(health / 16);
  if (bad == 0) return watch_density(health);
  const std::string who = culprit(check, bad);
  if (bad == 4) throw InstabilityError("non-finite particle state (NaN or Inf)" + when() + who);
  if (bad == 3) throw InstabilityError("a particle left the domain through a closed side" + when() + who);
  if (bad == 2)
    throw InstabilityError("an elastic particle moves faster than its P-wave speed" + when() + who +
                           ": the solid went unstable (lower solver.dt_factor)");
  throw InstabilityError("a fluid density is more than " + std::to_string(100 * opt_.max_density_deviation) +
                         " % off its reference" + when() + who +
                         ": the flow is no longer weakly compressible (raise the sound speed or lower the drive)");
}

// The largest deviation so far and, once, the particle that first passed the bound (its download
// on that step only).
template <int D, class B>
void Simulation<D, B>::watch_density(double dev) {
  if (!cx_.fluid) return;
  if (dev > watch_.peak) watch_.peak = dev, watch_.peak_time = t_, watch_.peak_step = steps_;
  note_density_deviation(dev);
  // Compared as the culprit's search compares (in Real), so that it finds the particle.
  if (watch_.exceeded() || watch_.bound <= 0 || !(Real(dev) > Real(watch_.bound))) return;
  const BadParticle<D> check{cx_.view(), cx_.grid, cx_.mats, Real(watch_.bound)};
  watch_.first.time = t_, watch_.first.step = steps_, watch_.first.value = dev;
  watch_.first.where = culprit(check, 1);
}

// Which particle failed the check, its material, where it is and how fast it moves (a reduction and
// a download, on the failure path only).
template <int D, class B>
std::string Simulation<D, B>::culprit(const BadParticle<D>& bad, int code) {
  const int i = cx_.template max_of<int>(BadParticleIndex<D>{bad, code});
  if (i < 0) return "";
  std::vector<Vec<D>> x, v;
  std::vector<std::uint8_t> mat;
  std::vector<std::int32_t> id;
  cx_.s.x.download(x), cx_.s.v.download(v), cx_.s.material.download(mat), cx_.s.id.download(id);
  std::ostringstream o;
  o.precision(4);
  o << " (particle " << id[std::size_t(i)] << ", material " << material_names_.at(mat[std::size_t(i)]) << ", at (";
  for (int k = 0; k < D; ++k) o << (k ? ", " : "") << x[std::size_t(i)][k];
  o << ") m, speed " << norm(v[std::size_t(i)]) << " m/s)";
  return o.str();
}

template <int D, class B>
StepStats Simulation<D, B>::stats() {
  const ProfileRecording recording(profile_);  // the monitors' cost, beside the step's
  const StageScope scope("monitors");
  StepStats st;
  const ParticleView<D> v = cx_.view();
  st.v_max = cx_.template max_of<Real>(SpeedOf<D>{v});
  st.a_max = cx_.template max_of<Real>(AccelerationOf<D>{v});
  st.kinetic_energy = cx_.template sum_of<Real>(KineticEnergyOf<D>{v, cx_.mats});
  st.density_deviation_max = cx_.template max_of<Real>(DensityDeviationOf<D>{v, cx_.mats});
  st.elastic_energy = elastic_.elastic_energy(cx_, damage_.moduli());
  st.dissipated_energy = elastic_.dissipated_energy();
  st.dt_limit = dt_limit_;
  st.linear_iterations = fluid_.linear_iterations();
  return st;
}

template <int D, class B>
Checkpoint Simulation<D, B>::checkpoint() {
  Checkpoint c;  // the state as it is: with "list_positions", a restart rebuilds the same lists
  c.dimension = D, c.particles = cx_.n(), c.precision = precision_name();
  c.time = t_, c.last_dt = dt_, c.first_dt = dt_first_, c.steps = steps_;
  elastic_.save(c);
  rigid_.save(c);
  for (const auto& f : cx_.s.fields().all()) {
    c.fields.push_back(CheckpointField{f.info.name, f.element_bytes, {}});
    f.to_host_bytes(c.fields.back().bytes);
  }
  return c;
}

// Everything is checked before anything is restored.
template <int D, class B>
void Simulation<D, B>::restore(const Checkpoint& c) {
  auto differs = [](const std::string& what, const std::string& ours, const std::string& theirs) {
    throw std::invalid_argument("the checkpoint " + what + " (" + theirs + ") differs from the case's (" + ours + ")");
  };
  const int n = cx_.n();
  if (c.dimension != D) differs("dimension", std::to_string(D), std::to_string(c.dimension));
  if (c.particles != n) differs("particle count", std::to_string(n), std::to_string(c.particles));
  if (c.precision != precision_name()) differs("precision", precision_name(), c.precision);
  const bool saved_lists = c.field(kListPositionsField) != nullptr;  // older checkpoints have none
  for (const auto& f : cx_.s.fields().all()) {
    const CheckpointField* cf = c.field(f.info.name);
    if (!cf && f.info.name == kListPositionsField) continue;
    if (!cf) throw std::invalid_argument("the checkpoint has no field '" + f.info.name + "'");
    if (cf->element_bytes != f.element_bytes || cf->bytes.size() != f.element_bytes * std::size_t(n))
      differs("size of field '" + f.info.name + "'", std::to_string(f.element_bytes * n) + " bytes",
              std::to_string(cf->bytes.size()) + " bytes");
  }
  const std::string rigid = rigid_.mismatch(c);
  if (!rigid.empty()) throw std::invalid_argument("the checkpoint " + rigid);
  for (const auto& f : cx_.s.fields().all())
    if (const CheckpointField* cf = c.field(f.info.name)) f.from_host_bytes(cf->bytes);
  rigid_.load(c);
  elastic_.load(c);
  t_ = c.time, dt_ = c.last_dt, dt_first_ = c.first_dt, steps_ = c.steps;
  ramp(t_);
  if (saved_lists) {
    cx_.neighbours.build_as_saved(cx_.s, cx_.grid, cx_.mats, cx_.list_needs());
    elastic_.lists_built(cx_);
  } else {
    rebuild();
  }
  rigid_.sum_loads(cx_);  // the accelerations are the checkpoint's
}

}  // namespace psph
