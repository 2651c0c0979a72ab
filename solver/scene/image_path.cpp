// Image files by search path (scene/image_path.hpp).
#include "scene/image_path.hpp"

#include <cstdlib>
#include <filesystem>
#include <sstream>

#ifndef PORESPH_IMAGE_DIRS
#define PORESPH_IMAGE_DIRS ""
#endif

namespace psph {
namespace {

void split_into(const std::string& list, std::vector<std::string>& out) {
  std::stringstream in(list);
  for (std::string dir; std::getline(in, dir, ':');)
    if (!dir.empty()) out.push_back(dir);
}

}  // namespace

std::string find_image_file(const std::string& file, const std::string& case_file, std::vector<std::string>& tried) {
  namespace fs = std::filesystem;
  std::vector<std::string> dirs;
  if (fs::path(file).is_absolute()) dirs.push_back("");
  else {
    dirs.push_back(fs::path(case_file).parent_path().string());
    if (const char* env = std::getenv("PORESPH_IMAGE_PATH")) split_into(env, dirs);
    split_into(PORESPH_IMAGE_DIRS, dirs);
  }
  for (const std::string& dir : dirs) {
    const fs::path p = (dir.empty() ? fs::path(file) : fs::path(dir) / file).lexically_normal();
    tried.push_back(p.string());
    std::error_code ec;
    if (fs::exists(p, ec)) return fs::absolute(p, ec).lexically_normal().string();
  }
  return "";
}

}  // namespace psph
