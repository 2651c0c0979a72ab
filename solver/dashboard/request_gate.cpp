#include "dashboard/request_gate.hpp"

#include "dashboard/accepted_sockets.hpp"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <string>

#include <fcntl.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

namespace psph {
namespace {

bool iequal(const std::string& a, const char* b) {
  return a.size() == std::strlen(b) &&
         std::equal(a.begin(), a.end(), b, [](char x, char y) { return std::tolower(x) == std::tolower(y); });
}

enum class Arrival { Waiting, Whole, Chunked };

// How much of the request in `data` has arrived: the head up to its blank line, then as many
// body bytes as Content-Length says (a body over `body_max` goes on for cpp-httplib to refuse).
Arrival arrival(const char* data, std::size_t n, std::size_t body_max) {
  const std::string text(data, n);
  const auto end = text.find("\r\n\r\n");
  if (end == std::string::npos) return Arrival::Waiting;
  std::size_t length = 0, at = text.find("\r\n") + 2;
  while (at < end) {
    const auto eol = text.find("\r\n", at), colon = text.find(':', at);
    if (colon < eol) {
      const std::string name = text.substr(at, colon - at);
      if (iequal(name, "Transfer-Encoding")) return Arrival::Chunked;
      if (iequal(name, "Content-Length")) length = std::strtoull(text.c_str() + colon + 1, nullptr, 10);
    }
    at = eol + 2;
  }
  return length > body_max || n >= end + 4 + length ? Arrival::Whole : Arrival::Waiting;
}

}  // namespace

RequestGate::RequestGate(std::size_t threads, int port, GateLimits limits)
    : pool_(threads), port_(port), limits_(limits), peek_(limits.head_max + limits.body_max) {
  if (::pipe2(wake_, O_CLOEXEC | O_NONBLOCK) != 0) wake_[0] = wake_[1] = -1;
  gate_ = std::thread([this] { watch(); });
}

RequestGate::~RequestGate() { shutdown(); }

void RequestGate::wake() {
  const char c = 0;
  if (wake_[1] >= 0 && ::write(wake_[1], &c, 1) < 0) {
  }  // full: the gate is awake anyway
}

void RequestGate::enqueue(std::function<void()> fn) {
  std::unique_lock<std::mutex> lock(m_);
  const int fd = newly_accepted(port_, known_);
  if (fd < 0 || wake_[1] < 0) {  // not found: served as before, without the gate
    lock.unlock();
    return pool_.enqueue(std::move(fn));
  }
  if (held_ >= limits_.pending_max) {
    known_.erase(fd);
    lock.unlock();
    return refuse(fd, 503, "Service Unavailable");
  }
  ++held_;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                                               std::chrono::duration<double>(limits_.deadline));
  waiting_.push_back({fd, deadline, std::move(fn)});
  lock.unlock();
  wake();
}

// Answers `code` on a connection that will not reach a worker, and closes it (its job is dropped:
// cpp-httplib's job only serves and closes the socket).
void RequestGate::refuse(int fd, int code, const char* reason) {
  const std::string body = std::string("{\"error\":\"") + reason + "\"}";
  const std::string res = "HTTP/1.1 " + std::to_string(code) + " " + reason +
                          "\r\nContent-Type: application/json\r\nConnection: close\r\n" +
                          (code == 503 ? "Retry-After: 5\r\n" : "") + "Content-Length: " + std::to_string(body.size()) +
                          "\r\n\r\n" + body;
  if (::send(fd, res.data(), res.size(), MSG_NOSIGNAL | MSG_DONTWAIT) < 0) {
  }  // the client has gone: nothing to tell it
  ::shutdown(fd, SHUT_RDWR);
  ::close(fd);
}

bool RequestGate::settle(Waiting& w, short events) {
  if (events) {
    const ssize_t n = ::recv(w.fd, peek_.data(), peek_.size(), MSG_PEEK | MSG_DONTWAIT);
    const bool more = n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK);
    const Arrival a = n > 0 ? arrival(peek_.data(), static_cast<std::size_t>(n), limits_.body_max) : Arrival::Waiting;
    if (a == Arrival::Chunked) return refuse(w.fd, 411, "Length Required"), true;
    // Whole, too large to wait for, or the client is done sending (or gone): cpp-httplib answers.
    const bool done = (events & (POLLRDHUP | POLLHUP | POLLERR)) || (n <= 0 && !more);
    if (a == Arrival::Whole || done || (n > 0 && static_cast<std::size_t>(n) >= limits_.head_max)) {
      pool_.enqueue(std::move(w.job));
      return true;
    }
  }
  if (std::chrono::steady_clock::now() < w.deadline) return false;
  refuse(w.fd, 408, "Request Timeout");
  return true;
}

void RequestGate::watch() {
  std::vector<pollfd> fds;
  for (;;) {
    std::vector<Waiting> mine;
    {
      std::lock_guard<std::mutex> lock(m_);
      if (stopping_) return;
      mine.swap(waiting_);
    }
    auto next = std::chrono::steady_clock::now() + std::chrono::seconds(1);
    fds.assign(1, pollfd{wake_[0], POLLIN, 0});
    for (const Waiting& w : mine) fds.push_back({w.fd, POLLIN | POLLRDHUP, 0}), next = std::min(next, w.deadline);
    const auto wait = std::chrono::duration_cast<std::chrono::milliseconds>(next - std::chrono::steady_clock::now());
    ::poll(fds.data(), fds.size(), static_cast<int>(std::max<long>(0, wait.count()) + 1));
    char drain[64];
    while (::read(wake_[0], drain, sizeof drain) > 0) {
    }
    std::vector<Waiting> still;
    for (std::size_t k = 0; k < mine.size(); ++k)
      if (!settle(mine[k], fds[k + 1].revents)) still.push_back(std::move(mine[k]));
    std::lock_guard<std::mutex> lock(m_);
    held_ -= mine.size() - still.size();
    for (Waiting& w : still) waiting_.push_back(std::move(w));
  }
}

void RequestGate::shutdown() {
  {
    std::lock_guard<std::mutex> lock(m_);
    if (stopping_) return;
    stopping_ = true;
  }
  wake();
  if (gate_.joinable()) gate_.join();
  for (Waiting& w : waiting_) refuse(w.fd, 503, "Service Unavailable");
  waiting_.clear();
  pool_.shutdown();
  for (int& fd : wake_)
    if (fd >= 0) ::close(fd), fd = -1;
}

}  // namespace psph
