#pragma once
// The dynamic softening bar of Deptulski 2021 §4.2 (cases/softening_bar_2d.toml): a strip of
// `points` x `rows` particles over [-L, L], support radius `support`, pulled at its grips. Measured:
// the strain plateau behind the incident waves at t = L / (2 c_e) against v / c_e, when and where
// damage first appears (the waves meet at the centre at L / c_e), and the width of the damaged
// band at t = 3 L / (2 c_e), the time of the thesis' Fig. 4.6.
#include <string>

#include "scene/case_file.hpp"

namespace psph {

// `model`: the case's pcw, or at1, at2, rankine_mohr_coulomb with their peak stress at the same
// strain eps_0 = 0.022 (for the stability sweep).
Case softening_bar_case(int points, int rows, double support, const std::string& model = "pcw");

struct SofteningBar {
  double half_length = 0.1, wave_speed = 0, pull_speed = 0, spacing = 0, support = 0;
  double plateau_strain = 0;      // median engineering strain behind the incident fronts at L / (2 c_e)
  double onset_time = -1;         // first step with a damaged particle (D > 1e-3); -1: none
  double onset_position = 0;      // |x0| of the most damaged particle then (m)
  double band_width = 0;          // damaged volume (D > 1e-3, |x0| < L / 2) / cross-section at 3 L / (2 c_e) (m)
  double peak_damage = 0;         // at 3 L / (2 c_e)
  long steps = 0;
  int particles = 0;
  double seconds = 0;
};

SofteningBar run_softening_bar(const Case& c, const std::string& backend);

}  // namespace psph
