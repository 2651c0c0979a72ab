#pragma once
// An engine that runs in another length unit (core/length_unit.hpp) behind the SI interface: the
// scene goes in scaled (engine/scene_units.hpp); the clock, statistics, fields (by their units),
// monitors, rigid bodies and checkpoints come out in SI, and checkpoints go back in from SI, so
// that a checkpoint restarts in any build.
#include <functional>
#include <memory>

#include "core/length_unit.hpp"
#include "engine/engine.hpp"

namespace psph {

class UnitScaledEngine final : public Engine {
 public:
  // `make` builds the inner engine from the scene in `unit`.
  UnitScaledEngine(const Scene& si, const LengthUnit& unit, const std::function<std::unique_ptr<Engine>(const Scene&)>& make);

  int dimension() const override { return inner_->dimension(); }
  int particles() const override { return inner_->particles(); }
  double time() const override { return u_.to_si(inner_->time(), 1); }
  long steps() const override { return inner_->steps(); }
  double last_dt() const override { return u_.to_si(inner_->last_dt(), 1); }
  void step(double t_stop) override { inner_->step(u_.to_engine(t_stop, 1)); }
  StepStats stats() override;
  const DensityWatch& density_watch() const override;
  std::vector<double> field(const std::string& name) override { return to_si(inner_->field(name), name); }
  std::vector<double> field_slice(const std::string& name) override { return to_si(inner_->field_slice(name), name); }
  std::vector<std::string> field_names() const override { return inner_->field_names(); }
  FieldInfo field_info(const std::string& name) const override { return inner_->field_info(name); }
  std::string backend() const override { return inner_->backend(); }
  std::string device() const override { return inner_->device(); }
  double mean_neighbours() override { return inner_->mean_neighbours(); }
  Checkpoint checkpoint() override { return converted(inner_->checkpoint(), true); }
  void restore(const Checkpoint& c) override { inner_->restore(converted(c, false)); }
  std::vector<MonitorValue> monitors() override;
  PassProfile& profile() override { return inner_->profile(); }
  SharingStats sharing() const override { return inner_->sharing(); }
  std::vector<RigidBodyState> rigid_bodies() const override;

  const LengthUnit& unit() const { return u_; }

 private:
  std::vector<double> to_si(std::vector<double> values, const std::string& field) const;
  Checkpoint converted(Checkpoint c, bool to_si) const;

  LengthUnit u_;
  std::unique_ptr<Engine> inner_;
  mutable DensityWatch watch_;
};

// The engine `make` builds from `scene`, in the length unit of this build (engine_length_unit):
// wrapped in a UnitScaledEngine where that is not SI; as it is for a scene already in an engine's unit.
std::unique_ptr<Engine> in_engine_unit(const Scene& scene, const std::function<std::unique_ptr<Engine>(const Scene&)>& make);

}  // namespace psph
