#pragma once
// One run of a case: the engine (or a restart), the run directory, its outputs on their clocks
// (monitors, extracts, frames, checkpoints), the dashboard's requests, and the summary at the end.
#include <chrono>
#include <memory>
#include <string>

#include <nlohmann/json.hpp>

#include "app/commands.hpp"
#include "app/output_clock.hpp"
#include "app/run_supervision.hpp"
#include "catalyst/insitu_session.hpp"
#include "dashboard/dashboard_server.hpp"
#include "engine/engine.hpp"
#include "io/checkpoint_file.hpp"
#include "io/durable_file.hpp"
#include "io/particle_output.hpp"
#include "io/run_directory.hpp"
#include "monitors/pressure_probes.hpp"
#include "monitors/two_phase.hpp"
#include "scene/case_file.hpp"
#include "scene/compressibility.hpp"

namespace psph {

class RunDriver {
 public:
  RunDriver(Case& c, const RunOptions& opt) : c_(c), opt_(opt) {}
  // The exit code of commands.hpp.
  int run();

 private:
  using clock = std::chrono::steady_clock;
  int open();           // engine, restart, in-situ session, run directory: 0 or 2 (nothing left behind)
  Checkpoint restart_checkpoint();
  int discard(const std::string& what, int code = 2);  // refuses and removes the new run directory
  void plan_outputs();  // extract fields, output intervals and clocks
  int start();          // supervision, dashboard, the first outputs: 0 or an exit code
  void loop();          // steps to the end, a stop or an interrupt
  void outputs_due();
  void progress_line();
  void watch_density();  // a warning, once, when the fluid's density passes its bound
  bool controls();      // the dashboard's requests and a pause; true: leave the loop
  bool decide();        // the same, on the first process of a shared run
  int supervise(const RunStatus& base);  // status file and dashboard: 0 or an exit code
  int agreed(int code);                  // the largest of every process's exit codes
  void stop_every_process();             // a shared run whose process failed alone
  bool root() const { return comm_.rank() == 0; }
  void take_requests();
  void monitor();
  void checkpoint();
  void write_failed(const std::string& what);
  // Runs `write`; a WriteError ends the run (write_failed) and gives false.
  template <class F>
  bool wrote(F&& write) {
    try {
      write();
      return true;
    } catch (const WriteError& e) {
      write_failed(e.what());
      return false;
    }
  }
  void finish();
  nlohmann::json summary(double wall) const;
  double wall_now() const { return std::chrono::duration<double>(clock::now() - t0_).count(); }
  void log(const std::string& line) { rd_->log(line); }

  Case& c_;
  const RunOptions& opt_;
  Communicator& comm_ = world();  // the processes of a shared run (mpirun), or this one
  CompressibilityEstimate compressibility_;
  std::string compressibility_text_;  // as `check` prints it: to stderr past 1 %, and to log.txt
  std::unique_ptr<Engine> engine_;
  std::string restart_file_, dir_;
  std::vector<std::string> restart_notes_;
  std::unique_ptr<InSituSession> insitu_;
  std::unique_ptr<RunDirectory> rd_;
  std::unique_ptr<ParticleWriter> writer_;
  std::unique_ptr<TwoPhaseMonitor> two_phase_;
  std::unique_ptr<RunSupervision> supervision_;
  std::unique_ptr<DashboardServer> dashboard_;
  PassProfile outputs_;  // the time writing monitors, extracts, figures, checkpoints (app/profile_report.hpp)
  bool extracts_ = false, paused_ = false, stop_ = false, density_warned_ = false;
  double dt_mon_ = 0, dt_vis_ = 0, dt_ext_ = 0;
  OutputClock mon_{1, 0}, ext_{1, 0}, ck_{1, 0}, vis_{1, 0};
  long last_checkpoint_step_ = -1;
  clock::time_point t0_, last_print_;
  std::string status_ = "completed", diagnostic_;
  int code_ = 0;
};

}  // namespace psph
