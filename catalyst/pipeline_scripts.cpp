#include "catalyst/pipeline_scripts.hpp"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace fs = std::filesystem;

namespace psph {
namespace {

const char* kFieldsTag = "# poresph-fields:";

// Reads the `# poresph-fields:` line among the leading comment lines; false when there is none.
bool declared_fields(const std::string& path, std::vector<std::string>& out) {
  std::ifstream in(path);
  std::string line;
  while (std::getline(in, line) && (line.empty() || line[0] == '#')) {
    if (line.rfind(kFieldsTag, 0) != 0) continue;
    std::stringstream ss(line.substr(std::string(kFieldsTag).size()));
    std::string f;
    while (std::getline(ss, f, ',')) {
      f.erase(0, f.find_first_not_of(" \t"));
      f.erase(f.find_last_not_of(" \t\r") + 1);
      if (!f.empty()) out.push_back(f);
    }
    return true;
  }
  return false;
}

}  // namespace

std::string pipeline_directory() {
  if (const char* env = std::getenv("PORESPH_PIPELINES"); env && *env) return env;
  return PORESPH_PIPELINE_DIR;
}

std::vector<std::string> bundled_pipelines() {
  std::vector<std::string> names, unused;
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(pipeline_directory(), ec))
    if (e.path().extension() == ".py" && declared_fields(e.path().string(), unused))
      names.push_back(e.path().stem().string());
  std::sort(names.begin(), names.end());
  return names;
}

PipelineScript find_pipeline(const std::string& arg, const std::string& where) {
  const std::string ctx = where.empty() ? "--pipeline " + arg : where;
  const bool is_path = arg.find('/') != std::string::npos || fs::path(arg).extension() == ".py";
  const fs::path p = is_path ? fs::path(arg) : fs::path(pipeline_directory()) / (arg + ".py");
  if (!fs::is_regular_file(p)) {
    std::string choices;
    for (const auto& n : bundled_pipelines()) choices += (choices.empty() ? "" : ", ") + n;
    throw std::invalid_argument(ctx + ": no such pipeline" +
                                (is_path ? " file" : " in " + pipeline_directory()) + "; expected one of: " + choices +
                                ", or the path of a .py pipeline script");
  }
  PipelineScript s;
  s.name = p.stem().string();
  s.path = fs::absolute(p).lexically_normal().string();
  if (!declared_fields(s.path, s.fields))
    throw std::invalid_argument(ctx + ": " + s.path + " does not declare its fields; expected a line '" +
                                kFieldsTag + " name, ...' at the top of the script");
  return s;
}

}  // namespace psph
