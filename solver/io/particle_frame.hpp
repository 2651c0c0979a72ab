#pragma once
// Host staging buffers for one output step: positions and the named per-particle fields the
// pipelines asked for, as float, vectors padded to 3 components. The Catalyst adaptor wraps these
// buffers in VTK arrays without copying, so they must stay alive and unmoved until execute() returns.
#include <string>
#include <vector>

namespace psph {

struct StagedField {
  std::string name;
  int components = 1;       // 1, or 3 for vectors and principal values
  std::vector<float> data;  // components interleaved, n * components
};

struct ParticleFrame {
  int dimension = 3;
  int n = 0;
  std::vector<float> position;  // 3 n, z = 0 in 2D
  std::vector<StagedField> fields;

  const StagedField* find(const std::string& name) const {
    for (const auto& f : fields)
      if (f.name == name) return &f;
    return nullptr;
  }
  // The buffer for `name`, created on first use and reused (no reallocation at a fixed n).
  StagedField& slot(const std::string& name) {
    for (auto& f : fields)
      if (f.name == name) return f;
    fields.push_back(StagedField{name, 1, {}});
    return fields.back();
  }
};

}  // namespace psph
