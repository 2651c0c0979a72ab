#pragma once
// A scene expressed in an engine's length unit (core/length_unit.hpp): lengths and times divided by
// L, masses by L^D, viscosities and surface tension by L, accelerations and rates times L; densities,
// velocities, pressures, moduli, strengths and strains unchanged.
#include "core/length_unit.hpp"
#include "engine/scene.hpp"

namespace psph {

// `sc` must be in SI; throws std::logic_error otherwise.
Scene in_units(const Scene& sc, const LengthUnit& unit);

}  // namespace psph
