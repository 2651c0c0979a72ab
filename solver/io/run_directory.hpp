#pragma once
// The run directory contract (GUIDE §5): case.resolved.toml, log.txt, monitors.csv, summary.json,
// extracts/, images/, checkpoints/.
#include <fstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "engine/engine.hpp"

namespace psph {

class RunDirectory {
 public:
  // Creates the directory (it must not exist or be empty) and writes the resolved case.
  RunDirectory(const std::string& path, const std::string& resolved_case_toml);
  const std::string& path() const { return path_; }
  std::string extracts() const { return path_ + "/extracts"; }

  // A line to the terminal and to log.txt.
  void log(const std::string& line);
  // Columns after the engine's own (step ... density_deviation_max), before the first monitor row.
  void add_monitor_columns(const std::vector<std::string>& names);
  // A row of monitors.csv: the engine's statistics, then `extra` (one value per added column).
  void monitor(Engine& e, const std::vector<double>& extra = {});
  void write_summary(const nlohmann::json& j) const;
  // Writes checkpoints/step_<step>.ckpt and deletes the oldest beyond `keep`; returns its path.
  std::string save_checkpoint(Engine& e, const std::string& case_name, int keep);

 private:
  std::string path_;
  std::ofstream log_, monitors_;
  std::vector<std::string> extra_columns_;
  bool header_written_ = false;
};

// Default run directory: runs/<case name>-<UTC timestamp>.
std::string default_run_directory(const std::string& case_name);

}  // namespace psph
