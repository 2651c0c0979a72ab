#include "catalyst/vis_settings.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "kernels/kernel.hpp"
#include "state/derived_fields.hpp"

namespace psph {
namespace {

using V3 = std::array<double, 3>;

V3 add(V3 a, V3 b, double s = 1) { return {a[0] + s * b[0], a[1] + s * b[1], a[2] + s * b[2]}; }
double norm(V3 a) { return std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]); }
V3 unit(V3 a) {
  const double l = norm(a);
  return {a[0] / l, a[1] / l, a[2] / l};
}

V3 cross(V3 a, V3 b) { return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}; }

// Parallel projection of a width x height rectangle centred on the focal point, with a 5 % margin;
// with a scalar bar, the scene moves left so that the right 20 % of the image stays free for it.
void frame_parallel(CameraOptions& c, double width, double height, double aspect, bool scalar_bar) {
  const double used = scalar_bar ? 0.8 : 1.0;
  c.parallel_scale = 0.55 * std::max(height, width / (aspect * used));
  const V3 right = unit(cross(add(c.focal_point, c.position, -1), c.view_up));
  const double shift = (1 - used) * c.parallel_scale * aspect;  // half the freed width
  c.focal_point = add(c.focal_point, right, shift);
  c.position = add(c.position, right, shift);
}

nlohmann::json camera_json(const CameraOptions& c) {
  nlohmann::json j = {{"position", c.position}, {"focal_point", c.focal_point}, {"view_up", c.view_up}};
  if (c.parallel_scale > 0) j["parallel_scale"] = c.parallel_scale;
  return j;
}

// Axis "up": against the first non-zero body force, else y in 2D and z in 3D.
int up_axis(const Scene& s) {
  for (const auto& m : s.materials) {
    int best = -1;
    double big = 0;
    for (int k = 0; k < s.dimension; ++k)
      if (std::fabs(m.body_force[k]) > big) big = std::fabs(m.body_force[k]), best = k;
    if (best >= 0) return best;
  }
  return s.dimension == 3 ? 2 : 1;
}

// A field's default colour range: damage on [0, 1) (just below 1 so that fully damaged particles
// take the above-range colour), colour function on [-1, 1], stresses symmetric about zero,
// pressure from 0 to at least the hydrostatic rho0 |g| H, anything else the first frame's range.
std::array<double, 2> default_range(const std::string& name, const ParticleFrame& f, double pressure_scale) {
  if (name == "damage") return {0.0, 0.999};
  if (name == "colour") return {-1.0, 1.0};  // gas -1, liquid +1 (Pazdniakou eq. 6)
  const StagedField* s = f.find(name);
  double lo = 0, hi = 0, big = 0;
  if (s && !s->data.empty()) {
    lo = hi = s->data[0];
    for (float v : s->data) lo = std::min<double>(lo, v), hi = std::max<double>(hi, v), big = std::max<double>(big, std::fabs(v));
  }
  if (name == "principal_stress") return big > 0 ? std::array<double, 2>{-big, big} : std::array<double, 2>{-1.0, 1.0};
  // Pressure: at least the hydrostatic range, since a run often starts at rest with p ~ 0.
  // Round-off below zero (a fluid at rest) is not a range worth showing.
  if (name == "pressure") {
    const double top = std::max(hi, pressure_scale);
    return {lo < -1e-3 * top ? lo : 0.0, top};
  }
  if (hi > lo) return {lo, hi};
  return {lo - 1, hi + 1};
}

// Vertical extent of the water and gas particles plus one spacing (`fallback` without phases).
double fluid_height(const ParticleFrame& f, int up, double spacing, double fallback) {
  const StagedField* phase = f.find("phase");
  if (!phase) return fallback;
  double lo = HUGE_VAL, hi = -HUGE_VAL;
  for (int i = 0; i < f.n; ++i)
    if (phase->data[i] == float(Phase::Water) || phase->data[i] == float(Phase::Gas))
      lo = std::min<double>(lo, f.position[3 * i + up]), hi = std::max<double>(hi, f.position[3 * i + up]);
  return hi >= lo ? hi - lo + spacing : fallback;
}

}  // namespace

nlohmann::json resolve_vis_settings(const Case& c, const ParticleFrame& first, const std::string& images_dir,
                                    const std::string& extracts_dir, const std::string& live_url) {
  const VisualisationOptions& v = c.visualisation;
  const Scene& s = c.scene;
  const int D = s.dimension;
  V3 lo{0, 0, 0}, hi{0, 0, 0};
  for (int k = 0; k < D; ++k) lo[k] = s.lower[k], hi[k] = s.upper[k];
  const V3 centre = add(lo, add(hi, lo, -1), 0.5);
  const V3 extent = add(hi, lo, -1);
  const double aspect = double(v.image_size[0]) / v.image_size[1];
  const int up = up_axis(s);
  V3 up_v{0, 0, 0};
  up_v[up] = 1;

  nlohmann::json j;
  j["dimension"] = D;
  j["image_size"] = v.image_size;
  j["images_dir"] = images_dir;
  j["extracts_dir"] = extracts_dir;
  j["point_radius"] = v.point_radius > 0 ? v.point_radius : 0.5 * s.options.spacing;
  // The domain and a point's radius around it: where every process's renderer may draw.
  const double r = j["point_radius"].get<double>();
  j["bounds"] = {lo[0] - r, hi[0] + r, lo[1] - r, hi[1] + r, lo[2] - r, hi[2] + r};
  j["scalar_bar"] = v.scalar_bar;
  j["time_label"] = v.time_label;
  j["live_url"] = live_url;

  // Default 3D camera: from the side of the longer horizontal extent, a little from above, the
  // whole domain in a 30-degree view angle. 2D: looking down z, parallel projection.
  int a = (up + 1) % 3, b = (up + 2) % 3;
  if (extent[a] < extent[b]) std::swap(a, b);  // a: the longer horizontal axis, seen face on
  CameraOptions cam = v.camera;
  if (!cam.set) {
    cam.focal_point = centre;
    cam.view_up = up_v;
    if (D == 3) {
      V3 dir{0, 0, 0};
      dir[a] = 0.3, dir[b] = 1.0, dir[up] = 0.5;
      const double dist = 0.55 * norm(extent) / std::tan(M_PI / 12);
      cam.position = add(centre, unit(dir), dist);
    } else {
      cam.position = add(centre, V3{0, 0, 1}, norm(extent));
      frame_parallel(cam, extent[0], extent[1], aspect, v.scalar_bar);
    }
  }
  j["camera"] = camera_json(cam);

  // Default slab: through the domain centre, normal to the camera's depth axis, one smoothing length thick.
  V3 n = v.slab_normal, o = v.slab_set ? v.slab_origin : centre;
  if (!v.slab_set && D == 3) n = {0, 0, 0}, n[b] = 1;
  n = unit(n);
  const double h = s.options.support_radius / support_per_smoothing_length(s.options.kernel);
  CameraOptions sc = v.slab_camera;
  if (!sc.set) {
    sc.focal_point = o;
    sc.position = add(o, n, norm(extent));
    const bool up_in_plane = std::fabs(n[up]) < 0.9;
    sc.view_up = up_in_plane ? up_v : V3{double(a == 0), double(a == 1), double(a == 2)};
    const int vert = up_in_plane ? up : a;
    int horiz = 0;
    while (horiz == vert || std::fabs(n[horiz]) > 0.9) ++horiz;
    frame_parallel(sc, extent[horiz], extent[vert], aspect, v.scalar_bar);
  }
  j["slab"] = {{"origin", o},
               {"normal", n},
               {"half_thickness", v.slab_half_thickness > 0 ? v.slab_half_thickness : h},
               {"camera", camera_json(sc)}};

  // Hydrostatic scale rho0 |g| H, for a pressure range when the first frame is at rest and flat;
  // H is the fluid's height when the frame has phases, else the domain's.
  const double height = fluid_height(first, up, s.options.spacing, extent[up]);
  double p_scale = 0;
  for (const auto& m : s.materials)
    if (m.props.kind == MaterialKind::Fluid)
      p_scale = std::max(p_scale, double(m.props.rest_density) * norm(m.body_force) * height);
  if (p_scale <= 0) p_scale = 1;
  nlohmann::json ranges = nlohmann::json::object(), maps = nlohmann::json::object();
  for (const StagedField& f : first.fields) {
    if (f.name == "phase") continue;  // categorical
    const auto it = v.ranges.find(f.name);
    ranges[f.name] = it != v.ranges.end() ? it->second : default_range(f.name, first, p_scale);
    // Displacements start at zero: a fifth of a spacing either way (small-strain solids).
    if (f.name == "displacement" && it == v.ranges.end())
      ranges[f.name] = std::array<double, 2>{-0.2 * c.scene.options.spacing, 0.2 * c.scene.options.spacing};
  }
  for (const auto& [name, r] : v.ranges) ranges[name] = r;
  maps["pressure"] = "Viridis (matplotlib)";
  maps["damage"] = "Inferno (matplotlib)";
  maps["principal_stress"] = "Cool to Warm";
  maps["displacement"] = "Cool to Warm";
  maps["colour"] = "Blue Orange (divergent)";
  for (const auto& [name, m] : v.colour_maps) maps[name] = m;
  j["ranges"] = ranges;
  j["colour_maps"] = maps;
  return j;
}

}  // namespace psph
