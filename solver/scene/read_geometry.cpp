// [[geometry]]: the shapes that place each material's particles, in order (a later shape takes the
// particles of an earlier one where they overlap; "empty" removes them).
#include <algorithm>
#include <cmath>

#include "scene/case_tables.hpp"

namespace psph {

void read_image_geometry(CaseReader& r, CaseDraft& d, std::size_t index);

namespace {

// The packing tries each grain against those placed, and each lattice site in the box against
// every grain: both are bounded before the pack is drawn.
constexpr double kMaxGrains = 1e4, kMaxSiteGrainTests = 2e10;

void bound_grain_pack(CaseReader& r, const GrainPackSpec& p, const CaseDraft& d) {
  const int D = d.dimension();
  double box = 1;
  for (int k = 0; k < D; ++k) box *= p.upper[k] - p.lower[k];
  const double grains = p.solid_fraction * box / (unit_ball_volume(D) * std::pow(p.grain_radius, D));
  const double sites = box / std::pow(d.c.scene.options.spacing, D);
  if (!(grains <= kMaxGrains))
    r.fail("grain_radius", "expected a pack of at most " + CaseReader::fmt(kMaxGrains) + " grains, got about " +
                               CaseReader::fmt(grains) + " (solid_fraction x box volume / grain volume)");
  if (!(grains * sites <= kMaxSiteGrainTests))
    r.fail("grain_radius", "expected at most " + CaseReader::fmt(kMaxSiteGrainTests) + " site-grain tests, got about " +
                               CaseReader::fmt(grains * sites) + " (" + CaseReader::fmt(grains) + " grains x " +
                               CaseReader::fmt(sites) + " lattice sites in the box)");
}

std::shared_ptr<const Shape> read_grain_pack(CaseReader& r, CaseDraft& d) {
  GrainPackSpec p;
  r.box(d.dimension(), p.lower, p.upper);
  p.grain_radius = r.positive("grain_radius");
  p.radius_spread = r.non_negative("radius_spread", 0.2);
  if (p.radius_spread >= 1) r.fail("radius_spread", "expected a fraction of the radius in [0, 1)");
  p.min_gap = r.non_negative("min_gap", 2 * d.c.scene.options.spacing);
  p.solid_fraction = r.positive("solid_fraction");
  if (p.solid_fraction > 0.9) r.fail("solid_fraction", "expected a fraction in (0, 0.9]");
  const long seed = r.integer("seed", 1);
  if (seed < 0) r.fail("seed", "expected an integer >= 0");
  p.seed = static_cast<std::uint64_t>(seed);
  bound_grain_pack(r, p, d);
  try {
    return make_grain_pack(p, generate_grain_pack(p, d.dimension()).grains, d.dimension());
  } catch (const std::invalid_argument& e) {
    r.fail("solid_fraction", e.what());
  }
}

// A shape wholly outside the domain would be dropped silently.
void require_overlap(CaseReader& r, const Scene& sc, const Bounds& b, const std::string& key) {
  for (int k = 0; k < sc.dimension; ++k)
    if (!(b.upper[k] > sc.lower[k] && b.lower[k] < sc.upper[k]))
      r.fail(key, "expected a shape that overlaps the domain; it lies wholly outside it along axis " + std::to_string(k));
}

// A lens: its centre, half_length (centre to tips), half_thickness (< half_length) and the axis
// of its thickness ("x", "y" or "z"; the last axis by default).
std::shared_ptr<const Shape> read_lens(CaseReader& r, int D) {
  if (D < 2) r.fail("shape", "expected a lens in 2D or 3D only");
  LensSpec l;
  l.center = r.vec<double>("center", D);
  l.half_length = r.positive("half_length");
  l.half_thickness = r.positive("half_thickness");
  if (!(l.half_thickness < l.half_length))
    r.fail("half_thickness", "expected less than half_length (" + CaseReader::fmt(l.half_length) + " m), got " +
                                 CaseReader::fmt(l.half_thickness) + " m");
  const std::string axes[3] = {"x", "y", "z"};
  const std::string axis = r.choice("axis", std::vector<std::string>(axes, axes + D), axes[D - 1]);
  l.axis = int(std::find(axes, axes + D, axis) - axes);
  return make_lens(l, D);
}

// The shape's own keys.
std::shared_ptr<const Shape> read_shape(CaseReader& r, CaseDraft& d, const std::string& shape) {
  const int D = d.dimension();
  if (shape != "sphere" && r.has("layout"))
    r.fail("layout", "expected a layout only on a sphere (boxes, lenses and grain packs take the lattice)");
  if (shape == "grain_pack") return read_grain_pack(r, d);
  if (shape == "box") {
    Bounds b;
    b.dimension = D;
    r.box(D, b.lower, b.upper);
    return make_box(b);
  }
  if (shape == "lens") return read_lens(r, D);
  const std::array<double, 3> centre = r.vec<double>("center", D);
  const double radius = r.positive("radius");
  // "lattice": the domain's lattice sites inside; "concentric": shells fitted to the surface.
  const bool concentric = r.choice("layout", {"lattice", "concentric"}, "lattice") == "concentric";
  // Its shells are placed whole before the domain clips them.
  auto sphere = make_sphere(centre, radius, concentric, D);
  const double points = sphere->point_estimate(d.c.scene.options.spacing);
  if (!(points <= kMaxParticles))
    r.fail("radius", "expected a concentric sphere of at most 4e8 particles, got about " +
                         CaseReader::fmt(points));
  return sphere;
}

// What fills the shape, and how it moves at the start.
void read_filling(CaseReader& r, CaseDraft& d, GeometryShape& s, bool pack) {
  const std::vector<SceneMaterial>& mats = d.c.scene.materials;
  const std::string mname = r.string("material");
  if (mname == "empty") s.material = -1;
  else if (d.mat_index.count(mname)) s.material = d.mat_index.at(mname);
  else r.fail("material", "expected \"empty\" or the name of a table under [materials], got \"" + shown(mname) + "\"");
  const bool rigid = s.material >= 0 && mats[s.material].props.kind == MaterialKind::Rigid;
  if (pack && rigid)
    r.fail("material", "expected a box or a sphere for a rigid material (each geometry is one rigid body: a "
                       "grain pack would move as one clump)");
  s.velocity = r.vec<double>("velocity", d.dimension(), std::array<double, 3>{0, 0, 0});
  // A rigid body's initial angular velocity (rad/s) about its centre of mass: a number in 2D
  // (about z), a vector in 3D.
  if (r.has("angular_velocity")) {
    if (!rigid) r.fail("angular_velocity", "expected a geometry of a material with kind = \"rigid\" for it to apply to");
    if (d.dimension() == 1) r.fail("angular_velocity", "expected no rotation in 1D");
    if (d.dimension() == 2) s.angular_velocity[2] = r.number("angular_velocity");
    else s.angular_velocity = r.vec<double>("angular_velocity", 3);
  }
}

}  // namespace

void read_geometry(CaseReader& top, CaseDraft& d) {
  const toml::node* g = top.node("geometry");
  if (!g) top.fail("geometry", "missing required array of tables [[geometry]]");
  const toml::array* arr = g->as_array();
  if (!arr || arr->empty() || !arr->is_array_of_tables()) top.fail("geometry", "expected an array of tables [[geometry]]", g);
  std::size_t index = 0;
  top.each_table("geometry", arr->size(), "shapes", [&](CaseReader& r) {
    GeometryShape s;
    s.name = "geometry[" + std::to_string(index++) + "]";
    const std::string shape = r.choice("shape", {"box", "sphere", "lens", "grain_pack", "image"});
    if (shape == "image") return read_image_geometry(r, d, index - 1);  // a shape per material (scene/read_image.cpp)
    s.shape = read_shape(r, d, shape);
    require_overlap(r, d.c.scene, s.shape->bounds(), shape == "box" ? "upper" : shape == "grain_pack" ? "lower" : "center");
    read_filling(r, d, s, shape == "grain_pack");
    d.c.geometry.push_back(s);
  });
}

}  // namespace psph
