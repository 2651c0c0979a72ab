// Built when nvcc is absent: the CUDA backend reports itself unavailable.
#include <stdexcept>

#include "engine/engine.hpp"

namespace psph {

std::unique_ptr<Engine> make_cuda_engine(const Scene&, Communicator&) {
  throw std::runtime_error("--backend cuda: this poresph was built without CUDA (no nvcc found at configure time)");
}
bool cuda_available() { return false; }

}  // namespace psph
