#pragma once
// Owning array in a backend's memory (host memory for the CPU backend, cudaMalloc for CUDA). Its
// allocation only grows: a resize within it keeps the values in place (a process's share of a
// run shrinks and grows at every migration: parallel/particle_domain.hpp).
#include <cstddef>
#include <utility>
#include <vector>

namespace psph {

template <class T, class B>
class DeviceArray {
 public:
  DeviceArray() = default;
  explicit DeviceArray(std::size_t n) { resize(n); }
  ~DeviceArray() { B::release(ptr_); }
  DeviceArray(const DeviceArray&) = delete;
  DeviceArray& operator=(const DeviceArray&) = delete;
  DeviceArray(DeviceArray&& o) noexcept
      : ptr_(std::exchange(o.ptr_, nullptr)), n_(std::exchange(o.n_, 0)), cap_(std::exchange(o.cap_, 0)) {}
  DeviceArray& operator=(DeviceArray&& o) noexcept {
    swap(o);
    return *this;
  }

  // `n` values; those within the allocation keep their place, a larger size loses every value.
  void resize(std::size_t n) {
    reserve(n);
    n_ = n;
  }
  // An allocation of at least `n` values; a larger one than today's loses every value.
  void reserve(std::size_t n) {
    if (n > cap_) reallocate(n);
  }
  // `n` values in an allocation of about their size (a process's first share of a whole run: the
  // whole run's allocation is given back); the values are lost where it is reallocated.
  void fit(std::size_t n) {
    if (n > cap_ || cap_ > 2 * n + 64) reallocate(n);
    n_ = n;
  }
  void swap(DeviceArray& o) noexcept {
    std::swap(ptr_, o.ptr_);
    std::swap(n_, o.n_);
    std::swap(cap_, o.cap_);
  }
  void upload(const std::vector<T>& h) {
    resize(h.size());
    B::upload(ptr_, h.data(), h.size() * sizeof(T));
  }
  void download(std::vector<T>& h) const {
    h.resize(n_);
    B::download(h.data(), ptr_, n_ * sizeof(T));
  }
  std::vector<T> host() const {
    std::vector<T> h;
    download(h);
    return h;
  }
  void zero() { B::fill_zero(ptr_, n_ * sizeof(T)); }

  T* data() { return ptr_; }
  const T* data() const { return ptr_; }
  std::size_t size() const { return n_; }
  std::size_t capacity() const { return cap_; }

 private:
  void reallocate(std::size_t n) {
    T* fresh = static_cast<T*>(B::allocate(n * sizeof(T)));  // before the release: a failure keeps the old one
    B::release(ptr_);
    ptr_ = fresh, cap_ = n, n_ = 0;
  }

  T* ptr_ = nullptr;
  std::size_t n_ = 0, cap_ = 0;
};

}  // namespace psph
