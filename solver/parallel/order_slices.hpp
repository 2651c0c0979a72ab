#pragma once
// One process's particle order cut into consecutive slices, one per process, for writing a file
// in parallel: each process sends its particles' values to the process whose slice holds them and
// receives its own slice, sorted, ready to write at `first()`. The order is given by one distinct
// key per particle (the position it would have in one process); the slices' bounds are drawn from
// regular samples of every process's sorted keys (parallel sorting by regular sampling, Shi and
// Schaeffer 1992), so that no slice holds much more than its share and no process ever holds more
// than its slice.
#include <algorithm>
#include <cstring>
#include <numeric>
#include <stdexcept>
#include <vector>

#include "parallel/communicator.hpp"

namespace psph {

class OrderSlices {
 public:
  // `key[i]`: particle i's place in the order; particles with `mine[i]` false are not this process's.
  OrderSlices(Communicator& comm, const std::vector<long long>& key, const std::vector<std::uint8_t>& mine)
      : comm_(comm) {
    for (std::size_t i = 0; i < key.size(); ++i)
      if (mine.empty() || mine[i]) local_.push_back(int(i));
    std::sort(local_.begin(), local_.end(), [&](int a, int b) { return key[a] < key[b]; });
    const std::vector<long long> bound = bounds(key);
    to_.assign(comm_.size(), {});
    std::vector<Bytes> send(comm_.size()), recv;
    for (int i : local_) {
      const int r = int(std::upper_bound(bound.begin(), bound.end(), key[i]) - bound.begin());
      to_[r].push_back(i);
      append(send[r], &key[i], sizeof(long long));
    }
    comm_.exchange(send, recv);
    std::vector<std::pair<long long, std::size_t>> got;  // key, place in the received values
    for (const Bytes& b : recv)
      for (std::size_t at = 0; at + sizeof(long long) <= b.size(); at += sizeof(long long)) {
        long long k;
        std::memcpy(&k, b.data() + at, sizeof k);
        got.emplace_back(k, got.size());
      }
    std::sort(got.begin(), got.end());
    for (const auto& g : got) from_.push_back(g.second);
    const std::vector<long long> counts = all_counts(static_cast<long long>(from_.size()));
    first_ = std::accumulate(counts.begin(), counts.begin() + comm_.rank(), 0LL);
    total_ = std::accumulate(counts.begin(), counts.end(), 0LL);
  }

  long long first() const { return first_; }  // this slice's first place in the whole order
  long long count() const { return static_cast<long long>(from_.size()); }
  long long total() const { return total_; }

  // The same for `comps` values per particle.
  std::vector<double> slice(const std::vector<double>& values, int comps) const {
    Bytes b(values.size() * sizeof(double));
    if (!b.empty()) std::memcpy(b.data(), values.data(), b.size());
    b = slice(b, sizeof(double) * std::size_t(comps));
    std::vector<double> out(b.size() / sizeof(double));
    if (!b.empty()) std::memcpy(out.data(), b.data(), b.size());
    return out;
  }
  // This process's slice of a field whose particles' values are `elem` bytes each.
  Bytes slice(const Bytes& values, std::size_t elem) const {
    std::vector<Bytes> send(comm_.size()), recv;
    for (int r = 0; r < comm_.size(); ++r)
      for (int i : to_[r]) append(send[r], values.data() + std::size_t(i) * elem, elem);
    comm_.exchange(send, recv);
    Bytes all;
    for (const Bytes& b : recv) all.insert(all.end(), b.begin(), b.end());
    if (all.size() != from_.size() * elem) throw std::logic_error("order slices: values and keys differ in count");
    Bytes out(all.size());
    for (std::size_t k = 0; k < from_.size(); ++k) std::memcpy(out.data() + k * elem, all.data() + from_[k] * elem, elem);
    return out;
  }

 private:
  static void append(Bytes& b, const void* p, std::size_t n) {
    const auto* c = static_cast<const unsigned char*>(p);
    b.insert(b.end(), c, c + n);
  }

  // size - 1 increasing keys: slice r holds the keys k with bound[r - 1] <= k < bound[r].
  std::vector<long long> bounds(const std::vector<long long>& key) const {
    const int p = comm_.size();
    Bytes samples;
    for (int s = 0; s < p && !local_.empty(); ++s)
      append(samples, &key[local_[std::size_t(s) * local_.size() / std::size_t(p)]], sizeof(long long));
    std::vector<long long> all;
    for (const Bytes& b : comm_.all_gather(samples))
      for (std::size_t at = 0; at + sizeof(long long) <= b.size(); at += sizeof(long long)) {
        long long k;
        std::memcpy(&k, b.data() + at, sizeof k);
        all.push_back(k);
      }
    std::sort(all.begin(), all.end());
    std::vector<long long> bound;
    for (int r = 1; r < p && !all.empty(); ++r) bound.push_back(all[std::size_t(r) * all.size() / std::size_t(p)]);
    return bound;
  }

  std::vector<long long> all_counts(long long mine) const {
    Bytes b(sizeof mine);
    std::memcpy(b.data(), &mine, sizeof mine);
    std::vector<long long> out;
    for (const Bytes& g : comm_.all_gather(b)) {
      long long c = 0;
      if (g.size() == sizeof c) std::memcpy(&c, g.data(), sizeof c);
      out.push_back(c);
    }
    return out;
  }

  Communicator& comm_;
  std::vector<int> local_;                 // this process's particles, by key
  std::vector<std::vector<int>> to_;       // to_[r]: the particles whose values go to process r, by key
  std::vector<std::size_t> from_;          // slice place k: the k-th value received (in arrival order)
  long long first_ = 0, total_ = 0;
};

}  // namespace psph
