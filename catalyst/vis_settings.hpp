#pragma once
// The settings the pipeline scripts read (pipelines/poresph_views.py): the case's [visualisation]
// table with every unset value filled from the scene and the first output frame. Written once per
// run (images/visualisation.json), so that colour ranges stay fixed and `poresph figures`
// re-renders with exactly the same settings.
#include <string>

#include <nlohmann/json.hpp>

#include "io/particle_frame.hpp"
#include "scene/case_file.hpp"

namespace psph {

// `images_dir`/`extracts_dir`: absolute folders of the run directory.
nlohmann::json resolve_vis_settings(const Case& c, const ParticleFrame& first, const std::string& images_dir,
                                    const std::string& extracts_dir, const std::string& live_url);

}  // namespace psph
