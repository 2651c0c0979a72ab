#pragma once
// The files of a run directory the dashboard serves (GET /run/PATH): images/, extracts/ and the
// run's text records; not its token, control requests or checkpoints, nothing outside the run
// directory (links followed), and never the token under another name (a hard link to it
// placed in images/: the opened file is compared with the token by device and inode).
#include <cstdint>
#include <memory>
#include <string>

namespace psph {

class RunFile {
 public:
  // 200 with the file open, 403 (not servable) or 404 (no such regular file).
  RunFile(const std::string& run_dir, const std::string& rel);
  ~RunFile();
  RunFile(const RunFile&) = delete;
  RunFile& operator=(const RunFile&) = delete;
  int status() const { return status_; }
  std::uintmax_t size() const { return size_; }
  const char* content_type() const { return type_; }
  // Up to `length` bytes at `offset` into `buf`; the count read (0 at the end or on error).
  std::size_t read(char* buf, std::size_t length, std::uintmax_t offset) const;

 private:
  int fd_ = -1, status_ = 403;
  std::uintmax_t size_ = 0;
  const char* type_ = "";
};

}  // namespace psph
