// The memory bound of an image (image/image_memory.hpp).
#include "image/image_memory.hpp"

#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "image/image_error.hpp"

namespace psph {
namespace {

constexpr double kGiB = 1024.0 * 1024.0 * 1024.0;
constexpr const char* kVariable = "PORESPH_IMAGE_MEMORY_LIMIT";

std::string gib(double bytes) {
  char b[64];
  std::snprintf(b, sizeof b, bytes < 0.1 * kGiB ? "%.4f GiB" : "%.1f GiB", bytes / kGiB);
  return b;
}

// MemAvailable in bytes, or a negative value where /proc/meminfo has none (an old kernel, no /proc).
double mem_available() {
  std::ifstream in("/proc/meminfo");
  std::string key;
  double kib = 0;
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream fields(line);
    if (fields >> key >> kib && key == "MemAvailable:") return kib * 1024.0;
  }
  return -1;
}

}  // namespace

double image_memory_limit(const std::string& file, std::string* source) {
  if (const char* env = std::getenv(kVariable); env && *env) {
    char* end = nullptr;
    errno = 0;
    const double bytes = std::strtod(env, &end);
    if (end == env || *end != '\0' || errno == ERANGE || !(bytes > 0) || !std::isfinite(bytes))
      throw ImageError(file, std::string(kVariable) + ": expected a positive number of bytes, got \"" + env + "\"");
    if (source) *source = std::string("the bound ") + kVariable + " sets";
    return bytes;
  }
  if (const double available = mem_available(); available > 0) {
    if (source) *source = "the memory available on this machine (MemAvailable in /proc/meminfo)";
    return available;
  }
  if (source) *source = "the memory available on this machine (sysconf's available pages)";
  return double(sysconf(_SC_AVPHYS_PAGES)) * double(sysconf(_SC_PAGESIZE));
}

void check_image_memory(const std::string& file, const std::array<long, 3>& voxels, double bytes,
                        const std::string& needs) {
  std::string source;
  const double limit = image_memory_limit(file, &source);
  if (bytes <= limit) return;
  const char* env = std::getenv(kVariable);
  throw ImageError(file, std::to_string(voxels[0]) + " x " + std::to_string(voxels[1]) + " x " + std::to_string(voxels[2]) +
                             " voxels need about " + gib(bytes) + " to read (" + needs + "); expected at most " +
                             gib(limit) + ", " + source +
                             (env && *env ? "" : std::string("; ") + kVariable + " sets another bound, in bytes"));
}

}  // namespace psph
