#include "scene/case_tables.hpp"

namespace psph {

void CaseDraft::note(const toml::table& t, const std::string& path) {
  for (const auto& [k, v] : t) given[path + "." + std::string(k.str())] = toml_line_of(v);
}

void CaseDraft::refuse_unless(bool applies, const std::string& key, const std::string& why) const {
  const auto it = given.find(key);
  if (!applies && it != given.end()) throw CaseError(file + ": " + key + it->second + ": expected " + why);
}

int CaseDraft::material(CaseReader& r, const std::string& key, MaterialKind kind, const std::string& what) const {
  const std::string name = r.string(key);
  const auto it = mat_index.find(name);
  if (it == mat_index.end() || c.scene.materials[it->second].props.kind != kind)
    r.fail(key, "expected the name of " + what + " under [materials], got \"" + shown(name) + "\"");
  return it->second;
}

}  // namespace psph
