#include "dashboard/run_status.hpp"

#include "io/durable_file.hpp"

#include <cerrno>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <unistd.h>

namespace psph {

nlohmann::json to_json(const RunStatus& s) {
  return {{"state", s.state},
          {"diagnostic", s.diagnostic},
          {"warnings", s.warnings},
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
          {"pid_start", s.pid_start},
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
  if (j.contains("pid_start")) get("pid_start", s.pid_start);  // not in older run directories
  if (j.contains("warnings")) get("warnings", s.warnings);
  return s;
}

namespace {

// When process `pid` started (field 22 of /proc/PID/stat, clock ticks after boot); 0 when unknown.
long process_start(long pid) {
  std::ifstream in("/proc/" + std::to_string(pid) + "/stat");
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const auto name_end = text.rfind(')');  // the command's name may hold spaces and parentheses
  if (name_end == std::string::npos) return 0;
  std::istringstream fields(text.substr(name_end + 1));
  std::string f;
  for (int k = 3; k <= 22 && fields >> f; ++k)
    if (k == 22) return std::atol(f.c_str());
  return 0;
}

}  // namespace

bool writer_gone(const RunStatus& s) {
  if (s.pid <= 0) return false;  // unknown writer: no verdict
  if (::kill(static_cast<pid_t>(s.pid), 0) != 0 && errno == ESRCH) return true;
  const long start = s.pid_start > 0 ? process_start(s.pid) : 0;
  return start > 0 && start != s.pid_start;
}

bool mark_lost(const std::string& run_dir, nlohmann::json& j) {
  const RunStatus s = status_from_json(j);
  if (!s.live() || !writer_gone(s)) return false;
  j["state"] = "lost";
  j["diagnostic"] = "the run's process (pid " + std::to_string(j["pid"].get<long>()) + ") ended without a final status";
  const std::string path = run_dir + "/status.json", tmp = path + ".lost." + std::to_string(::getpid()) + ".tmp";
  {
    std::ofstream o(tmp);
    o << j.dump(1) << "\n";
    if (!o) return true;  // a reader without write access there: lost for it alone
  }
  std::error_code ec;
  std::filesystem::rename(tmp, path, ec);
  if (ec) std::filesystem::remove(tmp, ec);
  return true;
}

StatusFile::StatusFile(std::string run_dir, double period) : path_(std::move(run_dir) + "/status.json"), period_(period) {}

bool StatusFile::due() const {
  return !written_ || std::chrono::duration<double>(std::chrono::steady_clock::now() - last_write_).count() >= period_;
}

void StatusFile::write(RunStatus s) {
  const auto now = std::chrono::steady_clock::now();
  static const long own_start = process_start(::getpid());
  s.pid = static_cast<long>(::getpid()), s.pid_start = own_start;
  s.updated = std::chrono::duration<double>(std::chrono::system_clock::now().time_since_epoch()).count();
  write_file_atomically(path_, to_json(s).dump(1) + "\n");  // a WriteError when the disk is full
  last_ = s, written_ = true, last_write_ = now;
}

}  // namespace psph
