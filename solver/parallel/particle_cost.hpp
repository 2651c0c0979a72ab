#pragma once
// A particle's share of a step's cost, which the decomposition balances (parallel/): a fluid or
// solid particle's neighbour sums against a wall's (lists only near the fluid, no force pass).
#include "core/material.hpp"

namespace psph {

inline double particle_cost(MaterialKind kind) { return kind == MaterialKind::Wall ? 0.25 : 1.0; }

}  // namespace psph
