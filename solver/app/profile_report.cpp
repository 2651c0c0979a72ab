#include "app/profile_report.hpp"

#include <cstdio>

namespace psph {

namespace {

nlohmann::json rows(const std::vector<PassTime>& times, double wall) {
  nlohmann::json out = nlohmann::json::array();
  for (const PassTime& t : times) {
    nlohmann::json r = {{"stage", t.stage}, {"calls", t.calls}, {"seconds", t.seconds},
                        {"share", wall > 0 ? t.seconds / wall : 0.0}};
    if (!t.pass.empty()) r["pass"] = t.pass;
    out.push_back(r);
  }
  return out;
}

std::string line(const PassTime& t, double wall) {
  char b[200];
  const std::string what = t.pass.empty() ? t.stage : t.pass + " (" + t.stage + ")";
  std::snprintf(b, sizeof b, "  %-44s %6.1f %%  %10.3f s  %9ld calls  %9.3g ms/call", what.c_str(),
                wall > 0 ? 100 * t.seconds / wall : 0.0, t.seconds, t.calls, t.calls ? 1e3 * t.seconds / t.calls : 0.0);
  return b;
}

}  // namespace

nlohmann::json profile_json(PassProfile& engine, PassProfile& outputs, double wall) {
  return {{"wall_seconds", wall},
          {"passes_seconds", engine.seconds()},
          {"stages", rows(engine.stages(), wall)},
          {"passes", rows(engine.passes(), wall)},
          {"outputs", rows(outputs.passes(), wall)}};
}

std::vector<std::string> profile_lines(PassProfile& engine, PassProfile& outputs, double wall, int top) {
  char head[200];
  std::snprintf(head, sizeof head, "profile: %.1f %% of the wall time (%.3g s) in the solver's passes; by stage, then the %d largest passes:",
                wall > 0 ? 100 * engine.seconds() / wall : 0.0, wall, top);
  std::vector<std::string> out{head, " stages:"};
  for (const PassTime& t : engine.stages()) out.push_back(line(t, wall));
  out.push_back(" passes:");
  int k = 0;
  for (const PassTime& t : engine.passes())
    if (k++ < top) out.push_back(line(t, wall));
  const std::vector<PassTime> written = outputs.passes();
  if (!written.empty()) out.push_back(" outputs (with their monitors' passes):");
  for (const PassTime& t : written) out.push_back(line(t, wall));
  return out;
}

}  // namespace psph
