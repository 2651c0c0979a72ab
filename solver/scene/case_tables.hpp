#pragma once
// What the readers of a case file's tables share: one reader per table (scene/read_*.cpp,
// declared and called in order by scene/case_file.cpp), then the cross-checks between them
// (scene/cross_check.cpp). Each reader consumes its table's keys and refuses what is unknown or
// out of range; the cross-checks refuse combinations and keys that have no effect in the case,
// with the reason.
#include <map>
#include <string>
#include <vector>

#include "scene/case_file.hpp"
#include "scene/case_reader.hpp"

namespace psph {

// What the readers learn as they go.
struct CaseDraft {
  CaseDraft(Case& c_, const std::string& file_) : c(c_), file(file_) {}
  Case& c;
  const std::string file;
  std::map<std::string, int> mat_index;         // material name -> index
  std::vector<std::string> walls_without_angle;  // walls and solids with no contact_angle
  std::map<std::string, double> poisson_ratio;   // per elastic material (checked against the formulation)
  bool has_liquid = false, has_gas = false, has_elastic = false, has_rigid = false, has_walls = false;
  std::map<std::string, std::string> given;      // dotted key -> " (line N)", every key the file sets
  std::vector<std::pair<std::size_t, std::string>> image_files;  // [[geometry]] index -> the image found (absolute)

  bool has_fluid() const { return has_liquid || has_gas; }
  int dimension() const { return c.scene.dimension; }
  // Remembers the keys of a table that the file sets.
  void note(const toml::table& t, const std::string& path);
  // Refuses `key` when the file sets it and `applies` is false: "expected <why>".
  void refuse_unless(bool applies, const std::string& key, const std::string& why) const;
  // Reads `key` of r as the name of a material of that kind ("a fluid", "an elastic material").
  int material(CaseReader& r, const std::string& key, MaterialKind kind, const std::string& what) const;
};

// A [discretisation] kernel name as its KernelType (scene/read_setup.cpp; unknown: the cubic spline).
KernelType kernel_from(const std::string& name);

// Combinations that cannot run, keys without effect (scene/cross_check.cpp).
void cross_check(const CaseDraft& d);

}  // namespace psph
