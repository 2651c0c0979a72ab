#include <stdexcept>

#include "scene/embedded_cases.hpp"

namespace psph {

std::string embedded_case_text(const std::string& name) {
  for (const auto& c : embedded_cases())
    if (name == c.name) return c.text;
  throw std::invalid_argument("no embedded case named '" + name + "'");
}

}  // namespace psph
