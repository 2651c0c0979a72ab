#include "scene/visualisation_options.hpp"

#include "scene/case_reader.hpp"

namespace psph {
namespace {

CameraOptions camera(CaseReader& parent, const std::string& key, const std::string& file, const std::string& path) {
  CameraOptions c;
  if (!parent.has(key)) return c;
  CaseReader r(parent.table(key, false), file, path + "." + key);
  c.set = true;
  c.position = r.vec<double>("position", 3);
  c.focal_point = r.vec<double>("focal_point", 3);
  c.view_up = r.vec<double>("view_up", 3, std::array<double, 3>{0, 1, 0});
  c.parallel_scale = r.non_negative("parallel_scale", 0.0);
  r.finish();
  return c;
}

}  // namespace

VisualisationOptions parse_visualisation(const toml::table& table, const std::string& file) {
  VisualisationOptions v;
  CaseReader t(table, file, "visualisation");
  v.pipelines = t.strings("pipelines", {});
  v.interval = t.non_negative("interval", 0.0);
  v.every_frame = t.boolean("every_frame", false);
  const auto size = t.vec<double>("image_size", 2, std::array<double, 3>{800, 600, 0});
  for (int k = 0; k < 2; ++k) {
    if (!(size[k] >= 16 && size[k] <= 8192 && size[k] == static_cast<int>(size[k])))
      t.fail("image_size", "expected two whole numbers of pixels between 16 and 8192");
    v.image_size[k] = static_cast<int>(size[k]);
  }
  v.point_radius = t.non_negative("point_radius", 0.0);
  v.scalar_bar = t.boolean("scalar_bar", true);
  v.time_label = t.boolean("time_label", true);
  v.camera = camera(t, "camera", file, "visualisation");
  if (t.has("slab")) {
    CaseReader s(t.table("slab", false), file, "visualisation.slab");
    v.slab_set = s.has("origin");
    v.slab_origin = s.vec<double>("origin", 3, std::array<double, 3>{0, 0, 0});
    v.slab_normal = s.vec<double>("normal", 3, std::array<double, 3>{0, 0, 1});
    if (v.slab_normal[0] == 0 && v.slab_normal[1] == 0 && v.slab_normal[2] == 0)
      s.fail("normal", "expected a non-zero normal vector");
    v.slab_set |= s.has("normal");
    v.slab_half_thickness = s.non_negative("half_thickness", 0.0);
    v.slab_camera = camera(s, "camera", file, "visualisation.slab");
    s.finish();
  }
  if (t.has("ranges")) {
    const toml::table& rt = t.table("ranges", false);
    CaseReader rr(rt, file, "visualisation.ranges");
    for (const auto& [k, node] : rt) {
      const std::string key(k.str());
      const auto lohi = rr.vec<double>(key, 2);
      if (!(lohi[0] < lohi[1])) rr.fail(key, "expected [low, high] with low < high", &node);
      v.ranges[key] = {lohi[0], lohi[1]};
    }
  }
  if (t.has("colour_maps")) {
    const toml::table& ct = t.table("colour_maps", false);
    CaseReader cr(ct, file, "visualisation.colour_maps");
    for (const auto& [k, node] : ct) v.colour_maps[std::string(k.str())] = cr.string(std::string(k.str()));
  }
  t.finish();
  return v;
}

}  // namespace psph
