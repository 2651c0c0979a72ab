#include "io/durable_file.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <unistd.h>

namespace psph {
namespace {

std::string directory_of(const std::string& path) {
  const std::size_t slash = path.rfind('/');
  return slash == std::string::npos ? "." : slash == 0 ? "/" : path.substr(0, slash);
}

}  // namespace

DurableFile::DurableFile(std::string path, bool sync)
    : path_(std::move(path)), partial_(path_ + ".partial"), sync_(sync) {
  fd_ = ::open(partial_.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd_ < 0) fail("cannot create the file");
}

DurableFile::~DurableFile() {
  if (fd_ < 0) return;
  ::close(fd_);
  ::unlink(partial_.c_str());
}

void DurableFile::fail(const std::string& what) {
  const std::string reason = std::strerror(errno);
  if (fd_ >= 0) ::close(fd_), fd_ = -1;
  ::unlink(partial_.c_str());
  throw WriteError(path_ + ": " + what + ": " + reason);
}

void DurableFile::write(const void* data, std::size_t bytes) {
  const char* p = static_cast<const char*>(data);
  while (bytes > 0) {
    const ssize_t w = ::write(fd_, p, bytes);
    if (w < 0 && errno == EINTR) continue;
    if (w <= 0) fail("writing failed");
    p += w, bytes -= static_cast<std::size_t>(w);
  }
}

void DurableFile::commit() {
  if (sync_ && ::fsync(fd_) != 0) fail("flushing to the disk failed");
  const int fd = fd_;
  fd_ = -1;
  if (::close(fd) != 0) fail("closing failed");
  if (::rename(partial_.c_str(), path_.c_str()) != 0) fail("renaming the finished file failed");
  if (!sync_) return;
  // The rename itself is durable once the directory is.
  const int dir = ::open(directory_of(path_).c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (dir >= 0) ::fsync(dir), ::close(dir);
}

void publish_durably(const std::string& partial, const std::string& path) {
  auto fail = [&](const std::string& what) {
    const std::string reason = std::strerror(errno);
    ::unlink(partial.c_str());
    throw WriteError(path + ": " + what + ": " + reason);
  };
  const int fd = ::open(partial.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) fail("cannot open the finished file");
  const bool synced = ::fsync(fd) == 0;
  ::close(fd);
  if (!synced) fail("flushing to the disk failed");
  if (::rename(partial.c_str(), path.c_str()) != 0) fail("renaming the finished file failed");
  const int dir = ::open(directory_of(path).c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (dir >= 0) ::fsync(dir), ::close(dir);
}

namespace {
void write_whole(const std::string& path, const std::string& text, bool sync) {
  DurableFile f(path, sync);
  f.write(text);
  f.commit();
}
}  // namespace

void write_file_durably(const std::string& path, const std::string& text) { write_whole(path, text, true); }
void write_file_atomically(const std::string& path, const std::string& text) { write_whole(path, text, false); }

}  // namespace psph
