#include "parallel/communicator.hpp"

#include <cstdlib>
#include <cstring>
#include <numeric>
#include <stdexcept>

namespace psph {

void Communicator::abort(int code) { std::_Exit(code); }

// One process: what it sends itself.
void Communicator::exchange_known(const unsigned char* send, const std::vector<std::size_t>& send_bytes,
                                  unsigned char* recv, const std::vector<std::size_t>& recv_bytes) {
  const std::size_t n = std::accumulate(send_bytes.begin(), send_bytes.end(), std::size_t(0));
  if (n != std::accumulate(recv_bytes.begin(), recv_bytes.end(), std::size_t(0)))
    throw std::logic_error("exchange_known: one process receives other than it sends");
  if (n) std::memcpy(recv, send, n);
}

std::string first_message(Communicator& comm, const std::string& mine, int* from) {
  const std::vector<Bytes> all = comm.all_gather(Bytes(mine.begin(), mine.end()));
  for (std::size_t r = 0; r < all.size(); ++r)
    if (!all[r].empty()) {
      if (from) *from = int(r);
      return std::string(all[r].begin(), all[r].end());
    }
  if (from) *from = -1;
  return "";
}

// The environment that OpenMPI's mpirun, MPICH/Hydra, PMIx and Slurm's srun give each process.
bool launched_by_mpi() {
  for (const char* v : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK", "MPI_LOCALNRANKS"})
    if (std::getenv(v)) return true;
  return false;
}

int local_rank() {
  for (const char* v : {"OMPI_COMM_WORLD_LOCAL_RANK", "MPI_LOCALRANKID", "SLURM_LOCALID", "PMIX_LOCAL_RANK"})
    if (const char* s = std::getenv(v)) return std::atoi(s);
  return 0;
}

}  // namespace psph
