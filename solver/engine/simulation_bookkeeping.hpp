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
  cx.smoothing_length = double(opt_.support_radius) / double(support_per_smoothing_length(opt_.kernel));
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
  std::vector<Point<D>> x(n);
  std::vector<Vec<D>> v(n);
  std::vector<Real> m(n), rho(n);
  std::vector<std::uint8_t> mat(n);
  std::vector<std::int32_t> id(n);
  for (int i = 0; i < n; ++i) {
    for (int k = 0; k < D; ++k) x[i][k] = Coord(sc.x[i * D + k]), v[i][k] = Real(sc.v[i * D + k]);
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

// A run over several processes: each keeps the particles of its box and a halo
// (parallel/particle_domain.hpp). What is not shared out yet is refused before any work.
template <int D, class B>
void Simulation<D, B>::share_out(const Scene& sc) {
  if (!comm_.parallel()) return;
  Box box;
  std::array<bool, 3> periodic{false, false, false};
  for (int k = 0; k < D; ++k) box.lo[k] = sc.lower[k], box.hi[k] = sc.upper[k], periodic[k] = sc.periodic[k];
  domain_ = std::make_unique<ParticleDomain<D, B>>(comm_, box, periodic);
  halo_width_ = cx_.neighbours.radius() + halo_reach(sc);  // every neighbour in the lists, and beyond
  domain_->split(cx_.s, particle_costs(true), halo_width_);
  cx_.domain = domain_.get();
}

// Each particle's class (parallel/particle_cost.hpp); kCostClasses for a halo copy. `whole`: every
// particle is here, before lists (a first share): each counts, a wall as near the fluid.
template <int D, class B>
std::vector<std::uint8_t> Simulation<D, B>::cost_classes(bool whole) const {
  const std::vector<std::uint8_t> mat = cx_.s.material.host();
  const std::vector<std::uint8_t> near = whole ? std::vector<std::uint8_t>(mat.size(), 1) : cx_.s.near_fluid.host();
  const std::vector<std::uint8_t> own = whole ? near : owned_flags();
  std::vector<std::uint8_t> klass(mat.size());
  for (std::size_t i = 0; i < mat.size(); ++i)
    klass[i] = own[i] ? std::uint8_t(cost_class(cx_.mats.m[mat[i]].kind, near[i] != 0)) : std::uint8_t(kCostClasses);
  return klass;
}

// Each particle's share of a step's cost, which the decomposition balances: its class's.
template <int D, class B>
std::vector<double> Simulation<D, B>::particle_costs(bool whole) const {
  const std::vector<std::uint8_t> klass = cost_classes(whole);
  std::vector<double> cost(klass.size(), 0.0);
  for (std::size_t i = 0; i < klass.size(); ++i)
    if (klass[i] < kCostClasses) cost[i] = sharing_.class_costs.per_particle[klass[i]];
  return cost;
}

// The costs measured anew after this list build (the initial state's last one counts): from the
// particles' classification, after the sort.
template <int D, class B>
void Simulation<D, B>::begin_cost_measurement() {
  cx_.calibration = nullptr;
  calibration_ = std::make_unique<CostCalibration<B>>();
}

// After a sort: the halo's plan, and the run's particle count.
template <int D, class B>
void Simulation<D, B>::plan_halo() {
  domain_->plan(cx_.s);
  slices_.reset();
  particles_ = int(comm_.sum(static_cast<long long>(domain_->owned_count())));
  sharing_.processes = comm_.size();
  sharing_.halo_particles = comm_.sum(static_cast<long long>(domain_->halo_count()));
  // Every clamp partner of an owned particle is here (the halo is wide enough for it unless the
  // solid moved by far more than small strain allows): otherwise an error naming the particle.
  const int far = elastic_.missing_reference_partner(cx_);
  if (far >= 0)
    throw InstabilityError("a reference neighbour (t = 0) of particle " + std::to_string(far) +
                           " lies beyond the halo of the process that holds it: the solid stretched past the halo's "
                           "reach (the lists' radius and two support radii)" + when());
  if (!(cx_.elastic && cx_.walls)) return;
  const int missing = cx_.template max_of<int>(MissingClampPartner<D>{cx_.view()});
  if (missing >= 0)
    throw InstabilityError("the clamp partner of particle " + std::to_string(missing) +
                           " lies beyond the halo of the process that holds it" + when());
}

// At a list build: the slowest process's time in the steps since the last build over the mean.
// Past solver.rebalance_imbalance the domain is cut anew, each particle weighing its class's cost
// times its process's measured time per unit of cost (the cuts change no number: only the speed).
template <int D, class B>
std::vector<double> Simulation<D, B>::rebalance_costs() {
  constexpr double kMinBusy = 1.0;  // seconds of steps before a verdict
  if (measured_cut_due_) {
    measured_cut_due_ = false, busy_ = 0, ++sharing_.rebalances;
    return particle_costs();
  }
  const double slowest = comm_.max(busy_);
  ExactSum total;
  total.add(busy_);
  comm_.sum(&total, 1);
  const double mean = total.value() / comm_.size(), mine = busy_;
  const bool always = opt_.rebalance_imbalance <= 1;
  if (!always && !(slowest >= kMinBusy)) return {};
  sharing_.imbalance = mean > 0 ? slowest / mean : 1;
  busy_ = 0;
  if (!always && !(sharing_.imbalance > opt_.rebalance_imbalance)) return {};
  std::vector<double> cost = particle_costs();
  const std::vector<std::uint8_t> own = owned_flags();
  ExactSum weight;
  for (std::size_t i = 0; i < cost.size(); ++i)
    if (own[i]) weight.add(cost[i]);
  const double per_cost = weight.value() > 0 ? mine / weight.value() : 1;
  for (double& c : cost) c *= per_cost;
  ++sharing_.rebalances;
  return cost;
}

// The order of one process's particles: by cell bucket at the last list build, then by id, as
// the lists' sort orders them; the outputs of a shared run gather the fields in it.
template <int D, class B>
std::vector<long long> Simulation<D, B>::output_order() const {
  std::vector<double> xb;
  cx_.s.fields().get(kListPositionsField).to_host_double(xb);
  const std::vector<std::uint8_t> mat = cx_.s.material.host();
  const std::vector<std::int32_t> id = cx_.s.id.host();
  std::vector<long long> order(id.size());
  for (std::size_t i = 0; i < id.size(); ++i) {
    Point<D> x;
    for (int k = 0; k < D; ++k) x[k] = Coord(xb[i * D + k]);
    const long long bucket = 2LL * cx_.grid.cell_of(x) + (cx_.mats.is_fluid(mat[i]) ? 0 : 1);
    order[i] = bucket << 32 | static_cast<std::uint32_t>(id[i]);
  }
  return order;
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
      throw InstabilityError("time step collapsed to " + std::to_string(seconds(dt)) + " s (" + dt_limit_ + " limit)" +
                             when() + "; first step was " + std::to_string(seconds(dt_first_)) + " s");
  }
  if (t_ + dt > t_stop) dt = t_stop - t_;
  if (t_ + dt >= t_stop * (1 - 1e-12)) dt = t_stop - t_;  // land exactly on output times
  if (!(t_ + dt > t_)) {
    char b[32];
    std::snprintf(b, sizeof b, "%.3g", seconds(dt));
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
  const bool stop = opt_.stop_on_density_deviation && opt_.max_density_deviation > 0;
  const BadParticle<D> check{cx_.view(), cx_.grid, cx_.mats, Real(stop ? opt_.max_density_deviation : 1e30)};
  const double health = cx_.template max_of<Real>(HealthOf<D>{check});
  if (!(health >= 0)) return;  // no particle at all: the reduction of nothing is the lowest Real
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
  const int wanted = cx_.template max_of<int>(BadParticleId<D>{bad, code});
  if (wanted < 0) return "";
  std::vector<Point<D>> x;
  std::vector<Vec<D>> v;
  std::vector<std::uint8_t> mat;
  std::vector<std::int32_t> id;
  cx_.s.x.download(x), cx_.s.v.download(v), cx_.s.material.download(mat), cx_.s.id.download(id);
  const std::vector<std::uint8_t> own = owned_flags();
  std::ostringstream o;
  o.precision(4);
  for (std::size_t i = 0; i < id.size(); ++i) {
    if (id[i] != wanted || !own[i]) continue;
    o << " (particle " << id[i] << ", material " << material_names_.at(mat[i]) << ", at (";
    for (int k = 0; k < D; ++k) o << (k ? ", " : "") << unit_.to_si(double(x[i][k]), 1);
    o << ") m, speed " << norm(v[i]) << " m/s)";
  }
  return domain_ ? from_owner(o.str()) : o.str();
}

// Which particles of one process's order this process writes of an output (drawn once per list build).
template <int D, class B>
const OrderSlices& Simulation<D, B>::output_slices() {
  if (!slices_) slices_ = std::make_unique<OrderSlices>(comm_, output_order(), owned_flags());
  return *slices_;
}

// Told by the one process that knows it (its owner), to every process.
template <int D, class B>
std::string Simulation<D, B>::from_owner(const std::string& mine) {
  return first_message(comm_, mine);
}

template <int D, class B>
std::vector<std::uint8_t> Simulation<D, B>::owned_flags() const {
  if (!cx_.owned()) return std::vector<std::uint8_t>(std::size_t(cx_.n()), 1);
  std::vector<std::uint8_t> own(std::size_t(cx_.n()));
  B::download(own.data(), cx_.owned(), own.size());
  return own;
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
  if (domain_) sharing_.halo_bytes = comm_.sum(domain_->halo_bytes()), sharing_.refreshes = domain_->refreshes();
  return st;
}

template <int D, class B>
Checkpoint Simulation<D, B>::checkpoint() {
  Checkpoint c;  // the state as it is: with "list_positions", a restart rebuilds the same lists
  c.dimension = D, c.particles = cx_.n(), c.precision = precision_name();
  c.time = t_, c.last_dt = dt_, c.first_dt = dt_first_, c.steps = steps_;
  elastic_.save(c);
  rigid_.save(c);
  // Over several processes each holds a slice of one process's particle order: written together,
  // the very checkpoint of one process, which restarts on any number of them.
  const OrderSlices* slices = domain_ ? &output_slices() : nullptr;
  if (slices) c.particles = particles_, c.first = slices->first();
  for (const auto& f : cx_.s.fields().all()) {
    const FieldInfo& i = f.info;
    c.fields.push_back(CheckpointField{i.name, f.element_bytes, {}, i.type, i.components, i.unit, i.description});
    f.to_host_bytes(c.fields.back().bytes);
    if (slices) c.fields.back().bytes = slices->slice(c.fields.back().bytes, f.element_bytes);
  }
  return c;
}

// Everything is checked before anything is restored. A checkpoint of another precision is
// converted first (state/checkpoint.hpp); the run's log says so (app/run_driver.cpp).
template <int D, class B>
void Simulation<D, B>::restore(const Checkpoint& c) {
  if (c.precision != precision_name()) {
    for (const CheckpointField& f : c.fields)
      if (f.components <= 0)  // the raw format: no field says its components
        throw std::invalid_argument("the checkpoint was written in " + c.precision + " precision in the raw format, which "
                                    "cannot be converted to " + precision_name() + ": restart it with a " + c.precision + " build");
    return restore(with_precision_of(c, cx_.s.fields(), precision_name()));
  }
  auto differs = [](const std::string& what, const std::string& ours, const std::string& theirs) {
    throw std::invalid_argument("the checkpoint " + what + " (" + theirs + ") differs from the case's (" + ours + ")");
  };
  const int n = particles();
  if (!c.whole()) throw std::logic_error("restore: a slice of a checkpoint, not the whole of it");
  if (c.dimension != D) differs("dimension", std::to_string(D), std::to_string(c.dimension));
  if (c.particles != n) differs("particle count", std::to_string(n), std::to_string(c.particles));
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
    else f.from_host_bytes(c.field("position")->bytes);  // the list positions: rebuilt below
  if (domain_) {  // every particle is here: this process keeps its share, cut anew
    cx_.s.set_count(n);
    domain_->split(cx_.s, particle_costs(true), halo_width_);
  }
  rigid_.load(c);
  elastic_.load(c);
  t_ = c.time, dt_ = c.last_dt, dt_first_ = c.first_dt, steps_ = c.steps;
  ramp(t_);
  if (saved_lists) {
    cx_.neighbours.build_as_saved(cx_.s, cx_.grid, cx_.mats, cx_.list_needs());
    if (domain_) plan_halo(), cx_.halo_fresh();
    elastic_.lists_built(cx_);
  } else {
    rebuild();
  }
  rigid_.sum_loads(cx_);  // the accelerations are the checkpoint's
}

}  // namespace psph
