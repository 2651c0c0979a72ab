#pragma once
// The dashboard's HTTP server (cpp-httplib), over one run directory (dashboard/run_watcher.hpp):
//   GET  /                 the front-end built from web/ (index.html, assets/)
//   GET  /api/state        everything so far: status, monitor columns and rows, frames, extracts
//   GET  /api/events       server-sent events after ?since=N (or Last-Event-ID): status,
//                          columns, monitors, frame, extract; 503 with Retry-After beyond
//                          max_streams in all or max_streams_per_client from one address
//   POST /api/control      {"action": ...} (dashboard/run_control.hpp) with the run's token in
//                          the X-Poresph-Token header: 403 without it, 400 when malformed, 409
//                          when the run is no longer live
//   GET  /run/PATH         images/, extracts/ and the run's text files (not its token, control
//                          requests or checkpoints); anything outside the run directory: 403
// A request that has not arrived whole within request_deadline gets 408 (it held no thread).
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
  // Event streams in all and from one address: the other threads stay for pages, state, control.
  int max_streams = 32, max_streams_per_client = 8;
  double request_deadline = 10;    // s for a whole request to arrive (dashboard/request_gate.hpp)
  int listen_backlog = 256;        // connections waiting to be accepted
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
