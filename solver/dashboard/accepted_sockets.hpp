#pragma once
// The server's accepted connections among the process's descriptors (cpp-httplib shows neither
// its task queue nor its handlers the socket): the sockets whose local port is the server's, that
// are not listening. Linux (/proc/self/fd, socket cookies).
#include <cstdint>
#include <map>
#include <string>

namespace psph {

// The connection to `port` accepted since the last call, or -1 when there is not exactly one;
// `known` (descriptor -> socket cookie, never reused) holds what the last call saw.
int newly_accepted(int port, std::map<int, std::uint64_t>& known);
// The connection to `port` from peer_ip:peer_port, or -1.
int connection_from(int port, const std::string& peer_ip, int peer_port);
// True when the client at the other end of `fd` has closed its side (or `fd` is -1: unknown, false).
bool peer_left(int fd);

}  // namespace psph
