#include "engine/density_watch.hpp"

#include <algorithm>
#include <mutex>

namespace psph {
namespace {

std::mutex ledger_mutex;
double ledger_peak = -1;  // -1: no fluid since the last take

}  // namespace

void note_density_deviation(double value) {
  const std::lock_guard<std::mutex> lock(ledger_mutex);
  ledger_peak = std::max(ledger_peak, value);
}

double take_density_deviation_peak() {
  const std::lock_guard<std::mutex> lock(ledger_mutex);
  const double p = ledger_peak;
  ledger_peak = -1;
  return p;
}

}  // namespace psph
