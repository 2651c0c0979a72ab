#pragma once
// The subcommands of the poresph command line (GUIDE §5).
#include <string>
#include <vector>

namespace psph {

struct RunOptions {
  std::string backend = "cpu";
  std::string out;  // run directory; empty = runs/<case>-<timestamp>
  bool quiet = false;
  std::string restart;  // checkpoint file, or a run directory (its newest checkpoint)
  std::vector<std::string> pipelines;  // Catalyst pipelines (names in pipelines/ or .py paths)
  std::string live;                    // HOST:PORT of a ParaView GUI for Catalyst Live
  int serve = -1;                      // dashboard port (0: any free one); -1: no dashboard
  std::string bind = "127.0.0.1";      // the dashboard's address
  std::vector<std::string> sets;       // "KEY=VALUE" and "!KEY" (--set, --unset; scene/case_file.hpp), in order
};

// Exit codes: 0 done, 2 bad input (nothing written), 3 unstable run (diagnostic in log.txt),
// 4 runtime failure, 5 an output could not be written (disk full), 130 interrupted.
int cmd_run(const std::string& case_path, const RunOptions& opt);
int cmd_demo(const RunOptions& opt);
int cmd_check(const std::string& case_path, const std::vector<std::string>& sets = {}, bool json = false);
// Re-renders a run's figure sequences from its extracts (`pipelines` empty = the run's own).
int cmd_figures(const std::string& run_dir, const std::vector<std::string>& pipelines);
// Serves the dashboard of a run directory (finished, or still running in another process) until
// interrupted.
int cmd_serve(const std::string& run_dir, int port, const std::string& bind);
// Plots of one run's monitors, or of several together (`out` then required; default RUNDIR/report):
// saturations, phase and capillary pressures, Pc against S_w, the percolation times. Exit 2 on a
// folder that is no run directory, 4 when the plots fail (matplotlib missing).
int cmd_report(const std::vector<std::string>& run_dirs, const std::string& out);
int cmd_validate(const std::vector<std::string>& names, bool full, bool json, const std::string& backend);
// One line per validation case: its name, a tab, its description (the CTest validation tests are
// generated from it: tests/list_validations.cmake).
int cmd_validate_list();
// `names`: benchmarks to run (default all); an unknown name is exit 2. `profile`: each benchmark's
// time by stage and pass too (app/profile_report.hpp).
int cmd_bench(const std::vector<std::string>& names, bool json, const std::string& backend, bool quick,
              bool accuracy, bool stability, bool profile, bool decomposition = false);

}  // namespace psph
