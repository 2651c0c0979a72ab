#include "dashboard/run_files.hpp"

#include <filesystem>
#include <set>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace psph {
namespace fs = std::filesystem;
namespace {

const char* content_type_of(const fs::path& p) {
  const std::string e = p.extension().string();
  if (e == ".png") return "image/png";
  if (e == ".vtp" || e == ".vtu" || e == ".pvtp" || e == ".pvtu" || e == ".pvd") return "application/octet-stream";
  if (e == ".csv") return "text/csv";
  if (e == ".json") return "application/json";
  return "text/plain; charset=utf-8";
}

// True when `p` (relative to the run directory) is in images/ or extracts/, or one of the run's
// text files.
bool allowed(const fs::path& p) {
  static const std::set<std::string> files{"monitors.csv", "log.txt", "summary.json", "case.resolved.toml", "status.json"};
  if (p.empty()) return false;
  const std::string top = p.begin()->string();
  const auto depth = std::distance(p.begin(), p.end());
  return ((top == "images" || top == "extracts") && depth > 1) || (files.count(top) && depth == 1);
}

// The file under the run directory that `rel` names, or "" when it may not be served: only what
// allowed() lets through, no '..', and the same again once links are followed (a link may not
// lead out of the run directory, nor to its token).
fs::path servable(const fs::path& run, const std::string& rel) {
  if (rel.empty() || rel.find('\0') != std::string::npos || rel.find('\\') != std::string::npos || rel.front() == '/')
    return {};
  const fs::path p(rel);
  for (const auto& part : p)
    if (part == ".." || part == "." || part.empty()) return {};
  if (!allowed(p)) return {};
  std::error_code ec;
  const fs::path root = fs::canonical(run, ec);
  if (ec) return {};
  const fs::path full = fs::weakly_canonical(run / p, ec);
  if (ec) return {};
  const fs::path inside = full.lexically_relative(root);
  if (inside.empty() || *inside.begin() == ".." || !allowed(inside)) return {};
  return full;
}

}  // namespace

RunFile::RunFile(const std::string& run_dir, const std::string& rel) {
  const fs::path p = servable(run_dir, rel);
  if (p.empty()) return;
  fd_ = ::open(p.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK);  // O_NONBLOCK: a FIFO does not hang the thread
  struct stat st{}, token{};
  if (fd_ < 0 || ::fstat(fd_, &st) != 0 || !S_ISREG(st.st_mode)) {
    status_ = 404;
    return;
  }
  // The token by another name: what was opened, not what the path said a moment before.
  const std::string token_path = run_dir + "/token";
  if (::stat(token_path.c_str(), &token) == 0 && token.st_dev == st.st_dev && token.st_ino == st.st_ino) return;
  status_ = 200, size_ = static_cast<std::uintmax_t>(st.st_size), type_ = content_type_of(p);
}

RunFile::~RunFile() {
  if (fd_ >= 0) ::close(fd_);
}

std::size_t RunFile::read(char* buf, std::size_t length, std::uintmax_t offset) const {
  const ssize_t n = ::pread(fd_, buf, length, static_cast<off_t>(offset));
  return n > 0 ? static_cast<std::size_t>(n) : 0;
}

}  // namespace psph
