#pragma once
// Gas drainage of the synthetic claystone sample with a damaging elastic clay matrix
// (cases/claystone_drainage.toml; Pazdniakou 2018 §5.2, Table 5): the case with overrides, and a
// run that keeps what the monitors say over time, for the consistency checks of CI and the
// percolation figures of the full cell.
#include <string>
#include <vector>

#include "scene/case_file.hpp"
#include "validation/validation_cases.hpp"

namespace psph {

struct ClaystoneDrainage {
  double percolation_time = -1;          // s, < 0: none before the end
  double saturation_at_percolation = 0;  // gas saturation then
  double image_porosity = 0;             // of the image (crop), before any particle moves
  double porosity_start = 0, porosity_end = 0;  // the monitors' fluid volume / sample volume
  double worst_saturation_sum = 0;       // max |S_w + S_g - 1| over the monitor rows
  double worst_damage_ratio = 0;         // max total damage / damaging (clay) particles (each D <= 1)
  double damaged_end = 0, total_damage_end = 0, saturation_gas_end = 0;
  long steps = 0;
  int particles = 0;
  double seconds = 0;
};

// The embedded case with `--set`-style overrides (KEY=VALUE).
Case claystone_case(const std::vector<std::string>& sets);
// Runs to the case's end, or to percolation when `stop_at_percolation`.
ClaystoneDrainage run_claystone_drainage(const Case& c, const std::string& backend, bool stop_at_percolation);

// `poresph validate claystone_drainage`: CI, the consistency of the monitors on a crop at 6 MPa;
// --full, the published cell (2 particles per voxel) to percolation against Table 5.
std::vector<ValidationRecord> claystone_drainage_records(const ValidationContext& ctx);

}  // namespace psph
