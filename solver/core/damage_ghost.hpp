#pragma once
// A damage ghost (Pazdniakou 2018 §4.7, Fig. 14d; damage/ghosts.hpp): a particle whose damage
// reached the threshold of [damage] degraded = "ghost". Pending from the damage pass until the next
// list build, retired after it: out of every list, at rest where it dropped out, for good.
#include <cstdint>

#include "core/config.hpp"

namespace psph {

inline constexpr std::uint8_t kGhostPending = 1, kGhostRetired = 2;

PSPH_HD inline bool is_retired_ghost(const std::uint8_t* ghost, int i) { return ghost && ghost[i] == kGhostRetired; }

}  // namespace psph
