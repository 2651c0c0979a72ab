// The CPU (OpenMP) instantiation of the one-source simulation.
#include "backend/cpu_backend.hpp"
#include "engine/simulation.hpp"

namespace psph {

std::unique_ptr<Engine> make_cpu_engine(const Scene& scene, Communicator& comm) {
  return make_simulation<CpuBackend>(scene, comm);
}

}  // namespace psph
