#pragma once
// The damage and fracture validations (Deptulski 2021 §4.2, §4.3; a pressurised pore in clay):
// each returns its records for `poresph validate` (validation/validation_cases.cpp lists them).
#include <vector>

#include "validation/validation_cases.hpp"

namespace psph {

std::vector<ValidationRecord> softening_bar(const ValidationContext& ctx);
std::vector<ValidationRecord> plate_inclusion(const ValidationContext& ctx);
std::vector<ValidationRecord> pressurised_pore(const ValidationContext& ctx);

}  // namespace psph
