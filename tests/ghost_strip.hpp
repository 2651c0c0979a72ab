#pragma once
// A notched strip pulled apart by its grips, breaking at the notch with Rankine-Mohr-Coulomb damage
// and degraded = "ghost" (tests/test_damage_ghosts.cpp; CPU/CUDA agreement: tests/test_gpu_agreement.cpp):
// 46 x 5 particles of 1 mm, a notch 2 wide and 2 deep at the top centre, grips of 3 columns pulled
// at 0.02 m/s each way (a strain rate of 1/s); f_t at a strain of 1e-3, D_t = 1 past 2e-3.
#include <string>

namespace psph::test {

inline std::string ghost_strip_case() {
  return R"([case]
name = "ghost_strip"
dimension = 2
[domain]
lower = [-0.03, -0.004]
upper = [0.03, 0.009]
[discretisation]
spacing = 1.0e-3
support_radius = 2.5e-3
kernel = "cubic_spline"
[materials.strip]
kind = "elastic"
density = 1000.0
young_modulus = 1.0e7
poisson_ratio = 0.25
[materials.grip]
kind = "elastic"
density = 1000.0
young_modulus = 1.0e7
poisson_ratio = 0.25
[solid]
damping_rate = 5.0e3
[damage]
model = "rankine_mohr_coulomb"
materials = ["strip"]
tensile_strength = 1.0e4
tensile_elastic_strain = 1.0e-3
tensile_ultimate_strain = 2.0e-3
compressive_strength = 1.0e9
degraded = "ghost"
combination = "max"
[time]
end = 0.004
[output]
monitor_interval = 1.0e-4
extract_interval = 1.0e-3
fields = ["damage", "strain", "velocity"]
[[geometry]]
shape = "box"
lower = [-0.023, 0.0]
upper = [0.023, 0.005]
material = "strip"
[[geometry]]
shape = "box"
lower = [-0.023, 0.0]
upper = [-0.02, 0.005]
material = "grip"
[[geometry]]
shape = "box"
lower = [0.02, 0.0]
upper = [0.023, 0.005]
material = "grip"
[[geometry]]
shape = "box"
lower = [-0.001, 0.003]
upper = [0.001, 0.005]
material = "empty"
[[solid_load]]
material = "grip"
lower = [-0.023, 0.0]
upper = [-0.02, 0.005]
velocity = [-0.02, 0.0]
[[solid_load]]
material = "grip"
lower = [0.02, 0.0]
upper = [0.023, 0.005]
velocity = [0.02, 0.0]
)";
}

}  // namespace psph::test
