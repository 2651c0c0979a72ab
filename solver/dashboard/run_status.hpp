#pragma once
// A run's state for its observers (the dashboard, `poresph serve`): status.json in the run
// directory, rewritten atomically (temporary file, then rename), so a server in another process
// can attach. The run writes it on every change of state and otherwise when due(), at most every
// `period` seconds (app/run_supervision.hpp); its readers mark a live status whose writer has
// gone as lost (mark_lost).
#include <chrono>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace psph {

struct RunStatus {
  // starting, running, paused; then completed, stopped (from the dashboard), interrupted (a
  // signal), unstable or failed (with `diagnostic`).
  std::string state = "starting";
  std::string diagnostic;
  std::vector<std::string> warnings;  // what the run said once and goes on with (a density past its bound)
  std::string case_name, backend, device, precision;
  int dimension = 0, particles = 0;
  long step = 0;
  double time = 0, dt = 0, end_time = 0;
  double steps_per_second = 0;  // over the last status period
  double elapsed = 0;           // wall seconds since the run started (pauses included)
  double time_left = -1;        // estimated wall seconds (-1: unknown)
  double monitor_interval = 0, extract_interval = 0, visualisation_interval = 0;  // simulated s
  bool extracts = false, pipelines = false, checkpoints = true;
  long pid = 0;
  long pid_start = 0;  // the writer's start (clock ticks after boot): tells a reused pid apart (0: unknown)
  double updated = 0;  // Unix time of the write

  bool live() const { return state == "starting" || state == "running" || state == "paused"; }
};

nlohmann::json to_json(const RunStatus& s);
// Throws std::invalid_argument naming the key that is missing or of the wrong type.
RunStatus status_from_json(const nlohmann::json& j);

// True when the process that wrote `s` has ended, or its pid is now another process's.
bool writer_gone(const RunStatus& s);
// A run killed before it could write its final state (SIGKILL, the machine's OOM killer) leaves
// status.json saying it is live: when `j` says so and its writer is gone, `j` becomes `lost` and
// status.json is rewritten so (atomically; for every later reader, not only this one). False
// when nothing was lost. A reader that may not write there still sees `lost` in `j`.
bool mark_lost(const std::string& run_dir, nlohmann::json& j);

class StatusFile {
 public:
  StatusFile(std::string run_dir, double period = 1.0);
  // True when nothing was written yet or `period` has passed since the last write.
  bool due() const;
  // Writes `s` (stamped with this process's id and the time).
  void write(RunStatus s);
  const RunStatus& last() const { return last_; }

 private:
  std::string path_;
  double period_;
  RunStatus last_;
  bool written_ = false;
  std::chrono::steady_clock::time_point last_write_{};
};

}  // namespace psph
