// poresph run / check / demo: load and check a case, then drive the run and its run directory.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <cstdio>
#include <iostream>
#include <sstream>
#include <thread>

#include "app/commands.hpp"
#include "app/interrupts.hpp"
#include "app/output_clock.hpp"
#include "app/run_supervision.hpp"
#include "dashboard/dashboard_server.hpp"
#include "catalyst/figures.hpp"
#include "catalyst/insitu_session.hpp"
#include "engine/engine.hpp"
#include "io/checkpoint_file.hpp"
#include "io/particle_output.hpp"
#include "io/run_directory.hpp"
#include "monitors/two_phase.hpp"
#include "scene/case_file.hpp"
#include "scene/embedded_cases.hpp"
#include "scene/scene_builder.hpp"

namespace psph {
namespace {


std::string seconds_text(double s) {
  char b[32];
  if (s < 120) std::snprintf(b, sizeof b, "%.0f s", s);
  else if (s < 7200) std::snprintf(b, sizeof b, "%.1f min", s / 60);
  else std::snprintf(b, sizeof b, "%.1f h", s / 3600);
  return b;
}

// Loads a case and builds its particles; prints the error and returns false on bad input.
bool prepare(Case& c, const std::string& path, const std::string* text) {
  try {
    c = text ? load_case_text(*text, path) : load_case_file(path);
    build_particles(c);
    return true;
  } catch (const CaseError& e) {
    std::cerr << "poresph: " << e.what() << "\n";
    return false;
  }
}

int drive(Case& c, const RunOptions& opt) {
  std::unique_ptr<Engine> engine;
  try {
    engine = make_engine(c.scene, opt.backend);
  } catch (const std::exception& e) {
    std::cerr << "poresph: " << e.what() << "\n";
    return 2;
  }
  std::string restart_file;
  if (!opt.restart.empty()) {
    restart_file = std::filesystem::is_directory(opt.restart) ? latest_checkpoint(opt.restart) : opt.restart;
    try {
      if (restart_file.empty()) throw CheckpointError(opt.restart + ": no checkpoint (checkpoints/step_*.ckpt) in this directory");
      engine->restore(read_checkpoint_file(restart_file));
    } catch (const std::exception& e) {
      const std::string msg = e.what();
      std::cerr << "poresph: --restart " << (msg.rfind(restart_file, 0) == 0 ? "" : restart_file + ": ") << msg << "\n";
      return 2;
    }
    if (engine->time() >= c.end_time) {
      std::cerr << "poresph: --restart " << restart_file << ": the checkpoint is at t = " << engine->time()
                << " s, not before the case's time.end = " << c.end_time << " s; raise time.end to continue\n";
      return 2;
    }
  }
  std::unique_ptr<InSituSession> insitu;
  try {
    insitu = std::make_unique<InSituSession>(c, opt.pipelines, opt.live);
  } catch (const std::exception& e) {
    std::cerr << "poresph: " << e.what() << "\n";
    return 2;
  }
  if (opt.serve >= 0 && !dashboard_available()) {
    std::cerr << "poresph: --serve: this poresph was built without the dashboard (cpp-httplib was not found at build time)\n";
    return 2;
  }
  const std::string dir = opt.out.empty() ? default_run_directory(c.name) : opt.out;
  std::unique_ptr<RunDirectory> rd;
  try {
    rd = std::make_unique<RunDirectory>(dir, c.source_text);
  } catch (const std::exception& e) {
    std::cerr << "poresph: " << e.what() << "\n";
    return 2;
  }
  std::ostringstream head;
  head << "poresph run " << c.file << ": case " << c.name << ", " << engine->particles() << " particles, "
       << c.scene.dimension << "D, backend " << engine->backend() << " (" << engine->device() << "), "
       << precision_name() << " precision, end time " << c.end_time << " s";
  rd->log(head.str());
  if (!restart_file.empty())
    rd->log("restarted from " + restart_file + " at t = " + std::to_string(engine->time()) + " s, step " +
            std::to_string(engine->steps()));

  const bool extracts = particle_output_available();
  if (!extracts) rd->log("note: built without ParaView's VTK, no particle extracts are written");
  if (!insitu->note().empty()) rd->log(insitu->note());
  // Extracts hold what the pipelines need, so that `poresph figures` can re-render from them.
  std::vector<std::string> extract_fields = c.output.fields;
  const std::vector<std::string> have = engine->field_names();
  for (const auto& f : insitu->fields())
    if (std::count(extract_fields.begin(), extract_fields.end(), f) == 0 && std::count(have.begin(), have.end(), f))
      extract_fields.push_back(f);
  ParticleWriter writer(rd->extracts(), extract_fields);
  const double t_end = c.end_time;
  double dt_mon = c.output.monitor_interval > 0 ? c.output.monitor_interval : t_end / 100;
  // With pipelines: a frame every visualisation.interval (default a fiftieth of the run), and
  // extracts at the same times unless output.extract_interval says otherwise.
  double dt_vis = c.visualisation.interval > 0 ? c.visualisation.interval : t_end / 50;
  double dt_ext = c.output.extract_interval > 0 ? c.output.extract_interval : insitu->active() ? dt_vis : t_end;
  const double dt_ck = c.output.checkpoint_interval > 0 ? c.output.checkpoint_interval : t_end / 10;
  OutputClock mon(dt_mon, engine->time()), ext(dt_ext, engine->time()), ck(dt_ck, engine->time()), vis(dt_vis, engine->time());
  long last_checkpoint_step = -1;
  auto checkpoint = [&] {
    if (engine->steps() == last_checkpoint_step) return;
    last_checkpoint_step = engine->steps();
    try {
      rd->log("checkpoint " + rd->save_checkpoint(*engine, c.name, c.output.checkpoint_keep));
    } catch (const std::exception& e) {
      rd->log(std::string("warning: no checkpoint: ") + e.what());
    }
  };
  // The stages' monitors as the engine names them, then the two-phase monitors of the run.
  std::unique_ptr<TwoPhaseMonitor> two_phase;
  if (c.two_phase) two_phase = std::make_unique<TwoPhaseMonitor>(c.scene, c.monitor_region);
  auto monitor = [&] {
    std::vector<MonitorValue> row = engine->monitors();
    if (!two_phase) return rd->monitor(*engine, row);
    const bool before = two_phase->percolation_time() >= 0;
    const std::vector<std::string> names = two_phase->columns();
    const std::vector<double> values = two_phase->sample(*engine);
    for (std::size_t k = 0; k < names.size(); ++k) row.push_back({names[k], values[k]});
    rd->monitor(*engine, row);
    if (!before && two_phase->percolation_time() >= 0)
      rd->log("gas percolates (joins the inlet and outlet of the monitor region) at t = " +
              std::to_string(two_phase->percolation_time()) + " s, gas saturation " +
              std::to_string(two_phase->last().saturation_gas));
  };
  using clock = std::chrono::steady_clock;
  const auto t0 = clock::now();  // the wall time includes Catalyst's start-up and first frame
  RunStatus base;
  base.case_name = c.name, base.backend = engine->backend(), base.device = engine->device();
  base.precision = precision_name(), base.dimension = c.scene.dimension, base.particles = engine->particles();
  base.end_time = t_end, base.extracts = extracts, base.pipelines = insitu->active();
  base.monitor_interval = dt_mon, base.extract_interval = dt_ext, base.visualisation_interval = dt_vis;
  RunSupervision supervision(rd->path(), base);
  auto wall_now = [&] { return std::chrono::duration<double>(clock::now() - t0).count(); };
  supervision.report(*engine, "starting", wall_now(), true);
  std::unique_ptr<DashboardServer> dashboard;
  if (opt.serve >= 0) {
    try {
      dashboard = std::make_unique<DashboardServer>(DashboardOptions{rd->path(), "", opt.bind, opt.serve});
    } catch (const std::exception& e) {  // nothing has run: no run directory is left
      std::cerr << "poresph: " << e.what() << "\n";
      rd.reset();
      std::filesystem::remove_all(dir);
      return 2;
    }
    // The token goes to the terminal only: log.txt is served to anyone who can reach the port.
    rd->log("dashboard: " + dashboard->url() + " (to pause, resume or stop: the token in " + rd->path() + "/token)");
    std::cout << "dashboard with control: " << dashboard->url() << "?token=" << supervision.token() << std::endl;
  }
  monitor();
  if (extracts) writer.write(*engine);
  if (insitu->active()) {
    try {
      insitu->start(*engine, c, rd->path(), [&](const std::string& l) { rd->log(l); });
    } catch (const std::exception& e) {
      rd->log(std::string("failed: in-situ visualisation: ") + e.what());
      supervision.finish(*engine, "failed", std::string("in-situ visualisation: ") + e.what(), wall_now());
      return 4;
    }
  }

  // Requests from the dashboard (dashboard/run_control.hpp): pause until resumed, stop, cadence.
  bool paused = false, stop = false;
  auto take_requests = [&] {
    for (const ControlRequest& r : supervision.requests([&](const std::string& l) { rd->log(l); })) {
      using A = ControlRequest::Action;
      if (r.action == A::Pause && !paused) paused = true, rd->log("paused at step " + std::to_string(engine->steps()));
      else if (r.action == A::Resume && paused) paused = false, rd->log("resumed at step " + std::to_string(engine->steps()));
      else if (r.action == A::Stop) stop = true;
      else if (r.action == A::Cadence) {
        const double t = engine->time(), shortest = cadence_floor(engine->last_dt(), t_end);
        bool too_short = false;
        for (double v : {r.monitor_interval, r.extract_interval, r.visualisation_interval}) too_short |= v > 0 && v < shortest;
        if (too_short) {
          rd->log("output cadence: ignored a request for an interval under " + std::to_string(shortest) + " s");
          continue;
        }
        if (r.monitor_interval > 0) dt_mon = r.monitor_interval, mon.set_interval(dt_mon, t);
        if (r.extract_interval > 0) dt_ext = r.extract_interval, ext.set_interval(dt_ext, t);
        if (r.visualisation_interval > 0) dt_vis = r.visualisation_interval, vis.set_interval(dt_vis, t);
        supervision.set_intervals(dt_mon, dt_ext, dt_vis);
        std::ostringstream l;
        l << "output cadence: monitors every " << dt_mon << " s, extracts every " << dt_ext << " s, frames every " << dt_vis << " s";
        rd->log(l.str());
      }
    }
  };

  catch_interrupts();
  auto last_print = t0;
  std::string status = "completed", diagnostic;
  int code = 0;
  try {
    while (engine->time() < t_end) {
      const double t_next = std::min({t_end, mon.next(), ext.next(), insitu->active() ? vis.next() : t_end});
      engine->step(t_next);
      const double t = engine->time();
      if (mon.due(t)) monitor(), mon.pass(t);
      if (ext.due(t)) {
        if (extracts) writer.write(*engine);
        ext.pass(t);
      }
      if (insitu->active() && vis.due(t)) insitu->output(*engine), vis.pass(t);
      if (ck.due(t)) checkpoint(), ck.pass(t);
      const auto now = clock::now();
      const double wall = std::chrono::duration<double>(now - t0).count();
      if (!opt.quiet && (std::chrono::duration<double>(now - last_print).count() > 2.0 || t >= t_end)) {
        last_print = now;
        const double sps = engine->steps() / std::max(wall, 1e-9);
        const double left = (t_end - t) / std::max(t, 1e-300) * wall;
        char line[256];
        std::snprintf(line, sizeof line, "step %ld  t = %.6g s (%.1f %%)  dt = %.3g s  %.1f steps/s  time left %s",
                      engine->steps(), t, 100 * t / t_end, engine->last_dt(), sps, seconds_text(left).c_str());
        rd->log(line);
      }
      take_requests();
      if (paused && !stop) {
        supervision.report(*engine, "paused", wall_now(), true);
        while (paused && !stop && !caught_interrupt()) {
          std::this_thread::sleep_for(std::chrono::milliseconds(50));
          take_requests();
          if (paused) supervision.report(*engine, "paused", wall_now());
        }
      }
      if (!stop && !caught_interrupt()) supervision.report(*engine, "running", wall_now());
      if (stop) {
        status = "stopped";
        rd->log("stopped from the dashboard at t = " + std::to_string(engine->time()) + " s, step " + std::to_string(engine->steps()));
        break;
      }
      if (caught_interrupt()) {
        status = "interrupted";
        code = 130;
        rd->log("interrupted by signal " + std::to_string(caught_interrupt()) + " at t = " + std::to_string(t) + " s");
        break;
      }
    }
  } catch (const InstabilityError& e) {
    status = "unstable";
    code = 3;
    diagnostic = e.what();
    rd->log(std::string("unstable: ") + e.what());
  } catch (const std::exception& e) {
    status = "failed";
    code = 4;
    diagnostic = e.what();
    rd->log(std::string("failed: ") + e.what());
  }
  release_interrupts();
  // An unstable or failed state is not saved: the last good checkpoint stays.
  if (status != "unstable" && status != "failed") {
    monitor();
    checkpoint();
  }
  if (extracts && (status == "interrupted" || status == "stopped")) writer.write(*engine);
  if (insitu->active()) {
    try {
      if (status == "interrupted" || status == "stopped") insitu->output(*engine);  // the state it stopped at, as a last frame
      insitu->finish();
    } catch (const std::exception& e) {
      rd->log(std::string("warning: in-situ visualisation: ") + e.what());
    }
  }

  const double wall = std::chrono::duration<double>(clock::now() - t0).count();
  const double steps = double(engine->steps());
  nlohmann::json j = {{"case", c.name},
                      {"status", status},
                      {"backend", engine->backend()},
                      {"device", engine->device()},
                      {"precision", precision_name()},
                      {"dimension", c.scene.dimension},
                      {"particles", engine->particles()},
                      {"steps", engine->steps()},
                      {"time", engine->time()},
                      {"end_time", t_end},
                      {"wall_seconds", wall},
                      {"particle_steps_per_second", steps * engine->particles() / std::max(wall, 1e-9)}};
  if (two_phase) {
    const TwoPhaseSample& s = two_phase->last();
    const double tp = two_phase->percolation_time();
    j["two_phase"] = {{"percolation_time", tp >= 0 ? nlohmann::json(tp) : nlohmann::json(nullptr)},
                      {"saturation_gas", s.saturation_gas},
                      {"capillary_pressure", s.pressure_gas - s.pressure_liquid}};
  }
  if (insitu->active()) {
    j["insitu"] = insitu->stats(wall);
    rd->log(insitu->report(wall));
  }
  rd->write_summary(j);
  supervision.finish(*engine, status, diagnostic, wall);
  if (dashboard) {
    dashboard->stop();  // after a last look at the run directory: its clients get the final state
    rd->log("dashboard closed; `poresph serve " + rd->path() + "` shows the finished run");
  }
  rd->log("run " + status + " after " + std::to_string(engine->steps()) + " steps in " + seconds_text(wall) +
          "; output in " + rd->path());
  return code;
}

}  // namespace

int cmd_check(const std::string& path) {
  Case c;
  if (!prepare(c, path, nullptr)) return 2;
  try {
    InSituSession pipelines(c, {}, "");  // the case's pipelines exist and declare their fields
  } catch (const std::exception& e) {
    std::cerr << "poresph: " << e.what() << "\n";
    return 2;
  }
  long fluid = 0;
  for (int m : c.scene.material) fluid += c.scene.materials[m].props.kind == MaterialKind::Fluid;
  std::cout << path << ": case " << c.name << " is valid: " << c.scene.count() << " particles (" << fluid
            << " fluid), " << c.scene.dimension << "D, support radius " << c.scene.options.support_radius
            << " m, spacing " << c.scene.options.spacing << " m, end time " << c.end_time << " s\n";
  return 0;
}

int cmd_run(const std::string& path, const RunOptions& opt) {
  Case c;
  if (!prepare(c, path, nullptr)) return 2;
  return drive(c, opt);
}

int cmd_figures(const std::string& run_dir, const std::vector<std::string>& pipelines) {
  return render_figures(run_dir, pipelines, std::cerr);
}

int cmd_demo(const RunOptions& opt) {
  const std::string name = "drainage_2d";
  for (const auto& ec : embedded_cases())
    if (name == ec.name) {
      const std::string text = ec.text;
      Case c;
      if (!prepare(c, "cases/" + name + ".toml (embedded)", &text)) return 2;
      return drive(c, opt);
    }
  std::cerr << "poresph: the embedded demo case is missing from this build\n";
  return 4;
}

}  // namespace psph
