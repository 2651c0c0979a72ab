#include "engine/unit_scaled_engine.hpp"

#include <algorithm>
#include <stdexcept>

#include "engine/scene_units.hpp"

namespace psph {

namespace {

// Each value of a real field (floats or doubles, kept so) times L^power or L^-power.
void scale_values(CheckpointField& f, const LengthUnit& u, int power, bool to_si) {
  const std::size_t width = f.element_bytes / std::size_t(f.components);
  if (width != 4 && width != 8)
    throw std::logic_error("checkpoint field '" + f.name + "': components of " + std::to_string(width) + " bytes");
  std::vector<double> v = real_values(f);
  for (double& x : v) x = u.convert(x, power, to_si);
  set_real_values(f, v, width);
}

}  // namespace

UnitScaledEngine::UnitScaledEngine(const Scene& si, const LengthUnit& unit,
                                   const std::function<std::unique_ptr<Engine>(const Scene&)>& make)
    : u_(unit), inner_(make(in_units(si, unit))) {
  for (const std::string& name : inner_->field_names()) length_power(inner_->field_info(name).unit, u_.dimension);
}

StepStats UnitScaledEngine::stats() {
  StepStats s = inner_->stats();
  const int D = u_.dimension;
  s.a_max = u_.to_si(s.a_max, -1);
  s.kinetic_energy = u_.to_si(s.kinetic_energy, D);
  s.elastic_energy = u_.to_si(s.elastic_energy, D);
  s.dissipated_energy = u_.to_si(s.dissipated_energy, D);
  return s;
}

const DensityWatch& UnitScaledEngine::density_watch() const {
  watch_ = inner_->density_watch();
  watch_.peak_time = u_.to_si(watch_.peak_time, 1);
  if (watch_.exceeded()) watch_.first.time = u_.to_si(watch_.first.time, 1);
  return watch_;
}

std::vector<double> UnitScaledEngine::to_si(std::vector<double> values, const std::string& field) const {
  const int k = length_power(inner_->field_info(field).unit, u_.dimension);
  if (k != 0)
    for (double& v : values) v = u_.to_si(v, k);
  return values;
}

std::vector<MonitorValue> UnitScaledEngine::monitors() {
  std::vector<MonitorValue> out = inner_->monitors();
  for (MonitorValue& m : out) m.value = u_.to_si(m.value, length_power(m.unit, u_.dimension));
  return out;
}

std::vector<RigidBodyState> UnitScaledEngine::rigid_bodies() const {
  std::vector<RigidBodyState> out = inner_->rigid_bodies();
  for (RigidBodyState& b : out) b = in_unit(b, u_, true);
  return out;
}

// Real fields by their units' powers; the other fields hold no dimension (ids, flags, materials).
// A field the case does not register is left as it is (the restore ignores it); one of an earlier
// raw file, which says neither its components nor its unit, takes them from the registry.
Checkpoint UnitScaledEngine::converted(Checkpoint c, bool to_si) const {
  const int D = u_.dimension;
  auto f = [&](double& v, int k) { v = u_.convert(v, k, to_si); };
  f(c.time, 1), f(c.last_dt, 1), f(c.first_dt, 1), f(c.dissipated_energy, D);
  if (c.rigid_bodies.size() % kPackedRigidState == 0) {  // else the restore refuses it
    std::vector<RigidBodyState> bodies = unpack_states(c.rigid_bodies, c.rigid_bodies.size() / kPackedRigidState);
    for (RigidBodyState& b : bodies) b = in_unit(b, u_, to_si);
    c.rigid_bodies = pack_states(bodies);
  }
  const std::vector<std::string> known = inner_->field_names();
  for (CheckpointField& cf : c.fields) {
    if (std::find(known.begin(), known.end(), cf.name) == known.end()) continue;
    const FieldInfo info = inner_->field_info(cf.name);
    if (cf.components <= 0 && cf.unit.empty()) cf.type = info.type, cf.components = info.components, cf.unit = info.unit;
    int k = 0;
    try {
      k = length_power(cf.unit, D);
    } catch (const std::logic_error&) {
      throw std::invalid_argument("the checkpoint's field '" + cf.name + "' has the unit '" + cf.unit + "', expected '" +
                                  info.unit + "'");
    }
    if (k == 0) continue;
    if (cf.type != FieldType::Real || cf.components <= 0 || cf.element_bytes % std::size_t(cf.components) != 0)
      throw std::invalid_argument("the checkpoint's field '" + cf.name + "' (" + std::to_string(cf.element_bytes) +
                                  " bytes a particle) is not the " + std::to_string(info.components) +
                                  " real components of its unit " + info.unit);
    scale_values(cf, u_, k, to_si);
  }
  return c;
}

std::unique_ptr<Engine> in_engine_unit(const Scene& scene, const std::function<std::unique_ptr<Engine>(const Scene&)>& make) {
  const LengthUnit unit = engine_length_unit(scene.options.support_radius, scene.dimension);
  if (unit.si() || !scene.unit.si()) return make(scene);
  return std::make_unique<UnitScaledEngine>(scene, unit, make);
}

}  // namespace psph
