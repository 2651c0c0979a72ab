#pragma once
// Case files compiled into the binary (generated from cases/*.toml by scripts/embed_cases.cmake).
#include <string>
#include <vector>

namespace psph {

struct EmbeddedCase {
  const char* name;  // file stem, e.g. "poiseuille_couette"
  const char* text;  // the TOML text
};

const std::vector<EmbeddedCase>& embedded_cases();

// The text of an embedded case by name; throws std::invalid_argument for an unknown name.
std::string embedded_case_text(const std::string& name);

}  // namespace psph
