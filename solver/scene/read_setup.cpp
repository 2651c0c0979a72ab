// The case tables that set up a run: [case], [domain], [discretisation], [time], [output],
// [visualisation], [monitors].
#include <algorithm>
#include <cctype>
#include <cmath>

#include "kernels/kernel.hpp"
#include "scene/case_tables.hpp"

namespace psph {
namespace {

// Neighbour candidates per particle, (2 support / spacing)^D: the references use 2-3 spacings (64
// to 216 in 3D); the non-local rods of Deptulski 2021 Ch. 3, up to 100 spacings in 1D (200).
constexpr double kMaxCandidates = 1e4;

// The case name becomes a directory name (runs/<name>-<time>) and is printed on the terminal.
constexpr std::size_t kMaxNameLength = 64;

bool valid_case_name(const std::string& name) {
  if (name.empty() || name.size() > kMaxNameLength || name[0] == '.' || name[0] == '-') return false;
  for (const char ch : name)
    if (!std::isalnum(static_cast<unsigned char>(ch)) && ch != '_' && ch != '-' && ch != '.' && ch != '+') return false;
  return true;
}

// Outputs a run may write: an interval that would write more is refused before the run fills a disk.
constexpr double kMaxFiles = 1e5, kMaxRows = 1e7;

void bound_outputs(CaseReader& r, const std::string& key, double end, double interval, double most, const char* what) {
  if (interval > 0 && !(end / interval <= most))
    r.fail(key, "expected at most " + CaseReader::fmt(most) + " " + what + " in the run (time.end / " + key + "), got " +
                    CaseReader::fmt(end / interval), r.node(key));
}

}  // namespace

KernelType kernel_from(const std::string& s) {
  return s == "wendland_c2" ? KernelType::WendlandC2 : s == "quintic_spline" ? KernelType::QuinticSpline
                                                                              : KernelType::CubicSpline;
}

void read_case_table(CaseReader& top, CaseDraft& d) {
  CaseReader r(top.table("case", true), d.file, "case");
  d.c.name = r.string("name");
  if (!valid_case_name(d.c.name))
    r.fail("name", "expected 1 to " + std::to_string(kMaxNameLength) + " letters, digits, '_', '-', '.' or '+', not "
                   "starting with '.' or '-' (it names the run directory), got \"" + shown(d.c.name) + "\"");
  d.c.description = r.string("description", "");
  const long dim = r.integer("dimension");
  if (dim < 1 || dim > 3) r.fail("dimension", "expected 1, 2 or 3, got " + std::to_string(dim));
  d.c.scene.dimension = static_cast<int>(dim);
  d.c.stress_scale = r.has("stress_scale") ? r.positive("stress_scale") : 0.0;
  d.c.length_scale = r.positive("length_scale", 1.0);
  r.finish();
}

void read_domain(CaseReader& top, CaseDraft& d) {
  Scene& sc = d.c.scene;
  CaseReader r(top.table("domain", true), d.file, "domain");
  r.box(d.dimension(), sc.lower, sc.upper);
  sc.periodic = r.vec<bool>("periodic", d.dimension(), std::array<bool, 3>{false, false, false});
  r.finish();
}

void read_discretisation(CaseReader& top, CaseDraft& d) {
  Scene& sc = d.c.scene;
  SolverOptions& o = sc.options;
  const toml::table& t = top.table("discretisation", true);
  d.note(t, "discretisation");
  CaseReader r(t, d.file, "discretisation");
  o.spacing = r.positive("spacing");
  o.jitter = r.non_negative("jitter", 0.0);
  if (o.jitter > 0.5) r.fail("jitter", "expected a fraction of the spacing in [0, 0.5]");
  o.kernel = kernel_from(r.choice("kernel", {"cubic_spline", "wendland_c2", "quintic_spline"}, "cubic_spline"));
  const bool has_R = r.has("support_radius"), has_h = r.has("smoothing_length");
  if (has_R == has_h) r.fail("support_radius", "give exactly one of support_radius and smoothing_length");
  o.support_radius = has_R ? r.positive("support_radius")
                           : r.positive("smoothing_length") * support_per_smoothing_length(o.kernel);
  if (o.support_radius < o.spacing)
    r.fail(has_R ? "support_radius" : "smoothing_length", "expected a support radius of at least one spacing");
  // The work per particle grows as (support / spacing)^D: bounded before anything is built.
  const double ratio = o.support_radius / o.spacing, candidates = std::pow(2 * ratio, d.dimension());
  if (!(candidates <= kMaxCandidates))
    r.fail(has_R ? "support_radius" : "smoothing_length",
           "expected at most " + CaseReader::fmt(kMaxCandidates) + " neighbour candidates per particle, (2 support / "
           "spacing)^" + std::to_string(d.dimension()) + ", got " + CaseReader::fmt(candidates) + " (" +
               CaseReader::fmt(ratio) + " spacings)");
  for (int k = 0; k < d.dimension(); ++k) {
    const double cells = (sc.upper[k] - sc.lower[k]) / o.spacing;
    if (sc.periodic[k] && std::fabs(cells - std::round(cells)) > 1e-6 * cells)
      r.fail("spacing", "expected the periodic domain length along axis " + std::to_string(k) +
                            " to be a whole number of spacings (got " + CaseReader::fmt(cells) + ")");
    if (sc.periodic[k] && sc.upper[k] - sc.lower[k] < 3 * o.support_radius)
      r.fail("support_radius", "periodic axis " + std::to_string(k) + " is shorter than 3 support radii");
  }
  r.finish();
}

void read_time_and_output(CaseReader& top, CaseDraft& d) {
  Case& c = d.c;
  {
    const toml::table& t = top.table("time", true);
    d.note(t, "time");
    CaseReader r(t, d.file, "time");
    c.end_time = r.positive("end");
    c.after_percolation = r.has("after_percolation") ? r.non_negative("after_percolation", 0.0) : -1.0;
    r.finish();
  }
  CaseReader r(top.table("output", false), d.file, "output");
  c.output.monitor_interval = r.non_negative("monitor_interval", 0.0);
  c.output.extract_interval = r.non_negative("extract_interval", 0.0);
  c.output.checkpoint_interval = r.non_negative("checkpoint_interval", 0.0);
  c.output.checkpoint_keep = static_cast<int>(r.positive_integer("checkpoint_keep", c.output.checkpoint_keep));
  c.output.fields = r.strings("fields", c.output.fields);
  c.output.extract_format = r.choice("extract_format", {"vtp", "vtu"}, "vtp");
  bound_outputs(r, "monitor_interval", c.end_time, c.output.monitor_interval, kMaxRows, "monitor rows");
  bound_outputs(r, "extract_interval", c.end_time, c.output.extract_interval, kMaxFiles, "extract files");
  bound_outputs(r, "checkpoint_interval", c.end_time, c.output.checkpoint_interval, kMaxFiles, "checkpoints");
  r.finish();
  c.visualisation = parse_visualisation(top.table("visualisation", false), d.file);
  CaseReader v(top.table("visualisation", false), d.file, "visualisation");
  bound_outputs(v, "interval", c.end_time, c.visualisation.interval, kMaxFiles, "frames per pipeline");
}

// The region and axis of the two-phase monitors (monitors/two_phase.hpp).
void read_monitors(CaseReader& top, CaseDraft& d) {
  const Scene& sc = d.c.scene;
  const int D = d.dimension();
  const toml::table& t = top.table("monitors", false);
  d.note(t, "monitors");
  CaseReader r(t, d.file, "monitors");
  MonitorRegion& m = d.c.monitor_region;
  m.lower = r.vec<double>("region_lower", D, sc.lower);
  m.upper = r.vec<double>("region_upper", D, sc.upper);
  for (int k = 0; k < D; ++k)
    if (!(m.upper[k] > m.lower[k]) || m.lower[k] < sc.lower[k] || m.upper[k] > sc.upper[k])
      r.fail("region_upper", "expected region_lower < region_upper inside the domain on every axis (axis " +
                                 std::to_string(k) + ")");
  m.flow_axis = r.axis("flow_axis", D, std::string(1, "xyz"[D - 1]));
  // Lattice neighbours (1 and sqrt(2) spacings) connect; a one-particle water film (2) does not.
  m.percolation_distance = r.positive("percolation_distance", 1.5 * sc.options.spacing);
  r.finish();
}

// Pressure probes (monitors/pressure_probes.hpp): a name that makes a column, a point in the domain.
void read_probes(CaseReader& top, CaseDraft& d) {
  const Scene& sc = d.c.scene;
  const int D = d.dimension();
  top.each_table("probe", 64, "probes", [&](CaseReader& r) {
    Probe p;
    p.name = r.string("name");
    const bool word = !p.name.empty() && std::all_of(p.name.begin(), p.name.end(), [](char ch) {
      return std::isalnum(static_cast<unsigned char>(ch)) || ch == '_';
    });
    if (!word) r.fail("name", "expected a name of letters, digits and '_' (it makes the column pressure_<name>)");
    for (const Probe& q : d.c.probes)
      if (q.name == p.name) r.fail("name", "expected a name no other probe has, got \"" + p.name + "\" twice");
    p.position = r.vec<double>("position", D);
    for (int k = 0; k < D; ++k)
      if (p.position[k] < sc.lower[k] || p.position[k] > sc.upper[k])
        r.fail("position", "expected a point inside the domain (axis " + std::to_string(k) + ")");
    d.c.probes.push_back(p);
  });
}

}  // namespace psph
