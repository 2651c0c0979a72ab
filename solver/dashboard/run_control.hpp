#pragma once
// Control of a running run from outside it (pause, resume, stop, output cadence): each request is
// a small JSON file in the run directory's control/ folder, written atomically by whoever asks (the
// dashboard's server, in the run's process or attached from another) and taken by the run loop,
// which looks at most every `period` seconds. The run's token (run_dir/token, owner-only) is what
// the server asks of a client before it posts a request.
#include <chrono>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace psph {

struct ControlRequest {
  enum class Action { Pause, Resume, Stop, Cadence } action = Action::Pause;
  // Cadence (simulated seconds; 0 leaves one unchanged).
  double monitor_interval = 0, extract_interval = 0, visualisation_interval = 0;
};

// {"action": "pause" | "resume" | "stop" | "cadence", and for cadence one or more of
// "monitor_interval", "extract_interval", "visualisation_interval" (positive numbers)}.
// Throws std::invalid_argument saying what is wrong.
ControlRequest control_request_from_json(const nlohmann::json& j);
nlohmann::json to_json(const ControlRequest& r);
const char* action_name(ControlRequest::Action a);

// The shortest output interval a run takes: its time step, and a millionth of the run (a cadence
// request below it is refused).
inline double cadence_floor(double dt, double end_time) { return dt > 1e-6 * end_time ? dt : 1e-6 * end_time; }
// Why a run at time step `dt` that ends at `end_time` cannot take the cadence request `r`, or "":
// each interval given must be at least cadence_floor() and at most the run's end time (a longer
// one would mean never; 1e308 s once overflowed the output clocks' arithmetic).
std::string cadence_problem(const ControlRequest& r, double dt, double end_time);

// Writes one request into run_dir/control/ (temporary file, then rename; names sort by time).
void post_control_request(const std::string& run_dir, const ControlRequest& r);

class ControlInbox {
 public:
  explicit ControlInbox(std::string run_dir, double period = 0.2);
  // The requests that arrived since the last look, oldest first, each file removed once read; an
  // unreadable one is removed and described in `rejected`. Looks at most every `period` seconds.
  std::vector<ControlRequest> take(std::vector<std::string>* rejected = nullptr);

 private:
  std::string dir_;
  double period_;
  std::chrono::steady_clock::time_point last_{};
};

// A fresh random token (32 hex digits) written to run_dir/token, readable by the owner only.
std::string create_run_token(const std::string& run_dir);
// The run's token, or "" when the run directory has none.
std::string read_run_token(const std::string& run_dir);

}  // namespace psph
