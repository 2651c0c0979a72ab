// [sample] expanded into the ordinary tables (scene/sample_table.hpp).
#include "scene/sample_table.hpp"

#include <algorithm>
#include <cmath>

#include "kernels/kernel.hpp"
#include "scene/case_reader.hpp"
#include "scene/case_tables.hpp"
#include "scene/open_image.hpp"

namespace psph {
namespace {

using Vec3 = std::array<double, 3>;

// A number or an array of `D` numbers of the image table (the image reader checks them again).
Vec3 per_axis(CaseReader& r, const std::string& key, int D, double def) {
  Vec3 v{def, def, def};
  if (!r.has(key)) return v;
  if (r.node(key)->is_array()) return r.vec<double>(key, D);
  v.fill(r.positive(key));
  return v;
}

// The image's voxels along x, y, z as the case will hold them: the crop, or the file's own size
// (the crop's upper 0: to the file's end, as the image reader takes it).
std::array<long, 3> file_voxels(CaseReader& r, const std::string& case_file) {
  std::array<long, 3> lo{0, 0, 0}, hi{0, 0, 0};
  if (r.has("crop")) {
    CaseReader c(r.table("crop", true), case_file, r.qualified("crop"));
    lo = c.vec<long>("lower", 3), hi = c.vec<long>("upper", 3);
    if (hi[0] > 0 && hi[1] > 0 && hi[2] > 0) return {hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]};
  }
  std::string format, found;
  const auto src = open_image(r, case_file, format, found);  // the image reader's own, on the same keys
  std::array<long, 3> n{1, 1, 1};
  for (int s = 0; s < 3; ++s) n[std::size_t(src->storage_axes()[std::size_t(s)])] = src->size()[std::size_t(s)];
  for (int k = 0; k < 3; ++k) n[std::size_t(k)] = (hi[std::size_t(k)] > 0 ? hi[std::size_t(k)] : n[std::size_t(k)]) - lo[std::size_t(k)];
  return n;
}

toml::array array_of(const Vec3& v, int D) {
  toml::array a;
  for (int k = 0; k < D; ++k) a.push_back(v[std::size_t(k)]);
  return a;
}

toml::table box(const Vec3& lo, const Vec3& hi, int D) {
  return toml::table{{"lower", array_of(lo, D)}, {"upper", array_of(hi, D)}};
}

// A material's kind as the file states it ("" when it does not).
std::string kind_of(const toml::table& tbl, const std::string& name) {
  return tbl["materials"][name]["kind"].value_or(std::string());
}

struct Cell {
  int D = 3, axis = 2;
  Vec3 sample{}, origin{}, extent{};  // the image's size, its lower corner, the domain's upper corner
  double lateral = 0, reservoir = 0, plate = 0;  // thicknesses (m); plate: whole voxels along the axis
  double margin = 0;  // empty space beyond the lateral layer, into which its faces may bulge (m)
  // The box of the particles: the domain less the margins on the lateral axes.
  Vec3 outer_lower() const {
    Vec3 v{margin, margin, margin};
    v[std::size_t(axis)] = 0;
    return v;
  }
  Vec3 outer_upper() const {
    Vec3 v{extent[0] - margin, extent[1] - margin, extent[2] - margin};
    v[std::size_t(axis)] = extent[std::size_t(axis)];
    return v;
  }
  // Inside the lateral layer, along the whole flow axis.
  Vec3 inner_lower() const {
    Vec3 v = outer_lower();
    for (int k = 0; k < D; ++k) v[std::size_t(k)] += k == axis ? 0 : lateral;
    return v;
  }
  Vec3 inner_upper() const {
    Vec3 v = outer_upper();
    for (int k = 0; k < D; ++k) v[std::size_t(k)] -= k == axis ? 0 : lateral;
    return v;
  }
};

// The geometries: walls around everything, the lateral layer beside the sample (between the
// plates), the reservoirs' gas inside, the image over it (later geometries win).
toml::array geometries(const Cell& c, toml::table img, const std::string& walls, const std::string& lateral,
                       const std::string& gas, double plate_thickness, double guard) {
  const int D = c.D, a = c.axis;
  toml::array g;
  auto add = [&](Vec3 lo, Vec3 hi, const std::string& m) {
    toml::table t = box(lo, hi, D);
    t.insert("shape", "box"), t.insert("material", m);
    g.push_back(std::move(t));
  };
  add(c.outer_lower(), c.outer_upper(), walls);
  Vec3 lo = c.outer_lower(), hi = c.outer_upper();
  lo[a] = c.origin[a] + c.plate, hi[a] = c.origin[a] + c.sample[a] - c.plate;
  if (lateral != walls) add(lo, hi, lateral);
  add(c.inner_lower(), c.inner_upper(), gas);
  img.insert_or_assign("shape", "image");
  img.insert_or_assign("origin", array_of(c.origin, D));
  img.insert_or_assign("end_plates", walls);
  img.insert_or_assign("end_plate_thickness", plate_thickness);
  img.insert_or_assign("end_plate_axis", std::string(1, "xyz"[a]));
  if (guard > 0) img.insert_or_assign("end_guard", lateral), img.insert_or_assign("end_guard_thickness", guard);
  g.push_back(std::move(img));
  return g;
}

// The reservoirs' gas driven along -axis: rho_g |F| (2 H_r) = pressure drop.
toml::array drive(const Cell& c, const std::string& gas, double force, double ramp) {
  const int D = c.D, a = c.axis;
  toml::array regions;
  for (int side = 0; side < 2; ++side) {
    Vec3 lo = c.inner_lower(), hi = c.inner_upper();
    lo[a] = side ? c.origin[a] + c.sample[a] : 0, hi[a] = side ? c.extent[a] : c.origin[a];
    Vec3 f{0, 0, 0};
    f[a] = -force;
    toml::table t = box(lo, hi, D);
    t.insert("material", gas), t.insert("body_force", array_of(f, D));
    if (ramp > 0) t.insert("ramp_time", ramp);
    regions.push_back(std::move(t));
  }
  return regions;
}

// The confinement: traction -sigma n_out on the outermost layer of each lateral face.
toml::array confinement(const Cell& c, const std::string& lateral, double sigma, double ramp, double spacing) {
  const int D = c.D, a = c.axis;
  toml::array loads;
  for (int k = 0; k < D; ++k) {
    if (k == a) continue;
    for (int side = 0; side < 2; ++side) {
      Vec3 lo = c.outer_lower(), hi = c.outer_upper(), t{0, 0, 0};
      lo[a] = c.origin[a] + c.plate, hi[a] = c.origin[a] + c.sample[a] - c.plate;
      if (side) lo[k] = hi[k] - spacing;
      else hi[k] = lo[k] + spacing;
      t[k] = side ? -sigma : sigma;
      toml::table l = box(lo, hi, D);
      l.insert("material", lateral), l.insert("traction", array_of(t, D));
      if (ramp > 0) l.insert("ramp_time", ramp);
      loads.push_back(std::move(l));
    }
  }
  return loads;
}

}  // namespace

bool expand_sample(toml::table& tbl, const std::string& file) {
  if (!tbl.contains("sample")) return false;
  const toml::table* sample = tbl["sample"].as_table();
  if (!sample) throw CaseError(file + ": sample" + toml_line_of(*tbl.get("sample")) + ": expected a table");
  CaseReader r(*sample, file, "sample");
  for (const char* t : {"domain", "monitors", "body_force_region", "solid_load"})
    if (tbl.contains(t))
      throw CaseError(file + ": " + t + toml_line_of(*tbl.get(t)) + ": expected it from [sample] alone: the sample makes "
                      "the domain, the monitors' region, the reservoirs' drive and the confinement (remove it)");
  Cell c;
  c.D = int(tbl["case"]["dimension"].value_or(int64_t(3)));
  if (c.D < 2 || c.D > 3) throw CaseError(file + ": sample: expected a 2D or 3D case ([case] dimension)");
  const auto spacing = tbl["discretisation"]["spacing"].value<double>();
  if (!spacing || !(*spacing > 0))
    throw CaseError(file + ": sample: expected [discretisation] spacing (> 0) for the sample's layers");
  c.axis = r.axis("flow_axis", c.D, std::string(1, "xyz"[c.D - 1]));
  const std::string lateral = r.string("lateral_material"), walls = r.string("plate_material");
  const std::string gas = r.string("reservoir_material");
  if (kind_of(tbl, lateral) != "elastic" && kind_of(tbl, lateral) != "wall")
    r.fail("lateral_material", "expected an elastic or wall material under [materials], got \"" + shown(lateral) + "\"");
  if (kind_of(tbl, walls) != "wall") r.fail("plate_material", "expected a wall material under [materials], got \"" + shown(walls) + "\"");
  const auto rho_g = tbl["materials"][gas]["density"].value<double>();
  if (kind_of(tbl, gas) != "fluid" || !rho_g || !(*rho_g > 0))
    r.fail("reservoir_material", "expected a fluid with a density under [materials], got \"" + shown(gas) + "\"");
  c.lateral = r.positive("lateral_thickness");
  // Two support radii (at least four spacings) of empty space beyond the lateral faces: a face that
  // the pore water pushes out by half a spacing would otherwise leave the domain and stop the run.
  const KernelType kernel = kernel_from(tbl["discretisation"]["kernel"].value_or(std::string("cubic_spline")));
  const double support = tbl["discretisation"]["support_radius"].value_or(
      tbl["discretisation"]["smoothing_length"].value_or(*spacing) * double(support_per_smoothing_length(kernel)));
  c.margin = std::max(4.0, std::ceil(2 * support / *spacing - 1e-9)) * *spacing;
  c.reservoir = r.positive("reservoir_height");
  const double plate_thickness = r.positive("plate_thickness", *spacing);
  const double guard = r.non_negative("plate_guard_thickness", 0.0);
  if (guard > 0 && kind_of(tbl, lateral) != "elastic")
    r.fail("plate_guard_thickness", "expected an elastic lateral_material for the guard (\"" + shown(lateral) + "\" is a wall)");
  const double dp = r.positive("pressure_drop"), sigma = r.non_negative("confinement", 0.0);
  const double drive_ramp = r.non_negative("drive_ramp", 0.0), conf_ramp = r.non_negative("confinement_ramp", 0.0);
  if (sigma > 0 && kind_of(tbl, lateral) != "elastic")
    r.fail("confinement", "expected an elastic lateral_material to carry it (\"" + shown(lateral) + "\" is a wall)");
  if (c.lateral < support * (1 - 1e-9))
    r.fail("lateral_thickness", "expected at least the support radius (" + CaseReader::fmt(support) + " m): the layer "
                                "keeps the fluids from the empty margin beyond it, got " + CaseReader::fmt(c.lateral));
  for (const auto& [key, v] : std::array<std::pair<const char*, double>, 2>{{{"lateral_thickness", c.lateral}, {"reservoir_height", c.reservoir}}})
    if (v < *spacing * (1 - 1e-9) || std::fabs(v / *spacing - std::round(v / *spacing)) > 1e-6 * v / *spacing)
      r.fail(key, "expected a whole number of spacings (" + CaseReader::fmt(*spacing) + " m), got " + CaseReader::fmt(v));
  CaseReader img(r.table("image", true), file, "sample.image");
  for (const char* k : {"shape", "origin", "end_plates", "end_plate_thickness", "end_plate_axis", "end_guard", "end_guard_thickness"})
    if (img.has(k)) img.fail(k, "expected it from [sample] (remove it)");
  const Vec3 voxel = per_axis(img, "voxel_size", c.D, 0.0);
  Vec3 coarsen{1, 1, 1};
  if (img.has("coarsen")) coarsen = per_axis(img, "coarsen", c.D, 1.0);
  const std::array<long, 3> n = file_voxels(img, file);
  for (int k = 0; k < c.D; ++k) {
    if (!(voxel[std::size_t(k)] > 0)) img.fail("voxel_size", "missing required value (expected a number > 0)");
    const double cv = voxel[std::size_t(k)] * coarsen[std::size_t(k)];
    c.sample[std::size_t(k)] = std::floor(double(n[std::size_t(k)]) / coarsen[std::size_t(k)]) * cv;
    c.origin[std::size_t(k)] = k == c.axis ? c.reservoir : c.margin + c.lateral;
    c.extent[std::size_t(k)] = c.sample[std::size_t(k)] + 2 * c.origin[std::size_t(k)];
  }
  const double cv = voxel[std::size_t(c.axis)] * coarsen[std::size_t(c.axis)];
  c.plate = std::ceil(plate_thickness / cv - 1e-9) * cv;
  if (!(2 * c.plate < c.sample[std::size_t(c.axis)] * (1 - 1e-9)))
    r.fail("plate_thickness", "expected two plates thinner than half the sample along the flow axis (" +
                                  CaseReader::fmt(c.sample[std::size_t(c.axis)]) + " m), got " + CaseReader::fmt(c.plate) + " each");
  if (guard > 0 && !(2 * (c.plate + std::ceil(guard / cv - 1e-9) * cv) < c.sample[std::size_t(c.axis)] * (1 - 1e-9)))
    r.fail("plate_guard_thickness", "expected two plates and their guards thinner than half the sample along the flow axis (" +
                                        CaseReader::fmt(c.sample[std::size_t(c.axis)]) + " m), got " + CaseReader::fmt(guard) + " each");
  const auto percolation_distance = r.has("percolation_distance") ? r.positive("percolation_distance") : 0.0;
  r.finish();

  // Moved, not copied: toml++ keeps a node's source (its line, which the image's label order and
  // the messages use) only on a move.
  toml::array geometry = geometries(c, std::move(*tbl["sample"]["image"].as_table()), walls, lateral, gas, plate_thickness, guard);
  if (toml::array* user = tbl["geometry"].as_array())
    for (auto& g : *user) geometry.push_back(std::move(g));
  std::array<bool, 3> periodic{false, false, false};
  periodic[std::size_t(c.axis)] = true;
  toml::array per;
  for (int k = 0; k < c.D; ++k) per.push_back(periodic[std::size_t(k)]);
  toml::table domain = box({0, 0, 0}, c.extent, c.D);
  domain.insert("periodic", per);
  Vec3 hi{};
  for (int k = 0; k < 3; ++k) hi[std::size_t(k)] = c.origin[std::size_t(k)] + c.sample[std::size_t(k)];
  toml::table monitors{{"region_lower", array_of(c.origin, c.D)}, {"region_upper", array_of(hi, c.D)},
                       {"flow_axis", std::string(1, "xyz"[c.axis])}};
  if (percolation_distance > 0) monitors.insert("percolation_distance", percolation_distance);
  tbl.erase("sample");
  tbl.insert_or_assign("domain", domain);
  tbl.insert_or_assign("monitors", monitors);
  tbl.insert_or_assign("geometry", std::move(geometry));
  tbl.insert_or_assign("body_force_region", drive(c, gas, dp / (*rho_g * 2 * c.reservoir), drive_ramp));
  if (sigma > 0) tbl.insert_or_assign("solid_load", confinement(c, lateral, sigma, conf_ramp, *spacing));
  return true;
}

}  // namespace psph
