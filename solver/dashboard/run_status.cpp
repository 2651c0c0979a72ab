#include "dashboard/run_status.hpp"

#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <unistd.h>

namespace psph {

nlohmann::json to_json(const RunStatus& s) {
  return {{"state", s.state},
          {"diagnostic", s.diagnostic},
          {"case", s.case_name},
          {"backend", s.backend},
          {"device", s.device},
          {"precision", s.precision},
          {"dimension", s.dimension},
          {"particles", s.particles},
          {"step", s.step},
          {"time", s.time},
          {"dt", s.dt},
          {"end_time", s.end_time},
          {"steps_per_second", s.steps_per_second},
          {"elapsed", s.elapsed},
          {"time_left", s.time_left},
          {"monitor_interval", s.monitor_interval},
          {"extract_interval", s.extract_interval},
          {"visualisation_interval", s.visualisation_interval},
          {"extracts", s.extracts},
          {"pipelines", s.pipelines},
          {"checkpoints", s.checkpoints},
          {"pid", s.pid},
          {"updated", s.updated}};
}

RunStatus status_from_json(const nlohmann::json& j) {
  RunStatus s;
  auto get = [&](const char* key, auto& out) {
    if (!j.contains(key)) throw std::invalid_argument(std::string("status.json: missing key '") + key + "'");
    try {
      j.at(key).get_to(out);
    } catch (const nlohmann::json::exception&) {
      throw std::invalid_argument(std::string("status.json: key '") + key + "' has the wrong type");
    }
  };
  get("state", s.state), get("diagnostic", s.diagnostic), get("case", s.case_name), get("backend", s.backend);
  get("device", s.device), get("precision", s.precision), get("dimension", s.dimension), get("particles", s.particles);
  get("step", s.step), get("time", s.time), get("dt", s.dt), get("end_time", s.end_time);
  get("steps_per_second", s.steps_per_second), get("elapsed", s.elapsed), get("time_left", s.time_left);
  get("monitor_interval", s.monitor_interval), get("extract_interval", s.extract_interval);
  get("visualisation_interval", s.visualisation_interval), get("extracts", s.extracts), get("pipelines", s.pipelines);
  get("checkpoints", s.checkpoints), get("pid", s.pid), get("updated", s.updated);
  return s;
}

StatusFile::StatusFile(std::string run_dir, double period) : path_(std::move(run_dir) + "/status.json"), period_(period) {}

bool StatusFile::due() const {
  return !written_ || std::chrono::duration<double>(std::chrono::steady_clock::now() - last_write_).count() >= period_;
}

void StatusFile::write(RunStatus s) {
  const auto now = std::chrono::steady_clock::now();
  s.pid = static_cast<long>(::getpid());
  s.updated = std::chrono::duration<double>(std::chrono::system_clock::now().time_since_epoch()).count();
  {
    std::ofstream o(path_ + ".tmp");
    o << to_json(s).dump(1) << "\n";
  }
  std::filesystem::rename(path_ + ".tmp", path_);
  last_ = s, written_ = true, last_write_ = now;
}

}  // namespace psph
