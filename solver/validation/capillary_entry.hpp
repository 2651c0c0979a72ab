#pragma once
// Capillary entry into a slit (cases/capillary_entry_2d.toml): gas pushed by a reservoir body force
// enters a water-filled slit of width w when the driving pressure exceeds the Young-Laplace entry
// pressure 2 sigma cos(theta) / w (2D), and stays out below it.
#include <string>

#include "scene/case_file.hpp"

namespace psph {

// The case with the driving pressure at `ratio` times the entry pressure.
Case capillary_entry_case(double ratio);

struct EntryResult {
  double entry_pressure = 0;  // 2 sigma cos(theta) / w (Pa)
  double drive = 0;           // rho_gas g H (Pa)
  double depth = 0;           // how far the gas reached below the slit's mouth at the end (m)
  double width = 0;           // w (m)
  long steps = 0;
  int particles = 0;
  double seconds = 0;
};

EntryResult run_capillary_entry(const Case& c, const std::string& backend);

}  // namespace psph
