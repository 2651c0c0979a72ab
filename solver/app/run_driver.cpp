#include "app/run_driver.hpp"

#include <algorithm>
#include <cstring>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <sstream>
#include <thread>

#include "app/interrupts.hpp"
#include "app/profile_report.hpp"
#include "core/length_unit.hpp"
#include "image/image_report.hpp"
#include "io/checkpoint_file.hpp"
#include "io/durable_file.hpp"

namespace psph {
namespace {

std::string seconds_text(double s) {
  char b[32];
  if (s < 120) std::snprintf(b, sizeof b, "%.0f s", s);
  else if (s < 7200) std::snprintf(b, sizeof b, "%.1f min", s / 60);
  else std::snprintf(b, sizeof b, "%.1f h", s / 3600);
  return b;
}

// Exit 2 (bad input) or, for a write that failed before the run began, 5.
int refuse(const std::string& what, int code = 2) {
  std::cerr << "poresph: " << what << "\n";
  return code;
}

}  // namespace

int RunDriver::run() {
  if (const int code = agreed(open())) return code;
  try {
    plan_outputs();
  } catch (const std::exception& e) {
    return discard(e.what());
  }
  if (const int code = start()) return code;
  catch_interrupts();
  loop();
  release_interrupts();
  finish();
  return code_;
}

int RunDriver::open() {
  try {
    compressibility_ = estimate_compressibility(c_);
  } catch (const std::exception& e) {
    return refuse(std::string("the compressibility estimate: ") + e.what());
  }
  compressibility_text_ = compressibility_text(compressibility_, c_.file);
  if (compressibility_.exceeds()) std::cerr << compressibility_text_;
  if (c_.compressibility_strict && compressibility_.exceeds())
    return refuse(c_.file + ": solver.compressibility = \"strict\" refuses a case whose estimated density variation passes 1 %");
  try {
    engine_ = make_engine(c_.scene, opt_.backend);
    check_output_fields(c_, engine_->field_names());
  } catch (const std::exception& e) {
    return refuse(e.what());
  }
  if (!opt_.restart.empty()) {
    try {
      const Checkpoint saved = restart_checkpoint();
      engine_->restore(saved);
      if (saved.precision != precision_name())
        restart_notes_.push_back("the checkpoint was written in " + saved.precision + " precision: its real fields converted to " +
                                 precision_name() + " (double to float rounds to nearest; float to double is exact)");
    } catch (const std::exception& e) {
      const std::string msg = e.what();
      return refuse("--restart " + (msg.rfind(restart_file_, 0) == 0 ? "" : restart_file_ + ": ") + msg);
    }
    if (engine_->time() >= c_.end_time) {
      std::ostringstream m;
      m << "--restart " << restart_file_ << ": the checkpoint is at t = " << engine_->time()
        << " s, not before the case's time.end = " << c_.end_time << " s; raise time.end to continue";
      return refuse(m.str());
    }
  }
  try {
    insitu_ = std::make_unique<InSituSession>(c_, opt_.pipelines, opt_.live, comm_);
  } catch (const std::exception& e) {
    return refuse(e.what());
  }
  if (opt_.serve >= 0 && !dashboard_available())
    return refuse("--serve: this poresph was built without the dashboard (cpp-httplib was not found at build time)");
  dir_ = opt_.out.empty() ? default_run_directory(c_.name) : opt_.out;
  if (!root()) {  // another process of a shared run: the first one writes
    rd_ = std::make_unique<RunDirectory>(RunDirectory::follower(dir_, c_.source_text));
    return 0;
  }
  try {
    rd_ = std::make_unique<RunDirectory>(dir_, c_.source_text);
  } catch (const WriteError& e) {
    return refuse(e.what(), 5);
  } catch (const std::exception& e) {
    return refuse(e.what());
  }
  return 0;
}

// A refusal after the run directory was made: nothing has run, so no run directory is left.
int RunDriver::discard(const std::string& what, int code) {
  const bool made = rd_ && rd_->writes();
  rd_.reset();
  std::error_code ec;
  if (made) std::filesystem::remove_all(dir_, ec);
  return refuse(what, code);
}

// A run shared out over processes goes on only if every process can: the largest exit code.
int RunDriver::agreed(int code) {
  return comm_.parallel() ? int(comm_.max(static_cast<long long>(code))) : code;
}

// The checkpoint file given, or a run directory's newest intact one (the newer damaged ones are
// skipped and said so in the log).
Checkpoint RunDriver::restart_checkpoint() {
  restart_file_ = opt_.restart;
  if (!std::filesystem::is_directory(opt_.restart)) return read_checkpoint_file(opt_.restart);
  RestartCheckpoint r = newest_intact_checkpoint(opt_.restart);
  for (const auto& f : r.removed) restart_notes_.push_back("removed " + f + " (a checkpoint write cut short)");
  for (const auto& why : r.skipped) restart_notes_.push_back("skipped a damaged checkpoint: " + why);
  if (r.path.empty())
    throw CheckpointError(opt_.restart + ": no intact checkpoint (checkpoints/step_*.h5 or .ckpt) in this directory" +
                          (r.skipped.empty() ? "" : ": " + r.skipped.front()));
  restart_file_ = r.path;
  return std::move(r.data);
}

void RunDriver::plan_outputs() {
  std::ostringstream head;
  head << "poresph run " << c_.file << ": case " << c_.name << ", " << engine_->particles() << " particles, "
       << c_.scene.dimension << "D, backend " << engine_->backend() << " (" << engine_->device() << "), "
       << precision_name() << " precision, end time " << c_.end_time << " s";
  const LengthUnit unit = engine_length_unit(c_.scene.options.support_radius, c_.scene.dimension);
  if (!unit.si())
    head << "; the engine runs in a length unit of 2^" << unit.exponent << " m = " << unit.metres()
         << " m (core/length_unit.hpp), its outputs in SI";
  log(head.str());
  for (const auto& image : c_.images) {
    const std::string text = image_report_text(image);
    log("image " + text.substr(0, text.size() - 1));  // without its last newline
  }
  std::istringstream estimate(compressibility_text_);
  for (std::string line; std::getline(estimate, line);) log(line);
  for (const auto& note : restart_notes_) log(note);
  if (!restart_file_.empty())
    log("restarted from " + restart_file_ + " at t = " + std::to_string(engine_->time()) + " s, step " +
        std::to_string(engine_->steps()));
  extracts_ = particle_output_available();
  if (!extracts_) log("note: built without ParaView's VTK, no particle extracts are written");
  if (!insitu_->note().empty()) log(insitu_->note());
  // Extracts hold what the pipelines need, so that `poresph figures` can re-render from them.
  std::vector<std::string> fields = c_.output.fields;
  const std::vector<std::string> have = engine_->field_names();
  for (const auto& f : insitu_->fields())
    if (std::count(fields.begin(), fields.end(), f) == 0 && std::count(have.begin(), have.end(), f)) fields.push_back(f);
  writer_ = std::make_unique<ParticleWriter>(rd_->extracts(), fields, comm_, c_.output.extract_format);
  const double t_end = c_.end_time, t = engine_->time();
  dt_mon_ = c_.output.monitor_interval > 0 ? c_.output.monitor_interval : t_end / 100;
  // With pipelines: a frame every visualisation.interval (default a fiftieth of the run), and
  // extracts at the same times unless output.extract_interval says otherwise.
  dt_vis_ = c_.visualisation.interval > 0 ? c_.visualisation.interval : t_end / 50;
  dt_ext_ = c_.output.extract_interval > 0 ? c_.output.extract_interval : insitu_->active() ? dt_vis_ : t_end;
  const double dt_ck = c_.output.checkpoint_interval > 0 ? c_.output.checkpoint_interval : t_end / 10;
  mon_ = OutputClock(dt_mon_, t), ext_ = OutputClock(dt_ext_, t), ck_ = OutputClock(dt_ck, t), vis_ = OutputClock(dt_vis_, t);
  if (c_.two_phase) two_phase_ = std::make_unique<TwoPhaseMonitor>(c_.scene, c_.monitor_region, c_.stress_scale);
}

int RunDriver::start() {
  t0_ = last_print_ = clock::now();  // the wall time includes Catalyst's start-up and first frame
  RunStatus base;
  base.case_name = c_.name, base.backend = engine_->backend(), base.device = engine_->device();
  base.precision = precision_name(), base.dimension = c_.scene.dimension, base.particles = engine_->particles();
  base.end_time = c_.end_time, base.extracts = extracts_, base.pipelines = insitu_->active();
  base.monitor_interval = dt_mon_, base.extract_interval = dt_ext_, base.visualisation_interval = dt_vis_;
  if (const int code = agreed(root() ? supervise(base) : 0)) return code;
  // Both made (the extract is written by every process together), then a failure of one process
  // alone (monitors.csv, on the first) ends every process: the others would wait for it.
  const bool monitored = wrote([&] { monitor(); });
  const bool extracted = wrote([&] {
    if (extracts_) writer_->write(*engine_);
  });
  const bool first_outputs = monitored && extracted;
  if (!first_outputs) stop_every_process();
  if (!first_outputs || !insitu_->active()) return 0;  // a failed write: the loop does not start
  try {
    insitu_->start(*engine_, c_, rd_->path(), [&](const std::string& l) { log(l); });
  } catch (const std::exception& e) {
    log(std::string("failed: in-situ visualisation: ") + e.what());
    status_ = "failed", code_ = 4, diagnostic_ = std::string("in-situ visualisation: ") + e.what();
    stop_every_process();  // over several processes the others may wait for this one inside Catalyst
    supervision_->finish(*engine_, status_, diagnostic_, wall_now());
    return 4;
  }
  return 0;
}

// The status file, the dashboard and its token (the first process of a shared run only): 0 or the
// exit code of a refusal.
int RunDriver::supervise(const RunStatus& base) {
  try {
    supervision_ = std::make_unique<RunSupervision>(rd_->path(), base);
    supervision_->report(*engine_, "starting", wall_now(), true);
  } catch (const std::exception& e) {  // the token or status.json: the disk is full or read-only
    return discard(e.what(), 5);
  }
  if (opt_.serve >= 0) {
    try {
      dashboard_ = std::make_unique<DashboardServer>(DashboardOptions{rd_->path(), "", opt_.bind, opt_.serve});
    } catch (const std::exception& e) {
      return discard(e.what());
    }
    // The token goes to the terminal only: log.txt is served to anyone who can reach the port.
    log("dashboard: " + dashboard_->url() + " (to pause, resume or stop: the token in " + rd_->path() + "/token)");
    std::cout << "dashboard with control: " << dashboard_->url() << "?token=" << supervision_->token() << std::endl;
  }
  return 0;
}

void RunDriver::loop() {
  if (code_) return;
  try {
    while (engine_->time() < c_.end_time) {
      const double t_end = c_.end_time;
      engine_->step(std::min({t_end, mon_.next(), ext_.next(), insitu_->active() ? vis_.next() : t_end}));
      outputs_due();
      watch_density();
      progress_line();
      if (!rd_->write_failure().empty()) throw WriteError(rd_->write_failure());
      if (controls()) break;
    }
  } catch (const InstabilityError& e) {
    status_ = "unstable", code_ = 3, diagnostic_ = e.what();
    log(std::string("unstable: ") + e.what());
  } catch (const WriteError& e) {
    write_failed(e.what());
    stop_every_process();
  } catch (const std::exception& e) {
    status_ = "failed", code_ = 4, diagnostic_ = e.what();
    log(std::string("failed: ") + e.what());
    stop_every_process();
  }
}

// A failure of one process of a shared run (its writes, its memory) ends every process, with its
// message and its number; an instability is found by every process at once and ends normally.
void RunDriver::stop_every_process() {
  if (!comm_.parallel()) return;
  std::fprintf(stderr, "poresph: process %d of %d: %s\n", comm_.rank(), comm_.size(), diagnostic_.c_str());
  if (supervision_) supervision_->finish(*engine_, status_, diagnostic_, wall_now());
  comm_.abort(code_);
}

void RunDriver::outputs_due() {
  static const std::string monitors = "monitors", extracts = "extracts", figures = "in-situ figures",
                           checkpoints = "checkpoints";
  const ProfileRecording recording(outputs_);
  const StageScope scope("output");
  const double t = engine_->time();
  if (mon_.due(t)) {
    const HostPassClock clock(monitors);
    monitor(), mon_.pass(t);
  }
  if (ext_.due(t)) {
    const HostPassClock clock(extracts);
    if (extracts_) writer_->write(*engine_);
    ext_.pass(t);
  }
  if (insitu_->active() && vis_.due(t)) {
    const HostPassClock clock(figures);
    insitu_->output(*engine_), vis_.pass(t);
  }
  if (ck_.due(t)) {
    const HostPassClock clock(checkpoints);
    checkpoint(), ck_.pass(t);
  }
}

void RunDriver::progress_line() {
  const auto now = clock::now();
  const double t = engine_->time(), t_end = c_.end_time;
  if (opt_.quiet || !(std::chrono::duration<double>(now - last_print_).count() > 2.0 || t >= t_end)) return;
  last_print_ = now;
  const double wall = std::chrono::duration<double>(now - t0_).count();
  const double sps = engine_->steps() / std::max(wall, 1e-9);
  const double left = (t_end - t) / std::max(t, 1e-300) * wall;
  char line[256];
  std::snprintf(line, sizeof line, "step %ld  t = %.6g s (%.1f %%)  dt = %.3g s  %.1f steps/s  time left %s",
                engine_->steps(), t, 100 * t / t_end, engine_->last_dt(), sps, seconds_text(left).c_str());
  log(line);
}

void RunDriver::watch_density() {
  const DensityWatch& w = engine_->density_watch();
  if (density_warned_ || !w.exceeded()) return;
  density_warned_ = true;
  std::ostringstream m;
  m.precision(3);
  m << "the fluid's density is " << 100 * w.first.value << " % off its reference, past solver.max_density_deviation = "
    << 100 * w.bound << " %, at t = " << w.first.time << " s, step " << w.first.step << w.first.where
    << ": the flow is no longer weakly compressible; raise the sound speed or lower the drive (poresph check estimates both)";
  log("warning: " + m.str());
  if (!supervision_) return;
  supervision_->warn(m.str());
  supervision_->report(*engine_, "running", wall_now(), true);
}

// The first process decides (the dashboard, signals) and tells the others, with the output
// cadence, so that every process of a shared run leaves at the same step.
bool RunDriver::controls() {
  const bool leave = root() ? decide() : false;
  if (!comm_.parallel()) return leave;
  struct Decision {
    int leave, code, stopped;
    double monitor, extract, visualisation;
  } d{leave, code_, status_ == "stopped", dt_mon_, dt_ext_, dt_vis_};
  Bytes b(sizeof d);
  std::memcpy(b.data(), &d, sizeof d);
  comm_.broadcast(b, 0);
  std::memcpy(&d, b.data(), sizeof d);
  if (root()) return leave;
  const double t = engine_->time();
  if (d.monitor != dt_mon_) dt_mon_ = d.monitor, mon_.set_interval(dt_mon_, t);
  if (d.extract != dt_ext_) dt_ext_ = d.extract, ext_.set_interval(dt_ext_, t);
  if (d.visualisation != dt_vis_) dt_vis_ = d.visualisation, vis_.set_interval(dt_vis_, t);
  if (d.leave) code_ = d.code, status_ = d.stopped ? "stopped" : "interrupted";
  return d.leave != 0;
}

bool RunDriver::decide() {
  take_requests();
  if (paused_ && !stop_) {
    supervision_->report(*engine_, "paused", wall_now(), true);
    while (paused_ && !stop_ && !caught_interrupt()) {
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
      take_requests();
      if (paused_) supervision_->report(*engine_, "paused", wall_now());
    }
  }
  if (!stop_ && !caught_interrupt()) supervision_->report(*engine_, "running", wall_now());
  const std::string when = " at t = " + std::to_string(engine_->time()) + " s";
  if (stop_) {
    status_ = "stopped";
    log("stopped from the dashboard" + when + ", step " + std::to_string(engine_->steps()));
    return true;
  }
  if (caught_interrupt()) {
    status_ = "interrupted", code_ = 130;
    log("interrupted by signal " + std::to_string(caught_interrupt()) + when);
    return true;
  }
  return false;
}

// Requests from the dashboard (dashboard/run_control.hpp): pause until resumed, stop, cadence.
void RunDriver::take_requests() {
  for (const ControlRequest& r : supervision_->requests([&](const std::string& l) { log(l); })) {
    using A = ControlRequest::Action;
    const std::string at = " at step " + std::to_string(engine_->steps());
    if (r.action == A::Pause && !paused_) paused_ = true, log("paused" + at);
    else if (r.action == A::Resume && paused_) paused_ = false, log("resumed" + at);
    else if (r.action == A::Stop) stop_ = true;
    if (r.action != A::Cadence) continue;
    const double t = engine_->time();
    const std::string why = cadence_problem(r, engine_->last_dt(), c_.end_time);
    if (!why.empty()) {
      log("output cadence: ignored a request: " + why);
      continue;
    }
    if (r.monitor_interval > 0) dt_mon_ = r.monitor_interval, mon_.set_interval(dt_mon_, t);
    if (r.extract_interval > 0) dt_ext_ = r.extract_interval, ext_.set_interval(dt_ext_, t);
    if (r.visualisation_interval > 0) dt_vis_ = r.visualisation_interval, vis_.set_interval(dt_vis_, t);
    supervision_->set_intervals(dt_mon_, dt_ext_, dt_vis_);
    std::ostringstream l;
    l << "output cadence: monitors every " << dt_mon_ << " s, extracts every " << dt_ext_ << " s, frames every " << dt_vis_ << " s";
    log(l.str());
  }
}

// The stages' monitors as the engine names them, the pressure probes, then the two-phase monitors.
void RunDriver::monitor() {
  std::vector<MonitorValue> row = engine_->monitors();
  if (!c_.probes.empty()) {
    const std::vector<std::string> names = probe_columns(c_.probes);
    const std::vector<double> values = sample_probes(*engine_, c_.scene, c_.probes);
    for (std::size_t k = 0; k < names.size(); ++k) row.push_back({names[k], values[k], "Pa"});
  }
  if (!two_phase_) return rd_->monitor(*engine_, row);
  const bool before = two_phase_->percolation_time() >= 0;
  const std::vector<std::string> names = two_phase_->columns();
  const std::vector<double> values = two_phase_->sample(*engine_);
  for (std::size_t k = 0; k < names.size(); ++k) row.push_back({names[k], values[k], "SI"});  // measured in SI
  rd_->monitor(*engine_, row);
  if (before || two_phase_->percolation_time() < 0) return;
  log("gas percolates (joins the inlet and outlet of the monitor region) at t = " +
      std::to_string(two_phase_->percolation_time()) + " s, gas saturation " +
      std::to_string(two_phase_->last().saturation_gas));
  if (c_.after_percolation < 0) return;
  c_.end_time = std::min(c_.end_time, std::max(engine_->time(), two_phase_->percolation_time() + c_.after_percolation));
  if (supervision_) supervision_->set_end_time(c_.end_time);
  log("the run ends at t = " + std::to_string(c_.end_time) + " s (time.after_percolation)");
}

void RunDriver::checkpoint() {
  if (engine_->steps() == last_checkpoint_step_) return;
  last_checkpoint_step_ = engine_->steps();
  const std::string file = rd_->save_checkpoint(*engine_, c_.name, c_.output.checkpoint_keep, comm_);
  log("checkpoint " + file);
}

// A record or checkpoint that could not be written ends the run (exit 5): its newest checkpoint
// on disk is intact, the outputs after it are not all there.
void RunDriver::write_failed(const std::string& what) {
  status_ = "write_failed", code_ = 5, diagnostic_ = what;
  log("write failed: " + what);
  std::cerr << "poresph: write failed: " << what << "\n";
}

void RunDriver::finish() {
  // An unstable or failed state is not saved: the last good checkpoint stays.
  const bool cut_short = status_ == "interrupted" || status_ == "stopped";
  // One write each: a failed one does not skip the others, which every process of a shared run makes.
  const bool saved = code_ == 0 || code_ == 130;
  if (saved) wrote([&] { monitor(); }), wrote([&] { checkpoint(); });
  if (extracts_ && cut_short) wrote([&] { writer_->write(*engine_); });
  if (insitu_->active()) {
    try {
      if (cut_short) insitu_->output(*engine_);  // the state it stopped at, as a last frame
      insitu_->finish();
    } catch (const std::exception& e) {
      // The render thread's error (a pipeline script that raised) fails a run that asked for figures.
      if (code_ == 0) status_ = "failed", code_ = 4, diagnostic_ = std::string("in-situ visualisation: ") + e.what();
      log(std::string(code_ == 4 ? "failed" : "warning") + ": in-situ visualisation: " + e.what());
    }
  }
  const double wall = wall_now();
  nlohmann::json j = summary(wall);
  if (insitu_->active()) {
    j["insitu"] = insitu_->stats(wall);
    log(insitu_->report(wall));
  }
  j["profile"] = profile_json(engine_->profile(), outputs_, wall);
  for (const std::string& l : profile_lines(engine_->profile(), outputs_, wall, 8)) log(l);
  wrote([&] { rd_->write_summary(j); });
  if (supervision_) wrote([&] { supervision_->finish(*engine_, status_, diagnostic_, wall); });
  if (dashboard_) {
    dashboard_->stop();  // after a last look at the run directory: its clients get the final state
    log("dashboard closed; `poresph serve " + rd_->path() + "` shows the finished run");
  }
  log("run " + status_ + " after " + std::to_string(engine_->steps()) + " steps in " + seconds_text(wall) +
      "; output in " + rd_->path());
}

nlohmann::json RunDriver::summary(double wall) const {
  const double steps = double(engine_->steps());
  nlohmann::json j = {{"case", c_.name},
                      {"status", status_},
                      {"backend", engine_->backend()},
                      {"device", engine_->device()},
                      {"precision", precision_name()},
                      {"dimension", c_.scene.dimension},
                      {"particles", engine_->particles()},
                      {"steps", engine_->steps()},
                      {"time", engine_->time()},
                      {"end_time", c_.end_time},
                      {"wall_seconds", wall},
                      {"particle_steps_per_second", steps * engine_->particles() / std::max(wall, 1e-9)}};
  const DensityWatch& w = engine_->density_watch();
  nlohmann::json first = nullptr;
  if (w.exceeded())
    first = {{"time", w.first.time}, {"step", w.first.step}, {"value", w.first.value}, {"particle", w.first.where}};
  const SharingStats sh = engine_->sharing();
  if (sh.processes > 1)
    j["processes"] = {{"count", sh.processes}, {"rebalances", sh.rebalances}, {"imbalance", sh.imbalance},
                      {"halo_particles", sh.halo_particles}, {"halo_bytes", sh.halo_bytes},
                      {"halo_refreshes", sh.refreshes}};
  if (sh.processes > 1) {
    nlohmann::json costs;  // seconds a particle-step where measured, else the static weights
    for (int c = 0; c < kCostClasses; ++c) costs[cost_class_name(c)] = sh.class_costs.per_particle[c];
    j["processes"]["class_costs"] = costs;
    j["processes"]["class_costs_measured"] = sh.class_costs.measured;
  }
  j["compressibility"] = to_json(compressibility_);
  j["density_deviation"] = {{"bound", w.bound}, {"max", w.peak}, {"max_time", w.peak_time},
                            {"max_step", w.peak_step}, {"first_exceeded", first}};
  if (!c_.images.empty()) j["images"] = c_.images;
  if (c_.stress_scale > 0) j["stress_scale"] = c_.stress_scale;  // physical per case units ([case])
  j["length_scale"] = c_.length_scale;
  if (two_phase_) {
    const TwoPhaseSample& s = two_phase_->last();
    const double tp = two_phase_->percolation_time();
    const double sp = two_phase_->saturation_at_percolation();
    j["two_phase"] = {{"percolation_time", tp >= 0 ? nlohmann::json(tp) : nlohmann::json(nullptr)},
                      {"saturation_gas_at_percolation", tp >= 0 ? nlohmann::json(sp) : nlohmann::json(nullptr)},
                      {"saturation_gas", s.saturation_gas},
                      {"porosity", s.porosity},
                      {"capillary_pressure", s.pressure_gas - s.pressure_liquid},
                      {"flow_axis", std::string(1, "xyz"[c_.monitor_region.flow_axis])}};
  }
  return j;
}

}  // namespace psph
