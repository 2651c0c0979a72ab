#pragma once
// Fills a ParticleFrame from an engine: on output steps only, exactly the fields asked for.
#include <string>
#include <vector>

#include "io/particle_frame.hpp"
#include "engine/engine.hpp"
#include "parallel/communicator.hpp"

namespace psph {

// Copies positions and `fields` (registered or derived) into `frame` as float, vectors of D
// components padded to 3. Returns the names the engine does not have (those are left out).
// `slice`: this process's slice of them only (Engine::field_slice), as each writes its piece.
std::vector<std::string> stage_frame(Engine& e, const std::vector<std::string>& fields, ParticleFrame& frame,
                                     bool slice = false);
// A process whose slice is empty cannot tell a vector from a scalar by its size: every process
// takes the components of those that hold particles (every process calls).
void agree_components(ParticleFrame& frame, Communicator& comm);

}  // namespace psph
