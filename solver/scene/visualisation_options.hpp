#pragma once
// The [visualisation] table of a case file: Catalyst pipelines, their cadence, camera, slab,
// colour maps and colour ranges. Unset values get defaults from the scene at the first output
// step (catalyst/vis_settings.hpp); ranges then stay fixed for the whole run.
#include <array>
#include <map>
#include <string>
#include <vector>

#include <toml++/toml.h>


namespace psph {

struct CameraOptions {
  bool set = false;
  std::array<double, 3> position{0, 0, 0}, focal_point{0, 0, 0}, view_up{0, 1, 0};
  double parallel_scale = 0;  // > 0: parallel projection with this half-height (m)
};

struct VisualisationOptions {
  std::vector<std::string> pipelines;  // names in pipelines/ or paths to .py scripts
  double interval = 0;                 // s between output steps; 0 = a fiftieth of the run
  bool every_frame = false;  // the solver waits for the renderer instead of dropping frames
  std::array<int, 2> image_size{800, 600};
  double point_radius = 0;  // m; 0 = half the spacing
  bool scalar_bar = true;
  bool time_label = true;  // "t = ... s" in the upper left corner of each image
  CameraOptions camera;
  bool slab_set = false;
  std::array<double, 3> slab_origin{0, 0, 0}, slab_normal{0, 0, 1};
  double slab_half_thickness = 0;  // m; 0 = one smoothing length
  CameraOptions slab_camera;
  std::map<std::string, std::array<double, 2>> ranges;
  std::map<std::string, std::string> colour_maps;  // ParaView preset names
};

// Parses the [visualisation] table (empty when absent). Errors name `file` and the dotted key.
VisualisationOptions parse_visualisation(const toml::table& visualisation, const std::string& file);

}  // namespace psph
