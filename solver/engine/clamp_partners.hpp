#pragma once
// Mirror partners of clamps. A wall particle w next to an elastic solid presents the displacement of
// its mirror image through the clamp surface, u_w = 2 u_wall - u_p (solid/clamp.hpp): the odd
// extension of the solid's displacement, linear across the clamp, so that the strain next to it is
// exact and the clamped plane lies on the wall surface. The partner p is the elastic particle at
// the image point x_w + (2 r - dx) n, where r and n are the distance and direction from w to its
// nearest elastic particle (the surface lies half a spacing dx in front of the first solid layer).
#include <cstdint>
#include <vector>

#include "engine/scene.hpp"

namespace psph {

// Per particle of the scene: for a wall, the index of its partner; for an elastic particle, the
// index of the wall whose partner it is; -1 otherwise. One to one: a solid particle mirrors at most
// one wall (the nearest first); a wall whose image holds no elastic particle within dx/4 has no
// partner and presents its own displacement.
std::vector<std::int32_t> clamp_mirror_partners(const Scene& sc);

}  // namespace psph
