#pragma once
// poresph figures RUNDIR: re-renders a run's figure sequences from its saved particle extracts
// with ParaView's batch mode (pvbatch), through the same pipeline scripts and settings
// (images/visualisation.json) as the run, and assembles an MP4 per view when ffmpeg is installed.
#include <ostream>
#include <string>
#include <vector>

namespace psph {

// `pipelines`: names or paths; empty = the run's own. Returns an exit code (0 done, 2 bad input,
// 4 failure); messages go to `log`.
int render_figures(const std::string& run_dir, const std::vector<std::string>& pipelines, std::ostream& log);

}  // namespace psph
