#pragma once
// The run directory contract (GUIDE §5): case.resolved.toml, log.txt, monitors.csv, summary.json,
// extracts/, images/, checkpoints/.
#include <fstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "engine/engine.hpp"
#include "parallel/communicator.hpp"

namespace psph {

class RunDirectory {
 public:
  // Creates the directory (it must not exist or be empty) and writes the resolved case.
  RunDirectory(const std::string& path, const std::string& resolved_case_toml);
  // The other processes of a run shared out over several: the first one writes, they make the
  // engine's collective calls (statistics) and write their share of the checkpoints.
  static RunDirectory follower(const std::string& path, const std::string& resolved_case_toml);
  bool writes() const { return writes_; }
  const std::string& path() const { return path_; }
  std::string extracts() const { return path_ + "/extracts"; }

  // A line to the terminal and to log.txt. It does not throw (it reports failures of the other
  // writes): the first failed write to log.txt is kept in write_failure().
  void log(const std::string& line);
  const std::string& write_failure() const { return write_failure_; }
  // A row of monitors.csv: the engine's statistics, then the named `extra` values (the stages'
  // monitors and the run's own); the first row's names are the columns, later rows repeat them.
  void monitor(Engine& e, const std::vector<MonitorValue>& extra = {});
  // The writes below throw a WriteError (io/durable_file.hpp) naming the file and the reason.
  void write_summary(const nlohmann::json& j) const;
  // Writes checkpoints/step_<step>.h5 (.ckpt without HDF5), every process its share, and deletes
  // the oldest beyond `keep`; returns its path.
  std::string save_checkpoint(Engine& e, const std::string& case_name, int keep, Communicator& comm);

 private:
  RunDirectory() = default;
  std::string path_, resolved_;
  bool writes_ = false;
  std::ofstream log_, monitors_;
  std::vector<std::string> extra_columns_;
  std::string write_failure_;
  bool header_written_ = false;
};

// Default run directory: runs/<case name>-<UTC timestamp>.
std::string default_run_directory(const std::string& case_name);

}  // namespace psph
