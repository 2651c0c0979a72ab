#pragma once
// Rigid bodies of a scene: their particles, mass, centre of mass and inertia from the particles
// (Pazdniakou eqs. 62, 64), across periodic sides by the minimum image.
#include <vector>

#include "rigid/rigid_bodies.hpp"
#include "engine/scene.hpp"

namespace psph {

SceneRigidBodies rigid_bodies_of(const Scene& sc);

// Adds each body's rotation omega x (x - X) to its particles' velocities.
void add_rigid_rotation(Scene& sc);

}  // namespace psph
