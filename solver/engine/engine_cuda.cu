// The CUDA instantiation of the one-source simulation.
#include "backend/cuda_backend.cuh"
#include "engine/simulation.hpp"

namespace psph {

bool cuda_available() {
  int n = 0;
  return cudaGetDeviceCount(&n) == cudaSuccess && n > 0;
}

std::unique_ptr<Engine> make_cuda_engine(const Scene& scene) {
  if (!cuda_available()) throw std::runtime_error("--backend cuda: no CUDA device is visible on this machine");
  return make_simulation<CudaBackend>(scene);
}

}  // namespace psph
