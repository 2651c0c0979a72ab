// [[geometry]] shape = "image" (scene/image_shape.hpp): a segmented image's labels mapped to the
// case's materials, cropped and coarsened (image/phase_volume.hpp), its pore components selected
// (image/pore_components.hpp), and one shape per material. The image's report goes to the log and
// summary.json (Case::images).
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>

#include "image/image_error.hpp"
#include "image/deep_voxels.hpp"
#include "image/image_report.hpp"
#include "image/pore_components.hpp"
#include "image/volume_source.hpp"
#include "scene/case_tables.hpp"
#include "scene/image_path.hpp"
#include "scene/image_shape.hpp"
#include "scene/open_image.hpp"

namespace psph {
namespace {

constexpr double kMaxCoarseVoxels = 2147483647.0;  // the components' labels are 32-bit

// labels = { "0" = "water", "1..3" = "clay" }: each phase is a material (or "empty"), in the order
// the map first names them.
// "3" or "3..7" (labels of at most 18 digits, either sign).
bool label_range(const std::string& key, LabelRange& lr) {
  auto number = [](const std::string& t, std::int64_t& v) {
    const std::size_t digits = t.size() - (t.size() && t[0] == '-');
    if (digits < 1 || digits > 18 || t.find_first_not_of("0123456789", t[0] == '-') != std::string::npos) return false;
    v = std::stoll(t);
    return true;
  };
  const std::size_t dots = key.find("..");
  if (dots == std::string::npos) return number(key, lr.lo) && (lr.hi = lr.lo, true);
  return number(key.substr(0, dots), lr.lo) && number(key.substr(dots + 2), lr.hi) && lr.lo <= lr.hi;
}

struct Phases {
  std::vector<int> material;  // per phase: the material index, -1 for "empty"
  unsigned pore = 0;          // phases of fluid materials
};

Phases read_labels(CaseReader& r, const CaseDraft& d, PhaseSpec& spec) {
  const toml::table& t = r.table("labels", true);
  // In the file's order (a TOML table is sorted by key): the order names the phases.
  std::vector<std::pair<std::string, const toml::node*>> entries;
  for (const auto& [k, v] : t) entries.emplace_back(std::string(k.str()), &v);
  std::stable_sort(entries.begin(), entries.end(), [](const auto& a, const auto& b) {
    const auto &p = a.second->source().begin, &q = b.second->source().begin;
    return p.line != q.line ? p.line < q.line : p.column < q.column;
  });
  Phases ph;
  for (const auto& [key, v] : entries) {
    const std::string where = "labels." + key;
    LabelRange lr;
    if (!label_range(key, lr)) r.fail(where, "expected a label (\"3\") or a range of labels (\"3..7\") as the key", v);
    for (const LabelRange& o : spec.labels)
      if (lr.lo <= o.hi && o.lo <= lr.hi) r.fail(where, "expected ranges that do not overlap: it shares labels with an earlier one", v);
    const auto name = v->value_exact<std::string>();
    if (!name) r.fail(where, "expected the name of a material or \"empty\"", v);
    int mat = -1;
    if (*name != "empty") {
      if (!d.mat_index.count(*name)) r.fail(where, "expected \"empty\" or the name of a table under [materials], got \"" + shown(*name) + "\"", v);
      mat = d.mat_index.at(*name);
    }
    const auto it = std::find(ph.material.begin(), ph.material.end(), mat);
    lr.phase = int(it - ph.material.begin());
    if (it == ph.material.end()) ph.material.push_back(mat);
    spec.labels.push_back(lr);
  }
  if (spec.labels.empty()) r.fail("labels", "expected at least one label mapped to a material");
  if (ph.material.size() > 32) r.fail("labels", "expected at most 32 materials (and \"empty\") in an image");
  for (std::size_t p = 0; p < ph.material.size(); ++p)
    if (ph.material[p] >= 0 && d.c.scene.materials[std::size_t(ph.material[p])].props.kind == MaterialKind::Fluid)
      ph.pore |= 1u << p;
  spec.phases = int(ph.material.size());
  spec.pore_phases = ph.pore;
  return ph;
}

// crop = { lower = [...], upper = [...] } (voxels of the file, upper excluded); coarsen = n or
// [nx, ny, nz]; in 2D the layer `slice` (coarse voxels along z) alone.
void read_extent(CaseReader& r, const CaseDraft& d, const VolumeSource& src, PhaseSpec& spec, long& slice) {
  if (r.has("crop")) {
    CaseReader c(r.table("crop", true), d.file, r.qualified("crop"));
    spec.crop_lower = c.vec<long>("lower", 3), spec.crop_upper = c.vec<long>("upper", 3);
    c.finish();
  }
  const toml::node* n = r.node("coarsen");  // one factor, or one per axis of the case (2D: z not coarsened)
  const int D = d.dimension();
  if (n && n->is_array()) {
    const auto f = r.vec<long>("coarsen", D);
    for (int k = 0; k < D; ++k) spec.coarsen[k] = int(f[k]);
  } else if (n) {
    for (int k = 0; k < D; ++k) spec.coarsen[k] = int(r.positive_integer("coarsen", 1));
  }
  for (int f : spec.coarsen)
    if (f < 1 || f > 64) r.fail("coarsen", "expected factors from 1 to 64", n);
  slice = d.dimension() == 2 ? r.integer("slice", 0) : 0;
  if (d.dimension() != 2 && r.has("slice")) r.fail("slice", "expected a 2D case for it to apply to");
  if (d.dimension() == 1) r.fail("shape", "expected an image in a 2D or 3D case");
  if (d.dimension() == 2) {  // the file's layer `slice` (from the crop's lower corner) alone
    const auto size = src.size();
    const auto axes = src.storage_axes();
    long nz = 0;
    for (int s = 0; s < 3; ++s)
      if (axes[s] == 2) nz = size[s];
    const long lo = spec.crop_lower[2] + slice * spec.coarsen[2];
    if (slice < 0 || lo + spec.coarsen[2] > (spec.crop_upper[2] ? spec.crop_upper[2] : nz))
      r.fail("slice", "expected a layer of the image (it has " + std::to_string(nz) + " voxels along z)");
    spec.crop_lower[2] = lo, spec.crop_upper[2] = lo + spec.coarsen[2];
    slice = 0;
  }
}

// The phase of material `mat` (-1: "empty"), added when the labels named none.
std::uint8_t phase_of(CaseReader& r, Phases& ph, int mat, const char* key) {
  auto it = std::find(ph.material.begin(), ph.material.end(), mat);
  if (it != ph.material.end()) return std::uint8_t(it - ph.material.begin());
  if (ph.material.size() >= 32) r.fail(key, "expected at most 32 phases in an image");
  ph.material.push_back(mat);
  return std::uint8_t(ph.material.size() - 1);
}

// pores = "all" | "largest" | "percolating" (along percolation_axis) | a component's index; the
// others keep their material, or take other_pores.
void select_pores(CaseReader& r, const CaseDraft& d, ImageGrid& g, Phases& ph, const PoreComponents& c) {
  const toml::node* n = r.node("pores");
  std::vector<bool> keep(c.components.size(), true);
  if (n && n->is_integer()) {
    const long i = r.integer("pores");
    if (i < 0 || i >= long(c.components.size()))
      r.fail("pores", "expected a component's index from 0 to " + std::to_string(long(c.components.size()) - 1), n);
    keep.assign(keep.size(), false), keep[std::size_t(i)] = true;
  } else {
    const std::string how = r.choice("pores", {"all", "largest", "percolating"}, "all");
    if (how == "largest") keep.assign(keep.size(), false), keep[0] = true;
    if (how == "percolating") {
      const int axis = r.axis("percolation_axis", d.dimension());  // required
      for (std::size_t k = 0; k < keep.size(); ++k) keep[k] = c.components[k].percolates[std::size_t(axis)];
      if (std::find(keep.begin(), keep.end(), true) == keep.end())
        r.fail("pores", std::string("expected a pore component that percolates along ") + "xyz"[axis] + ": none does", n);
    }
  }
  const std::string other = r.string("other_pores", "keep");
  if (other == "keep") return;
  if (!d.mat_index.count(other) && other != "empty")
    r.fail("other_pores", "expected \"keep\", \"empty\" or the name of a table under [materials], got \"" + shown(other) + "\"");
  const std::uint8_t to = phase_of(r, ph, other == "empty" ? -1 : d.mat_index.at(other), "other_pores");
  for (std::size_t i = 0; i < c.label.size(); ++i)
    if (c.label[i] >= 0 && !keep[std::size_t(c.label[i])]) g.volume.phase[i] = to;
}

// voxel_size (m, one number or one per axis), origin (the crop's lower corner; the domain's lower
// corner by default), particles_per_voxel (checked against the spacing), and the image inside the
// domain.
void place(CaseReader& r, const CaseDraft& d, ImageGrid& g, const PhaseSpec& spec) {
  const int D = d.dimension();
  const toml::node* n = r.node("voxel_size");
  std::array<double, 3> voxel{};
  if (n && n->is_array()) voxel = r.vec<double>("voxel_size", D);
  else voxel.fill(r.positive("voxel_size"));
  for (int k = 0; k < D; ++k) {
    if (!(voxel[k] > 0)) r.fail("voxel_size", "expected sizes > 0", n);
    g.voxel[k] = voxel[k] * spec.coarsen[k];
  }
  std::array<double, 3> lower{};
  for (int k = 0; k < D; ++k) lower[k] = d.c.scene.lower[k];
  g.origin = r.vec<double>("origin", D, lower);
  const double h = d.c.scene.options.spacing;
  if (r.has("particles_per_voxel")) {
    const long p = r.positive_integer("particles_per_voxel", 1);
    for (int k = 0; k < D; ++k)
      if (std::fabs(g.voxel[k] - double(p) * h) > 1e-9 * g.voxel[k])
        r.fail("particles_per_voxel", "expected the coarse voxel (" + CaseReader::fmt(g.voxel[k]) + " m along " + "xyz"[k] +
                                          ") to be " + std::to_string(p) + " x discretisation.spacing (" +
                                          CaseReader::fmt(h) + " m)");
  }
  for (int k = 0; k < D; ++k) {
    const double hi = g.origin[k] + double(g.volume.size[k]) * g.voxel[k];
    if (g.origin[k] < d.c.scene.lower[k] - 1e-9 * g.voxel[k] || hi > d.c.scene.upper[k] + 1e-9 * g.voxel[k])
      r.fail("origin", std::string("expected the image inside the domain: along ") + "xyz"[k] + " it spans [" +
                           CaseReader::fmt(g.origin[k]) + ", " + CaseReader::fmt(hi) + "] m, the domain [" +
                           CaseReader::fmt(d.c.scene.lower[k]) + ", " + CaseReader::fmt(d.c.scene.upper[k]) + "] m");
  }
}

// wall_depth (m): a wall material's voxels farther than this from another material's voxel (or
// the image's faces) hold no particle: a rigid wall acts only within a support radius.
void trim_walls(CaseReader& r, const CaseDraft& d, ImageGrid& g, Phases& ph) {
  if (!r.has("wall_depth")) return;
  const double depth = r.positive("wall_depth");
  if (depth < d.c.scene.options.support_radius)
    r.fail("wall_depth", "expected at least the support radius (" + CaseReader::fmt(d.c.scene.options.support_radius) +
                             " m): the fluid next to a wall sums its particles that far");
  unsigned walls = 0;
  for (std::size_t p = 0; p < ph.material.size(); ++p)
    if (ph.material[p] >= 0 && d.c.scene.materials[std::size_t(ph.material[p])].props.kind == MaterialKind::Wall)
      walls |= 1u << p;
  std::array<long, 3> reach{0, 0, 0};
  for (int k = 0; k < d.dimension(); ++k) reach[std::size_t(k)] = long(std::ceil(depth / g.voxel[std::size_t(k)] - 1e-9));
  replace_deep_voxels(g.volume, walls, reach, d.dimension(), phase_of(r, ph, -1, "wall_depth"));
}

// end_plates (a wall material), end_plate_thickness (m), end_plate_axis (default the case's last):
// the voxels of solid materials within that thickness of the image's two faces along the axis take
// the wall material, the pores stay open (Pazdniakou 2018 §5.2: rigid plates hold the sample top
// and bottom, so that it does not drift, and gas enters and water leaves through its pores).
// end_guard (an elastic material), end_guard_thickness (m): the elastic voxels within that
// thickness beyond each plate take it (an undamaged guard between the plates' clamp and a damaging
// matrix: fully damaged particles beside the clamp made the claystone cell unstable, VALIDATION.md).
void end_plates(CaseReader& r, const CaseDraft& d, ImageGrid& g, Phases& ph) {
  for (const char* key : {"end_plate_thickness", "end_plate_axis", "end_guard"})
    if (!r.has("end_plates") && r.has(key)) r.fail(key, "expected end_plates (a wall material) for it to apply to");
  if (r.has("end_guard_thickness") && !r.has("end_guard")) r.fail("end_guard_thickness", "expected end_guard (an elastic material) for it to apply to");
  if (!r.has("end_plates")) return;
  const int plate = d.material(r, "end_plates", MaterialKind::Wall, "a wall material");
  const int axis = r.axis("end_plate_axis", d.dimension(), std::string(1, "xyz"[d.dimension() - 1]));
  const double voxel = g.voxel[std::size_t(axis)];
  const long n = g.volume.size[std::size_t(axis)], layers = long(std::ceil(r.positive("end_plate_thickness") / voxel - 1e-9));
  long guard = 0;
  int guard_mat = -1;
  if (r.has("end_guard")) {
    guard_mat = d.material(r, "end_guard", MaterialKind::Elastic, "an elastic material");
    guard = long(std::ceil(r.positive("end_guard_thickness") / voxel - 1e-9));
  }
  if (2 * (layers + guard) >= n)
    r.fail(guard ? "end_guard_thickness" : "end_plate_thickness",
           "expected two plates" + std::string(guard ? " and their guards" : "") + " thinner than half the image along " +
               std::string(1, "xyz"[axis]) + " (" + std::to_string(n) + " voxels; they take " + std::to_string(layers + guard) + " each)");
  const std::uint8_t to = phase_of(r, ph, plate, "end_plates");
  const std::uint8_t to_guard = guard ? phase_of(r, ph, guard_mat, "end_guard") : to;
  const auto& size = g.volume.size;
  auto kind = [&](int m) { return d.c.scene.materials[std::size_t(m)].props.kind; };
  for (long i = 0; i < g.volume.voxels(); ++i) {
    const std::array<long, 3> q{i % size[0], i / size[0] % size[1], i / (size[0] * size[1])};
    const long a = q[std::size_t(axis)], from_face = std::min(a, n - 1 - a);
    const int m = ph.material[g.volume.phase[std::size_t(i)]];
    if (m < 0 || kind(m) == MaterialKind::Fluid) continue;
    if (from_face < layers) g.volume.phase[std::size_t(i)] = to;
    else if (from_face < layers + guard && kind(m) == MaterialKind::Elastic) g.volume.phase[std::size_t(i)] = to_guard;
  }
}

bool is_rigid(const CaseDraft& d, int mat) {
  return mat >= 0 && d.c.scene.materials[std::size_t(mat)].props.kind == MaterialKind::Rigid;
}

// Each face-connected inclusion of a rigid material's voxels is one rigid body (a shape of its
// own); inclusions of fewer than inclusion_min_voxels coarse voxels take the material
// small_inclusions instead (a body of a particle or two has no inertia to turn with).
void add_inclusions(CaseReader& r, CaseDraft& d, const std::shared_ptr<ImageGrid>& g, Phases& ph, const std::string& file,
                    const std::string& name) {
  unsigned rigid = 0;
  for (std::size_t p = 0; p < ph.material.size(); ++p)
    if (is_rigid(d, ph.material[p])) rigid |= 1u << p;
  for (const char* key : {"inclusion_min_voxels", "small_inclusions"})
    if (!rigid && r.has(key)) r.fail(key, "expected a label mapped to a rigid material for it to apply to");
  if (!rigid) return;
  const long min_voxels = r.positive_integer("inclusion_min_voxels", 1);
  std::uint8_t small = 0;
  if (min_voxels > 1 || r.has("small_inclusions")) {
    const std::string m = r.string("small_inclusions");  // required with a minimum
    if (m != "empty" && (!d.mat_index.count(m) || is_rigid(d, d.mat_index.at(m))))
      r.fail("small_inclusions", "expected \"empty\" or a material that is not rigid, got \"" + shown(m) + "\"");
    small = phase_of(r, ph, m == "empty" ? -1 : d.mat_index.at(m), "small_inclusions");
  }
  g->inclusion.assign(std::size_t(g->volume.voxels()), -1);
  for (std::size_t p = 0; p < ph.material.size(); ++p) {
    if (!(rigid >> p & 1u)) continue;
    const PoreComponents c = pore_components(g->volume, 1u << p, 6, file);
    std::vector<std::int32_t> body(c.components.size(), -1);
    std::vector<std::array<long, 3>> lo(c.components.size(), g->volume.size), hi(c.components.size(), {0, 0, 0});
    for (std::size_t k = 0; k < c.components.size(); ++k)
      if (c.components[k].voxels >= min_voxels) body[k] = std::int32_t(d.c.geometry.size() + k);
    const auto& n = g->volume.size;
    for (long i = 0; i < g->volume.voxels(); ++i) {
      const std::int32_t l = c.label[std::size_t(i)];
      if (l < 0) continue;
      if (body[std::size_t(l)] < 0) {
        g->volume.phase[std::size_t(i)] = small;
        continue;
      }
      g->inclusion[std::size_t(i)] = body[std::size_t(l)];
      const std::array<long, 3> q{i % n[0], i / n[0] % n[1], i / (n[0] * n[1])};
      for (int a = 0; a < 3; ++a) lo[std::size_t(l)][a] = std::min(lo[std::size_t(l)][a], q[a]), hi[std::size_t(l)][a] = std::max(hi[std::size_t(l)][a], q[a] + 1);
    }
    for (std::size_t k = 0; k < c.components.size(); ++k) {
      if (body[k] < 0) continue;
      GeometryShape s;
      s.name = name + " (inclusion " + std::to_string(k) + " of \"" + d.c.scene.materials[std::size_t(ph.material[p])].name +
               "\", " + std::to_string(c.components[k].voxels) + " voxels)";
      s.shape = make_image_inclusion(g, body[k], lo[k], hi[k]);
      s.material = ph.material[p];
      d.c.geometry.push_back(s);
    }
  }
}

}  // namespace

// The volume as the file is, with the raw keys checked against the format (scene/open_image.hpp).
std::unique_ptr<VolumeSource> open_image(CaseReader& r, const std::string& case_file, std::string& format, std::string& file) {
  file = r.string("file");
  std::vector<std::string> tried;
  const std::string found = find_image_file(file, case_file, tried);
  if (found.empty()) {
    std::string list;
    for (const std::string& t : tried) list += (list.empty() ? "" : ", ") + t;
    r.fail("file", "expected an image file: \"" + shown(file) + "\" is at none of " + list +
                       " (a relative path: next to the case file, then in PORESPH_IMAGE_PATH's folders)");
  }
  file = found;
  format = r.choice("format", {"auto", "raw", "tiff", "npy"}, "auto");
  if (format == "auto") format = format_of(file);
  for (const char* key : {"dimensions", "voxel_type", "byte_order", "header_bytes", "order"})
    if (format != "raw" && r.has(key)) r.fail(key, "expected format = \"raw\" for it to apply to (the file is " + format + ")");
  if (format != "tiff" && r.has("first_page")) r.fail("first_page", "expected a TIFF series for it to apply to");
  RawSpec raw;
  if (format == "raw") {
    raw.dimensions = r.vec<long>("dimensions", 3);
    for (long n : raw.dimensions)
      if (n < 1) r.fail("dimensions", "expected at least 1 voxel along each axis");
    if (!parse_voxel_type(r.choice("voxel_type", {"uint8", "int8", "uint16", "int16", "uint32", "int32", "float32"}, "uint8"),
                          raw.type))
      r.fail("voxel_type", "expected a voxel type");
    raw.big_endian = r.choice("byte_order", {"little", "big"}, "little") == "big";
    raw.header_bytes = r.integer("header_bytes", 0);
    if (raw.header_bytes < 0) r.fail("header_bytes", "expected a byte count >= 0");
    raw.order = r.choice("order", {"xyz", "xzy", "yxz", "yzx", "zxy", "zyx"}, "xyz");
  }
  const long first = r.integer("first_page", 0);
  try {
    return open_volume(file, format, &raw, first);
  } catch (const ImageError& e) {
    r.fail(e.topic().empty() ? "file" : e.topic(), e.what());
  }
}

void read_image_geometry(CaseReader& r, CaseDraft& d, std::size_t index) {
  std::string format, file;
  auto src = open_image(r, d.file, format, file);
  d.image_files.emplace_back(index, file);
  PhaseSpec spec;
  Phases ph = read_labels(r, d, spec);
  auto g = std::make_shared<ImageGrid>();
  g->dimension = d.dimension();
  read_extent(r, d, *src, spec, g->slice);
  try {
    g->volume = read_phases(*src, spec);
  } catch (const ImageError& e) {
    r.fail(e.topic().empty() ? "file" : e.topic(), e.what());
  }
  if (double(g->volume.voxels()) > kMaxCoarseVoxels) r.fail("coarsen", "expected at most 2^31 coarse voxels (coarsen or crop more)");
  const int connectivity = int(r.integer("connectivity", 6));
  if (connectivity != 6 && connectivity != 18 && connectivity != 26) r.fail("connectivity", "expected 6, 18 or 26");
  const PoreComponents c = pore_components(g->volume, ph.pore, connectivity, file);
  if (ph.pore && c.components.empty()) r.fail("labels", file + ": expected a pore space: no voxel has a fluid's label");
  ImageReportInput in;
  in.file = file, in.format = format, in.volume = &g->volume, in.pores = &c, in.pore_phases = ph.pore;
  in.coarsen = spec.coarsen, in.connectivity = connectivity, in.dimension = d.dimension();
  d.c.images.push_back(image_report(in));
  if (ph.pore) select_pores(r, d, *g, ph, c);
  for (const char* key : {"pores", "percolation_axis", "other_pores"})
    if (!ph.pore && r.has(key)) r.fail(key, "expected a label mapped to a fluid (the pore space) for it to apply to");
  place(r, d, *g, spec);
  end_plates(r, d, *g, ph);
  trim_walls(r, d, *g, ph);
  const std::string name = "geometry[" + std::to_string(index) + "]";
  add_inclusions(r, d, g, ph, file, name);
  for (std::size_t p = 0; p < ph.material.size(); ++p) {
    if (is_rigid(d, ph.material[p])) continue;
    GeometryShape s;
    s.name = name;
    s.shape = make_image_phases(g, 1u << p);
    s.material = ph.material[p];
    d.c.geometry.push_back(s);
  }
}

}  // namespace psph
