#pragma once
// Longitudinal vibration of a 1D elastic rod (cases/vibrating_rod_1d.toml; Deptulski 2021 Ch. 3,
// its §3 and §4.4, Tables 1-3): the rod starts undeformed with the velocity profile of mode k,
//   clamped-clamped v = C2 w sin(k pi x / L),  clamped-free v = C2 w sin((2k - 1) pi x / (2L))
// (eq. C3-41, C2 = L/2000), and vibrates at w = beta c / L. The frequency parameter beta^2 is read
// from the zero crossings of the modal coordinate over three periods.
#include <string>

#include "scene/case_file.hpp"

namespace psph {

// The rod with mode `k` set up; `clamped_free` removes the clamp at x = L; the support radius is
// lambda = support_over_length L (the case's 0.05 by default), the clamps one support deep.
Case vibrating_rod_case(int k, bool clamped_free, SolidFormulation form = SolidFormulation::Stress,
                        double support_over_length = 0.05);

struct RodVibration {
  double beta2 = 0;          // (w L / c)^2 measured
  double beta2_local = 0;    // of the local continuum: (k pi)^2 or ((2k - 1) pi / 2)^2
  double energy_drift = 0;   // max |E(t) / E(0) - 1|, E = kinetic + elastic
  long steps = 0;
  int particles = 0;
  double seconds = 0;
};

RodVibration run_vibrating_rod(const Case& c, int k, bool clamped_free, const std::string& backend);

}  // namespace psph
