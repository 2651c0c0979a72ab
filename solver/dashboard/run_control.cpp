#include "dashboard/run_control.hpp"

#include <atomic>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <random>
#include <set>
#include <stdexcept>

#include <fcntl.h>
#include <unistd.h>

namespace psph {
namespace fs = std::filesystem;

const char* action_name(ControlRequest::Action a) {
  switch (a) {
    case ControlRequest::Action::Pause: return "pause";
    case ControlRequest::Action::Resume: return "resume";
    case ControlRequest::Action::Stop: return "stop";
    default: return "cadence";
  }
}

ControlRequest control_request_from_json(const nlohmann::json& j) {
  if (!j.is_object()) throw std::invalid_argument("expected a JSON object {\"action\": ...}");
  if (!j.contains("action") || !j["action"].is_string())
    throw std::invalid_argument("expected \"action\": \"pause\", \"resume\", \"stop\" or \"cadence\"");
  const std::string a = j["action"];
  ControlRequest r;
  using A = ControlRequest::Action;
  if (a == "pause") r.action = A::Pause;
  else if (a == "resume") r.action = A::Resume;
  else if (a == "stop") r.action = A::Stop;
  else if (a == "cadence") r.action = A::Cadence;
  else throw std::invalid_argument("action: expected \"pause\", \"resume\", \"stop\" or \"cadence\", got \"" + a + "\"");
  if (r.action != A::Cadence) return r;
  int given = 0;
  for (auto [key, out] : {std::pair{"monitor_interval", &r.monitor_interval}, std::pair{"extract_interval", &r.extract_interval},
                          std::pair{"visualisation_interval", &r.visualisation_interval}}) {
    if (!j.contains(key)) continue;
    if (!j[key].is_number() || !(j[key].get<double>() > 0) || !std::isfinite(j[key].get<double>()))
      throw std::invalid_argument(std::string(key) + ": expected a positive number of simulated seconds");
    *out = j[key].get<double>(), ++given;
  }
  if (given == 0)
    throw std::invalid_argument("cadence: expected one or more of monitor_interval, extract_interval, visualisation_interval");
  return r;
}

std::string cadence_problem(const ControlRequest& r, double dt, double end_time) {
  const double shortest = cadence_floor(dt, end_time);
  auto g = [](double v) {
    char b[32];
    std::snprintf(b, sizeof b, "%g", v);
    return std::string(b);
  };
  for (auto [key, v] : {std::pair{"monitor_interval", r.monitor_interval}, std::pair{"extract_interval", r.extract_interval},
                        std::pair{"visualisation_interval", r.visualisation_interval}}) {
    if (v == 0) continue;  // unchanged
    if (!(v >= shortest))
      return std::string(key) + ": " + g(v) + " s is shorter than the run allows (" + g(shortest) +
             " s: a time step, and a millionth of the run)";
    if (!(v <= end_time)) return std::string(key) + ": " + g(v) + " s is longer than the run (it ends at " + g(end_time) + " s)";
  }
  return "";
}

nlohmann::json to_json(const ControlRequest& r) {
  nlohmann::json j = {{"action", action_name(r.action)}};
  if (r.monitor_interval > 0) j["monitor_interval"] = r.monitor_interval;
  if (r.extract_interval > 0) j["extract_interval"] = r.extract_interval;
  if (r.visualisation_interval > 0) j["visualisation_interval"] = r.visualisation_interval;
  return j;
}

void post_control_request(const std::string& run_dir, const ControlRequest& r) {
  static std::atomic<unsigned> counter{0};
  const fs::path dir = fs::path(run_dir) / "control";
  fs::create_directories(dir);
  const auto ns = std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::system_clock::now().time_since_epoch()).count();
  char name[64];
  std::snprintf(name, sizeof name, "req_%020lld_%06u", static_cast<long long>(ns), counter++ % 1000000);
  const fs::path tmp = dir / (std::string(name) + ".tmp"), final = dir / (std::string(name) + ".json");
  {
    std::ofstream o(tmp);
    o << to_json(r).dump() << "\n";
    if (!o) throw std::runtime_error(tmp.string() + ": cannot write the control request");
  }
  fs::rename(tmp, final);
}

ControlInbox::ControlInbox(std::string run_dir, double period) : dir_(std::move(run_dir) + "/control"), period_(period) {}

std::vector<ControlRequest> ControlInbox::take(std::vector<std::string>* rejected) {
  std::vector<ControlRequest> out;
  const auto now = std::chrono::steady_clock::now();
  if (std::chrono::duration<double>(now - last_).count() < period_) return out;
  last_ = now;
  std::error_code ec;
  if (!fs::is_directory(dir_, ec)) return out;
  std::set<fs::path> files;  // names sort by time
  for (const auto& f : fs::directory_iterator(dir_, ec))
    if (f.path().extension() == ".json") files.insert(f.path());
  for (const fs::path& f : files) {
    try {
      std::ifstream in(f);
      out.push_back(control_request_from_json(nlohmann::json::parse(in)));
    } catch (const std::exception& e) {
      if (rejected) rejected->push_back(f.filename().string() + ": " + e.what());
    }
    fs::remove(f, ec);
  }
  return out;
}

std::string create_run_token(const std::string& run_dir) {
  std::random_device rd;
  char hex[33];
  for (int k = 0; k < 4; ++k) std::snprintf(hex + 8 * k, 9, "%08x", static_cast<unsigned>(rd()));
  const fs::path p = fs::path(run_dir) / "token";
  // Created readable by the owner only (never for a moment by others).
  const int fd = ::open(p.c_str(), O_WRONLY | O_CREAT | O_EXCL, 0600);
  const std::string line = std::string(hex) + "\n";
  const bool ok = fd >= 0 && ::write(fd, line.data(), line.size()) == static_cast<ssize_t>(line.size());
  if (fd >= 0) ::close(fd);
  if (!ok) throw std::runtime_error(p.string() + ": cannot write the run's token");
  return hex;
}

std::string read_run_token(const std::string& run_dir) {
  std::ifstream in(fs::path(run_dir) / "token");
  std::string t;
  in >> t;
  return t;
}

}  // namespace psph
