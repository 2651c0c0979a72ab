#pragma once
// When the next output of one kind (monitors, extracts, frames, checkpoints) is due: at whole
// multiples of its interval in simulated time, the first after the start (a restart starts
// part-way); the interval may change during a run (the dashboard's cadence control).
#include <cmath>

namespace psph {

struct OutputClock {
  double interval;
  long next_index;

  OutputClock(double dt, double t) : interval(dt), next_index(first_after(dt, t)) {}
  static long first_after(double dt, double t) { return long(std::floor(t / dt * (1 + 1e-12))) + 1; }
  double next() const { return next_index * interval; }
  bool due(double t) const { return t >= next() * (1 - 1e-12); }
  // After an output at t: the next multiple beyond it.
  void pass(double t) {
    while (next_index * interval <= t * (1 + 1e-12)) ++next_index;
  }
  void set_interval(double dt, double t) { interval = dt, next_index = first_after(dt, t); }
};

}  // namespace psph
