#pragma once
// A bound on the dashboard's event streams, each of which holds one of the server's threads for
// as long as its page is open: at most `total` in all and `per_client` from one address, so that
// threads stay free for the page, its state and control requests (a client beyond the bound gets
// 503 with Retry-After).
#include <map>
#include <mutex>
#include <string>

namespace psph {

class StreamSlots {
 public:
  StreamSlots(int total, int per_client) : total_(total), per_client_(per_client) {}
  // Takes a slot for `client`; "" when taken, else why not.
  std::string take(const std::string& client);
  void give_back(const std::string& client);

 private:
  int total_, per_client_;
  std::mutex m_;
  int open_ = 0;
  std::map<std::string, int> by_client_;
};

}  // namespace psph
