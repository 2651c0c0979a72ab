// The CUDA instantiation of the one-source simulation.
#include "backend/cuda_backend.cuh"
#include "engine/simulation.hpp"
#include "engine/unit_scaled_engine.hpp"

namespace psph {

bool cuda_available() {
  int n = 0;
  return cudaGetDeviceCount(&n) == cudaSuccess && n > 0;
}

// Over several processes, one GPU each: a node's processes take its devices in turn.
std::unique_ptr<Engine> make_cuda_engine(const Scene& scene, Communicator& comm) {
  int devices = 0;
  if (cudaGetDeviceCount(&devices) != cudaSuccess || devices == 0)
    throw std::runtime_error("--backend cuda: no CUDA device is visible on this machine");
  if (comm.parallel()) PSPH_CUDA(cudaSetDevice(local_rank() % devices));
  return in_engine_unit(scene, [&](const Scene& s) { return make_simulation<CudaBackend>(s, comm); });
}

}  // namespace psph
