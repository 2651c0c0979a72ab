#pragma once
// One simulation, written once for every backend B and dimension D: the stages of a step in
// order. Each stage (its folder's *_stage.hpp) owns its options, fields, launches, monitors and
// checkpoint data; this file only orders them. Compiled by the host compiler for the CPU backend
// and by nvcc for the CUDA backend.
#include <chrono>
#include <memory>
#include <string>
#include <vector>

#include "boundary/open_boundary_stage.hpp"
#include "damage/damage_stage.hpp"
#include "engine/engine.hpp"
#include "fluid/fluid_stage.hpp"
#include "integrate/kick_drift.hpp"
#include "integrate/timestep.hpp"
#include "interface/interface_stage.hpp"
#include "engine/rigid_scene.hpp"
#include "rigid/rigid_stage.hpp"
#include "engine/scene.hpp"
#include "engine/clamp_partners.hpp"
#include "parallel/order_slices.hpp"
#include "parallel/particle_cost.hpp"
#include "solid/coupling_stage.hpp"
#include "solid/elastic_stage.hpp"
#include "solid/solid_load_stage.hpp"
#include "stage/step_context.hpp"
#include "state/derived_fields.hpp"

namespace psph {

// Seconds since start() less the time spent waiting for other processes meanwhile.
class BusyTime {
 public:
  void start(const Communicator& comm) {
    comm_ = &comm, t0_ = std::chrono::steady_clock::now(), waited0_ = comm.seconds_in_calls();
  }
  double seconds() const {
    if (!comm_) return 0;
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0_).count() -
           (comm_->seconds_in_calls() - waited0_);
  }

 private:
  const Communicator* comm_ = nullptr;
  std::chrono::steady_clock::time_point t0_;
  double waited0_ = 0;
};

// Adds a scope's wall time, less its time in calls to the other processes, to `seconds`: a
// process's own work in its steps, which a run shared out over processes balances.
class BusyClock {
 public:
  BusyClock(double& seconds, const Communicator& comm) : seconds_(seconds) { time_.start(comm); }
  ~BusyClock() { seconds_ += time_.seconds(); }
  BusyClock(const BusyClock&) = delete;
  BusyClock& operator=(const BusyClock&) = delete;

 private:
  double& seconds_;
  BusyTime time_;
};

template <int D, class B>
class Simulation final : public Engine {
 public:
  explicit Simulation(const Scene& sc, Communicator& comm = world()) : opt_(sc.options), unit_(sc.unit), comm_(comm) {
    watch_.bound = opt_.max_density_deviation;
    if (sc.dimension != D) throw std::logic_error("scene dimension mismatch");
    for (const auto& m : sc.materials) material_names_.push_back(m.name);
    setup_context(sc);
    interface_.setup(cx_, opt_);
    elastic_.setup(cx_, opt_, cx_.elastic ? clamp_mirror_partners(sc) : std::vector<std::int32_t>{},
                   opt_.damage_model != DamageModel::None);
    damage_.setup(cx_, opt_, opt_.solid_formulation == SolidFormulation::Displacement ||
                                 (cx_.fluid && opt_.solid_coupling == SolidCoupling::PairEos));
    loads_.setup(cx_, sc.solid_loads, sc.load_mask);
    setup_rigid(sc);
    coupling_.setup(cx_, opt_.solid_coupling);
    fluid_.setup(cx_, opt_, opt_, sc.force_regions);
    open_.setup(cx_, sc.open_boundary, opt_.support_radius, opt_.spacing);
    dt_inputs_ = time_step_inputs(cx_.mats.m, cx_.mats.count, opt_.implicit_viscosity, opt_.surface_tension,
                                  opt_.solid_artificial_viscosity, opt_.solid_artificial_viscosity_beta, D);
    share_out(sc);
    ramp(0);
    start();
  }

  int dimension() const override { return D; }
  int particles() const override { return domain_ ? particles_ : cx_.n(); }
  double time() const override { return t_; }
  long steps() const override { return steps_; }
  double last_dt() const override { return dt_; }
  std::string backend() const override { return B::name; }
  std::string device() const override { return B::device_name(); }
  std::vector<RigidBodyState> rigid_bodies() const override { return rigid_.bodies().all(); }
  PassProfile& profile() override { return profile_; }
  SharingStats sharing() const override { return sharing_; }
  const DensityWatch& density_watch() const override { return watch_; }

  // The step: kick, drift, forces at the new positions (eqs. 48, 49).
  void step(double t_stop) override {
    const ProfileRecording recording(profile_);
    const BusyClock busy(busy_, comm_);
    const double dt = next_dt(t_stop);
    ramp(t_ + dt);  // the forces evaluated in this step are those at its end
    open_.buffer_velocity(cx_, dt);
    if (opt_.implicit_viscosity) {
      // Explicit kick with the non-viscous forces, backward-Euler viscous step, drift.
      kick(dt);
      fluid_.viscous_step(cx_, dt, [this] { return when(); });
      fluid_.density_rate(cx_);
      drift(dt);
      evaluate();
    } else if (opt_.integrator == Integrator::VelocityVerlet) {
      // Kick-drift-kick (eq. 49): a(t) is known from the previous force evaluation.
      kick(0.5 * dt);
      fluid_.density_rate(cx_);
      drift(dt);
      evaluate();
      kick(0.5 * dt);
    } else {
      // Leapfrog (eq. 48): v(t+dt/2) = v(t-dt/2) + dt a(t), x(t+dt) = x(t) + dt v_hat(t+dt/2).
      kick(dt);
      fluid_.density_rate(cx_);
      drift(dt);
      evaluate();
    }
    elastic_.end_of_step(cx_, dt);
    t_ += dt;
    ++steps_;
    dt_ = dt;
    check_health();
  }

  std::vector<double> field(const std::string& name) override {
    elastic_.prepare_field(cx_, name, steps_);
    std::vector<double> out;
    if (cx_.s.fields().has(name)) {
      const FieldHandle& f = cx_.s.fields().get(name);
      f.to_host_double(out);
      return domain_ ? domain_->gather(out, f.info.components, output_order()) : out;
    }
    const std::vector<Material> materials(cx_.mats.m, cx_.mats.m + cx_.mats.count);
    return compute_derived_field(name, D, materials, [this](const std::string& src) { return field(src); });
  }
  std::vector<double> field_slice(const std::string& name) override {
    if (!domain_) return field(name);
    elastic_.prepare_field(cx_, name, steps_);
    if (!cx_.s.fields().has(name)) {
      const std::vector<Material> materials(cx_.mats.m, cx_.mats.m + cx_.mats.count);
      return compute_derived_field(name, D, materials, [this](const std::string& src) { return field_slice(src); });
    }
    const FieldHandle& f = cx_.s.fields().get(name);
    std::vector<double> out;
    f.to_host_double(out);
    return output_slices().slice(out, f.info.components);
  }
  std::vector<std::string> field_names() const override { return available_field_names(cx_.s.fields()); }
  FieldInfo field_info(const std::string& name) const override {
    if (cx_.s.fields().has(name)) return cx_.s.fields().get(name).info;
    for (const DerivedField& f : derived_fields())
      if (f.info.name == name) return f.info;
    throw std::invalid_argument("unknown particle field '" + name + "'");
  }

  Checkpoint checkpoint() override;
  void restore(const Checkpoint& c) override;
  StepStats stats() override;
  std::vector<MonitorValue> monitors() override {
    const ProfileRecording recording(profile_);
    const StageScope scope("monitors");
    std::vector<MonitorValue> out;
    elastic_.monitors(cx_, out, damage_.moduli());
    damage_.monitors(cx_, out);
    rigid_.monitors(out);
    return out;
  }
  double mean_neighbours() override {
    const Real total = cx_.template sum_of<Real>(NeighbourCount<D>{cx_.list(), cx_.s.material.data(), cx_.mats});
    const Real moving = cx_.template sum_of<Real>(IsDynamic<D>{cx_.s.material.data(), cx_.mats});
    return moving > 0 ? double(total / moving) : 0.0;
  }

 private:
  // The initial state: lists, densities (the walls' reference density from a first summation),
  // forces. A shared run measures its particle classes' costs in the force evaluation after its
  // last list build, and cuts the domain with them (parallel/cost_calibration.hpp): nothing has
  // moved, so the lists built again are those of the first build.
  void start() {
    measure_costs_ = domain_ != nullptr;
    initial_state();
    if (!measure_costs_) return;
    sharing_.class_costs = calibration_->costs(comm_, cost_clock_.seconds());
    measure_costs_ = false, cx_.calibration = nullptr, calibration_.reset();
    measured_cut_due_ = sharing_.class_costs.measured;
    // Damage ghosts made at t = 0 enter the lists at the first step's build, as on one process:
    // the cut waits for it.
    if (measured_cut_due_ && !damage_.ghosts_pending(cx_)) rebuild();
  }
  void initial_state() {
    if (cx_.fluid) {
      open_.convert_inlet(cx_);
      if (cx_.continuity) {
        rebuild();
        open_.buffer_mass(cx_);
        fluid_.density(cx_);  // the pressure of the initial density
      } else {
        rebuild(true);
        open_.buffer_mass(cx_);
        fluid_.wall_rest_density(cx_);  // with every wall's whole neighbourhood
        rebuild();
      }
      open_.buffer_state(cx_);
    } else {
      rebuild();
    }
    elastic_.strain(cx_);
    damage_.update(cx_);
    forces();
  }

  // Neighbours, density (or the EOS after continuity), forces at the new positions.
  void evaluate() {
    if (cx_.lists_expired() || damage_.ghosts_pending(cx_)) rebuild();
    elastic_.strain(cx_);  // before the fluid's sums, which read the solid's volumes
    damage_.update(cx_);   // the degraded stress, before the forces read it
    if (cx_.fluid) {
      open_.convert_inlet(cx_);
      open_.buffer_mass(cx_);
      fluid_.density(cx_);
      open_.buffer_state(cx_);
    }
    forces();
  }

  // Every force of a step (after the solids' strain): the pressure and velocity that solids and
  // walls present to the fluid, the interface's curvature, the fluid's forces, the solids' own
  // forces and contacts, the fluid's reaction on them; last the loads, so that an imposed
  // velocity overrides every force, the damage ghosts held at rest, and the rigid bodies' sums.
  void forces() {
    if (cx_.fluid) {
      coupling_.present_solids(cx_, damage_.moduli());
      fluid_.present_walls(cx_);
      interface_.curvature(cx_);
      fluid_.forces(cx_);
    }
    elastic_.forces(cx_, damage_.moduli());
    rigid_.contact(cx_);
    coupling_.fluid_on_solids(cx_, fluid_.force_options());
    loads_.apply(cx_);
    damage_.pin_ghosts(cx_);
    rigid_.sum_loads(cx_);
  }

  // Rigid particles move with their bodies (rigid/rigid_stage.hpp): the same kicks, then their
  // particles are placed.
  void kick(double h) {
    const StageScope scope("integrate");
    cx_.launch(KickPass<D>{cx_.view(), cx_.mats, Real(h)});
    rigid_.kick(cx_, h);
  }
  void drift(double dt) {
    const StageScope scope("integrate");
    cx_.launch(DriftPass<D>{cx_.view(), cx_.grid, Real(dt), cx_.continuity});
    rigid_.drift(cx_, dt);
  }
  // `every_particle`: lists for walls far from the fluid too (the walls' initial density).
  // A run shared out over processes first moves particles to their owners and gathers the halo
  // again (parallel/particle_domain.hpp).
  void rebuild(bool every_particle = false) {
    if (measure_costs_) begin_cost_measurement();
    damage_.retire_ghosts(cx_);  // the damage ghosts leave the lists (damage/ghosts.hpp)
    if (domain_) domain_->redistribute(cx_.s, rebalance_costs());
    cx_.neighbours.build(cx_.s, cx_.grid, cx_.mats, cx_.list_needs(), every_particle);
    if (domain_) plan_halo(), cx_.halo_fresh();
    if (calibration_) calibration_->classify(cost_classes()), cx_.calibration = calibration_.get(), cost_clock_.start(comm_);
    elastic_.lists_built(cx_);
  }
  void ramp(double t) {
    cx_.force_time = t;
    fluid_.ramp_regions(cx_, t);
    fluid_.ramp_pressure(cx_, t);
  }

  void setup_context(const Scene& sc);
  void share_out(const Scene& sc);
  void plan_halo();
  const OrderSlices& output_slices();
  std::vector<std::uint8_t> cost_classes(bool whole = false) const;
  std::vector<double> particle_costs(bool whole = false) const;
  void begin_cost_measurement();
  std::vector<double> rebalance_costs();
  std::vector<long long> output_order() const;
  std::vector<std::uint8_t> owned_flags() const;
  std::string from_owner(const std::string& mine);
  void setup_rigid(const Scene& sc);
  double next_dt(double t_stop);
  void check_health();
  void watch_density(double deviation);
  std::string culprit(const BadParticle<D>& bad, int code);
  // Messages speak SI whatever unit the engine runs in.
  double seconds(double t) const { return unit_.to_si(t, 1); }
  std::string when() const { return " at t = " + std::to_string(seconds(t_)) + " s, step " + std::to_string(steps_); }

  SolverOptions opt_;
  LengthUnit unit_;  // the scene's (engine/scene_units.hpp)
  Communicator& comm_;
  std::unique_ptr<ParticleDomain<D, B>> domain_;  // a run shared out over processes only
  std::unique_ptr<OrderSlices> slices_;           // this process's slice of the outputs, until the next sort
  int particles_ = 0;  // of the whole run
  double halo_width_ = 0;
  double busy_ = 0;    // seconds in step() since the last list build
  std::unique_ptr<CostCalibration<B>> calibration_;  // in a shared run's initial state
  BusyTime cost_clock_;              // since the measurement began
  bool measure_costs_ = false;       // in the initial state of a shared run
  bool measured_cut_due_ = false;    // the costs were measured: cut with them at the next list build
  SharingStats sharing_;
  StepContext<D, B> cx_;
  InterfaceStage<D, B> interface_;
  ElasticStage<D, B> elastic_;
  DamageStage<D, B> damage_;
  SolidLoadStage<D, B> loads_;
  RigidStage<D, B> rigid_;
  CouplingStage<D, B> coupling_;
  FluidStage<D, B> fluid_;
  OpenBoundaryStage<D, B> open_;
  TimeStepInputs dt_inputs_;
  double t_ = 0, dt_ = 0, dt_first_ = 0;
  long steps_ = 0;
  std::string dt_limit_ = "none";
  std::vector<std::string> material_names_;
  PassProfile profile_;
  DensityWatch watch_;
};

}  // namespace psph

#include "engine/simulation_bookkeeping.hpp"

namespace psph {

template <class B>
std::unique_ptr<Engine> make_simulation(const Scene& sc, Communicator& comm) {
  switch (sc.dimension) {
    case 1: return std::make_unique<Simulation<1, B>>(sc, comm);
    case 2: return std::make_unique<Simulation<2, B>>(sc, comm);
    case 3: return std::make_unique<Simulation<3, B>>(sc, comm);
  }
  throw std::invalid_argument("dimension must be 1, 2 or 3");
}

}  // namespace psph
