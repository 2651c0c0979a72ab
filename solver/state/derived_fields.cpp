#include "state/derived_fields.hpp"

#include <stdexcept>

#include "core/symmetric_eigen.hpp"

namespace psph {

Phase phase_of(const Material& m) {
  switch (m.kind) {
    case MaterialKind::Wall: return Phase::Wall;
    case MaterialKind::Fluid: return m.colour < 0 ? Phase::Gas : Phase::Water;
    case MaterialKind::Elastic: return Phase::Solid;
    case MaterialKind::Rigid: return Phase::Rigid;
  }
  return Phase::Wall;
}

const std::vector<DerivedField>& derived_fields() {
  static const std::vector<DerivedField> fields = {
      {{"phase", FieldType::Int, 1, "-", "0 wall, 1 water, 2 gas, 3 elastic solid, 4 rigid"}, {"material"}},
      {{"principal_stress", FieldType::Real, 3, "Pa", "principal stresses sigma_1 >= sigma_2 >= sigma_3"}, {"stress"}},
      {{"principal_direction", FieldType::Real, 3, "-", "unit direction of sigma_1"}, {"stress"}},
  };
  return fields;
}

namespace {

template <int D>
void principal(const std::vector<double>& stress, bool directions, std::vector<double>& out) {
  const std::size_t n = stress.size() / (D * D);
  out.assign(3 * n, 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    double a[D][D], values[D], vectors[D][D];
    for (int r = 0; r < D; ++r)
      for (int c = 0; c < D; ++c) a[r][c] = stress[i * D * D + r * D + c];
    symmetric_eigen<D>(a, values, vectors);
    for (int k = 0; k < D; ++k) out[3 * i + k] = directions ? vectors[0][k] : values[k];
  }
}

}  // namespace

std::vector<double> compute_derived_field(const std::string& name, int dimension, const std::vector<Material>& materials,
                                          const std::function<std::vector<double>(const std::string&)>& source) {
  std::vector<double> out;
  if (name == "phase") {
    out = source("material");
    for (double& m : out) m = static_cast<double>(phase_of(materials.at(static_cast<std::size_t>(m))));
    return out;
  }
  if (name == "principal_stress" || name == "principal_direction") {
    const std::vector<double> s = source("stress");
    const bool dir = name == "principal_direction";
    if (dimension == 1) principal<1>(s, dir, out);
    else if (dimension == 2) principal<2>(s, dir, out);
    else principal<3>(s, dir, out);
    return out;
  }
  throw std::invalid_argument("unknown particle field '" + name + "'");
}

std::vector<std::string> available_field_names(const FieldRegistry& registered) {
  std::vector<std::string> names;
  for (const auto& f : registered.all()) names.push_back(f.info.name);
  for (const auto& d : derived_fields()) {
    bool ok = true;
    for (const auto& src : d.sources) ok &= registered.has(src);
    if (ok) names.push_back(d.info.name);
  }
  return names;
}

}  // namespace psph
