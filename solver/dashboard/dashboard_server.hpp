#pragma once
// The dashboard's HTTP server (cpp-httplib), over one run directory (dashboard/run_watcher.hpp):
//   GET  /                 the front-end built from web/ (index.html, assets/)
//   GET  /api/state        everything so far: status, monitor columns and rows, frames, extracts
//   GET  /api/events       server-sent events after ?since=N (or Last-Event-ID): status,
//                          columns, monitors, frame, extract
//   POST /api/control      {"action": ...} (dashboard/run_control.hpp) with the run's token in
//                          the X-Poresph-Token header: 403 without it, 400 when malformed, 409
//                          when the run is no longer live
//   GET  /run/PATH         images/, extracts/ and the run's text files (not its token, control
//                          requests or checkpoints); anything outside the run directory: 403
// Binds to 127.0.0.1 unless told otherwise. The server's threads only read files and write
// control requests, and look at the run directory only while an event stream is open (or a
// request asks): the run never waits for a client. (At nice 19 they starved under a fully loaded
// machine: a page took over 30 s to load; they run at the solver's priority.)
#include <memory>
#include <string>

namespace psph {

struct DashboardOptions {
  std::string run_dir;
  std::string web_dir;             // the built front-end; "" = the build's (web_directory())
  std::string bind = "127.0.0.1";
  int port = 8080;                 // 0: any free port
  double poll_period = 1.0;        // s, between looks at the run directory (each wakes every stream)
  int threads = 64;                // each event stream holds one
};

// Where this build put the front-end (PORESPH_WEB_DIR overrides); "" when it was not built.
std::string web_directory();
bool dashboard_available();  // built with cpp-httplib

class DashboardServer {
 public:
  // Binds the port (throws std::runtime_error naming the address when it cannot) and starts
  // serving and watching in background threads.
  explicit DashboardServer(const DashboardOptions& opt);
  ~DashboardServer();  // stops
  int port() const;
  std::string url() const;  // http://bind:port/
  void stop();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace psph
