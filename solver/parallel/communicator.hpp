#pragma once
// The processes of a run as the solver sees them: global reductions and byte exchanges. One
// process (SerialCommunicator) is the default; parallel/mpi_communicator.cpp implements it over
// MPI. No stage includes MPI: they reduce through the step context, which reduces through this.
#include <memory>
#include <string>
#include <vector>

#include "core/exact_sum.hpp"

namespace psph {

using Bytes = std::vector<unsigned char>;

class Communicator {
 public:
  virtual ~Communicator() = default;
  virtual int rank() const { return 0; }
  virtual int size() const { return 1; }
  // Exact sums over the processes (core/exact_sum.hpp): their digits add as integers, so the
  // result does not depend on how the terms were shared out.
  virtual void sum(ExactSum*, int) {}
  virtual double max(double x) { return x; }
  // Each of `count` values, the largest over the processes, in place.
  virtual void max(double*, int) {}
  virtual long long max(long long x) { return x; }
  virtual long long sum(long long x) { return x; }
  // send[r] goes to process r; recv[q] is what process q sent here (sizes known to no one before).
  virtual void exchange(const std::vector<Bytes>& send, std::vector<Bytes>& recv) { recv = send; }
  // Bytes whose sizes both sides know (a halo planned at the last list build): send_bytes[r] of
  // `send` (laid out process after process) to process r, recv_bytes[q] from process q into `recv`
  // (likewise). Only the processes with something to send or receive are addressed. Host memory,
  // or the backend's device memory where device_memory() says so.
  virtual void exchange_known(const unsigned char* send, const std::vector<std::size_t>& send_bytes,
                              unsigned char* recv, const std::vector<std::size_t>& recv_bytes);
  // Whether exchange_known takes device memory: a CUDA-aware MPI, asked for with
  // PORESPH_CUDA_AWARE_MPI=1 (off by default: the halos are staged through the host).
  virtual bool device_memory() const { return false; }
  // Why PORESPH_CUDA_AWARE_MPI=1 cannot be honoured; empty where it can or was not asked for.
  virtual std::string device_memory_refusal() const { return ""; }
  // Process `root`'s bytes, on every process.
  virtual void broadcast(Bytes&, int /*root*/) {}
  // Every process's bytes, on every process.
  virtual std::vector<Bytes> all_gather(const Bytes& mine) { return {mine}; }
  virtual void barrier() {}
  // Ends every process at once (a process that cannot continue alone): never returns.
  [[noreturn]] virtual void abort(int code);
  bool parallel() const { return size() > 1; }
  // The MPI communicator (an MPI_Comm*) for libraries that take one (parallel HDF5, Catalyst);
  // null for one process without MPI.
  virtual const void* mpi_comm() const { return nullptr; }
  // A new MPI communicator of the same processes (an MPI_Comm*, freed with the handle; every
  // process calls), for a library that calls MPI from another thread (Catalyst on the render
  // thread); null without MPI or where MPI does not allow calls from several threads.
  virtual std::shared_ptr<void> duplicate_for_thread() { return nullptr; }
  // Seconds spent in the calls above since the start (waiting for other processes included).
  virtual double seconds_in_calls() const { return 0; }
};

// The first non-empty message of the processes, by rank, on every process (empty if none);
// `from`, if given, its process (-1 if none). Every process calls.
std::string first_message(Communicator& comm, const std::string& mine, int* from = nullptr);

// The process's communicator: MPI's world when launched by mpirun/srun (and built with MPI),
// otherwise one process. Initialises MPI on first use.
Communicator& world();
// What launched this process: "mpirun"-like (an MPI launcher's environment) or nothing.
bool launched_by_mpi();
// This process's rank among those of its node (the launcher's environment; 0 if none says).
int local_rank();
// MPI's finalisation at a normal exit (a no-op without MPI).
void finalise_world();

}  // namespace psph
