// The dashboard against hostile local clients, over real sockets and threads: event streams are
// bounded (per address and in all) and leave threads for state and control, slow requests hold
// no thread and time out whole, the listen backlog is raised; a cadence longer than the run is
// refused.
#include <atomic>
#include <chrono>
#include <thread>
#include <vector>

#include <gtest/gtest.h>
#include <linux/inet_diag.h>
#include <linux/netlink.h>
#include <linux/sock_diag.h>
#include <netinet/in.h>
#include <sys/socket.h>

#include "dashboard_fixture.hpp"

namespace {

using ms = std::chrono::milliseconds;

std::string get_request(int port, const std::string& path) {
  return "GET " + path + " HTTP/1.1\r\nHost: 127.0.0.1:" + std::to_string(port) + "\r\n\r\n";
}

// /api/state and a pause request, each answered within `within` (a client that waits no longer).
void state_and_control_answer(Served& s, ms within) {
  httplib::Client c = s.client();
  const time_t sec = within.count() / 1000, usec = within.count() % 1000 * 1000;
  c.set_connection_timeout(sec, usec);
  c.set_read_timeout(sec, usec);
  auto state = c.Get("/api/state");
  ASSERT_TRUE(state) << "no answer to /api/state within " << within.count() << " ms";
  EXPECT_EQ(state->status, 200);
  auto pause = c.Post("/api/control", {{"X-Poresph-Token", s.run.token}}, R"({"action":"pause"})", "application/json");
  ASSERT_TRUE(pause) << "no answer to /api/control within " << within.count() << " ms";
  EXPECT_EQ(pause->status, 202);
}

// The accept queue's bound of the socket listening on `port` (sock_diag: what `ss -lt` shows).
int listen_backlog(int port) {
  const int nl = ::socket(AF_NETLINK, SOCK_DGRAM | SOCK_CLOEXEC, NETLINK_SOCK_DIAG);
  struct {
    nlmsghdr h;
    inet_diag_req_v2 r;
  } req{};
  req.h.nlmsg_len = sizeof req, req.h.nlmsg_type = SOCK_DIAG_BY_FAMILY, req.h.nlmsg_flags = NLM_F_REQUEST | NLM_F_DUMP;
  req.r.sdiag_family = AF_INET, req.r.sdiag_protocol = IPPROTO_TCP, req.r.idiag_states = 1u << 10;  // TCP_LISTEN
  if (nl < 0 || ::send(nl, &req, sizeof req, 0) < 0) return -1;
  alignas(nlmsghdr) char buf[16384];
  int found = -1;
  for (ssize_t n; found < 0 && (n = ::recv(nl, buf, sizeof buf, 0)) > 0;) {
    bool done = false;
    for (auto* h = reinterpret_cast<nlmsghdr*>(buf); NLMSG_OK(h, n); h = NLMSG_NEXT(h, n)) {
      if (h->nlmsg_type == NLMSG_DONE || h->nlmsg_type == NLMSG_ERROR) done = true;
      const auto* m = static_cast<const inet_diag_msg*>(NLMSG_DATA(h));
      if (!done && ntohs(m->id.idiag_sport) == port) found = static_cast<int>(m->idiag_wqueue);
    }
    if (done) break;
  }
  ::close(nl);
  return found;
}

}  // namespace

TEST(DashboardLimits, EventStreamsAreBoundedAndLeaveThreadsForStateAndControl) {
  Served s("streams");
  const int port = s.server.port();
  // 64 streams asked for (once enough to take every thread): 8 addresses, 9 each.
  std::vector<int> open;
  int accepted = 0, refused = 0;
  for (int a = 1; a <= 8; ++a)
    for (int k = 0; k < 9; ++k) {
      const std::string from = "127.0.0." + std::to_string(a);
      const int fd = connect_from(port, from.c_str());
      ASSERT_GE(fd, 0) << from;
      const std::string req = get_request(port, "/api/events?since=0");
      ASSERT_GT(::send(fd, req.data(), req.size(), MSG_NOSIGNAL), 0);
      const std::string head = response_head(fd, ms(3000));
      if (head.rfind("HTTP/1.1 200", 0) == 0) ++accepted;
      else if (head.rfind("HTTP/1.1 503", 0) == 0 && head.find("Retry-After: ") != std::string::npos) ++refused;
      else ADD_FAILURE() << from << " stream " << k << ": " << head;
      // The ninth from one address is beyond its bound; from the fifth address on, beyond the total.
      EXPECT_EQ(head.rfind("HTTP/1.1 200", 0) == 0, k < 8 && a <= 4) << from << " stream " << k;
      open.push_back(fd);
    }
  EXPECT_EQ(accepted, 32);
  EXPECT_EQ(refused, 40);
  state_and_control_answer(s, ms(3000));
  for (int fd : open) ::close(fd);
  // Closed pages give their slots back within about a second (not at the next event).
  const auto end = std::chrono::steady_clock::now() + ms(5000);
  std::string head;
  do {
    const int fd = connect_from(port, "127.0.0.8");
    const std::string req = get_request(port, "/api/events?since=0");
    ::send(fd, req.data(), req.size(), MSG_NOSIGNAL);
    head = response_head(fd, ms(3000));
    ::close(fd);
    if (head.rfind("HTTP/1.1 200", 0) != 0) std::this_thread::sleep_for(ms(100));
  } while (head.rfind("HTTP/1.1 200", 0) != 0 && std::chrono::steady_clock::now() < end);
  EXPECT_EQ(head.rfind("HTTP/1.1 200", 0), 0u) << head;
}

TEST(DashboardLimits, SlowRequestsHoldNoThreadAndTimeOutWhole) {
  constexpr double kDeadline = 3;
  Served s("slow", "running", kDeadline);
  const int port = s.server.port();
  // 70 clients that send a header byte every 0.5 s (each read well within cpp-httplib's 5 s).
  std::vector<int> slow;
  for (int k = 0; k < 70; ++k) {
    const int fd = connect_from(port);
    ASSERT_GE(fd, 0);
    const std::string start = "GET /api/state HTTP/1.1\r\nHost: 127.0.0.1:" + std::to_string(port) + "\r\nX-Slow: ";
    ASSERT_GT(::send(fd, start.data(), start.size(), MSG_NOSIGNAL), 0);
    slow.push_back(fd);
  }
  const auto started = std::chrono::steady_clock::now();
  std::atomic<bool> done{false};
  std::thread drip([&] {
    while (!done) {
      for (int fd : slow) ::send(fd, "a", 1, MSG_NOSIGNAL | MSG_DONTWAIT);
      std::this_thread::sleep_for(ms(500));
    }
  });
  // Answered while they drip, before their deadline.
  state_and_control_answer(s, ms(2000));
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count(), kDeadline);
  // Each gets 408 once its deadline has passed, though it never stopped sending.
  for (int fd : slow) {
    const std::string head = response_head(fd, ms(static_cast<int>(kDeadline * 1000) + 4000));
    EXPECT_EQ(head.rfind("HTTP/1.1 408", 0), 0u) << head;
  }
  EXPECT_GE(std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count(), kDeadline - 0.5);
  done = true;
  drip.join();
  for (int fd : slow) ::close(fd);
}

TEST(DashboardLimits, ConnectionsBeyondTheWaitingBoundAreRefusedAtOnce) {
  Served s("flood");
  const int port = s.server.port();
  std::vector<int> idle;  // connected, saying nothing (each a descriptor of the server's process)
  for (int k = 0; k < 128; ++k) idle.push_back(connect_from(port));
  const int late = connect_from(port);
  const std::string req = get_request(port, "/api/state");
  ASSERT_GT(::send(late, req.data(), req.size(), MSG_NOSIGNAL), 0);
  const std::string head = response_head(late, ms(3000));
  EXPECT_EQ(head.rfind("HTTP/1.1 503", 0), 0u) << head;
  EXPECT_NE(head.find("Retry-After: "), std::string::npos) << head;
  ::close(late);
  for (int fd : idle) ::close(fd);
  // Once they have gone the server answers again.
  const auto end = std::chrono::steady_clock::now() + ms(3000);
  int code = -1;
  while ((code = status_of(s, "/api/state")) != 200 && std::chrono::steady_clock::now() < end) std::this_thread::sleep_for(ms(50));
  EXPECT_EQ(code, 200);
}

TEST(DashboardLimits, ChunkedRequestBodiesAreRefused) {
  Served s("chunked");
  const int fd = connect_from(s.server.port());
  const std::string req = "POST /api/control HTTP/1.1\r\nHost: 127.0.0.1:" + std::to_string(s.server.port()) +
                          "\r\nX-Poresph-Token: " + s.run.token + "\r\nTransfer-Encoding: chunked\r\n\r\n5\r\n{\"act";
  ASSERT_GT(::send(fd, req.data(), req.size(), MSG_NOSIGNAL), 0);
  EXPECT_EQ(response_head(fd, ms(3000)).rfind("HTTP/1.1 411", 0), 0u);
  ::close(fd);
  EXPECT_FALSE(fs::exists(s.run.dir / "control"));
}

TEST(DashboardLimits, ListensWithARaisedBacklog) {
  Served s("backlog");
  std::ifstream in("/proc/sys/net/core/somaxconn");
  int most = 4096;
  in >> most;
  EXPECT_EQ(listen_backlog(s.server.port()), std::min(256, most));  // cpp-httplib's own: 5
}

TEST(DashboardLimits, ACadenceLongerThanTheRunIsRefused) {
  Served s("cadence");
  for (const char* body : {R"({"action":"cadence","monitor_interval":1e308})", R"({"action":"cadence","extract_interval":1.5})"}) {
    auto r = s.client().Post("/api/control", {{"X-Poresph-Token", s.run.token}}, body, "application/json");
    ASSERT_TRUE(r);
    EXPECT_EQ(r->status, 400) << body;
    EXPECT_NE(r->body.find("longer than the run"), std::string::npos) << r->body;
  }
  EXPECT_FALSE(fs::exists(s.run.dir / "control"));
  EXPECT_EQ(post_control(s, R"({"action":"cadence","visualisation_interval":1})", &s.run.token), 202);  // the whole run
}
