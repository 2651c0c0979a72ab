// poresph report RUNDIR...: the curves of a run's monitors.csv (or of several runs together) as PNG
// plots, drawn by pipelines/report_plots.py with matplotlib (app/commands.hpp).
#include <cstdlib>
#include <filesystem>
#include <iostream>

#include "app/commands.hpp"
#include "catalyst/pipeline_scripts.hpp"
#include "catalyst/run_program.hpp"

namespace psph {

int cmd_report(const std::vector<std::string>& run_dirs, const std::string& out) {
  namespace fs = std::filesystem;
  for (const std::string& d : run_dirs)
    if (!fs::is_regular_file(fs::path(d) / "monitors.csv")) {
      std::cerr << "poresph report: " << d << ": expected a run directory (no monitors.csv there)\n";
      return 2;
    }
  if (run_dirs.size() > 1 && out.empty()) {
    std::cerr << "poresph report: --out: expected a folder for the plots of several runs\n";
    return 2;
  }
  const std::string dir = out.empty() ? (fs::path(run_dirs[0]) / "report").string() : out;
  // PORESPH_PYTHON, else Debian's own (where python3-matplotlib installs), else the PATH's.
  std::string python = fs::exists("/usr/bin/python3") ? "/usr/bin/python3" : "python3";
  if (const char* env = std::getenv("PORESPH_PYTHON"); env && *env) python = env;
  std::vector<std::string> cmd{python, (fs::path(pipeline_directory()) / "report_plots.py").string(), dir};
  cmd.insert(cmd.end(), run_dirs.begin(), run_dirs.end());
  const int rc = run_program(cmd);
  if (rc == 127) std::cerr << "poresph report: python3 not found (apt-get install python3-matplotlib)\n";
  return rc == 0 ? 0 : rc == 2 ? 2 : 4;
}

}  // namespace psph
