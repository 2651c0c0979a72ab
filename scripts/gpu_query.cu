// The smallest proof that the CUDA runtime can use a GPU here (scripts/gpu-check.sh runs it before
// building anything): the device's name and size, then a 1 MiB allocation written and read back.
#include <cstdio>
#include <cuda_runtime.h>

static int fail(const char* what, cudaError_t e) {
  std::fprintf(stderr, "gpu_query: %s: %s\n", what, cudaGetErrorString(e));
  return 1;
}

int main() {
  int n = 0, driver = 0, runtime = 0;
  cudaError_t e = cudaGetDeviceCount(&n);
  if (e != cudaSuccess) return fail("no usable CUDA device", e);
  if (n == 0) return fail("no usable CUDA device", cudaErrorNoDevice);
  cudaDriverGetVersion(&driver);
  cudaRuntimeGetVersion(&runtime);
  cudaDeviceProp p{};
  if ((e = cudaGetDeviceProperties(&p, 0)) != cudaSuccess) return fail("device properties", e);
  std::printf("devices %d; device 0: %s, compute capability %d.%d, %d multiprocessors, %.1f GiB; driver %d, runtime %d\n",
              n, p.name, p.major, p.minor, p.multiProcessorCount, p.totalGlobalMem / 1073741824.0, driver, runtime);
  const size_t bytes = 1 << 20;
  unsigned char* d = nullptr;
  unsigned char back = 0;
  if ((e = cudaMalloc(&d, bytes)) != cudaSuccess) return fail("cudaMalloc", e);
  if ((e = cudaMemset(d, 0x5a, bytes)) != cudaSuccess) return fail("cudaMemset", e);
  if ((e = cudaMemcpy(&back, d + bytes - 1, 1, cudaMemcpyDeviceToHost)) != cudaSuccess) return fail("cudaMemcpy", e);
  cudaFree(d);
  if (back != 0x5a) {
    std::fprintf(stderr, "gpu_query: read back %#x, expected 0x5a\n", back);
    return 1;
  }
  return 0;
}
