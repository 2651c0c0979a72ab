// Strict case-file reader: each table's keys are consumed as they are read; what is left over is
// an unknown key and rejected.
#include "scene/case_file.hpp"

#include "integrate/timestep.hpp"

#include <cmath>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

namespace psph {
namespace {

std::string where(const toml::node& n) {
  const auto& src = n.source();
  return src.begin.line ? " (line " + std::to_string(src.begin.line) + ")" : "";
}

// Reads one table and remembers which keys were used.
class Reader {
 public:
  Reader(const toml::table& t, std::string file, std::string path)
      : t_(t), file_(std::move(file)), path_(std::move(path)) {}

  [[noreturn]] void fail(const std::string& key, const std::string& expected, const toml::node* n = nullptr) const {
    throw CaseError(file_ + ": " + qualified(key) + (n ? where(*n) : "") + ": " + expected);
  }
  std::string qualified(const std::string& key) const { return path_.empty() ? key : path_ + "." + key; }

  const toml::node* node(const std::string& key) {
    used_.insert(key);
    return t_.get(key);
  }
  bool has(const std::string& key) const { return t_.contains(key); }

  double number(const std::string& key, std::optional<double> def = std::nullopt) {
    const toml::node* n = node(key);
    if (!n) {
      if (def) return *def;
      fail(key, "missing required value (expected a number)");
    }
    if (auto v = n->value<double>()) return *v;  // integers convert too
    fail(key, std::string("expected a number, got ") + type_name(*n), n);
  }
  double positive(const std::string& key, std::optional<double> def = std::nullopt) {
    const double v = number(key, def);
    if (!(v > 0) || !std::isfinite(v)) fail(key, "expected a number > 0, got " + fmt(v), node(key));
    return v;
  }
  double non_negative(const std::string& key, std::optional<double> def = std::nullopt) {
    const double v = number(key, def);
    if (!(v >= 0) || !std::isfinite(v)) fail(key, "expected a number >= 0, got " + fmt(v), node(key));
    return v;
  }
  long integer(const std::string& key, std::optional<long> def = std::nullopt) {
    const toml::node* n = node(key);
    if (!n) {
      if (def) return *def;
      fail(key, "missing required value (expected an integer)");
    }
    if (auto v = n->value_exact<int64_t>()) return static_cast<long>(*v);
    fail(key, std::string("expected an integer, got ") + type_name(*n), n);
  }
  long positive_integer(const std::string& key, long def) {
    const long v = integer(key, def);
    if (v < 1) fail(key, "expected an integer >= 1, got " + std::to_string(v), node(key));
    return v;
  }
  std::string string(const std::string& key, std::optional<std::string> def = std::nullopt) {
    const toml::node* n = node(key);
    if (!n) {
      if (def) return *def;
      fail(key, "missing required value (expected a string)");
    }
    if (auto v = n->value_exact<std::string>()) return *v;
    fail(key, std::string("expected a string, got ") + type_name(*n), n);
  }
  std::string choice(const std::string& key, const std::vector<std::string>& options,
                     std::optional<std::string> def = std::nullopt) {
    const std::string v = string(key, def);
    for (const auto& o : options)
      if (o == v) return v;
    std::string list;
    for (const auto& o : options) list += (list.empty() ? "" : ", ") + ("\"" + o + "\"");
    fail(key, "expected one of " + list + ", got \"" + v + "\"", node(key));
  }
  bool boolean(const std::string& key, bool def) {
    const toml::node* n = node(key);
    if (!n) return def;
    if (auto v = n->value_exact<bool>()) return *v;
    fail(key, std::string("expected true or false, got ") + type_name(*n), n);
  }
  // An array of exactly `dim` numbers (or booleans when `T` is bool).
  template <class T>
  std::array<T, 3> vec(const std::string& key, int dim, std::optional<std::array<T, 3>> def = std::nullopt) {
    const toml::node* n = node(key);
    const char* what = std::is_same_v<T, bool> ? "booleans" : "numbers";
    if (!n) {
      if (def) return *def;
      fail(key, "missing required value (expected an array of " + std::to_string(dim) + " " + what + ")");
    }
    const toml::array* arr = n->as_array();
    if (!arr || static_cast<int>(arr->size()) != dim)
      fail(key, "expected an array of " + std::to_string(dim) + " " + what + " (one per dimension)", n);
    std::array<T, 3> out{};
    for (int k = 0; k < dim; ++k) {
      std::optional<T> v;
      if constexpr (std::is_same_v<T, bool>) v = (*arr)[k].value_exact<bool>();
      else v = (*arr)[k].value<T>();
      if (!v) fail(key, "expected an array of " + std::to_string(dim) + " " + what, n);
      out[k] = *v;
    }
    return out;
  }
  std::vector<std::string> strings(const std::string& key, std::vector<std::string> def) {
    const toml::node* n = node(key);
    if (!n) return def;
    const toml::array* arr = n->as_array();
    if (!arr) fail(key, "expected an array of strings", n);
    std::vector<std::string> out;
    for (const auto& e : *arr) {
      auto v = e.value_exact<std::string>();
      if (!v) fail(key, "expected an array of strings", n);
      out.push_back(*v);
    }
    return out;
  }
  const toml::table& table(const std::string& key, bool required) {
    const toml::node* n = node(key);
    static const toml::table empty;
    if (!n) {
      if (required) fail(key, "missing required table [" + qualified(key) + "]");
      return empty;
    }
    if (!n->is_table()) fail(key, "expected a table", n);
    return *n->as_table();
  }
  // Rejects every key that was not read.
  void finish() const {
    for (const auto& [k, v] : t_) {
      const std::string key(k.str());
      if (!used_.count(key)) fail(key, "unknown key", &v);
    }
  }

  static const char* type_name(const toml::node& n) {
    switch (n.type()) {
      case toml::node_type::string: return "a string";
      case toml::node_type::integer: return "an integer";
      case toml::node_type::floating_point: return "a number";
      case toml::node_type::boolean: return "a boolean";
      case toml::node_type::array: return "an array";
      case toml::node_type::table: return "a table";
      default: return "a date or time";
    }
  }
  static std::string fmt(double v) {
    std::ostringstream o;
    o << v;
    return o.str();
  }

 private:
  const toml::table& t_;
  std::string file_, path_;
  std::set<std::string> used_;
};

KernelType kernel_from(const std::string& s) {
  return s == "wendland_c2" ? KernelType::WendlandC2 : s == "quintic_spline" ? KernelType::QuinticSpline
                                                                              : KernelType::CubicSpline;
}

}  // namespace

Case parse_case(const toml::table& tbl, const std::string& file) {
  Case c;
  c.file = file;
  Reader top(tbl, file, "");
  Scene& sc = c.scene;

  {
    Reader r(top.table("case", true), file, "case");
    c.name = r.string("name");
    if (c.name.empty() || c.name.find_first_of("/\\ \t") != std::string::npos)
      r.fail("name", "expected a non-empty name without spaces or slashes");
    c.description = r.string("description", "");
    const long dim = r.integer("dimension");
    if (dim < 1 || dim > 3) r.fail("dimension", "expected 1, 2 or 3, got " + std::to_string(dim));
    sc.dimension = static_cast<int>(dim);
    r.finish();
  }
  const int D = sc.dimension;
  {
    Reader r(top.table("domain", true), file, "domain");
    sc.lower = r.vec<double>("lower", D);
    sc.upper = r.vec<double>("upper", D);
    sc.periodic = r.vec<bool>("periodic", D, std::array<bool, 3>{false, false, false});
    for (int k = 0; k < D; ++k)
      if (!(sc.upper[k] > sc.lower[k])) r.fail("upper", "expected upper > lower on every axis (axis " + std::to_string(k) + ")");
    r.finish();
  }
  SolverOptions& o = sc.options;
  {
    Reader r(top.table("discretisation", true), file, "discretisation");
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
    for (int k = 0; k < D; ++k) {
      const double cells = (sc.upper[k] - sc.lower[k]) / o.spacing;
      if (sc.periodic[k] && std::fabs(cells - std::round(cells)) > 1e-6 * cells)
        r.fail("spacing", "expected the periodic domain length along axis " + std::to_string(k) +
                              " to be a whole number of spacings (got " + Reader::fmt(cells) + ")");
      if (sc.periodic[k] && sc.upper[k] - sc.lower[k] < 3 * o.support_radius)
        r.fail("support_radius", "periodic axis " + std::to_string(k) + " is shorter than 3 support radii");
    }
    r.finish();
  }
  // Materials, in file order of their names (toml tables are ordered by key).
  std::map<std::string, int> mat_index;
  {
    const toml::table& mt = top.table("materials", true);
    if (mt.empty()) top.fail("materials", "expected at least one material");
    for (const auto& [k, v] : mt) {
      const std::string name(k.str());
      if (name == "empty") top.fail("materials.empty", "\"empty\" is reserved for removing particles");
      if (!v.is_table()) top.fail("materials." + name, "expected a table", &v);
      Reader r(*v.as_table(), file, "materials." + name);
      SceneMaterial m;
      m.name = name;
      const std::string kind = r.choice("kind", {"fluid", "wall"});
      m.props.kind = kind == "fluid" ? MaterialKind::Fluid : MaterialKind::Wall;
      // A wall's density is optional: by default it is the first fluid's (set below).
      m.props.rest_density = (kind == "fluid" || r.has("density")) ? Real(r.positive("density")) : Real(0);
      if (kind == "fluid") {
        m.props.viscosity = Real(r.non_negative("viscosity"));
        m.props.sound_speed = Real(r.positive("sound_speed"));
        m.props.eos = r.choice("equation_of_state", {"linear", "tait"}, "linear") == "tait" ? EquationOfState::Tait
                                                                                             : EquationOfState::Linear;
        m.props.tait_gamma = Real(r.positive("tait_gamma", 7.0));
        m.body_force = r.vec<double>("body_force", D, std::array<double, 3>{0, 0, 0});
      }
      r.finish();
      mat_index[name] = static_cast<int>(sc.materials.size());
      sc.materials.push_back(m);
    }
    if (sc.materials.size() > static_cast<std::size_t>(kMaxMaterials))
      top.fail("materials", "expected at most " + std::to_string(kMaxMaterials) + " materials");
    // Walls take the density and sound speed of the first fluid unless given (digest §7 item 17).
    const SceneMaterial* fluid = nullptr;
    for (const auto& m : sc.materials)
      if (m.props.kind == MaterialKind::Fluid) { fluid = &m; break; }
    if (!fluid) top.fail("materials", "expected at least one material with kind = \"fluid\"");
    Real c_max = 0;
    for (const auto& m : sc.materials)
      if (m.props.kind == MaterialKind::Fluid) c_max = std::max(c_max, m.props.sound_speed);
    for (auto& m : sc.materials)
      if (m.props.kind == MaterialKind::Wall) {
        if (m.props.rest_density == Real(0)) m.props.rest_density = fluid->props.rest_density;
        m.props.sound_speed = c_max;
      }
  }
  {
    Reader r(top.table("solver", false), file, "solver");
    const std::string d = r.choice("density", {"summation", "normalised_summation", "continuity"}, "summation");
    o.density = d == "continuity" ? DensityMethod::Continuity
                : d == "normalised_summation" ? DensityMethod::NormalisedSummation : DensityMethod::Summation;
    o.integrator = r.choice("integrator", {"velocity_verlet", "leapfrog"}, "velocity_verlet") == "leapfrog"
                       ? Integrator::Leapfrog : Integrator::VelocityVerlet;
    const std::string ns = r.choice("wall_noslip", {"curved", "mirror", "prescribed"}, "curved");
    o.wall_noslip = ns == "prescribed" ? WallNoSlip::Prescribed : ns == "mirror" ? WallNoSlip::Mirror : WallNoSlip::Curved;
    {
      const std::string lc = r.choice("laplacian_correction", {"trace", "tensor", "none"}, "trace");
      o.laplacian_correction = lc == "tensor" ? LaplacianCorrection::Tensor
                               : lc == "none" ? LaplacianCorrection::None
                                              : LaplacianCorrection::Trace;
    }
    o.wall_pressure = r.choice("wall_pressure", {"extrapolated", "summation"}, "extrapolated") == "summation"
                          ? WallPressure::Summation : WallPressure::Extrapolated;
    o.xsph = r.non_negative("xsph", 0.0);
    o.artificial_viscosity = r.non_negative("artificial_viscosity", 0.0);
    o.density_diffusion = r.non_negative("density_diffusion", 0.0);
    if (o.xsph > 1) r.fail("xsph", "expected an XSPH epsilon in [0, 1]");
    o.dt_factor = r.positive("dt_factor", 1.0);
    if (o.dt_factor > 4) r.fail("dt_factor", "expected a factor in (0, 4]");
    o.fixed_dt = r.non_negative("dt", 0.0);
    o.neighbour_skin = r.non_negative("neighbour_skin", 0.1);
    o.max_density_deviation = r.non_negative("max_density_deviation", 0.0);
    if (o.neighbour_skin > 1) r.fail("neighbour_skin", "expected a fraction of the support radius in [0, 1]");
    r.finish();
  }
  {
    Reader r(top.table("time", true), file, "time");
    c.end_time = r.positive("end");
    if (o.fixed_dt > c.end_time) r.fail("end", "expected an end time of at least one fixed step (solver.dt)");
    r.finish();
    if (o.fixed_dt > 0) {
      // The limits known before the run: acoustic (at rest) and viscous (Pazdniakou eqs. 50-52).
      double c_max = 0, nu_max = 0;
      for (const auto& m : sc.materials) {
        c_max = std::max(c_max, double(m.props.sound_speed));
        if (m.props.kind == MaterialKind::Fluid) nu_max = std::max(nu_max, double(m.props.viscosity / m.props.rest_density));
      }
      const double hs = o.support_radius / support_per_smoothing_length(o.kernel);
      const TimeStepLimits lim = time_step_limits(hs, c_max, 0.0, 0.0, nu_max, 1.0);
      const double limit = lim.min();
      if (o.fixed_dt > 2 * limit)
        throw CaseError(file + ": solver.dt: a fixed step of " + Reader::fmt(o.fixed_dt) +
                        " s is impossible: the acoustic/viscous stability limit is " + Reader::fmt(limit) + " s");
    }
  }
  {
    Reader r(top.table("output", false), file, "output");
    c.output.monitor_interval = r.non_negative("monitor_interval", 0.0);
    c.output.extract_interval = r.non_negative("extract_interval", 0.0);
    c.output.checkpoint_interval = r.non_negative("checkpoint_interval", 0.0);
    c.output.checkpoint_keep = static_cast<int>(r.positive_integer("checkpoint_keep", c.output.checkpoint_keep));
    c.output.fields = r.strings("fields", c.output.fields);
    r.finish();
  }
  {
    const toml::node* g = top.node("geometry");
    if (!g) top.fail("geometry", "missing required array of tables [[geometry]]");
    const toml::array* arr = g->as_array();
    if (!arr || arr->empty() || !arr->is_array_of_tables()) top.fail("geometry", "expected an array of tables [[geometry]]", g);
    int idx = 0;
    for (const auto& e : *arr) {
      Reader r(*e.as_table(), file, "geometry[" + std::to_string(idx++) + "]");
      GeometryShape s;
      s.kind = r.choice("shape", {"box", "sphere"}) == "sphere" ? GeometryShape::Kind::Sphere : GeometryShape::Kind::Box;
      if (s.kind == GeometryShape::Kind::Box) {
        s.lower = r.vec<double>("lower", D);
        s.upper = r.vec<double>("upper", D);
      } else {
        s.center = r.vec<double>("center", D);
        s.radius = r.positive("radius");
      }
      const std::string mname = r.string("material");
      if (mname == "empty") s.material = -1;
      else if (mat_index.count(mname)) s.material = mat_index[mname];
      else r.fail("material", "expected \"empty\" or the name of a table under [materials], got \"" + mname + "\"");
      s.velocity = r.vec<double>("velocity", D, std::array<double, 3>{0, 0, 0});
      r.finish();
      c.geometry.push_back(s);
    }
  }
  top.finish();
  std::ostringstream os;
  os << tbl;
  c.source_text = os.str();
  return c;
}

Case load_case_text(const std::string& text, const std::string& file) {
  toml::table tbl;
  try {
    tbl = toml::parse(text, file);
  } catch (const toml::parse_error& e) {
    throw CaseError(file + " (line " + std::to_string(e.source().begin.line) + "): not valid TOML: " +
                    std::string(e.description()));
  }
  return parse_case(tbl, file);
}

Case load_case_file(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw CaseError(path + ": cannot open the case file");
  std::stringstream ss;
  ss << in.rdbuf();
  return load_case_text(ss.str(), path);
}

void set_case_value(toml::table& tbl, const std::string& dotted_key, const toml::node& value) {
  toml::table* t = &tbl;
  std::size_t start = 0;
  for (;;) {
    const std::size_t dot = dotted_key.find('.', start);
    const std::string part = dotted_key.substr(start, dot == std::string::npos ? std::string::npos : dot - start);
    if (dot == std::string::npos) {
      value.visit([&](auto&& v) { t->insert_or_assign(part, v); });
      return;
    }
    toml::node* next = t->get(part);
    if (!next) {
      t->insert(part, toml::table{});
      next = t->get(part);
    }
    if (!next->is_table()) throw std::logic_error("set_case_value: " + dotted_key + " crosses a non-table");
    t = next->as_table();
    start = dot + 1;
  }
}

}  // namespace psph
