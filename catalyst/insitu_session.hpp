#pragma once
// The solver's side of in-situ visualisation for one run: which pipelines (case file and command
// line), which fields they need, and on each output step the staging of exactly those fields
// and the hand-over to the render thread (catalyst/render_thread.hpp), timed.
#include <fstream>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "catalyst/insitu.hpp"
#include "catalyst/pipeline_scripts.hpp"
#include "catalyst/render_thread.hpp"
#include "engine/engine.hpp"
#include "parallel/communicator.hpp"
#include "scene/case_file.hpp"

namespace psph {

class InSituSession {
 public:
  // Resolves the pipelines of the case and of --pipeline, and --live (which alone uses the
  // `live` pipeline). Throws std::invalid_argument or InSituUnavailable, before anything is written.
  // Over several processes (`comm`) every process renders its piece of every frame together with
  // the others (no frame is dropped: every process must draw the same ones).
  InSituSession(const Case& c, const std::vector<std::string>& cli_pipelines, const std::string& live_url,
                Communicator& comm);
  ~InSituSession();
  bool active() const { return !scripts_.empty(); }
  // Fields the pipelines declared (their union).
  const std::vector<std::string>& fields() const { return fields_; }
  // A line for the log when the case's pipelines are skipped (a build without Catalyst).
  const std::string& note() const { return note_; }

  // First output step: resolves the settings from this frame, writes images/visualisation.json,
  // starts Catalyst on the render thread (its start-up errors are thrown here) and hands it frame 0.
  void start(Engine& e, const Case& c, const std::string& run_dir, const std::function<void(const std::string&)>& log);
  // A later output step: staged here, rendered on the render thread. Throws the renderer's error.
  void output(Engine& e);
  // Waits for the frames handed over to be rendered; throws the renderer's error.
  void finish();
  long last_step() const { return last_step_; }
  // Frames rendered and dropped; seconds spent starting Catalyst (display, Python, pipeline
  // scripts), in the first CoProcess (builds the pipelines) and in all of them (on the render
  // thread), staging, waiting for room (every_frame) and, at the end, for the frames left (the
  // solver's); the solver's share of `wall`.
  nlohmann::json stats(double wall) const;
  std::string report(double wall) const;  // the same in one log line

 private:
  // Timed; returns the fields the engine lacks. `piece`: this process's slice of the particles.
  std::vector<std::string> stage(Engine& e, bool piece);
  void hand_over(Engine& e);                  // the staged frame to the render thread
  void rendered(long frame, long step, double time, double seconds);  // on the render thread

  Communicator& comm_;
  std::shared_ptr<void> render_comm_;  // the render thread's MPI communicator (several processes)
  std::vector<PipelineScript> scripts_;
  std::vector<std::string> fields_;
  std::string live_, note_;
  bool every_frame_ = false;  // [visualisation] every_frame: wait for the renderer, drop nothing
  std::ofstream frames_csv_;  // images/frames.csv: frame, step, time of each frame handed over
  ParticleFrame frame_;
  long frames_ = 0, last_step_ = -1;  // frames_: rendered (written by the render thread)
  double startup_s_ = 0, first_frame_s_ = 0, staging_s_ = 0, coprocess_s_ = 0;
  std::unique_ptr<RenderThread> render_;  // last: joined before the members its callback writes go
};

}  // namespace psph
