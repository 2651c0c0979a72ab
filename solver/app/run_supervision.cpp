#include "app/run_supervision.hpp"

#include <algorithm>

namespace psph {

RunSupervision::RunSupervision(const std::string& run_dir, RunStatus base)
    : file_(run_dir), inbox_(run_dir), base_(std::move(base)), token_(create_run_token(run_dir)) {}

RunStatus RunSupervision::status(const Engine& e, const std::string& state, double wall) {
  RunStatus s = base_;
  s.state = state;
  s.step = e.steps(), s.time = e.time(), s.dt = e.last_dt(), s.elapsed = wall;
  if (start_time_ < 0) start_time_ = e.time(), last_steps_ = e.steps(), last_wall_ = wall;
  // Speed over the last report; time left at the average speed in simulated time so far.
  s.steps_per_second = wall > last_wall_ ? (e.steps() - last_steps_) / (wall - last_wall_) : 0;
  const double done = e.time() - start_time_;
  s.time_left = done > 0 ? std::max(0.0, (s.end_time - e.time()) / done * wall) : -1;
  last_steps_ = e.steps(), last_wall_ = wall;
  return s;
}

void RunSupervision::report(const Engine& e, const std::string& state, double wall, bool force) {
  if (!force && state == file_.last().state && !file_.due()) return;
  file_.write(status(e, state, wall));
}

void RunSupervision::finish(const Engine& e, const std::string& state, const std::string& diagnostic, double wall) {
  RunStatus s = status(e, state, wall);
  s.diagnostic = diagnostic;
  s.time_left = 0;
  file_.write(s);
}

void RunSupervision::set_intervals(double monitor, double extract, double visualisation) {
  base_.monitor_interval = monitor, base_.extract_interval = extract, base_.visualisation_interval = visualisation;
}

std::vector<ControlRequest> RunSupervision::requests(const std::function<void(const std::string&)>& log) {
  std::vector<std::string> rejected;
  std::vector<ControlRequest> r = inbox_.take(&rejected);
  for (const auto& m : rejected) log("control: ignored " + m);
  return r;
}

}  // namespace psph
