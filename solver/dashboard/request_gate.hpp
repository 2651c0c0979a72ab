#pragma once
// The dashboard server's task queue (cpp-httplib's TaskQueue): a connection reaches one of the
// worker threads only once its whole request (head, and a body of at most `body_max` bytes) has
// arrived, so a client that sends slowly holds no thread. One gate thread watches the waiting
// connections (poll, MSG_PEEK: nothing is consumed); one that is not complete `deadline` seconds
// after it was accepted gets 408 and is closed (a total deadline: cpp-httplib's read timeout is
// per read, and a byte every few seconds resets it). Beyond `pending_max` waiting connections a
// new one gets 503 at once (each holds a descriptor of the solver's process).
#include <httplib.h>

#include <chrono>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

namespace psph {

struct GateLimits {
  double deadline = 10;           // s from accept to a complete request
  std::size_t head_max = 16384;   // bytes looked at for the end of the head (larger: cpp-httplib refuses it)
  std::size_t body_max = 4096;    // larger bodies go on at once (cpp-httplib answers 413)
  std::size_t pending_max = 128;  // connections waiting for their request
};

class RequestGate : public httplib::TaskQueue {
 public:
  // `port`: the server's, to tell its accepted connections from the process's other sockets.
  RequestGate(std::size_t threads, int port, GateLimits limits);
  ~RequestGate() override;
  void enqueue(std::function<void()> fn) override;
  void shutdown() override;

 private:
  struct Waiting {
    int fd;
    std::chrono::steady_clock::time_point deadline;
    std::function<void()> job;
  };
  void watch();                 // the gate thread
  bool settle(Waiting& w, short events);  // true when `w` leaves the gate (`events`: poll's)
  void refuse(int fd, int code, const char* reason);
  void wake();

  httplib::ThreadPool pool_;
  int port_;
  GateLimits limits_;
  std::mutex m_;
  std::vector<Waiting> waiting_;         // with m_: new ones, and those still waiting
  std::size_t held_ = 0;                 // with m_: connections in the gate
  std::map<int, std::uint64_t> known_;  // accepted connections seen so far: descriptor -> socket cookie
  bool stopping_ = false;
  int wake_[2] = {-1, -1};  // a pipe: a new connection, or shutdown
  std::vector<char> peek_;
  std::thread gate_;
};

}  // namespace psph
