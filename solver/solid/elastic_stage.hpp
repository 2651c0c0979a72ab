#pragma once
// The elastic-solid stage: displacements (mirrored on clamps), strain and stress, the elastic
// force in the stress form (solid/stress_form.hpp) or the displacement form
// (solid/elastic_force.hpp), small strain or Saint Venant-Kirchhoff on fixed lists of t = 0
// (neighbours/reference_list.hpp), the solid's artificial viscosity and damping.
#include <cstdint>
#include <string>
#include <vector>

#include "core/pass_profile.hpp"
#include "neighbours/reference_list.hpp"
#include "solid/artificial_viscosity.hpp"
#include "solid/clamp.hpp"
#include "solid/damping.hpp"
#include "solid/elastic_force.hpp"
#include "solid/fluid_coupling.hpp"
#include "solid/solid_options.hpp"
#include "solid/stress_form.hpp"
#include "stage/monitor_value.hpp"
#include "stage/step_context.hpp"
#include "state/checkpoint.hpp"

namespace psph {

template <int D, class B>
class ElasticStage {
 public:
  bool active() const { return active_; }

  // `mirror`: each particle's clamp partner (engine/clamp_partners.hpp); `strain_each_step`: a
  // later stage (damage) reads the strain in every step, also in the displacement form.
  void setup(StepContext<D, B>& cx, const SolidOptions& o, const std::vector<std::int32_t>& mirror,
             bool strain_each_step) {
    o_ = o;
    strain_each_step_ = strain_each_step;
    active_ = cx.elastic;
    if (!active_) return;
    ParticleState<D, B>& s = cx.s;
    const int n = cx.n();
    s.x0.resize(n), s.u.resize(n), s.strain.resize(n), s.stress.resize(n);
    s.shepard.resize(n), s.shepard_grad.resize(n), s.kcorr.resize(n);
    s.index_of_id.resize(n);
    s.u.zero(), s.strain.zero(), s.stress.zero();
    s.add_field(s.x0, D, "reference_position", "m", "initial position (small-strain reference configuration)");
    s.add_field(s.u, D, "displacement", "m", "displacement x - x0 of elastic solids");
    s.add_field(s.strain, D * D, "strain", "-", "small strain sym(grad u) (large strain: Green-Lagrange), row-major");
    s.add_field(s.stress, D * D, "stress", "Pa", "Cauchy stress (tension positive), row-major");
    s.mirror.upload(mirror);
    s.add_field(s.mirror, 1, "clamp_mirror", "-", "id of a clamp wall's mirror partner and back, -1 if none");
    B::copy(s.x0.data(), s.x.data(), sizeof(Point<D>) * n);
    if (large_strain()) {
      // The Piola stress of the strain pass is recomputed before every use: not registered. The
      // fluid reads a solid's volume det F before the next strain pass, so F must follow
      // reorderings and checkpoints.
      s.piola.resize(n);
      s.piola.zero();
      s.defgrad.upload(std::vector<Mat<D>>(n, Mat<D>::identity()));  // undeformed until the first strain pass
      s.add_field(s.defgrad, D * D, "deformation_gradient", "-", "F = I + grad u (large strain), row-major");
      // The lists of t = 0, a row per particle (recorded at the first list build).
      reference_width_ = reference_row_width(D, cx.kern.support, cx.spacing);
      reference_ids_.resize(std::size_t(reference_width_) * n), reference_count_.resize(n);
      reference_count_.zero();
      s.add_rows(reference_ids_, reference_width_, "reference_neighbours", "-",
                 "ids of the solid neighbours within the support at t = 0 (large strain), the first reference_count");
      s.add_field(reference_count_, 1, "reference_count", "-", "solid neighbours within the support at t = 0 (large strain)");
    }
    if (o.solid_hourglass > 0) s.grad_u.resize(n), s.grad_u.zero();
    cx.follow_ids |= cx.walls || large_strain();  // clamps and reference lists find particles by id
  }

  // After a list build (and reordering): at t = 0 (current = reference positions) the large-strain
  // solid records its lists of t = 0, and after every build drops the damage ghosts retired from the
  // current lists; a small-strain solid keeps its corrections (solid_sum_volume: rest volumes).
  void lists_built(StepContext<D, B>& cx) {
    const StageScope scope("solid");
    if (!active_) return;
    corrections_kept_ = !large_strain();
    if (corrections_kept_) cx.launch(SolidCorrectionPass<D>{cx.pairs(cx.reference_list())}), refresh_corrections(cx);
    if (!large_strain()) return;
    const int n = cx.n();
    if (!recorded_) record_reference_lists(cx);
    if (cx.s.ghost.size())
      B::for_each(n, PruneGhostReferences<D>{cx.view(), reference_ids_.data(), reference_count_.data(),
                                             reference_width_});
  }

  // A run shared out over processes: the id of a particle whose reference partner lies beyond its
  // process's halo, or -1 (engine/simulation_bookkeeping.hpp stops the run naming it).
  int missing_reference_partner(StepContext<D, B>& cx) const {
    if (!active_ || !large_strain()) return -1;
    return cx.template max_of<int>(MissingReferencePartner<D>{cx.s.id.data(), cx.s.index_of_id.data(),
                                                              reference_ids_.data(), reference_count_.data(),
                                                              reference_width_});
  }

  // Displacements and, where the step needs them, strain and stress (the fluid reads the solid's
  // volume change).
  void strain(StepContext<D, B>& cx) const {
    const StageScope scope("solid");
    if (!active_) return;
    cx.launch(DisplacementPass<D>{cx.view(), cx.grid});
    if (cx.walls) cx.launch(ClampDisplacementPass<D>{cx.view(), cx.mats});
    if (stress_form() || cx.fluid || strain_each_step_)
      with_solid_neighbours(cx, [&](auto nb) {
        cx.launch(StrainStressPass<D, decltype(nb)>{cx.pairs(nb), corrections_kept_});
      });
  }

  // `moduli`: per-particle moduli of the displacement form (damage/damage_stage.hpp), if any.
  void forces(StepContext<D, B>& cx, ParticleModuli moduli) const {
    const StageScope scope("solid");
    if (!active_) return;
    const Real zeta = Real(o_.solid_damping_rate);
    const bool traction = cx.fluid && o_.solid_coupling == SolidCoupling::Traction;
    if (traction) {
      cx.refresh_array(cx.s.fluid_contact.data(), cx.s.fluid_contact.size(), "fluid_contact");
      cx.launch(AmbientPressurePass<D>{cx.pairs(), Real(o_.solid_reference_pressure)});
    }
    // What the force passes read of neighbours beyond the registered fields (parallel/).
    if (!corrections_kept_) refresh_corrections(cx);
    cx.refresh_array(cx.s.piola.data(), cx.s.piola.size(), "piola");
    cx.refresh_array(cx.s.grad_u.data(), cx.s.grad_u.size(), "grad_u");
    with_solid_neighbours(cx, [&](auto nb) {
      using NB = decltype(nb);
      if (stress_form()) cx.launch(StressForcePass<D, NB>{cx.pairs(nb), zeta, traction, Real(o_.solid_hourglass)});
      else cx.launch(ElasticForcePass<D>{cx.pairs(cx.reference_list()), zeta, moduli});
      if (o_.solid_artificial_viscosity > 0 || o_.solid_artificial_viscosity_beta > 0 || o_.solid_xsph > 0)
        cx.launch(SolidViscosityPass<D, NB>{nb, cx.grid, cx.kern, cx.view(), cx.mats,
                                                      Real(o_.solid_artificial_viscosity),
                                                      Real(o_.solid_artificial_viscosity_beta), Real(o_.solid_xsph),
                                                      Real(cx.smoothing_length)});
    });
  }

  // The damping's power at the end of the step, times dt.
  void end_of_step(StepContext<D, B>& cx, double dt) {
    const StageScope scope("solid");
    if (active_ && o_.solid_damping_rate > 0)
      dissipated_ += dt * double(cx.template sum_of<Real>(DampingPowerOf<D>{cx.view(), cx.mats, Real(o_.solid_damping_rate)}));
  }

  double elastic_energy(StepContext<D, B>& cx, ParticleModuli moduli) const {
    const StageScope scope("solid");
    if (!active_) return 0;
    const ParticleView<D> v = cx.view();
    return stress_form() ? cx.template sum_of<Real>(StrainEnergyOf<D>{v, cx.mats})
                         : cx.template sum_of<Real>(ElasticEnergyOf<D>{{cx.pairs(cx.reference_list()), 0, moduli}});
  }
  double dissipated_energy() const { return dissipated_; }

  void monitors(StepContext<D, B>& cx, std::vector<MonitorValue>& out, ParticleModuli moduli) const {
    const StageScope scope("solid");
    if (!active_) return;
    out.push_back({"elastic_energy", elastic_energy(cx, moduli), "J"});
    if (o_.solid_damping_rate > 0) out.push_back({"dissipated_energy", dissipated_, "J"});
  }

  // The displacement form needs no strain or stress in its step (unless a later stage does): computed
  // when asked for, once per state.
  void prepare_field(StepContext<D, B>& cx, const std::string& name, long step) {
    const StageScope scope("solid");
    if (!active_ || stress_form() || strain_each_step_ || (name != "strain" && name != "stress") || strain_step_ == step) return;
    cx.launch(StrainStressPass<D>{cx.pairs(cx.reference_list()), corrections_kept_});
    strain_step_ = step;
  }

  void save(Checkpoint& c) const { c.dissipated_energy = dissipated_; }
  void load(const Checkpoint& c) {
    dissipated_ = c.dissipated_energy;
    strain_step_ = -1;
    recorded_ = true;  // the lists of t = 0 are the checkpoint's
  }

 private:
  bool stress_form() const { return o_.solid_formulation == SolidFormulation::Stress; }
  // The strain pass's gradient corrections of a run over several processes: the halo's from their
  // owners (a halo copy's own sums miss neighbours).
  void refresh_corrections(StepContext<D, B>& cx) const {
    ParticleState<D, B>& s = cx.s;
    cx.refresh_array(s.shepard.data(), s.shepard.size(), "shepard");
    cx.refresh_array(s.shepard_grad.data(), s.shepard_grad.size(), "shepard_grad");
    cx.refresh_array(s.kcorr.data(), s.kcorr.size(), "kcorr");
  }
  bool large_strain() const { return o_.solid_model == SolidModel::SaintVenantKirchhoff; }
  void record_reference_lists(StepContext<D, B>& cx) {
    const int n = cx.n();
    B::for_each(n, RecordReferenceNeighbours<D>{cx.list(), cx.view(), cx.mats, cx.grid, cx.kern.support * cx.kern.support,
                                                reference_ids_.data(), reference_count_.data(), reference_width_});
    const int most = cx.template max_of<int>(ListCount<D>{reference_count_.data()});
    if (most > reference_width_)
      throw std::runtime_error("a solid particle has " + std::to_string(most) + " solid neighbours within the support at "
                               "t = 0, more than the " + std::to_string(reference_width_) + " its lattice spacing "
                               "(discretisation.spacing) allows: are solid particles closer than the spacing?");
    recorded_ = true;
  }
  // Calls f with the solid's neighbours in the reference configuration: the fixed lists of t = 0
  // in large strain; in small strain the current lists with the reference positions (pairs closer
  // than the support there; the skin keeps them listed while the relative displacement of
  // neighbours stays below skin x support, i.e. strains and rotations below ~10 %).
  template <class F>
  void with_solid_neighbours(StepContext<D, B>& cx, F&& f) const {
    if (large_strain())
      f(ReferenceNeighbours<D>{cx.grid, cx.s.x0.data(), cx.s.index_of_id.data(), reference_ids_.data(),
                               reference_count_.data(), reference_width_, cx.kern.support * cx.kern.support});
    else f(cx.reference_list());
  }

  SolidOptions o_;
  bool active_ = false;
  bool strain_each_step_ = false;
  // Small strain: the corrections depend on the reference positions and the rest volumes only
  // (solid/elastic_force.hpp, solid_sum_volume), so they are computed after each list build and
  // kept, and the strain pass is one sum instead of three.
  bool corrections_kept_ = false;
  DeviceArray<std::int32_t, B> reference_ids_, reference_count_;  // large strain: lists of t = 0, a row each
  int reference_width_ = 0;
  bool recorded_ = false;
  double dissipated_ = 0;  // J, by the solid's damping
  long strain_step_ = -1;  // the step whose strain and stress the fields hold
};

}  // namespace psph
