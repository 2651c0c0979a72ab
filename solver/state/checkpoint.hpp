#pragma once
// A complete, backend-independent copy of a run's state: every registered field, byte for byte, plus
// the clock. Taken right after a neighbour rebuild, so that a run restored from it continues
// bitwise identically to the run that wrote it (io/checkpoint_file.hpp stores it). In a run over
// several processes each holds a slice of it: particles first .. first + count - 1 of one
// process's order, written together into one file; read back, a checkpoint is whole.
#include <cstring>
#include <string>
#include <vector>

#include "state/fields.hpp"

namespace psph {

struct CheckpointField {
  std::string name;
  std::size_t element_bytes = 0;
  std::vector<unsigned char> bytes;  // (particles in the slice) * element_bytes
  FieldType type = FieldType::Byte;  // what the bytes are: element_bytes / components each
  int components = 0;                // 0: unknown (opaque bytes)
  std::string unit, description;
};

struct Checkpoint {
  int dimension = 0;
  int particles = 0;  // in the whole run
  long long first = 0;  // the slice's first particle
  std::string precision;  // "double", "mixed" or "single"
  double time = 0, last_dt = 0, first_dt = 0;
  long steps = 0;
  double dissipated_energy = 0;  // by the solids' damping, from the run's start (J)
  std::vector<double> rigid_bodies;  // the rigid bodies' motion (rigid/rigid_bodies.hpp, pack())
  std::vector<CheckpointField> fields;

  bool whole() const { return first == 0 && (fields.empty() || fields[0].bytes.size() == fields[0].element_bytes * std::size_t(particles)); }

  // The field of that name (the last, if listed twice), null if none.
  const CheckpointField* field(const std::string& name) const {
    const CheckpointField* f = nullptr;
    for (const auto& g : fields)
      if (g.name == name) f = &g;
    return f;
  }
};

// A real field's values (components of 4 or 8 bytes, as its element_bytes / components say), as
// doubles: floats widen exactly.
inline std::vector<double> real_values(const CheckpointField& f) {
  const std::size_t from = f.element_bytes / std::size_t(f.components), n = f.bytes.size() / from;
  std::vector<double> out(n);
  for (std::size_t k = 0; k < n; ++k) {
    if (from == 8) std::memcpy(&out[k], f.bytes.data() + k * 8, 8);
    else { float g; std::memcpy(&g, f.bytes.data() + k * 4, 4); out[k] = double(g); }
  }
  return out;
}
// The field's bytes anew from `values`, `width` (4 or 8) bytes each: double to float rounds to nearest.
inline void set_real_values(CheckpointField& f, const std::vector<double>& values, std::size_t width) {
  std::vector<unsigned char> bytes(values.size() * width);
  for (std::size_t k = 0; k < values.size(); ++k) {
    if (width == 8) std::memcpy(bytes.data() + k * 8, &values[k], 8);
    else { const float g = float(values[k]); std::memcpy(bytes.data() + k * 4, &g, 4); }
  }
  f.bytes.swap(bytes);
  f.element_bytes = width * std::size_t(f.components);
}

// A checkpoint written in another precision with its real fields converted, component by component,
// to the sizes that `fields` (this build's registry) stores: double to float rounds to nearest,
// float to double is exact. A field whose components are unknown (the raw format) is left as it
// is, and the restore then refuses its size, naming it.
inline Checkpoint with_precision_of(const Checkpoint& c, const FieldRegistry& fields, const std::string& precision) {
  Checkpoint out = c;
  out.precision = precision;
  for (CheckpointField& cf : out.fields) {
    if (cf.type != FieldType::Real || cf.components <= 0 || !fields.has(cf.name)) continue;
    const std::size_t to = fields.get(cf.name).element_bytes / std::size_t(cf.components);
    const std::size_t from = cf.element_bytes / std::size_t(cf.components);
    if (to == from || (to != 4 && to != 8) || (from != 4 && from != 8)) continue;
    set_real_values(cf, real_values(cf), to);
  }
  return out;
}

}  // namespace psph
