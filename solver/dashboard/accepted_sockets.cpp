#include "dashboard/accepted_sockets.hpp"

#include <cstdlib>
#include <functional>
#include <vector>

#include <arpa/inet.h>
#include <dirent.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <sys/stat.h>

namespace psph {
namespace {

// The port of `a` (IPv4 or IPv6), or -1.
int port_of(const sockaddr_storage& a) {
  if (a.ss_family == AF_INET) return ntohs(reinterpret_cast<const sockaddr_in&>(a).sin_port);
  if (a.ss_family == AF_INET6) return ntohs(reinterpret_cast<const sockaddr_in6&>(a).sin6_port);
  return -1;
}

// True when `fd` is a connected (not listening) socket whose local port is `port`.
bool accepted_on(int fd, int port) {
  struct stat st{};
  if (::fstat(fd, &st) != 0 || !S_ISSOCK(st.st_mode)) return false;
  int listening = 0;
  socklen_t len = sizeof listening;
  if (::getsockopt(fd, SOL_SOCKET, SO_ACCEPTCONN, &listening, &len) != 0 || listening) return false;
  sockaddr_storage a{};
  len = sizeof a;
  return ::getsockname(fd, reinterpret_cast<sockaddr*>(&a), &len) == 0 && port_of(a) == port;
}

void each_accepted(int port, const std::function<void(int)>& fn) {
  DIR* dir = ::opendir("/proc/self/fd");
  if (!dir) return;
  while (const dirent* e = ::readdir(dir)) {
    if (e->d_name[0] < '0' || e->d_name[0] > '9') continue;
    const int fd = std::atoi(e->d_name);
    if (fd != ::dirfd(dir) && accepted_on(fd, port)) fn(fd);
  }
  ::closedir(dir);
}

}  // namespace

int newly_accepted(int port, std::map<int, std::uint64_t>& known) {
  std::map<int, std::uint64_t> now;
  std::vector<int> fresh;
  each_accepted(port, [&](int fd) {
    std::uint64_t cookie = 0;
    socklen_t len = sizeof cookie;
    if (::getsockopt(fd, SOL_SOCKET, SO_COOKIE, &cookie, &len) != 0) return;
    now[fd] = cookie;
    const auto k = known.find(fd);
    if (k == known.end() || k->second != cookie) fresh.push_back(fd);
  });
  known = std::move(now);
  return fresh.size() == 1 ? fresh[0] : -1;
}

int connection_from(int port, const std::string& peer_ip, int peer_port) {
  int found = -1;
  each_accepted(port, [&](int fd) {
    sockaddr_storage a{};
    socklen_t len = sizeof a;
    char ip[INET6_ADDRSTRLEN] = {};
    if (found >= 0 || ::getpeername(fd, reinterpret_cast<sockaddr*>(&a), &len) != 0 || port_of(a) != peer_port) return;
    const void* addr = a.ss_family == AF_INET ? static_cast<const void*>(&reinterpret_cast<const sockaddr_in&>(a).sin_addr)
                                              : static_cast<const void*>(&reinterpret_cast<const sockaddr_in6&>(a).sin6_addr);
    if (::inet_ntop(a.ss_family, addr, ip, sizeof ip) && peer_ip == ip) found = fd;
  });
  return found;
}

bool peer_left(int fd) {
  if (fd < 0) return false;
  pollfd p{fd, POLLRDHUP, 0};
  return ::poll(&p, 1, 0) > 0 && (p.revents & (POLLRDHUP | POLLHUP | POLLERR));
}

}  // namespace psph
