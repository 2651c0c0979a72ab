#pragma once
// One named value a stage reports at each monitor time (a column of monitors.csv).
#include <string>

namespace psph {

struct MonitorValue {
  std::string name;
  double value = 0;
  std::string unit = "-";  // SI (core/length_unit.hpp's table)
};

}  // namespace psph
