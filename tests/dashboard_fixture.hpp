#pragma once
// What the dashboard's tests share: a run directory written as a live run leaves it, a server
// over it, and plain sockets (for what cpp-httplib's client will not send).
#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>

#include <httplib.h>
#include <unistd.h>

#include "dashboard/dashboard_server.hpp"
#include "dashboard/run_control.hpp"
#include "dashboard/run_status.hpp"
#include "dashboard/run_watcher.hpp"

using namespace psph;
namespace fs = std::filesystem;

// A run directory as a live run leaves it: status, two monitor rows, a frame, an extract, a token.
struct FakeRun {
  fs::path dir;
  std::string token;
  explicit FakeRun(const std::string& name, const std::string& state = "running") {
    dir = fs::temp_directory_path() / ("poresph_dashboard_" + name + "_" + std::to_string(::getpid()));
    fs::remove_all(dir);
    for (const char* sub : {"images/phases", "extracts", "checkpoints"}) fs::create_directories(dir / sub);
    std::ofstream(dir / "case.resolved.toml") << "[case]\nname = \"fake\"\n";
    std::ofstream(dir / "checkpoints" / "step_0000000010.ckpt") << "secret state";
    std::ofstream(dir / "monitors.csv") << "step,time,kinetic_energy\n0,0,0\n10,0.001,2.5e-7\n";
    std::ofstream(dir / "images" / "phases" / "3d_000000.png") << "png bytes";
    std::ofstream(dir / "images" / "frames.csv") << "frame,step,time\n0,0,0\n";
    std::ofstream(dir / "extracts" / "particles_000000.vtp") << "<VTKFile/>";
    std::ofstream(dir / "extracts" / "particles.pvd")
        << "<VTKFile>\n<Collection>\n    <DataSet timestep=\"0\" file=\"particles_000000.vtp\"/>\n</Collection>\n</VTKFile>\n";
    set_state(state);
    token = create_run_token(dir.string());
  }
  ~FakeRun() { fs::remove_all(dir); }
  void set_state(const std::string& state) {
    RunStatus s;
    s.case_name = "fake", s.backend = "cpu", s.device = "test", s.precision = "double";
    s.state = state, s.step = 10, s.time = 0.001, s.end_time = 1;
    StatusFile(dir.string()).write(s);
  }
  void append_row(const std::string& row) { std::ofstream(dir / "monitors.csv", std::ios::app) << row << std::flush; }
};

inline DashboardOptions test_options(const FakeRun& run, double request_deadline = 10) {
  DashboardOptions o{run.dir.string(), "/nonexistent", "127.0.0.1", 0, 0.05};
  o.request_deadline = request_deadline;
  return o;
}

struct Served {
  FakeRun run;
  DashboardServer server;
  explicit Served(const std::string& name, const std::string& state = "running", double request_deadline = 10)
      : run(name, state), server(test_options(run, request_deadline)) {}
  httplib::Client client() const { return httplib::Client("127.0.0.1", server.port()); }
};

inline int post_control(Served& s, const std::string& body, const std::string* token) {
  httplib::Headers h;
  if (token) h.emplace("X-Poresph-Token", *token);
  auto r = s.client().Post("/api/control", h, body, "application/json");
  return r ? r->status : -1;
}

inline int status_of(Served& s, const std::string& path) {
  auto r = s.client().Get(path.c_str());
  return r ? r->status : -1;
}

// A TCP connection to 127.0.0.1:port from address `from` (any of 127/8: a client apart); -1 on failure.
int connect_from(int port, const char* from = "127.0.0.1");
// What arrives on `fd` until the end of a response head (or the connection's end, or `timeout`).
std::string response_head(int fd, std::chrono::milliseconds timeout);
