#include "io/run_directory.hpp"

#include <cerrno>
#include <chrono>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <iostream>
#include <set>

#include "io/checkpoint_file.hpp"
#include "io/durable_file.hpp"

namespace psph {
namespace fs = std::filesystem;

RunDirectory::RunDirectory(const std::string& path, const std::string& resolved)
    : path_(path), resolved_(resolved), writes_(true) {
  std::error_code ec;
  if (fs::exists(path, ec) && !(fs::is_directory(path, ec) && fs::is_empty(path, ec)))
    throw std::runtime_error("--out " + path + ": the run directory exists and is not empty; choose another");
  const bool existed = fs::exists(path, ec);
  try {
    for (const char* sub : {"", "/extracts", "/images", "/checkpoints"})
      if (fs::create_directories(path + sub, ec), ec)
        throw std::runtime_error("--out " + path + ": cannot create the run directory: " + ec.message());
    write_file_durably(path + "/case.resolved.toml", resolved + "\n");
    log_.open(path + "/log.txt");
    monitors_.open(path + "/monitors.csv");
    if (!log_ || !monitors_) throw WriteError("--out " + path + ": cannot create log.txt and monitors.csv in it");
  } catch (...) {  // nothing half-made is left
    if (!existed) fs::remove_all(path, ec);
    throw;
  }
}

RunDirectory RunDirectory::follower(const std::string& path, const std::string& resolved) {
  RunDirectory d;
  d.path_ = path, d.resolved_ = resolved;
  return d;
}

void RunDirectory::log(const std::string& line) {
  if (!writes()) return;
  std::cout << line << std::endl;
  log_ << line << '\n';
  log_.flush();
  if (!log_ && write_failure_.empty()) write_failure_ = path_ + "/log.txt: writing failed: " + std::strerror(errno);
}

void RunDirectory::monitor(Engine& e, const std::vector<MonitorValue>& extra) {
  if (!writes()) return void(e.stats());
  if (!header_written_) {
    monitors_ << "step,time,dt,dt_limit,kinetic_energy,v_max,a_max,density_deviation_max";
    for (const auto& m : extra) monitors_ << ',' << m.name, extra_columns_.push_back(m.name);
    monitors_ << '\n';
    header_written_ = true;
  }
  bool same = extra.size() == extra_columns_.size();
  for (std::size_t k = 0; same && k < extra.size(); ++k) same = extra[k].name == extra_columns_[k];
  if (!same) throw std::logic_error("monitor row and columns differ");
  const StepStats s = e.stats();
  monitors_.precision(10);
  monitors_ << e.steps() << ',' << e.time() << ',' << e.last_dt() << ',' << s.dt_limit << ',' << s.kinetic_energy
            << ',' << s.v_max << ',' << s.a_max << ',' << s.density_deviation_max;
  for (const auto& m : extra) monitors_ << ',' << m.value;
  monitors_ << '\n';
  monitors_.flush();
  if (!monitors_) throw WriteError(path_ + "/monitors.csv: writing failed: " + std::strerror(errno));
}

void RunDirectory::write_summary(const nlohmann::json& j) const {
  if (!writes()) return;
  write_file_durably(path_ + "/summary.json", j.dump(2) + "\n");
}

std::string RunDirectory::save_checkpoint(Engine& e, const std::string& case_name, int keep, Communicator& comm) {
  char name[40];
  std::snprintf(name, sizeof name, "/step_%010ld", e.steps());
  const std::string file = path_ + "/checkpoints" + name + checkpoint_extension();
  write_checkpoint_file(file, e.checkpoint(), CheckpointOrigin{case_name, resolved_}, comm);
  if (!writes()) return file;
  std::set<std::string> all;  // zero-padded names sort by step
  std::error_code ec;
  for (const auto& f : fs::directory_iterator(path_ + "/checkpoints", ec))
    if (f.path().extension() == checkpoint_extension()) all.insert(f.path().string());
  while (keep > 0 && int(all.size()) > keep) {
    fs::remove(*all.begin(), ec);
    all.erase(all.begin());
  }
  return file;
}

std::string default_run_directory(const std::string& case_name) {
  const std::time_t t = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  std::tm tm{};
  gmtime_r(&t, &tm);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y%m%d-%H%M%S", &tm);
  return "runs/" + case_name + "-" + buf;
}

}  // namespace psph
