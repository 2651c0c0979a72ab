#pragma once
// One named value a stage reports at each monitor time (a column of monitors.csv).
#include <string>
#include <utility>

namespace psph {

struct MonitorValue {
  // The unit is required: an engine running in another length unit converts by it.
  MonitorValue(std::string n, double v, std::string u) : name(std::move(n)), value(v), unit(std::move(u)) {}
  std::string name;
  double value = 0;
  // SI, as in core/length_unit.hpp's table ("-" for a number); "SI" for a value measured outside
  // the engine (never converted).
  std::string unit;
};

}  // namespace psph
