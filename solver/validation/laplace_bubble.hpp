#pragma once
// Laplace law (Pazdniakou 2018 §4.4): a gas bubble of radius R in liquid, at rest, holds a pressure
// jump sigma / R (2D) or 2 sigma / R (3D). The case cases/laplace_bubble_2d.toml, with the bubble
// radius and cell size set per run.
#include <string>

#include "scene/case_file.hpp"

namespace psph {

// The case with a bubble of `radius_spacings` spacings in a periodic cell of 4 R (at least
// 24 spacings in 2D, 16 in 3D) per side; the kernel and its support radius (in spacings) as
// given; `dimension` 2 (a disc, sigma / R) or 3 (a sphere, 2 sigma / R).
Case laplace_bubble_case(double radius_spacings, const std::string& kernel = "quintic_spline",
                         double support_spacings = 3, int dimension = 2);

struct BubbleMeasurement {
  double radius = 0;          // m, from the gas volume
  double jump = 0;            // p_gas - p_liquid (Pa), averaged over the last fifth of the run
  double jump_exact = 0;      // sigma (D - 1) / R
  double spurious_speed = 0;  // max |v| at the end (m/s)
  double capillary_speed = 0; // sigma / mu_liquid (m/s)
  int particles = 0;
  long steps = 0;
  double seconds = 0;
};

// Runs the case to its end time. Pressures are means over the particles more than one support
// radius away from the interface (gas inside, liquid outside).
BubbleMeasurement measure_bubble(const Case& c, const std::string& backend);

}  // namespace psph
