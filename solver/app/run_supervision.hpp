#pragma once
// A run as its observers see it (dashboard/): the status it writes to status.json (state, step,
// time, speed, estimated time left) and the control requests it takes from control/, with the
// token that guards them.
#include <functional>
#include <string>
#include <vector>

#include "dashboard/run_control.hpp"
#include "dashboard/run_status.hpp"
#include "engine/engine.hpp"

namespace psph {

class RunSupervision {
 public:
  // `base`: what does not change (case, backend, device, sizes, end time, output kinds and intervals).
  RunSupervision(const std::string& run_dir, RunStatus base);
  const std::string& token() const { return token_; }
  // The state now (running, paused); written at most once a second unless `force`.
  void report(const Engine& e, const std::string& state, double wall, bool force = false);
  // The final state (completed, stopped, interrupted, unstable, failed), always written.
  void finish(const Engine& e, const std::string& state, const std::string& diagnostic, double wall);
  void set_intervals(double monitor, double extract, double visualisation);
  void set_end_time(double t) { base_.end_time = t; }  // time.after_percolation moved it
  void warn(const std::string& w) { base_.warnings.push_back(w); }  // in every status from the next
  // Requests that arrived (unreadable ones go to `log`).
  std::vector<ControlRequest> requests(const std::function<void(const std::string&)>& log);

 private:
  RunStatus status(const Engine& e, const std::string& state, double wall);
  StatusFile file_;
  ControlInbox inbox_;
  RunStatus base_;
  std::string token_;
  long last_steps_ = 0;
  double last_wall_ = 0, start_time_ = -1;
};

}  // namespace psph
