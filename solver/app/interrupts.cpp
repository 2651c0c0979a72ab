#include "app/interrupts.hpp"

#include <atomic>
#include <csignal>

namespace psph {
namespace {
std::atomic<int> g_signal{0};
extern "C" void on_signal(int sig) { g_signal = sig; }
}  // namespace

void catch_interrupts() {
  g_signal = 0;
  std::signal(SIGINT, on_signal);
  std::signal(SIGTERM, on_signal);
}

void release_interrupts() {
  std::signal(SIGINT, SIG_DFL);
  std::signal(SIGTERM, SIG_DFL);
}

int caught_interrupt() { return g_signal.load(); }

}  // namespace psph
