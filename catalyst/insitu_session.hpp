#pragma once
// The solver's side of in-situ visualisation for one run: which pipelines (case file and command
// line), which fields they need, and on each output step the staging of exactly those fields
// and the hand-over to Catalyst, timed.
#include <fstream>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "catalyst/insitu.hpp"
#include "catalyst/pipeline_scripts.hpp"
#include "engine/engine.hpp"
#include "scene/case_file.hpp"

namespace psph {

class InSituSession {
 public:
  // Resolves the pipelines of the case and of --pipeline, and --live (which alone uses the
  // `live` pipeline). Throws std::invalid_argument or InSituUnavailable, before anything is written.
  InSituSession(const Case& c, const std::vector<std::string>& cli_pipelines, const std::string& live_url);
  ~InSituSession();
  bool active() const { return !scripts_.empty(); }
  // Fields the pipelines declared (their union).
  const std::vector<std::string>& fields() const { return fields_; }
  // A line for the log when the case's pipelines are skipped (a build without Catalyst).
  const std::string& note() const { return note_; }

  // First output step: resolves the settings from this frame, writes images/visualisation.json,
  // starts Catalyst and hands it frame 0.
  void start(Engine& e, const Case& c, const std::string& run_dir, const std::function<void(const std::string&)>& log);
  // A later output step.
  void output(Engine& e);
  void finish();
  long last_step() const { return last_step_; }
  // Frames; seconds spent starting Catalyst (display, Python, pipeline scripts), in the first
  // CoProcess (builds the pipelines), in all CoProcess calls and staging; their share of `wall`.
  nlohmann::json stats(double wall) const;
  std::string report(double wall) const;  // the same in one log line

 private:
  std::vector<std::string> stage(Engine& e);  // timed; returns the fields the engine lacks
  void hand_over(Engine& e);                  // timed execute of the staged frame

  std::vector<PipelineScript> scripts_;
  std::vector<std::string> fields_;
  std::string live_, note_;
  std::unique_ptr<InSitu> insitu_;
  std::ofstream frames_csv_;  // images/frames.csv: frame, step, time of each frame handed over
  ParticleFrame frame_;
  long frames_ = 0, last_step_ = -1;
  double startup_s_ = 0, first_frame_s_ = 0, staging_s_ = 0, coprocess_s_ = 0;
};

}  // namespace psph
