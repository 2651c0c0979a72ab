#pragma once
// One simulation, written once for every backend B and dimension D: the ordered passes of a step.
// Compiled by the host compiler for the CPU backend and by nvcc for the CUDA backend.
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "boundary/open_boundary.hpp"
#include "boundary/wall_pressure.hpp"
#include "boundary/wall_velocity.hpp"
#include "engine/engine.hpp"
#include "engine/step_passes.hpp"
#include "fluid/continuity.hpp"
#include "fluid/density.hpp"
#include "fluid/momentum.hpp"
#include "integrate/bicgstab.hpp"
#include "integrate/kick_drift.hpp"
#include "interface/surface_tension.hpp"
#include "interface/wall_wetting.hpp"
#include "integrate/timestep.hpp"
#include "neighbours/cell_grid.hpp"
#include "neighbours/fluid_proximity.hpp"
#include "neighbours/neighbour_list.hpp"
#include "neighbours/reference_list.hpp"
#include "rigid/rigid_body.hpp"
#include "rigid/rigid_motion.hpp"
#include "scene/scene.hpp"
#include "solid/artificial_viscosity.hpp"
#include "solid/clamp_partners.hpp"
#include "solid/damping.hpp"
#include "solid/elastic_force.hpp"
#include "solid/fluid_coupling.hpp"
#include "solid/solid_load.hpp"
#include "solid/stress_form.hpp"
#include "state/derived_fields.hpp"
#include "state/particles.hpp"

namespace psph {

template <int D, class B>
class Simulation final : public Engine {
 public:
  explicit Simulation(const Scene& sc) : opt_(sc.options) {
    if (sc.dimension != D) throw std::logic_error("scene dimension mismatch");
    Real lo[D], hi[D];
    bool per[D];
    for (int k = 0; k < D; ++k) lo[k] = Real(sc.lower[k]), hi[k] = Real(sc.upper[k]), per[k] = sc.periodic[k];
    // List radius R (1 + skin), reduced where a periodic axis needs it to keep 3 cells.
    list_radius_ = opt_.support_radius * (1 + opt_.neighbour_skin);
    for (int k = 0; k < D; ++k)
      if (per[k]) list_radius_ = std::min(list_radius_, (sc.upper[k] - sc.lower[k]) / 3);
    list_radius_ = std::max(list_radius_, opt_.support_radius);
    if (!CellGrid<D>::make(lo, hi, per, Real(list_radius_), grid_))
      throw std::invalid_argument("a periodic axis is shorter than 3 support radii");
    kern_ = Kernel<D>::make(opt_.kernel, Real(opt_.support_radius));
    mats_.count = static_cast<int>(sc.materials.size());
    for (int k = 0; k < mats_.count; ++k) {
      mats_.m[k] = sc.materials[k].props;
      for (int d = 0; d < D; ++d) mats_.body_force[k][d] = Real(sc.materials[k].body_force[d]);
      c_max_ = std::max(c_max_, double(mats_.m[k].sound_speed));
      has_walls_ |= mats_.m[k].kind == MaterialKind::Wall;
      has_fluid_ |= mats_.m[k].kind == MaterialKind::Fluid;
      has_elastic_ |= mats_.m[k].kind == MaterialKind::Elastic;
      if (mats_.m[k].kind == MaterialKind::Fluid && mats_.m[k].viscosity > 0)
        nu_max_ = std::max(nu_max_, double(mats_.m[k].viscosity / mats_.m[k].rest_density));
      if (mats_.m[k].kind == MaterialKind::Fluid && opt_.surface_tension > 0) {
        const double r = mats_.m[k].rest_density / opt_.surface_tension;
        rho_over_sigma_ = rho_over_sigma_ > 0 ? std::min(rho_over_sigma_, r) : r;
      }
    }
    regions_ = sc.force_regions;
    mats_.region_count = static_cast<int>(regions_.size());
    for (int r = 0; r < mats_.region_count; ++r) {
      mats_.region[r].material = regions_[r].material;
      for (int d = 0; d < D; ++d)
        mats_.region[r].lower[d] = Real(regions_[r].lower[d]), mats_.region[r].upper[d] = Real(regions_[r].upper[d]);
    }
    ramp_body_forces(0);
    if (sc.open_boundary.axis >= 0) set_open_boundary(sc.open_boundary);
    if (opt_.implicit_viscosity) nu_max_ = 0;  // no viscous time-step limit
    upload(sc);
    if (opt_.surface_tension > 0) s_.enable_interface();
    if (has_elastic_) {
      s_.enable_solid();
      B::copy(s_.x0.data(), s_.x.data(), sizeof(Vec<D>) * n_);
      s_.mirror.upload(clamp_mirror_partners(sc));
      if (large_strain()) s_.enable_large_strain();
    }
    if (!sc.solid_loads.empty())
      s_.enable_solid_loads(std::vector<std::int32_t>(sc.load_mask.begin(), sc.load_mask.end()));
    solid_loads_ = sc.solid_loads;
    rigid_.setup(sc, s_);
    has_rigid_ = rigid_.active();
    if (has_fluid_ && has_solids()) s_.enable_coupling();
    bucket_start_.resize(2 * grid_.total), bucket_end_.resize(2 * grid_.total), cell_near_.resize(grid_.total);
    if (!has_fluid_) {
      build_neighbours();
      if (has_elastic_) solid_strain();
      forces();
      return;
    }
    if (mats_.open.active()) B::for_each(n_, ConvertInletFluid<D>{s_.view(), mats_});
    if (continuity()) {
      build_neighbours();
      B::for_each(n_, EquationOfStatePass<D>{s_.view(), mats_});
    } else {
      build_neighbours(true);
      density_pass(true);  // every wall's rest density is its initial summed density
      B::for_each(n_, SetWallRestDensity<D>{s_.view(), mats_});
      build_neighbours();
    }
    open_boundary_state();
    if (has_elastic_) solid_strain();
    forces();
  }

  int dimension() const override { return D; }
  int particles() const override { return n_; }
  double time() const override { return t_; }
  long steps() const override { return steps_; }
  double last_dt() const override { return dt_; }
  std::string backend() const override { return B::name; }
  std::string device() const override { return B::device_name(); }
  std::vector<RigidBodyState> rigid_bodies() const override { return rigid_.bodies().all(); }

  std::vector<double> field(const std::string& name) override {
    std::vector<double> out;
    // The displacement form needs no strain or stress in its step: computed when asked for, once
    // per state.
    if (has_elastic_ && opt_.solid_formulation == SolidFormulation::Displacement &&
        (name == "strain" || name == "stress") && strain_step_ != steps_) {
      B::for_each(n_, StrainStressPass<D>{view_nb_reference(), kern_, s_.view(), mats_});
      strain_step_ = steps_;
    }
    if (s_.fields().has(name)) {
      s_.fields().get(name).to_host_double(out);
      return out;
    }
    const std::vector<Material> materials(mats_.m, mats_.m + mats_.count);
    return compute_derived_field(name, D, materials, [this](const std::string& src) { return field(src); });
  }
  std::vector<std::string> field_names() const override {
    std::vector<std::string> names;
    for (const auto& f : s_.fields().all()) names.push_back(f.info.name);
    for (const auto& d : derived_fields()) {
      bool ok = true;
      for (const auto& src : d.sources) ok &= s_.fields().has(src);
      if (ok) names.push_back(d.info.name);
    }
    return names;
  }

  Checkpoint checkpoint() override {
    build_neighbours();  // the lists are then a function of the saved positions alone
    Checkpoint c;
    c.dimension = D, c.particles = n_, c.precision = precision_name();
    c.time = t_, c.last_dt = dt_, c.first_dt = dt_first_, c.steps = steps_;
    c.dissipated_energy = dissipated_;
    c.rigid_bodies = rigid_.pack();
    for (const auto& f : s_.fields().all()) {
      c.fields.push_back(CheckpointField{f.info.name, f.element_bytes, {}});
      f.to_host_bytes(c.fields.back().bytes);
    }
    return c;
  }

  void restore(const Checkpoint& c) override {
    auto differs = [](const std::string& what, const std::string& ours, const std::string& theirs) {
      throw std::invalid_argument("the checkpoint " + what + " (" + theirs + ") differs from the case's (" + ours + ")");
    };
    if (c.dimension != D) differs("dimension", std::to_string(D), std::to_string(c.dimension));
    if (c.particles != n_) differs("particle count", std::to_string(n_), std::to_string(c.particles));
    if (c.precision != precision_name()) differs("precision", precision_name(), c.precision);
    for (const auto& f : s_.fields().all()) {
      const CheckpointField* cf = nullptr;
      for (const auto& g : c.fields)
        if (g.name == f.info.name) cf = &g;
      if (!cf) throw std::invalid_argument("the checkpoint has no field '" + f.info.name + "'");
      if (cf->element_bytes != f.element_bytes || cf->bytes.size() != f.element_bytes * std::size_t(n_))
        differs("size of field '" + f.info.name + "'", std::to_string(f.element_bytes * n_) + " bytes",
                std::to_string(cf->bytes.size()) + " bytes");
    }
    if (c.rigid_bodies.size() != rigid_.pack().size())
      differs("rigid bodies' state", std::to_string(rigid_.pack().size()) + " values",
              std::to_string(c.rigid_bodies.size()) + " values");
    for (const auto& f : s_.fields().all())
      for (const auto& g : c.fields)
        if (g.name == f.info.name) f.from_host_bytes(g.bytes);
    if (has_rigid_) rigid_.unpack(c.rigid_bodies);
    t_ = c.time, dt_ = c.last_dt, dt_first_ = c.first_dt, steps_ = c.steps;
    dissipated_ = c.dissipated_energy;
    strain_step_ = -1;
    ramp_body_forces(t_);
    build_neighbours();
    if (has_rigid_) rigid_.sum_loads(s_.view());  // the accelerations are the checkpoint's
  }

  StepStats stats() override {
    StepStats st;
    const ParticleView<D> v = s_.view();
    st.v_max = B::template max_of<Real>(n_, SpeedOf<D>{v});
    st.a_max = B::template max_of<Real>(n_, AccelerationOf<D>{v});
    st.kinetic_energy = B::template sum_of<Real>(n_, KineticEnergyOf<D>{v, mats_});
    st.density_deviation_max = B::template max_of<Real>(n_, DensityDeviationOf<D>{v, mats_});
    if (has_elastic_)
      st.elastic_energy =
          stress_form() ? B::template sum_of<Real>(n_, StrainEnergyOf<D>{v, mats_})
                        : B::template sum_of<Real>(n_, ElasticEnergyOf<D>{{view_nb_reference(), kern_, v, mats_}});
    st.dissipated_energy = dissipated_;
    st.dt_limit = dt_limit_;
    st.linear_iterations = linear_iterations_;
    return st;
  }

  double mean_neighbours() override {
    const Real total = B::template sum_of<Real>(n_, NeighbourCount<D>{view_nb(), s_.material.data(), mats_});
    const Real moving = B::template sum_of<Real>(n_, IsDynamic<D>{s_.material.data(), mats_});
    return moving > 0 ? double(total / moving) : 0.0;
  }

  void step(double t_stop) override {
    double dt = choose_dt();
    if (t_ + dt > t_stop) dt = t_stop - t_;
    if (t_ + dt >= t_stop * (1 - 1e-12)) dt = t_stop - t_;  // land exactly on output times
    ramp_body_forces(t_ + dt);  // the forces evaluated in this step are those at its end
    open_boundary_velocity(dt);
    // Rigid bodies move with the particles (rigid/rigid_motion.hpp): the same kicks, then their
    // particles are placed after the drift.
    if (opt_.implicit_viscosity) {
      // Explicit kick with the non-viscous forces, backward-Euler viscous step, drift.
      kick(dt);
      viscous_step(dt);
      continuity_pass();
      drift(dt);
      evaluate();
    } else if (opt_.integrator == Integrator::VelocityVerlet) {
      // Kick-drift-kick (eq. 49): a(t) is known from the previous force evaluation.
      kick(0.5 * dt);
      continuity_pass();
      drift(dt);
      evaluate();
      kick(0.5 * dt);
    } else {
      // Leapfrog (eq. 48): v(t+dt/2) = v(t-dt/2) + dt a(t), x(t+dt) = x(t) + dt v_hat(t+dt/2).
      kick(dt);
      continuity_pass();
      drift(dt);
      evaluate();
    }
    if (opt_.solid_damping_rate > 0)  // the power at the end of the step, times dt
      dissipated_ += dt * B::template sum_of<Real>(n_, DampingPowerOf<D>{s_.view(), mats_, Real(opt_.solid_damping_rate)});
    t_ += dt;
    ++steps_;
    dt_ = dt;
    check_health();
  }

 private:
  bool has_solids() const { return has_elastic_ || has_rigid_; }
  void kick(double h) {
    B::for_each(n_, KickPass<D>{s_.view(), mats_, Real(h)});
    if (!has_rigid_) return;
    rigid_.kick(h);
    rigid_.place(s_.view(), grid_);  // the bodies' particles take the kick's velocity
  }
  void drift(double dt) {
    B::for_each(n_, DriftPass<D>{s_.view(), grid_, Real(dt), continuity()});
    if (!has_rigid_) return;
    rigid_.drift(dt);
    rigid_.place(s_.view(), grid_);
  }

  // Summation density of a disordered start can be 20 % off for a few steps and recover, so the
  // density check is opt-in (solver.max_density_deviation).
  double density_limit() const { return opt_.max_density_deviation > 0 ? opt_.max_density_deviation : 1e30; }
  double smoothing_length() const { return opt_.support_radius / support_per_smoothing_length(opt_.kernel); }
  bool continuity() const { return opt_.density == DensityMethod::Continuity; }

  void upload(const Scene& sc) {
    n_ = sc.count();
    s_.resize(n_);
    std::vector<Vec<D>> x(n_), v(n_);
    std::vector<Real> m(n_), rho(n_), zero(n_, Real(0));
    std::vector<std::uint8_t> mat(n_);
    std::vector<std::int32_t> id(n_);
    for (int i = 0; i < n_; ++i) {
      for (int k = 0; k < D; ++k) x[i][k] = Real(sc.x[i * D + k]), v[i][k] = Real(sc.v[i * D + k]);
      m[i] = Real(sc.mass[i]);
      mat[i] = static_cast<std::uint8_t>(sc.material[i]);
      rho[i] = mats_.m[sc.material[i]].rest_density;
      id[i] = i;
    }
    s_.x.upload(x), s_.v.upload(v), s_.m.upload(m), s_.rho.upload(rho), s_.rho0.upload(rho);
    s_.material.upload(mat), s_.id.upload(id);
    s_.near_fluid.upload(std::vector<std::uint8_t>(n_, 1));  // recomputed per step when there are walls
    keys_.resize(n_), perm_.resize(n_), nb_count_.resize(n_), nb_fluid_count_.resize(n_);
  }

  NeighbourView<D> view_cells() const {
    return NeighbourView<D>{grid_, s_.x.data(), bucket_start_.data(), bucket_end_.data(),
                            Real(list_radius_ * list_radius_)};
  }
  NeighbourList<D> view_nb() const {
    return NeighbourList<D>{grid_, s_.x.data(), nb_index_.data(), nb_count_.data(), nb_fluid_count_.data(),
                            list_stride_i(), list_stride_k(), kern_.support * kern_.support};
  }
  // The same lists with the reference positions: small-strain elasticity lives in the reference
  // configuration (pairs closer than the support there; the skin keeps them listed while the
  // relative displacement of neighbours stays below skin x support, i.e. strains and rotations
  // below ~10 %).
  NeighbourList<D> view_nb_reference() const {
    NeighbourList<D> nb = view_nb();
    nb.x = s_.x0.data();
    return nb;
  }
  // Total-Lagrangian large strain: the fixed lists of t = 0 (neighbours/reference_list.hpp).
  bool large_strain() const { return opt_.solid_model == SolidModel::SaintVenantKirchhoff; }
  ReferenceNeighbours<D> view_reference_lists() const {
    return ReferenceNeighbours<D>{grid_, s_.x0.data(), s_.id.data(), s_.index_of_id.data(), reference_ids_.data(),
                                  reference_count_.data(), reference_capacity_, kern_.support * kern_.support};
  }
  // Calls f with the solid's neighbours in the reference configuration.
  template <class F>
  void with_solid_neighbours(F&& f) const {
    if (large_strain()) f(view_reference_lists());
    else f(view_nb_reference());
  }
  int list_stride_i() const { return B::list_rows_contiguous ? capacity_ : 1; }
  int list_stride_k() const { return B::list_rows_contiguous ? 1 : n_; }

  // Neighbour lists from the cell list; grows the capacity when a particle has more neighbours.
  void build_lists() {
    for (;;) {
      if (nb_index_.size() < std::size_t(capacity_) * n_) nb_index_.resize(std::size_t(capacity_) * n_);
      B::for_each(n_, BuildNeighbourList<D>{view_cells(), s_.material.data(), mats_, s_.near_fluid.data(),
                                            has_elastic_ && has_walls_ ? s_.mirror.data() : nullptr,
                                            !continuity(), !has_fluid_, nb_index_.data(), nb_count_.data(),
                                            nb_fluid_count_.data(), capacity_, list_stride_i(), list_stride_k()});
      const int most = n_ ? B::template max_of<int>(n_, ListCount<D>{nb_count_.data()}) : 0;
      if (most <= capacity_) return;
      capacity_ = most + most / 4 + 4;
    }
  }

  // Cell keys, sort by cell (fluid first in each cell), reorder every registered field, ranges.
  // `every_particle`: full lists for every particle (the initial density, which must see every
  // wall's whole neighbourhood to set its rest density); otherwise walls far from the fluid get none.
  void build_neighbours(bool every_particle = false) {
    B::for_each(n_, CellKeyPass<D>{grid_, s_.x.data(), s_.material.data(), mats_, keys_.data()});
    B::sort_by_cell(keys_.data(), n_, 2 * grid_.total, perm_.data(), bucket_start_.data(), bucket_end_.data());
    s_.permute(perm_.data());
    if ((has_elastic_ && (has_walls_ || large_strain())) || has_rigid_)  // clamps, reference lists, bodies
      B::for_each(n_, IndexOfIdPass<D>{s_.view()});
    if (every_particle) {
      s_.near_fluid.upload(std::vector<std::uint8_t>(n_, 1));
    } else if (has_walls_ && has_fluid_) {  // without fluids every wall lists all its neighbours
      B::for_each(grid_.total, CellNearFluid<D>{view_cells(), cell_near_.data()});
      B::for_each(n_, NearFluid<D>{grid_, s_.x.data(), cell_near_.data(), s_.near_fluid.data()});
    }
    build_lists();
    if (large_strain() && reference_count_.size() == 0) {  // at t = 0: current = reference
      reference_capacity_ = capacity_;
      reference_ids_.resize(std::size_t(capacity_) * n_), reference_count_.resize(n_);
      B::for_each(n_, RecordReferenceNeighbours<D>{view_nb(), s_.view(), mats_, reference_ids_.data(),
                                                   reference_count_.data(), capacity_});
    }
    x_build_.resize(n_);
    B::copy(x_build_.data(), s_.x.data(), sizeof(Vec<D>) * n_);
  }

  // The lists hold every pair within R as long as no particle moved by half the skin.
  bool lists_expired() {
    const double half_skin = 0.5 * (list_radius_ - opt_.support_radius);
    if (half_skin <= 0) return true;
    return B::template max_of<Real>(n_, DisplacementSinceBuild<D>{grid_, s_.x.data(), x_build_.data()}) >= half_skin;
  }

  void density_pass(bool all_particles = false) {
    const bool normalised = opt_.density == DensityMethod::NormalisedSummation;
    const bool number = opt_.density == DensityMethod::NumberSummation;
    if (normalised) B::for_each(n_, NumberDensityPass<D>{view_nb(), kern_, s_.view(), all_particles});
    B::for_each(n_, DensitySummationPass<D>{view_nb(), kern_, s_.view(), mats_, normalised, number, all_particles,
                                            has_solids()});
  }

  // d rho/dt with the velocity that drifts the particles (fluid/continuity.hpp).
  void continuity_pass() {
    if (!continuity()) return;
    B::for_each(n_, ContinuityPass<D>{view_nb(), kern_, s_.view(), mats_, Real(opt_.density_diffusion),
                                      Real(smoothing_length()), opt_.wall_pressure == WallPressure::Summation});
  }

  // Every force of a step (after the solids' strain): the fluid's forces (with the pressure and
  // velocity that walls and solids present to it), the solids' own forces and contacts, then the
  // fluid's reaction on them; last, the rigid bodies' loads.
  void forces() {
    if (has_fluid_ && has_solids())
      B::for_each(n_, SolidInterfacePressurePass<D>{view_nb(), kern_, s_.view(), mats_, opt_.solid_coupling});
    if (has_fluid_) force_pass();
    if (has_elastic_) solid_force();
    if (has_rigid_) B::for_each(n_, RigidContactPass<D>{view_nb(), s_.view(), mats_, Real(opt_.spacing)});
    if (has_fluid_ && has_solids())
      B::for_each(n_, FluidOnSolidPass<D>{view_nb(), kern_, s_.view(), mats_, fluid_force_options(),
                                          opt_.solid_coupling != SolidCoupling::Traction});
    // Last, so that an imposed velocity overrides every force on its particles.
    if (!solid_loads_.empty()) B::for_each(n_, SolidLoadPass<D>{s_.view(), solid_loads_at(force_time_)});
    if (has_rigid_) rigid_.sum_loads(s_.view());
  }

  FluidForceOptions fluid_force_options() const {
    FluidForceOptions fo;
    fo.xsph = Real(opt_.xsph);
    fo.laplacian = opt_.laplacian_correction;
    fo.artificial_viscosity = Real(opt_.artificial_viscosity);
    fo.smoothing_length = Real(smoothing_length());
    fo.number_density = opt_.density == DensityMethod::NumberSummation;
    fo.viscosity = !opt_.implicit_viscosity;
    fo.surface_tension = Real(opt_.surface_tension);
    fo.contact_line_force = opt_.contact_line_force && has_walls_;
    return fo;
  }

  void force_pass() {
    // Walls and solids present a pressure and a no-slip velocity (boundary/, solid/fluid_coupling.hpp).
    if (has_walls_ && opt_.wall_pressure == WallPressure::Extrapolated)
      B::for_each(n_, WallPressurePass<D>{view_nb(), kern_, s_.view(), mats_});
    if (has_walls_ || has_solids())
      B::for_each(n_, WallVelocityPass<D>{view_nb(), kern_, s_.view(), mats_, opt_.wall_noslip});
    const FluidForceOptions fo = fluid_force_options();
    if (opt_.surface_tension > 0) {
      const ParticleView<D> v = s_.view();
      if (opt_.geometric_wetting && has_walls_) {
        B::for_each(n_, ColourPass<D>{view_nb(), kern_, v, mats_, WallColour::FluidOnly});
        B::for_each(n_, NormalPass<D>{view_nb(), kern_, v, mats_, WallColour::FluidOnly});
        for (int k = 0; k < 2; ++k) {
          B::for_each(n_, WallWettingPass<D>{view_nb(), kern_, v, mats_});
          B::for_each(n_, ColourPass<D>{view_nb(), kern_, v, mats_, WallColour::NearWallsAgain});
          B::for_each(n_, NormalPass<D>{view_nb(), kern_, v, mats_, WallColour::NearWallsAgain});
        }
      } else {
        B::for_each(n_, ColourPass<D>{view_nb(), kern_, v, mats_, WallColour::Constant});
        B::for_each(n_, NormalPass<D>{view_nb(), kern_, v, mats_, WallColour::Constant});
      }
      B::for_each(n_, CurvaturePass<D>{view_nb(), kern_, v, mats_, Real(opt_.normal_threshold / smoothing_length()),
                                          opt_.geometric_wetting});
    }
    B::for_each(n_, FluidForcePass<D>{view_nb(), kern_, s_.view(), mats_, fo});
  }

  // Elastic solids (solid/): displacements (mirrored on clamps) and, where the step needs them,
  // strain and stress; then the elastic acceleration.
  bool stress_form() const { return opt_.solid_formulation == SolidFormulation::Stress; }
  void solid_strain() {
    B::for_each(n_, DisplacementPass<D>{s_.view(), grid_});
    if (has_walls_) B::for_each(n_, ClampDisplacementPass<D>{s_.view(), mats_});
    if (stress_form() || has_fluid_)  // the fluid reads the solid's volume change
      with_solid_neighbours([&](auto nb) {
        B::for_each(n_, StrainStressPass<D, decltype(nb)>{nb, kern_, s_.view(), mats_});
      });
  }
  void solid_force() {
    const Real zeta = Real(opt_.solid_damping_rate);
    const bool traction = has_fluid_ && opt_.solid_coupling == SolidCoupling::Traction;
    if (traction) B::for_each(n_, AmbientPressurePass<D>{view_nb(), kern_, s_.view(), mats_});
    with_solid_neighbours([&](auto nb) {
      using NB = decltype(nb);
      if (stress_form()) B::for_each(n_, StressForcePass<D, NB>{nb, kern_, s_.view(), mats_, zeta, traction});
      else B::for_each(n_, ElasticForcePass<D>{view_nb_reference(), kern_, s_.view(), mats_, zeta});
      if (opt_.solid_artificial_viscosity > 0 || opt_.solid_artificial_viscosity_beta > 0 || opt_.solid_xsph > 0)
        B::for_each(n_, SolidViscosityPass<D, NB>{nb, grid_, kern_, s_.view(), mats_, Real(opt_.solid_artificial_viscosity),
                                                  Real(opt_.solid_artificial_viscosity_beta), Real(opt_.solid_xsph),
                                                  Real(smoothing_length())});
    });
  }

  // The [[solid_load]]s at time t: tractions as forces on each particle's share of the surface
  // (spacing^(D-1)), ramped; imposed velocities until their duration ends.
  SolidLoads<D> solid_loads_at(double t) const {
    SolidLoads<D> l;
    l.count = static_cast<int>(solid_loads_.size());
    const double area = std::pow(opt_.spacing, D - 1);
    for (int g = 0; g < l.count; ++g) {
      const SceneSolidLoad& sl = solid_loads_[g];
      l.kind[g] = sl.velocity ? SolidLoadKind::Velocity : SolidLoadKind::Traction;
      const double f = sl.velocity ? (sl.duration > 0 && t > sl.duration ? 0.0 : 1.0)
                                   : area * ramp_factor(t, sl.ramp_time);
      for (int d = 0; d < D; ++d) l.value[g][d] = Real(f * sl.value[d]);
    }
    return l;
  }

  // v <- (I - dt L)^-1 v on the fluid (fluid/viscosity.hpp), L at the current positions with the
  // walls' no-slip velocities of the last force pass; those move to the right-hand side.
  void viscous_step(double dt) {
    const ParticleView<D> v = s_.view();
    for (auto* a : {&visc_b_, &visc_x_}) a->resize(n_);
    const bool normalise = opt_.laplacian_correction != LaplacianCorrection::None;
    auto op = [&](const Vec<D>* in, Vec<D>* out, bool walls) {
      B::for_each(n_, ImplicitViscosityOperator<D>{view_nb(), kern_, v, mats_, normalise, Real(dt), in, out, walls});
    };
    visc_x_.zero();
    op(visc_x_.data(), visc_b_.data(), true);  // A(0): the walls' part
    B::for_each(n_, FluidDifference<D>{visc_b_.data(), v.v, visc_b_.data(), v, mats_});
    B::for_each(n_, FluidDifference<D>{visc_x_.data(), v.v, visc_x_.data(), v, mats_});  // guess: v
    const KrylovResult r = krylov_.solve(
        n_, [&](const Vec<D>* in, Vec<D>* out) { op(in, out, false); }, visc_b_.data(), visc_x_.data(),
        opt_.implicit_tolerance, 1000);
    linear_iterations_ = r.iterations;
    if (!r.converged)
      throw InstabilityError("the implicit viscous solve did not converge (relative residual " +
                             std::to_string(r.relative_residual) + " after " + std::to_string(r.iterations) +
                             " BiCGSTAB iterations) at t = " + std::to_string(t_) + " s, step " + std::to_string(steps_));
    B::for_each(n_, SetFluidVelocity<D>{visc_x_.data(), v, mats_});
  }

  // min(1, t / ramp_time): a load applied quasi-statically (1 without a ramp).
  static double ramp_factor(double t, double ramp_time) { return ramp_time > 0 && t < ramp_time ? t / ramp_time : 1.0; }
  // Body-force regions at time t, each scaled by its ramp factor.
  void ramp_body_forces(double t) {
    force_time_ = t;
    for (int r = 0; r < mats_.region_count; ++r) {
      const double f = ramp_factor(t, regions_[r].ramp_time);
      for (int d = 0; d < D; ++d) mats_.region[r].acceleration[d] = Real(f * regions_[r].acceleration[d]);
    }
  }

  // Neighbours, density (or EOS after continuity), forces at the new positions.
  void evaluate() {
    if (lists_expired()) build_neighbours();
    if (has_elastic_) solid_strain();  // before the fluid's sums, which read the solid's volumes
    if (!has_fluid_) return forces();
    if (mats_.open.active()) B::for_each(n_, ConvertInletFluid<D>{s_.view(), mats_});
    if (continuity()) B::for_each(n_, EquationOfStatePass<D>{s_.view(), mats_});
    else density_pass();
    open_boundary_state();
    forces();
  }

  // Open pressure boundaries (boundary/open_boundary.hpp).
  void set_open_boundary(const SceneOpenBoundary& ob) {
    OpenBoundaryZone<D>& z = mats_.open;
    const int a = ob.axis;
    const Real lo = Real(ob.lower), hi = Real(ob.upper), b = Real(ob.thickness);
    z.axis = a;
    z.inlet_lower = ob.inlet_at_lower ? lo : hi - b, z.inlet_upper = ob.inlet_at_lower ? lo + b : hi;
    z.outlet_lower = ob.inlet_at_lower ? hi - b : lo, z.outlet_upper = ob.inlet_at_lower ? hi : lo + b;
    z.inlet_pressure = Real(ob.inlet_pressure), z.outlet_pressure = Real(ob.outlet_pressure);
    z.inlet_material = ob.inlet_material;
    z.face_band = Real(opt_.support_radius);
    z.domain_lower = lo;
  }
  // Each buffer's velocity gets the correction of the outgoing characteristic with its pressure p_b
  // imposed (linear acoustics: u_n - p/(rho c) is carried from the interior into the buffer, u_n the
  // velocity along the buffer's inward normal n): du_n = (p_b - p)/(rho c), with p and rho c the
  // means over the interior band next to the buffer. The pressure difference lets mass in or out
  // until the fluid next to a buffer has the buffer's pressure.
  // Runs after choose_dt: the buffers' new velocities differ from the last ones by du << c.
  void open_boundary_velocity(double dt) {
    if (!mats_.open.active()) return;
    const ParticleView<D> v = s_.view();
    Real u_band[2] = {0, 0}, du[2] = {0, 0};
    const BandSums sums = B::template sum_of<BandSums>(n_, BandSum<D>{v, mats_});
    for (int b = 0; b < 2; ++b) {
      const Real* q = sums.q[b];
      if (q[0] == 0) continue;
      const BufferZone z = b == 0 ? BufferZone::Inlet : BufferZone::Outlet;
      u_band[b] = q[1] / q[0];
      du[b] = mats_.open.inward(z) * (mats_.open.pressure(z) - q[2] / q[0]) / (q[3] / q[0]);
    }
    B::for_each(n_, SetBufferVelocity<D>{v, mats_, view_cells(), view_nb(), kern_, {u_band[0], u_band[1]}, {du[0], du[1]},
                                         Real(kBufferShift / dt)});
  }
  void open_boundary_state() {
    if (mats_.open.active()) B::for_each(n_, SetBufferState<D>{s_.view(), mats_});
  }

  double choose_dt() {
    if (opt_.fixed_dt > 0) {
      dt_limit_ = "fixed";
      return opt_.fixed_dt;
    }
    const ParticleView<D> v = s_.view();
    const double vmax = B::template max_of<Real>(n_, SpeedOf<D>{v});
    const double amax = B::template max_of<Real>(n_, AccelerationOf<D>{v});
    const TimeStepLimits lim =
        time_step_limits(smoothing_length(), c_max_, vmax, amax, nu_max_, opt_.dt_factor, rho_over_sigma_);
    dt_limit_ = lim.limiting();
    const double dt = lim.min();
    if (dt_first_ == 0) dt_first_ = dt;
    if (!(dt >= opt_.min_dt_ratio * dt_first_))
      throw InstabilityError("time step collapsed to " + std::to_string(dt) + " s (" + dt_limit_ +
                             " limit) at t = " + std::to_string(t_) + " s, step " + std::to_string(steps_) +
                             "; first step was " + std::to_string(dt_first_) + " s");
    return dt;
  }

  void check_health() {
    const int bad =
        B::template max_of<int>(n_, BadParticle<D>{s_.view(), grid_, mats_, Real(density_limit())});
    const std::string when = " at t = " + std::to_string(t_) + " s, step " + std::to_string(steps_);
    if (bad == 4) throw InstabilityError("non-finite particle state (NaN or Inf)" + when);
    if (bad == 3) throw InstabilityError("a particle left the domain through a closed side" + when);
    if (bad == 2)
      throw InstabilityError("an elastic particle moves faster than its P-wave speed" + when +
                             ": the solid went unstable (lower solver.dt_factor)");
    if (bad == 1)
      throw InstabilityError("a fluid density is more than " + std::to_string(100 * opt_.max_density_deviation) +
                             " % off its reference" + when +
                             ": the flow is no longer weakly compressible (raise the sound speed or lower dt_factor)");
  }

  SolverOptions opt_;
  CellGrid<D> grid_{};
  Kernel<D> kern_{};
  MaterialTable<D> mats_{};
  std::vector<SceneForceRegion> regions_;  // full body forces of the regions (mats_ holds them ramped)
  std::vector<SceneSolidLoad> solid_loads_;
  double force_time_ = 0;  // the time at which the forces being evaluated act
  ParticleState<D, B> s_;
  DeviceArray<int, B> keys_, perm_, bucket_start_, bucket_end_;
  DeviceArray<std::uint8_t, B> cell_near_;
  DeviceArray<int, B> nb_index_, nb_count_, nb_fluid_count_;
  DeviceArray<std::int32_t, B> reference_ids_, reference_count_;  // large strain: lists of t = 0 by id
  int reference_capacity_ = 0;
  int capacity_ = 32;
  DeviceArray<Vec<D>, B> x_build_;  // positions at the last list build
  BiCGStab<D, B> krylov_;
  DeviceArray<Vec<D>, B> visc_b_, visc_x_;  // implicit viscous step: right-hand side, solution
  int linear_iterations_ = 0;
  double list_radius_ = 0;
  int n_ = 0;
  double t_ = 0, dt_ = 0, dt_first_ = 0, c_max_ = 0, nu_max_ = 0, rho_over_sigma_ = 0;
  double dissipated_ = 0;  // J, by the solids' damping
  long steps_ = 0;
  long strain_step_ = -1;  // the step whose strain and stress the fields hold
  bool has_walls_ = false, has_fluid_ = false, has_elastic_ = false, has_rigid_ = false;
  RigidMotion<D, B> rigid_;
  std::string dt_limit_ = "none";
};

template <class B>
std::unique_ptr<Engine> make_simulation(const Scene& sc) {
  switch (sc.dimension) {
    case 1: return std::make_unique<Simulation<1, B>>(sc);
    case 2: return std::make_unique<Simulation<2, B>>(sc);
    case 3: return std::make_unique<Simulation<3, B>>(sc);
  }
  throw std::invalid_argument("dimension must be 1, 2 or 3");
}

}  // namespace psph
