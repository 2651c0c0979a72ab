#pragma once
// Pipeline scripts by name: pipelines/<name>.py (or a path to a user's own .py). A script declares
// the particle fields it needs in a header line `# poresph-fields: a, b`; only those are staged.
#include <string>
#include <vector>

namespace psph {

struct PipelineScript {
  std::string name;  // file stem, also the images/<name>/ folder
  std::string path;  // absolute
  std::vector<std::string> fields;
};

// The folder of the bundled pipelines: $PORESPH_PIPELINES, else the source tree's pipelines/.
std::string pipeline_directory();
// Names of the bundled pipelines (every pipelines/*.py that declares its fields).
std::vector<std::string> bundled_pipelines();
// Resolves a name or a path; throws std::invalid_argument naming `where` (default "--pipeline
// NAME") and the choices.
PipelineScript find_pipeline(const std::string& name_or_path, const std::string& where = "");

}  // namespace psph
