// poresph run / check / demo: load and check a case, then drive the run (app/run_driver.hpp).
#include <iostream>

#include "app/commands.hpp"
#include "app/run_driver.hpp"
#include "catalyst/figures.hpp"
#include "catalyst/insitu_session.hpp"
#include "image/image_report.hpp"
#include "scene/case_file.hpp"
#include "scene/compressibility.hpp"
#include "scene/embedded_cases.hpp"
#include "scene/scene_builder.hpp"

namespace psph {
namespace {

// Loads a case and builds its particles; prints the error and returns false on bad input.
bool prepare(Case& c, const std::string& path, const std::string* text, const std::vector<std::string>& sets = {}) {
  try {
    c = text ? load_case_text(*text, path, sets) : load_case_file(path, sets);
    build_particles(c);
    return true;
  } catch (const CaseError& e) {
    std::cerr << "poresph: " << e.what() << "\n";
    return false;
  }
}

int drive(Case& c, const RunOptions& opt) { return RunDriver(c, opt).run(); }

}  // namespace

int cmd_check(const std::string& path, const std::vector<std::string>& sets, bool json) {
  Case c;
  if (!prepare(c, path, nullptr, sets)) return 2;
  CompressibilityEstimate estimate;
  try {
    // What `run` builds before its run directory: the engine (on the CPU: the same fields on
    // every backend), the output fields it has, the pipelines and the fields they declare.
    check_output_fields(c, make_engine(c.scene, "cpu")->field_names());
    Communicator one;
    InSituSession pipelines(c, {}, "", one);
    estimate = estimate_compressibility(c);
  } catch (const std::exception& e) {
    std::cerr << "poresph: " << e.what() << "\n";
    return 2;
  }
  long fluid = 0;
  for (int m : c.scene.material) fluid += c.scene.materials[m].props.kind == MaterialKind::Fluid;
  const bool refused = c.compressibility_strict && estimate.exceeds();
  if (json) {
    nlohmann::json j = {{"file", path}, {"case", c.name}, {"valid", !refused}, {"particles", c.scene.count()},
                        {"fluid_particles", fluid}, {"dimension", c.scene.dimension},
                        {"compressibility", to_json(estimate)}, {"images", c.images}};
    std::cout << j.dump(2) << "\n";
  } else {
    std::cout << path << ": case " << c.name << (refused ? " is refused (below): " : " is valid: ") << c.scene.count()
              << " particles (" << fluid
              << " fluid), " << c.scene.dimension << "D, support radius " << c.scene.options.support_radius
              << " m, spacing " << c.scene.options.spacing << " m, end time " << c.end_time << " s\n";
    for (const auto& image : c.images) std::cout << "image " << image_report_text(image);
    std::cout << compressibility_text(estimate, path);
  }
  if (!refused) return 0;
  std::cerr << "poresph: " << path << ": solver.compressibility = \"strict\" refuses a case whose estimated density variation ("
            << 100 * estimate.total << " %) passes 1 %\n";
  return 2;
}

int cmd_run(const std::string& path, const RunOptions& opt) {
  Case c;
  if (!prepare(c, path, nullptr, opt.sets)) return 2;
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
