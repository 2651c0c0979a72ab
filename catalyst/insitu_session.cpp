#include "catalyst/insitu_session.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include "io/field_staging.hpp"
#include "catalyst/vis_settings.hpp"

namespace fs = std::filesystem;

namespace psph {
namespace {

constexpr double kCpuRenderShare = 0.05;

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

InSituSession::InSituSession(const Case& c, const std::vector<std::string>& cli, const std::string& live,
                             Communicator& comm)
    : comm_(comm), live_(live), every_frame_(c.visualisation.every_frame || comm.parallel()) {
  std::vector<std::string> names = c.visualisation.pipelines;
  names.insert(names.end(), cli.begin(), cli.end());
  if (names.empty() && !live.empty()) names.push_back("live");
  if (!live.empty() && live.find(':') == std::string::npos)
    throw std::invalid_argument("--live " + live + ": expected HOST:PORT (ParaView's Catalyst > Connect, default port 22222)");
  for (const std::string& n : names) {
    const bool from_case = std::find(cli.begin(), cli.end(), n) == cli.end();
    const PipelineScript s = find_pipeline(n, from_case ? c.file + ": visualisation.pipelines: " + n : "");
    if (std::any_of(scripts_.begin(), scripts_.end(), [&](const PipelineScript& p) { return p.path == s.path; })) continue;
    for (const auto& f : s.fields)
      if (std::find(fields_.begin(), fields_.end(), f) == fields_.end()) fields_.push_back(f);
    scripts_.push_back(s);
  }
  if (!scripts_.empty() && !insitu_available()) {
    // Asked for on the command line: an error. Only in the case file: the run goes on without.
    if (!cli.empty() || !live.empty()) make_insitu({});  // throws InSituUnavailable with the reason
    scripts_.clear(), fields_.clear();
    note_ = "note: this poresph was built without ParaView Catalyst; the case's visualisation.pipelines are skipped";
  }
}

InSituSession::~InSituSession() = default;

std::vector<std::string> InSituSession::stage(Engine& e, bool piece) {
  const auto t0 = std::chrono::steady_clock::now();
  std::vector<std::string> missing = stage_frame(e, fields_, frame_, piece);
  if (piece) agree_components(frame_, comm_);
  staging_s_ += seconds_since(t0);
  return missing;
}

void InSituSession::hand_over(Engine& e) {
  render_->submit(frame_, e.steps(), e.time());
  last_step_ = e.steps();
}

void InSituSession::rendered(long frame, long step, double time, double seconds) {
  if (frame == 0) first_frame_s_ = seconds;
  coprocess_s_ += seconds;
  frames_ = frame + 1;
  // The frame's images are written: say so to the dashboard (dashboard/run_watcher.hpp).
  if (frames_csv_.is_open()) frames_csv_ << frame << ',' << step << ',' << time << '\n' << std::flush;
}

void InSituSession::start(Engine& e, const Case& c, const std::string& run_dir,
                          const std::function<void(const std::string&)>& log) {
  // The settings from the whole first frame (the same on every process); the first process writes them.
  for (const auto& m : stage(e, false)) log("note: no field '" + m + "' in this case (its physics is not active); pipelines go without it");
  const fs::path run = fs::absolute(run_dir);
  nlohmann::json settings = resolve_vis_settings(c, frame_, (run / "images").string(), (run / "extracts").string(), live_);
  std::vector<std::string> paths;
  for (const auto& s : scripts_) paths.push_back(s.path);
  settings["pipelines"] = paths;
  const fs::path file = run / "images" / "visualisation.json";
  if (comm_.rank() == 0) {
    fs::create_directories(run / "images");
    frames_csv_.open(run / "images" / "frames.csv");
    frames_csv_.precision(10);
    frames_csv_ << "frame,step,time\n";
    std::ofstream(file) << settings.dump(2) << "\n";
  }
  comm_.barrier();  // written before any process's pipelines read it
  if (comm_.parallel()) {
    render_comm_ = comm_.duplicate_for_thread();
    if (!render_comm_)
      throw std::runtime_error("in-situ pipelines over several processes need an MPI that allows calls from several "
                               "threads (MPI_THREAD_MULTIPLE); run without them and render the extracts with poresph figures");
    stage(e, true);
  }
  const auto t0 = std::chrono::steady_clock::now();
  const InSituConfig config{paths, file.string(), live_, render_comm_.get()};
  // On the CPU backend the renderer shares the solver's cores: a twentieth of the wall time at most.
  const double share = e.backend() == "cpu" ? kCpuRenderShare : 1.0;
  render_ = std::make_unique<RenderThread>([config] { return make_insitu(config); }, every_frame_, share,
                                           [this](long f, long s, double t, double sec) { rendered(f, s, t, sec); });
  startup_s_ = seconds_since(t0);
  std::string names;
  for (const auto& s : scripts_) names += (names.empty() ? "" : ", ") + s.name;
  log("pipelines: " + names + " (" + render_->note() + "; rendered on a thread of their own, " +
      (every_frame_ ? "every frame" : "a frame the renderer has no time for is dropped") + ")");
  if (!live_.empty()) log("ParaView Live: connecting to " + live_ + " at each output step; the run carries on without it");
  hand_over(e);
}

void InSituSession::output(Engine& e) {
  if (!render_ || e.steps() == last_step_) return;
  stage(e, comm_.parallel());
  hand_over(e);
}

void InSituSession::finish() {
  if (render_) render_->finish();
}

nlohmann::json InSituSession::stats(double wall) const {
  const double waited = render_ ? render_->waited_seconds() : 0, drained = render_ ? render_->drained_seconds() : 0;
  return {{"frames", frames_},
          {"dropped_frames", render_ ? render_->dropped() : 0},
          {"every_frame", every_frame_},
          {"startup_seconds", startup_s_},
          {"first_frame_seconds", first_frame_s_},
          {"staging_seconds", staging_s_},
          {"coprocess_seconds", coprocess_s_},
          {"waiting_seconds", waited},
          {"drain_seconds", drained},
          {"share_of_wall_time", (startup_s_ + staging_s_ + waited + drained) / std::max(wall, 1e-9)}};
}

std::string InSituSession::report(double wall) const {
  const double later = frames_ > 1 ? (coprocess_s_ - first_frame_s_) / double(frames_ - 1) : 0;
  const long dropped = render_ ? render_->dropped() : 0;
  char line[400];
  std::snprintf(line, sizeof line,
                "in situ: %ld frames rendered, %ld dropped; start-up %.3g s, first frame %.3g s, then %.3g s per "
                "frame on the render thread; staging %.3g ms per frame; the solver's share %.1f %% of the wall time",
                frames_, dropped, startup_s_, first_frame_s_, later,
                1e3 * staging_s_ / std::max<long>(frames_ + dropped, 1), 100 * stats(wall)["share_of_wall_time"].get<double>());
  return line;
}

}  // namespace psph
