#pragma once
// A complete, backend-independent copy of a run's state: every registered field, byte for byte, plus
// the clock. Taken right after a neighbour rebuild, so that a run restored from it continues
// bitwise identically to the run that wrote it (io/checkpoint_file.hpp stores it). In a run over
// several processes each holds a slice of it: particles first .. first + count - 1 of one
// process's order, written together into one file; read back, a checkpoint is whole.
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
  std::string precision;  // "double" or "single"
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

}  // namespace psph
