#pragma once
// Case files (TOML): strict parsing and checking. Every error names the file, the key and what was
// expected, and is raised before anything is computed or written.
#include <array>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include <toml++/toml.h>

#include "monitors/monitor_region.hpp"
#include "monitors/pressure_probes.hpp"
#include "scene/shape.hpp"
#include "engine/scene.hpp"
#include "scene/visualisation_options.hpp"

namespace psph {

struct CaseError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// One [[geometry]] entry: a shape (scene/shape.hpp) filled with a material, or "empty".
struct GeometryShape {
  std::string name;  // for messages: "geometry[2]", or which part of an image
  std::shared_ptr<const Shape> shape;
  int material = -1;  // -1: "empty" (removes particles)
  std::array<double, 3> velocity{0, 0, 0};
  std::array<double, 3> angular_velocity{0, 0, 0};  // rigid bodies (rad/s, world frame; z in 2D)
};

struct OutputOptions {
  double monitor_interval = 0;  // s; 0 = every 1/100 of the run
  double extract_interval = 0;  // s; 0 = first and last state only
  double checkpoint_interval = 0;  // s; 0 = a tenth of the run. A final one is always written.
  int checkpoint_keep = 2;         // newest checkpoints kept in checkpoints/
  std::vector<std::string> fields{"velocity", "pressure", "density", "material"};
  // Extracts as VTK polydata ("vtp") or unstructured grids of vertex cells ("vtu"); over several
  // processes one piece each, gathered by a .pvtp or .pvtu.
  std::string extract_format = "vtp";
};

struct Case {
  std::string file;  // where it came from (for messages)
  std::string name, description;
  // Physical per case units ([case] stress_scale, length_scale): the scaled cases of the references
  // (Pazdniakou 2018 §5.2: 0.3 Pa for 15 MPa, 5e7) report physical values beside the scaled ones.
  double stress_scale = 0, length_scale = 1;  // 0: no physical stresses reported
  Scene scene;       // domain, materials, options (particles filled by the scene builder)
  std::vector<GeometryShape> geometry;
  double end_time = 0;
  double after_percolation = -1;  // [time] after_percolation: the run ends this long after gas percolates (< 0: at end_time)
  OutputOptions output;
  // [solver] compressibility = "strict": a case whose estimated density variation passes 1 % is
  // refused (scene/compressibility.hpp); "warn" (default) runs it with a warning.
  bool compressibility_strict = false;
  bool two_phase = false;  // a liquid and a gas: the two-phase monitors run (monitors/two_phase.hpp)
  MonitorRegion monitor_region;
  std::vector<Probe> probes;  // [[probe]]: pressure at fixed points (monitors/pressure_probes.hpp)
  VisualisationOptions visualisation;
  std::string source_text;  // the resolved case, as TOML
  std::vector<nlohmann::json> images;  // each image geometry's report (image/image_report.hpp)
};

// Parses and checks a case. `file` is used in messages only.
Case parse_case(const toml::table& tbl, const std::string& file);
// `sets`: overrides applied to the file's table before it is read (poresph run --set, --unset):
// "KEY=VALUE", KEY dotted (sample.confinement), VALUE a TOML value (0.16, "gas", [1, 2]) or else a
// string; "!KEY" (--unset) removes that key or table, which must be there; in the order given.
Case load_case_file(const std::string& path, const std::vector<std::string>& sets = {});
Case load_case_text(const std::string& text, const std::string& file, const std::vector<std::string>& sets = {});

// output.fields against the particle fields this case's engine has (`available`): throws a
// CaseError naming the first unknown field and the ones there are.
void check_output_fields(const Case& c, const std::vector<std::string>& available);

// Sets a dotted key (e.g. "discretisation.spacing") in a parsed table: for validation and benchmark
// variants of a case.
void set_case_value(toml::table& tbl, const std::string& dotted_key, const toml::node& value);
// Replaces the case's spacing; its support radius (or smoothing length) keeps its size in spacings.
void set_case_spacing(toml::table& tbl, double spacing);

}  // namespace psph
