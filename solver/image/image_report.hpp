#pragma once
// What a user first asks of a segmented image (`poresph image info`, and a run's summary.json):
// its size, labels and their fractions, porosity before and after coarsening, the pore
// components and which of them percolate along each axis.
#include <string>

#include <nlohmann/json.hpp>

#include "image/phase_volume.hpp"
#include "image/pore_components.hpp"

namespace psph {

struct ImageReportInput {
  std::string file, format;
  const PhaseVolume* volume = nullptr;
  const PoreComponents* pores = nullptr;
  unsigned pore_phases = 0;
  std::array<int, 3> coarsen{1, 1, 1};
  int connectivity = 6;
  int dimension = 3;        // 2: percolation along x and y only
  int largest_listed = 10;  // components listed, the largest first
};

nlohmann::json image_report(const ImageReportInput& in);
// The report as lines for a terminal or a log.
std::string image_report_text(const nlohmann::json& report);

}  // namespace psph
