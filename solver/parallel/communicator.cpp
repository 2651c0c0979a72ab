#include "parallel/communicator.hpp"

#include <cstdlib>

namespace psph {

void Communicator::abort(int code) { std::_Exit(code); }

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
