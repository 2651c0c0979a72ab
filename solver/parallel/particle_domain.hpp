#pragma once
// A process's particles when a run is shared out (parallel/decomposition.hpp): the ones it owns
// and, after them in the cell order, copies of the others' within the halo width of its box. At
// each list rebuild the halo is dropped, owned particles that left the box migrate to their new
// owner with every registered field, and the halo is gathered again; between rebuilds the order
// is fixed and refresh() brings a field's halo values from their owners. The halo width is the
// lists' radius: every neighbour of an owned particle is then here, and its sums are those of
// one process (the neighbours sorted by cell and id: neighbours/neighbour_stage.hpp).
#include <algorithm>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/pass_profile.hpp"
#include "parallel/communicator.hpp"
#include "parallel/decomposition.hpp"
#include "state/particles.hpp"

namespace psph {

template <int D, class B>
class ParticleDomain {
 public:
  ParticleDomain(Communicator& comm, const Box& domain, const std::array<bool, 3>& periodic)
      : comm_(comm), cuts_(D, domain, periodic), device_exchange_(!B::host_memory && comm.device_memory()) {}

  Communicator& comm() { return comm_; }
  const Decomposition& decomposition() const { return cuts_; }
  // Null when this process holds every particle (one process).
  const std::uint8_t* owned() const { return comm_.parallel() ? owned_.data() : nullptr; }
  int owned_count() const { return owned_count_; }
  int halo_count() const { return int(owned_.size()) - owned_count_; }
  // Bytes this process sent in halo refreshes, and how many refreshes, since the start.
  long long halo_bytes() const { return halo_bytes_; }
  long long refreshes() const { return refreshes_; }

  // The first share: every process holds every particle (the scene); the cuts balance `weight`
  // (one per particle), and each process keeps its own particles and its halo.
  void split(ParticleState<D, B>& s, const std::vector<double>& weight, double halo_width) {
    width_ = halo_width;
    const std::vector<double> x = positions(s);
    cuts_.bisect(x, weight, comm_.size(), comm_);
    std::vector<int> keep;
    for (int i = 0; i < s.size(); ++i)
      if (cuts_.owner(&x[std::size_t(i) * D]) == comm_.rank() || near_me(&x[std::size_t(i) * D])) keep.push_back(i);
    HostFields h(s);
    h.keep(keep);
    h.upload(s);
    plan(s);  // in the scene's order until the first sort: the same on every process
  }

  // At a list rebuild: the halo dropped, migrants sent to their owners, the halo gathered again.
  // With `cost` (one per particle here), the domain is cut anew first, balancing the owned
  // particles' costs. The staying particles stay on the device (a permutation, as the sort's);
  // only the migrants and the halo go through the host.
  void redistribute(ParticleState<D, B>& s, const std::vector<double>& cost = {}) {
    static const std::string what = "migration and halo (processes)";
    const HostPassClock clock(what);  // in the run's profile, beside the passes
    const ProfilePause inner;
    const std::vector<double> x = positions(s);
    const std::vector<std::uint8_t> own = owned_.host();
    const int me = comm_.rank(), n = s.size();
    if (!cost.empty()) {
      std::vector<double> xo, wo;
      for (int i = 0; i < n; ++i)
        if (own[i]) xo.insert(xo.end(), &x[std::size_t(i) * D], &x[std::size_t(i) * D] + D), wo.push_back(cost[i]);
      cuts_.bisect(xo, wo, comm_.size(), comm_);
    }
    std::vector<int> order, rest;  // the staying particles, then every other
    std::vector<std::vector<int>> go(comm_.size());
    for (int i = 0; i < n; ++i) {
      const int o = own[i] ? cuts_.owner(&x[std::size_t(i) * D]) : -1;
      (o == me ? order : rest).push_back(i);
      if (o >= 0 && o != me) go[o].push_back(i);
    }
    const HostFields migrants = receive(s, go);
    const int stay = int(order.size());
    std::vector<double> mine(std::size_t(stay) * D);  // the positions of the particles kept, then of the migrants
    for (int k = 0; k < stay; ++k)
      for (int d = 0; d < D; ++d) mine[std::size_t(k) * D + d] = x[std::size_t(order[k]) * D + d];
    order.insert(order.end(), rest.begin(), rest.end());
    perm_.upload(order);
    s.permute(perm_.data());
    for (const auto& f : s.fields().all()) f.keep_first(stay);
    migrants.place(s, stay);
    const std::vector<double> xm = migrants.positions();
    mine.insert(mine.end(), xm.begin(), xm.end());
    std::vector<std::vector<int>> copies(comm_.size());
    std::vector<int> near;
    const int owned = stay + migrants.count();
    for (int i = 0; i < owned; ++i) {
      cuts_.parts_near(&mine[std::size_t(i) * D], width_, me, near);
      for (int r : near) copies[r].push_back(i);
    }
    const HostFields halo = receive(s, copies);
    halo.place(s, owned);
    s.set_count(owned + halo.count());
  }

  // After the sort: which particles are owned, which go to whom, where the halo's values land
  // (both sides list them in their cell order, the same order).
  void plan(const ParticleState<D, B>& s) {
    const std::vector<double> x = positions(s);
    const int me = comm_.rank(), n = s.size();
    std::vector<std::uint8_t> own(n);
    send_.assign(comm_.size(), {}), recv_.assign(comm_.size(), {});
    std::vector<int> near;
    owned_count_ = 0;
    for (int i = 0; i < n; ++i) {
      const double* xi = &x[std::size_t(i) * D];
      const int o = cuts_.owner(xi);
      own[i] = o == me;
      if (o != me) {
        recv_[o].push_back(i);
        continue;
      }
      ++owned_count_;
      cuts_.parts_near(xi, width_, me, near);
      for (int r : near) send_[r].push_back(i);
    }
    owned_.upload(own);
    std::vector<int> all;
    for (const auto& l : send_) all.insert(all.end(), l.begin(), l.end());
    send_index_.upload(all);
    all.clear();
    for (const auto& l : recv_) all.insert(all.end(), l.begin(), l.end());
    recv_index_.upload(all);
  }

  // The halo's values of one field from their owners.
  void refresh(const FieldHandle& f) {
    refresh_raw(static_cast<unsigned char*>(f.data()), f.element_bytes, owned_.size(), f.info.name.c_str());
  }
  // The same for `n` values of a per-particle array in the backend's memory.
  template <class T>
  void refresh(T* a, std::size_t n, const char* what) {
    refresh_raw(reinterpret_cast<unsigned char*>(a), sizeof(T), n, what);
  }

  // Every owned particle's values (`elem` bytes each) on every process, in the order of `order`
  // (one distinct key per particle).
  Bytes gather(const Bytes& values, std::size_t elem, const std::vector<long long>& order) {
    const std::vector<std::uint8_t> own = owned_.host();
    const std::size_t rec = sizeof(long long) + elem;
    Bytes mine;
    for (std::size_t i = 0; i < own.size(); ++i) {
      if (!own[i]) continue;
      const std::size_t at = mine.size();
      mine.resize(at + rec);
      std::memcpy(mine.data() + at, &order[i], sizeof(long long));
      std::memcpy(mine.data() + at + sizeof(long long), values.data() + i * elem, elem);
    }
    std::vector<std::pair<long long, const unsigned char*>> all;
    const std::vector<Bytes> parts = comm_.all_gather(mine);
    for (const Bytes& b : parts)
      for (std::size_t at = 0; at + rec <= b.size(); at += rec) {
        long long key;
        std::memcpy(&key, b.data() + at, sizeof key);
        all.emplace_back(key, b.data() + at + sizeof(long long));
      }
    std::sort(all.begin(), all.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    Bytes out(all.size() * elem);
    for (std::size_t k = 0; k < all.size(); ++k) std::memcpy(out.data() + k * elem, all[k].second, elem);
    return out;
  }
  std::vector<double> gather(const std::vector<double>& values, int comps, const std::vector<long long>& order) {
    const std::size_t elem = sizeof(double) * comps;
    Bytes b(values.size() * sizeof(double));
    if (!b.empty()) std::memcpy(b.data(), values.data(), b.size());
    b = gather(b, elem, order);
    std::vector<double> out(b.size() / sizeof(double));
    if (!b.empty()) std::memcpy(out.data(), b.data(), b.size());
    return out;
  }

  double halo_width() const { return width_; }

 private:
  // Every registered field's bytes on the host, particle-major within each field.
  class HostFields {
   public:
    explicit HostFields(ParticleState<D, B>& s) {
      for (const auto& f : s.fields().all()) {
        elem_.push_back(f.element_bytes);
        data_.emplace_back();
        f.to_host_bytes(data_.back());
        if (f.info.name == "position") xfield_ = int(elem_.size()) - 1;
      }
      n_ = elem_.empty() ? 0 : int(data_[0].size() / elem_[0]);
    }
    HostFields() = default;
    // Only the particles `idx` (gathered on the device, then downloaded).
    HostFields(const ParticleState<D, B>& s, const std::vector<int>& idx) {
      for (const auto& f : s.fields().all()) {
        elem_.push_back(f.element_bytes);
        data_.emplace_back();
        f.gather_to_host(idx, data_.back());
        if (f.info.name == "position") xfield_ = int(elem_.size()) - 1;
      }
      n_ = int(idx.size());
    }
    int count() const { return n_; }
    // These particles' values into every field of `s` from particle `at` on.
    void place(ParticleState<D, B>& s, int at) const {
      std::size_t f = 0;
      for (const auto& h : s.fields().all()) h.place(data_[f++], at);
    }
    HostFields subset(const std::vector<int>& idx) const {
      HostFields out = empty_like();
      for (std::size_t f = 0; f < elem_.size(); ++f) {
        const std::size_t e = elem_[f];
        out.data_[f].resize(idx.size() * e);
        unsigned char* to = out.data_[f].data();
        for (std::size_t k = 0; k < idx.size(); ++k) std::memcpy(to + k * e, at(f, idx[k]), e);
      }
      out.n_ = int(idx.size());
      return out;
    }
    void keep(const std::vector<int>& idx) { *this = subset(idx); }
    // Field by field: the count, then each field's elements.
    Bytes pack() const {
      Bytes out(sizeof(int));
      std::memcpy(out.data(), &n_, sizeof(int));
      for (const auto& d : data_) out.insert(out.end(), d.begin(), d.end());
      return out;
    }
    void append_packed(const Bytes& b, int from) {
      int m = 0;
      if (b.size() < sizeof(int)) throw std::runtime_error("particles from process " + std::to_string(from) + " truncated");
      std::memcpy(&m, b.data(), sizeof(int));
      std::size_t at = sizeof(int);
      for (std::size_t f = 0; f < elem_.size(); ++f) {
        const std::size_t len = std::size_t(m) * elem_[f];
        if (at + len > b.size()) throw std::runtime_error("particles from process " + std::to_string(from) + " truncated");
        data_[f].insert(data_[f].end(), b.begin() + at, b.begin() + at + len);
        at += len;
      }
      n_ += m;
    }
    std::vector<double> positions() const {
      std::vector<double> x(std::size_t(n_) * D);
      const Coord* r = reinterpret_cast<const Coord*>(data_[xfield_].data());  // the field's Point<D> values
      for (std::size_t k = 0; k < x.size(); ++k) x[k] = double(r[k]);
      return x;
    }
    void upload(ParticleState<D, B>& s) const {
      std::size_t f = 0;
      for (const auto& h : s.fields().all()) h.from_host_bytes(data_[f++]);
      s.set_count(n_);
    }
    HostFields empty_like() const {
      HostFields out;
      out.elem_ = elem_, out.xfield_ = xfield_;
      out.data_.assign(elem_.size(), Bytes{});
      return out;
    }

   private:
    const unsigned char* at(std::size_t f, int i) const { return data_[f].data() + std::size_t(i) * elem_[f]; }
    std::vector<std::size_t> elem_;
    std::vector<Bytes> data_;
    int xfield_ = 0, n_ = 0;
  };

  // Sends to[r]'s particles of `s` (gathered on the device) to process r; what every process sent here.
  HostFields receive(const ParticleState<D, B>& s, const std::vector<std::vector<int>>& to) {
    std::vector<Bytes> send(comm_.size()), recv;
    for (int r = 0; r < comm_.size(); ++r)
      if (!to[r].empty()) send[r] = HostFields(s, to[r]).pack();
    comm_.exchange(send, recv);
    HostFields got(s, {});
    for (int q = 0; q < comm_.size(); ++q)
      if (!recv[q].empty()) got.append_packed(recv[q], q);
    return got;
  }

  // Packed on the backend (the values of send_index_), exchanged with the neighbouring processes
  // only, unpacked at recv_index_. A device's bytes go through the host unless MPI takes device
  // memory (Communicator::device_memory).
  void refresh_raw(unsigned char* a, std::size_t elem, std::size_t n, const char* what) {
    static const std::string refresh = "halo refresh (processes)";
    const HostPassClock clock(refresh);
    const ProfilePause inner;
    if (n != owned_.size())
      throw std::logic_error(std::string("halo of '") + what + "': " + std::to_string(n) + " values for " +
                             std::to_string(owned_.size()) + " particles");
    const int out = int(send_index_.size()), in = int(recv_index_.size());
    send_buf_.resize(std::size_t(out) * elem), recv_buf_.resize(std::size_t(in) * elem);
    if (out) B::for_each(out, GatherRows<unsigned char>{send_buf_.data(), a, send_index_.data(), int(elem)});
    std::vector<std::size_t> sb(comm_.size()), rb(comm_.size());
    for (int r = 0; r < comm_.size(); ++r) sb[r] = send_[r].size() * elem, rb[r] = recv_[r].size() * elem;
    if (B::host_memory || device_exchange_) {
      B::synchronize();  // the packing done before MPI reads it
      comm_.exchange_known(send_buf_.data(), sb, recv_buf_.data(), rb);
    } else {
      host_out_.resize(send_buf_.size()), host_in_.resize(recv_buf_.size());
      if (out) B::download(host_out_.data(), send_buf_.data(), host_out_.size());
      comm_.exchange_known(host_out_.data(), sb, host_in_.data(), rb);
      if (in) B::upload(recv_buf_.data(), host_in_.data(), host_in_.size());
    }
    if (in) B::for_each(in, ScatterRows<unsigned char>{a, recv_buf_.data(), recv_index_.data(), int(elem)});
    halo_bytes_ += static_cast<long long>(send_buf_.size());
    ++refreshes_;
  }

  bool near_me(const double* x) const { return cuts_.distance2(x, cuts_.box(comm_.rank())) < width_ * width_; }

  static std::vector<double> positions(const ParticleState<D, B>& s) {
    const std::vector<Point<D>> h = s.x.host();
    std::vector<double> x(h.size() * D);
    for (std::size_t i = 0; i < h.size(); ++i)
      for (int k = 0; k < D; ++k) x[i * D + k] = double(h[i][k]);
    return x;
  }

  Communicator& comm_;
  Decomposition cuts_;
  double width_ = 0;
  DeviceArray<std::uint8_t, B> owned_;
  DeviceArray<int, B> perm_;  // a migration's order: the staying particles first
  DeviceArray<int, B> send_index_, recv_index_;  // the halo's particles, process after process
  DeviceArray<unsigned char, B> send_buf_, recv_buf_;
  Bytes host_out_, host_in_;  // the staging of a device's halo through the host
  bool device_exchange_;      // MPI takes the device's buffers (CUDA-aware)
  int owned_count_ = 0;
  std::vector<std::vector<int>> send_, recv_;
  long long halo_bytes_ = 0, refreshes_ = 0;
};

}  // namespace psph
