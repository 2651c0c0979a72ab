// The CPU (OpenMP) instantiation of the one-source simulation.
#include "backend/cpu_backend.hpp"
#include "engine/simulation.hpp"
#include "engine/unit_scaled_engine.hpp"

namespace psph {

std::unique_ptr<Engine> make_cpu_engine(const Scene& scene, Communicator& comm) {
  return in_engine_unit(scene, [&](const Scene& s) { return make_simulation<CpuBackend>(s, comm); });
}

}  // namespace psph
