#pragma once
// The dashboard's view of a run directory, read from the files the run writes (so that the same
// code serves a run in this process, one in another process, and a finished one): status.json
// (or, for a run directory older than it, summary.json),
// monitors.csv (complete lines only), images/frames.csv (a row once a frame's images are written)
// with the images/<pipeline>/<view>_<frame>.png files, and extracts/particles.pvd. Each poll turns
// what is new into numbered events; a client gets the whole state once, then the events after it
// (of the status, only the latest).
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace psph {

struct DashboardEvent {
  long id = 0;
  std::string type;  // status, columns, monitors, frame, extract
  nlohmann::json data;
};

class RunWatcher {
 public:
  explicit RunWatcher(std::string run_dir);
  const std::string& run_dir() const { return dir_; }
  // Reads what changed since the last poll (one polling thread).
  void poll();
  // {"status", "columns", "rows", "frames", "extracts", "last_event"}: everything so far.
  nlohmann::json snapshot() const;
  // Events with id > since, oldest first; waits up to `wait` when there are none (or until stop()).
  std::vector<DashboardEvent> events_after(long since, std::chrono::milliseconds wait) const;
  // Wakes every waiting reader for good (server shutdown).
  void stop();
  bool stopped() const;

 private:
  void emit(const std::string& type, nlohmann::json data);  // mutex held
  void poll_status();
  nlohmann::json status_of_summary() const;
  void poll_monitors();
  void poll_frames();
  void poll_extracts();

  std::string dir_;
  mutable std::mutex m_;
  mutable std::condition_variable cv_;
  bool stopped_ = false;
  long seq_ = 0;                       // the last event's number
  std::vector<DashboardEvent> events_;  // all but status, by number
  DashboardEvent status_event_;         // the latest status (id 0: none yet)
  nlohmann::json status_ = nullptr, columns_ = nlohmann::json::array(), rows_ = nlohmann::json::array();
  nlohmann::json frames_ = nlohmann::json::array(), extracts_ = nlohmann::json::array();
  std::string status_text_, monitor_partial_;
  std::uintmax_t monitor_offset_ = 0, frames_offset_ = 0;
  std::string frames_partial_, pvd_text_;
};

}  // namespace psph
