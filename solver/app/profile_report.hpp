#pragma once
// The profile of a run or a benchmark as users read it (core/pass_profile.hpp): each pass and stage
// with its calls, seconds and share of the wall time, as JSON (summary.json) and as text lines.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/pass_profile.hpp"

namespace psph {

// {"wall_seconds", "passes_seconds", "stages": [...], "passes": [...], "outputs": [...]}: `outputs`
// the time spent writing monitors, extracts, figures and checkpoints (their own launches are also
// in the stage "monitors" of `engine`); shares are of `wall` seconds.
nlohmann::json profile_json(PassProfile& engine, PassProfile& outputs, double wall);
// The stages, then the `top` most expensive passes, a line each, with a header line.
std::vector<std::string> profile_lines(PassProfile& engine, PassProfile& outputs, double wall, int top);

}  // namespace psph
