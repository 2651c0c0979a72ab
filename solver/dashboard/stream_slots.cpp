#include "dashboard/stream_slots.hpp"

namespace psph {

std::string StreamSlots::take(const std::string& client) {
  std::lock_guard<std::mutex> lock(m_);
  if (open_ >= total_) return "the dashboard has " + std::to_string(total_) + " event streams open, its most";
  int& mine = by_client_[client];
  if (mine >= per_client_) return "this address has " + std::to_string(per_client_) + " event streams open, its most";
  ++mine, ++open_;
  return "";
}

void StreamSlots::give_back(const std::string& client) {
  std::lock_guard<std::mutex> lock(m_);
  const auto it = by_client_.find(client);
  if (it == by_client_.end()) return;
  --open_;
  if (--it->second == 0) by_client_.erase(it);
}

}  // namespace psph
