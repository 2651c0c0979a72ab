#pragma once
// The period of an oscillating signal q(t) from its zero crossings, each located by linear
// interpolation between samples; crossings come every half period.
#include <vector>

namespace psph {

class ZeroCrossings {
 public:
  void add(double t, double q) {
    if (started_ && ((q_ < 0 && q >= 0) || (q_ > 0 && q <= 0))) times_.push_back(t_ + (t - t_) * q_ / (q_ - q));
    t_ = t, q_ = q, started_ = true;
  }
  // T = 2 (t_n - t_1) / (n - 1); 0 with fewer than two crossings.
  double period() const {
    return times_.size() < 2 ? 0.0 : 2 * (times_.back() - times_.front()) / double(times_.size() - 1);
  }

 private:
  std::vector<double> times_;
  double t_ = 0, q_ = 0;
  bool started_ = false;
};

}  // namespace psph
