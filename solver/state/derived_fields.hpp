#pragma once
// Fields computed on request (output steps only) from registered ones, so that outputs and
// pipelines ask for them by name like any other field:
//   phase               0 wall, 1 water, 2 gas, 3 elastic solid, 4 rigid (from the material kind)
//   principal_stress    sigma_1 >= sigma_2 >= sigma_3 (Pa), from "stress" (D x D, row-major)
//   principal_direction unit direction of sigma_1, from "stress"
// A derived field exists only when its sources do (no stress field before the solid model).
#include <functional>
#include <string>
#include <vector>

#include "core/material.hpp"
#include "state/fields.hpp"

namespace psph {

enum class Phase : int { Wall = 0, Water = 1, Gas = 2, Solid = 3, Rigid = 4 };
Phase phase_of(const Material& m);

struct DerivedField {
  FieldInfo info;
  std::vector<std::string> sources;
};
const std::vector<DerivedField>& derived_fields();

// The registered fields' names, then the derived fields whose sources are all registered.
std::vector<std::string> available_field_names(const FieldRegistry& registered);

// Computes derived field `name` (components interleaved). `source(name)` returns a registered field;
// `materials[k]` is material index k.
std::vector<double> compute_derived_field(const std::string& name, int dimension, const std::vector<Material>& materials,
                                          const std::function<std::vector<double>(const std::string&)>& source);

}  // namespace psph
