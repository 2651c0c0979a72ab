// poresph command line: run, check, validate, bench, demo, figures, report, serve, image.
#include <CLI/CLI.hpp>
#include <iostream>
#include <vector>

#include "app/bench_cases.hpp"
#include "app/cmd_image.hpp"
#include "app/commands.hpp"
#include "app/last_resort.hpp"
#include "parallel/communicator.hpp"

namespace {

// --set KEY=VALUE and --unset KEY, kept in the order given (scene/case_file.hpp: "!KEY" unsets).
void add_case_overrides(CLI::App* cmd, std::vector<std::string>& sets) {
  cmd->add_option_function<std::vector<std::string>>(
         "--set", [&sets](const std::vector<std::string>& v) { sets.insert(sets.end(), v.begin(), v.end()); },
         "KEY=VALUE: override a case value, e.g. sample.confinement=0.16 (repeatable)")
      ->trigger_on_parse();
  cmd->add_option_function<std::vector<std::string>>(
         "--unset", [&sets](const std::vector<std::string>& v) { for (const auto& k : v) sets.push_back("!" + k); },
         "KEY: remove a case key or table, e.g. damage (repeatable)")
      ->trigger_on_parse();
}

}  // namespace

int main(int argc, char** argv) {
  psph::install_last_resort();
  CLI::App app{"poresph: pore-scale SPH simulation of gas, water and deforming clay"};
  app.require_subcommand(1);
  psph::RunOptions ro;
  const std::vector<std::string> backends{"cpu", "cuda"};

  std::string case_path, run_dir;
  auto* run = app.add_subcommand("run", "run a case file");
  run->add_option("case", case_path, "case file (TOML)")->required();
  run->add_option("--backend", ro.backend, "cpu or cuda")->check(CLI::IsMember(backends));
  run->add_option("--out", ro.out, "run directory (default runs/<case>-<time>)");
  run->add_flag("--quiet", ro.quiet, "no progress lines on the terminal");
  run->add_option("--restart", ro.restart, "continue from a checkpoint file, or a run directory's newest checkpoint");
  run->add_option("--pipeline", ro.pipelines, "Catalyst pipeline: a name in pipelines/ (phases, pressure, damage, "
                 "principal_stress, displacement, colour) or a .py script; repeatable");
  run->add_option("--live", ro.live, "HOST:PORT of a ParaView GUI to attach with Catalyst Live");
  run->add_option("--serve", ro.serve, "serve the browser dashboard on this port (0: any free port)")->check(CLI::Range(0, 65535));
  add_case_overrides(run, ro.sets);
  run->add_option("--bind", ro.bind, "the dashboard's address (default 127.0.0.1; 0.0.0.0 for every interface)");

  int serve_port = 8080;
  std::string serve_bind = "127.0.0.1";
  auto* serve = app.add_subcommand("serve", "serve the browser dashboard of a run directory (finished or running)");
  serve->add_option("rundir", run_dir, "run directory")->required();
  serve->add_option("--port", serve_port, "port (default 8080; 0: any free port)")->check(CLI::Range(0, 65535));
  serve->add_option("--bind", serve_bind, "address (default 127.0.0.1; 0.0.0.0 for every interface)");

  std::vector<std::string> fig_pipelines;
  auto* figures = app.add_subcommand("figures", "re-render a run's figure sequences from its extracts (pvbatch), MP4 with ffmpeg");
  figures->add_option("rundir", run_dir, "run directory")->required();
  figures->add_option("--pipeline", fig_pipelines, "pipelines to render (default: the run's own); repeatable");

  std::vector<std::string> report_dirs;
  std::string report_out;
  auto* report = app.add_subcommand("report", "PNG plots of a run's monitors (saturations, pressures, Pc-S), or of several runs");
  report->add_option("rundirs", report_dirs, "run directories (several: drawn together)")->required();
  report->add_option("--out", report_out, "folder for the plots (default RUNDIR/report; required for several runs)");

  std::vector<std::string> names;
  bool full = false, json = false, quick = false, accuracy = false, stability = false;
  auto* check = app.add_subcommand("check", "validate a case file, run nothing; estimate how far its fluids are compressed");
  check->add_option("case", case_path, "case file (TOML)")->required();
  check->add_flag("--json", json, "print the check and the compressibility estimate as JSON");
  add_case_overrides(check, ro.sets);

  std::string vbackend = "cpu";
  auto* validate = app.add_subcommand("validate", "run the validation cases against their references");
  validate->add_option("names", names, "validation cases to run (default: all)");
  validate->add_flag("--full", full, "published sizes instead of the reduced CI sizes");
  validate->add_flag("--json", json, "print a JSON array of records");
  validate->add_option("--backend", vbackend, "cpu or cuda")->check(CLI::IsMember(backends));
  bool validate_list = false;
  validate->add_flag("--list", validate_list, "print each validation case's name and description, run nothing");

  auto* bench = app.add_subcommand("bench", "measure the speed of the solver");
  std::vector<std::string> bench_names;
  bench->add_option("names", bench_names, "benchmarks to run, e.g. dam_break_3d or fluid_box_3d_1000000 (default: all; "
                    "--backend cuda adds the 1e7-particle boxes fluid_box_2d_10000000 and fluid_box_3d_10000000)");
  bool bench_list = false;
  bench->add_flag("--list", bench_list, "print the names of the benchmarks (for --backend and --quick), run nothing");
  bench->add_flag("--json", json, "print JSON records");
  bench->add_flag("--quick", quick, "small sizes only (a smoke run); with --accuracy: no sphere arrays");
  bench->add_flag("--accuracy", accuracy, "run time against error over kernels and resolutions");
  bench->add_flag("--stability", stability, "sweep the time-step factor and the initial disorder");
  bool decomposition = false;
  bench->add_flag("--decomposition", decomposition,
                  "halo and balance of SPHERIC test 2 at 6 mm and the published claystone cell over 2 ... 4,096 processes");
  bool profile = false;
  bench->add_flag("--profile", profile, "print each benchmark's time by stage and pass (with --json: a \"profile\" record)");
  bench->add_option("--backend", vbackend, "cpu or cuda")->check(CLI::IsMember(backends));

  auto* demo = app.add_subcommand("demo", "run the embedded default case");
  demo->add_option("--backend", ro.backend, "cpu or cuda")->check(CLI::IsMember(backends));
  demo->add_option("--out", ro.out, "run directory");
  demo->add_flag("--quiet", ro.quiet, "no progress lines on the terminal");
  demo->add_option("--pipeline", ro.pipelines, "Catalyst pipeline (as for run); repeatable");
  demo->add_option("--serve", ro.serve, "serve the browser dashboard on this port (0: any free port)")->check(CLI::Range(0, 65535));
  demo->add_option("--bind", ro.bind, "the dashboard's address (default 127.0.0.1)");

  psph::ImageInfoOptions image_opt;
  auto* image = psph::add_image_command(app, image_opt);

  CLI11_PARSE(app, argc, argv);
  // A command over several processes (mpirun) speaks through the first one: the others compute
  // the same and stay silent (a process that fails alone says so on stderr's descriptor directly).
  if (psph::launched_by_mpi() && psph::world().rank() != 0) std::cout.rdbuf(nullptr), std::cerr.rdbuf(nullptr);
  if (psph::launched_by_mpi()) {  // every process refuses if one does (their settings may differ)
    const std::string refusal = psph::first_message(psph::world(), psph::world().device_memory_refusal());
    if (!refusal.empty()) {
      std::cerr << "poresph: " << refusal << "\n";
      psph::finalise_world();
      return 2;
    }
  }
  const auto dispatch = [&]() -> int {
    if (*run) return psph::cmd_run(case_path, ro);
    if (*check) return psph::cmd_check(case_path, ro.sets, json);
    if (*serve) return psph::cmd_serve(run_dir, serve_port, serve_bind);
    if (*figures) return psph::cmd_figures(run_dir, fig_pipelines);
    if (*report) return psph::cmd_report(report_dirs, report_out);
    if (*validate && validate_list) return psph::cmd_validate_list();
    if (*validate) return psph::cmd_validate(names, full, json, vbackend);
    if (*bench && bench_list) {
      for (const auto& spec : psph::bench_specs(vbackend, quick)) std::cout << spec.name << "\n";
      return 0;
    }
    if (*bench) return psph::cmd_bench(bench_names, json, vbackend, quick, accuracy, stability, profile, decomposition);
    if (*demo) return psph::cmd_demo(ro);
    if (*image) return psph::cmd_image(*image, image_opt);
    return 1;
  };
  try {
    const int code = dispatch();
    psph::finalise_world();  // a run over several processes (mpirun) ends together
    return code;
  } catch (...) {
    psph::internal_error();
  }
}
