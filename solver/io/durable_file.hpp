#pragma once
// Files a run depends on (checkpoints, summary.json, case.resolved.toml): written whole to
// PATH.partial, flushed to the disk (fsync), then renamed, so that PATH is either the old file or
// the complete new one, also after a crash or a power cut. Every write is checked: a full disk is
// a WriteError naming the file, never a silent loss.
#include <cstddef>
#include <stdexcept>
#include <string>

namespace psph {

struct WriteError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

class DurableFile {
 public:
  // `sync` false: atomic and checked, not flushed to the disk (a file rewritten every second).
  explicit DurableFile(std::string path, bool sync = true);
  ~DurableFile();  // an uncommitted file is removed
  DurableFile(const DurableFile&) = delete;
  DurableFile& operator=(const DurableFile&) = delete;

  void write(const void* data, std::size_t bytes);
  void write(const std::string& s) { write(s.data(), s.size()); }
  // fsync, close, rename over PATH, fsync the directory (without `sync`: close and rename).
  void commit();

 private:
  [[noreturn]] void fail(const std::string& what);
  std::string path_, partial_;
  int fd_ = -1;
  bool sync_;
};

// A file another writer finished at `partial` (a library that writes its own files), flushed to the
// disk and renamed to `path`, durably; on failure `partial` is removed and a WriteError thrown.
void publish_durably(const std::string& partial, const std::string& path);
// The whole of `text` as PATH, durably.
void write_file_durably(const std::string& path, const std::string& text);
// The same, atomic and checked but not flushed to the disk.
void write_file_atomically(const std::string& path, const std::string& text);

}  // namespace psph
