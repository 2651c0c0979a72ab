#pragma once
// Static contact angle of a 2D sessile drop (cases/sessile_drop_2d.toml): the angle through the
// liquid at which a circle fitted to the interface meets the wall.
#include <string>
#include <vector>

#include "scene/case_file.hpp"

namespace psph {

// The case with the wall's contact angle (degrees), the drop starting as a circular cap at
// `initial_angle_deg` with the area of a half-disc of `radius_spacings` spacings.
Case sessile_drop_case(double contact_angle_deg, double initial_angle_deg, double radius_spacings = 10);

struct ContactAngle {
  double angle = 0;           // degrees, averaged over the last fifth of the run
  double radius = 0;          // of the fitted circle (m)
  double spurious_speed = 0;  // max |v| at the end (m/s)
  double capillary_speed = 0; // sigma / mu_liquid
  long steps = 0;
  int particles = 0;
  double seconds = 0;
};

// Circle through points (x, y interleaved) by the algebraic least-squares fit (Kasa 1976):
// returns {centre x, centre y, radius}.
std::vector<double> fit_circle(const std::vector<double>& xy);

ContactAngle measure_contact_angle(const Case& c, const std::string& backend);

}  // namespace psph
