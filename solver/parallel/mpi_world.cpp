// The communicator over MPI's world (OpenMPI from Debian). Only the main thread calls it; MPI is
// started with MPI_THREAD_MULTIPLE where it allows so that Catalyst, on the render thread, may
// composite over a communicator of its own (duplicate_for_thread).
#define OMPI_SKIP_MPICXX 1  // the C API only (the C++ bindings are deprecated and not linked)
#define MPICH_SKIP_MPICXX 1
#include <mpi.h>
#if defined(OPEN_MPI) && OPEN_MPI
#include <mpi-ext.h>  // MPIX_CUDA_AWARE_SUPPORT, MPIX_Query_cuda_support
#endif

#include <climits>
#include <cstdlib>
#include <stdexcept>
#include <string>

#include "parallel/communicator.hpp"

namespace psph {
namespace {

void check(int err, const char* what) {
  if (err == MPI_SUCCESS) return;
  char text[MPI_MAX_ERROR_STRING];
  int len = 0;
  MPI_Error_string(err, text, &len);
  throw std::runtime_error(std::string("MPI error in ") + what + ": " + std::string(text, len));
}

int bytes_count(std::size_t n) {
  if (n > std::size_t(INT_MAX)) throw std::runtime_error("an MPI message over 2 GiB");
  return int(n);
}

// Adds a call's wall time to `seconds`.
class CallClock {
 public:
  explicit CallClock(double& seconds) : seconds_(seconds), t0_(MPI_Wtime()) {}
  ~CallClock() { seconds_ += MPI_Wtime() - t0_; }
  CallClock(const CallClock&) = delete;
  CallClock& operator=(const CallClock&) = delete;

 private:
  double& seconds_;
  double t0_;
};

class MpiCommunicator final : public Communicator {
 public:
  MpiCommunicator() : world_(MPI_COMM_WORLD) {
    int ready = 0, provided = 0;
    MPI_Initialized(&ready);
    if (!ready) check(MPI_Init_thread(nullptr, nullptr, MPI_THREAD_MULTIPLE, &provided), "MPI_Init_thread");
    else MPI_Query_thread(&provided);
    threads_ = provided >= MPI_THREAD_MULTIPLE;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
    MPI_Comm_size(MPI_COMM_WORLD, &size_);
    ask_device_memory();
  }
  int rank() const override { return rank_; }
  int size() const override { return size_; }
  const void* mpi_comm() const override { return &world_; }
  std::shared_ptr<void> duplicate_for_thread() override {
    if (!threads_) return nullptr;
    auto* dup = new MPI_Comm;
    check(MPI_Comm_dup(world_, dup), "MPI_Comm_dup");
    return std::shared_ptr<void>(dup, [](void* p) {
      auto* c = static_cast<MPI_Comm*>(p);
      int finalised = 0;
      MPI_Finalized(&finalised);
      if (!finalised) MPI_Comm_free(c);
      delete c;
    });
  }

  void sum(ExactSum* acc, int count) override {
    const CallClock clock(seconds_);
    std::vector<long long> words(std::size_t(count) * ExactSum::kDigits);
    std::vector<int> special(count);
    for (int k = 0; k < count; ++k) {
      acc[k].carry();  // digits under 2^32: the sum over processes cannot overflow
      for (int w = 0; w < ExactSum::kDigits; ++w) words[std::size_t(k) * ExactSum::kDigits + w] = acc[k].words()[w];
      special[k] = acc[k].special();
    }
    check(MPI_Allreduce(MPI_IN_PLACE, words.data(), int(words.size()), MPI_LONG_LONG, MPI_SUM, MPI_COMM_WORLD),
          "MPI_Allreduce");
    check(MPI_Allreduce(MPI_IN_PLACE, special.data(), count, MPI_INT, MPI_BOR, MPI_COMM_WORLD), "MPI_Allreduce");
    for (int k = 0; k < count; ++k) {
      for (int w = 0; w < ExactSum::kDigits; ++w) acc[k].words()[w] = words[std::size_t(k) * ExactSum::kDigits + w];
      acc[k].special() = special[k];
    }
  }
  double max(double x) override {
    const CallClock clock(seconds_);
    check(MPI_Allreduce(MPI_IN_PLACE, &x, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD), "MPI_Allreduce");
    return x;
  }
  void max(double* x, int count) override {
    const CallClock clock(seconds_);
    check(MPI_Allreduce(MPI_IN_PLACE, x, count, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD), "MPI_Allreduce");
  }
  long long max(long long x) override {
    const CallClock clock(seconds_);
    check(MPI_Allreduce(MPI_IN_PLACE, &x, 1, MPI_LONG_LONG, MPI_MAX, MPI_COMM_WORLD), "MPI_Allreduce");
    return x;
  }
  long long sum(long long x) override {
    const CallClock clock(seconds_);
    check(MPI_Allreduce(MPI_IN_PLACE, &x, 1, MPI_LONG_LONG, MPI_SUM, MPI_COMM_WORLD), "MPI_Allreduce");
    return x;
  }

  void exchange(const std::vector<Bytes>& send, std::vector<Bytes>& recv) override {
    const CallClock clock(seconds_);
    std::vector<int> scount(size_), rcount(size_), sdispl(size_), rdispl(size_);
    Bytes out;
    for (int r = 0; r < size_; ++r) {
      sdispl[r] = bytes_count(out.size());
      scount[r] = bytes_count(send[r].size());
      out.insert(out.end(), send[r].begin(), send[r].end());
    }
    check(MPI_Alltoall(scount.data(), 1, MPI_INT, rcount.data(), 1, MPI_INT, MPI_COMM_WORLD), "MPI_Alltoall");
    std::size_t total = 0;
    for (int r = 0; r < size_; ++r) rdispl[r] = bytes_count(total), total += std::size_t(rcount[r]);
    Bytes in(total);
    check(MPI_Alltoallv(out.data(), scount.data(), sdispl.data(), MPI_BYTE, in.data(), rcount.data(),
                        rdispl.data(), MPI_BYTE, MPI_COMM_WORLD),
          "MPI_Alltoallv");
    recv.assign(size_, Bytes{});
    for (int r = 0; r < size_; ++r) recv[r].assign(in.begin() + rdispl[r], in.begin() + rdispl[r] + rcount[r]);
  }

  void exchange_known(const unsigned char* send, const std::vector<std::size_t>& send_bytes, unsigned char* recv,
                      const std::vector<std::size_t>& recv_bytes) override {
    const CallClock clock(seconds_);
    constexpr int kTag = 52;  // one exchange at a time: messages of a pair arrive in order
    for (int r = 0; r < size_; ++r) bytes_count(send_bytes[r]), bytes_count(recv_bytes[r]);  // before any is posted
    std::vector<MPI_Request> req;
    std::size_t at = 0;
    for (int q = 0; q < size_; ++q) {
      if (!recv_bytes[q]) continue;
      req.emplace_back();
      check(MPI_Irecv(recv + at, bytes_count(recv_bytes[q]), MPI_BYTE, q, kTag, MPI_COMM_WORLD, &req.back()), "MPI_Irecv");
      at += recv_bytes[q];
    }
    at = 0;
    for (int r = 0; r < size_; ++r) {
      if (!send_bytes[r]) continue;
      req.emplace_back();
      check(MPI_Isend(send + at, bytes_count(send_bytes[r]), MPI_BYTE, r, kTag, MPI_COMM_WORLD, &req.back()), "MPI_Isend");
      at += send_bytes[r];
    }
    check(MPI_Waitall(int(req.size()), req.data(), MPI_STATUSES_IGNORE), "MPI_Waitall");
  }
  bool device_memory() const override { return device_memory_; }
  std::string device_memory_refusal() const override { return refusal_; }

  void broadcast(Bytes& bytes, int root) override {
    const CallClock clock(seconds_);
    long long n = static_cast<long long>(bytes.size());
    check(MPI_Bcast(&n, 1, MPI_LONG_LONG, root, MPI_COMM_WORLD), "MPI_Bcast");
    bytes.resize(std::size_t(n));
    check(MPI_Bcast(bytes.data(), bytes_count(bytes.size()), MPI_BYTE, root, MPI_COMM_WORLD), "MPI_Bcast");
  }

  std::vector<Bytes> all_gather(const Bytes& mine) override {
    const CallClock clock(seconds_);
    int n = bytes_count(mine.size());
    std::vector<int> counts(size_), displ(size_);
    check(MPI_Allgather(&n, 1, MPI_INT, counts.data(), 1, MPI_INT, MPI_COMM_WORLD), "MPI_Allgather");
    std::size_t total = 0;
    for (int r = 0; r < size_; ++r) displ[r] = bytes_count(total), total += std::size_t(counts[r]);
    Bytes all(total);
    check(MPI_Allgatherv(mine.data(), n, MPI_BYTE, all.data(), counts.data(), displ.data(), MPI_BYTE, MPI_COMM_WORLD),
          "MPI_Allgatherv");
    std::vector<Bytes> out(size_);
    for (int r = 0; r < size_; ++r) out[r].assign(all.begin() + displ[r], all.begin() + displ[r] + counts[r]);
    return out;
  }

  void barrier() override { MPI_Barrier(MPI_COMM_WORLD); }
  double seconds_in_calls() const override { return seconds_; }
  [[noreturn]] void abort(int code) override {
    MPI_Abort(MPI_COMM_WORLD, code);
    Communicator::abort(code);
  }

 private:
  // PORESPH_CUDA_AWARE_MPI=1: device buffers straight to MPI, where this MPI says it takes them
  // (OpenMPI: MPIX_Query_cuda_support); an MPI that does not say is trusted.
  void ask_device_memory() {
    const char* ask = std::getenv("PORESPH_CUDA_AWARE_MPI");
    if (!ask || std::string(ask) == "0" || std::string(ask).empty()) return;
    if (std::string(ask) != "1") {
      refusal_ = "PORESPH_CUDA_AWARE_MPI='" + std::string(ask) + "': expected 1 (device memory to MPI) or 0";
      return;
    }
#if defined(MPIX_CUDA_AWARE_SUPPORT) && MPIX_CUDA_AWARE_SUPPORT
    if (MPIX_Query_cuda_support() != 1)
      refusal_ = "PORESPH_CUDA_AWARE_MPI=1, but this MPI's library was started without CUDA support "
                 "(MPIX_Query_cuda_support() = 0); unset it to stage the halos through the host";
#elif defined(MPIX_CUDA_AWARE_SUPPORT)
    refusal_ = "PORESPH_CUDA_AWARE_MPI=1, but this MPI was built without CUDA support (MPIX_CUDA_AWARE_SUPPORT 0); "
               "unset it to stage the halos through the host";
#endif
    device_memory_ = refusal_.empty();
  }

  int rank_ = 0, size_ = 1;
  bool device_memory_ = false;
  std::string refusal_;
  MPI_Comm world_;
  bool threads_ = false;  // MPI_THREAD_MULTIPLE provided
  double seconds_ = 0;
};

}  // namespace

Communicator& world() {
  if (!launched_by_mpi()) {
    static Communicator one;
    return one;
  }
  static MpiCommunicator mpi;
  return mpi;
}

void finalise_world() {
  int ready = 0, done = 0;
  MPI_Initialized(&ready);
  MPI_Finalized(&done);
  if (ready && !done) MPI_Finalize();
}

}  // namespace psph
