#pragma once
// A 1D rod clamped at x = 0 whose last 2 spacings move at 0.01 m/s for 5 ms: a 50 um
// displacement, then held; damped (its first mode: 500 rad/s), it settles to a uniform strain of
// 50 um / its length (tests/test_solid_load.cpp; with [damage]: tests/test_damage_stage.cpp).
#include <string>

namespace psph::test {

inline std::string stretched_rod_case() {
  return R"(
[case]
name = "rod"
dimension = 1
[domain]
lower = [-0.004]
upper = [0.1]
[discretisation]
spacing = 1.0e-3
support_radius = 2.0e-3
[materials.steel]
kind = "elastic"
density = 1000.0
young_modulus = 1.0e6
poisson_ratio = 0.0
[materials.clamp]
kind = "wall"
[solid]
damping_rate = 1.0e3
[time]
end = 0.05
[[geometry]]
shape = "box"
lower = [-0.004]
upper = [0.1]
material = "clamp"
[[geometry]]
shape = "box"
lower = [0.0]
upper = [0.1]
material = "steel"
[[solid_load]]
material = "steel"
lower = [0.098]
upper = [0.1]
velocity = [0.01]
duration = 5.0e-3
)";
}

}  // namespace psph::test
