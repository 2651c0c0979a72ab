#pragma once
// A load applied quasi-statically: min(1, t / ramp_time), 1 without a ramp (body-force regions,
// solid tractions).

namespace psph {

inline double ramp_factor(double t, double ramp_time) { return ramp_time > 0 && t < ramp_time ? t / ramp_time : 1.0; }

}  // namespace psph
