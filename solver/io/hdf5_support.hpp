#pragma once
// What the HDF5 checkpoint's writer and reader share (io/checkpoint_hdf5.hpp): the format's name
// and version, identifiers that close themselves, HDF5's reason for a failure.
#define OMPI_SKIP_MPICXX 1  // parallel HDF5's header includes MPI's: its C API only
#define MPICH_SKIP_MPICXX 1
#include <hdf5.h>

#include <string>

namespace psph::hdf5 {

inline constexpr const char* kFormat = "poresph checkpoint";
inline constexpr long kFormatVersion = 1;

// HDF5's own words for its last failure: the innermost message of its error stack, or the system's
// reason where it names one ("error message = '...'").
inline std::string hdf5_reason() {
  std::string inner;
  H5Ewalk2(
      H5E_DEFAULT, H5E_WALK_DOWNWARD,
      [](unsigned, const H5E_error2_t* e, void* out) -> herr_t {
        if (e->desc && *e->desc) *static_cast<std::string*>(out) = e->desc;
        return 0;
      },
      &inner);
  H5Eclear2(H5E_DEFAULT);
  const std::string tag = "error message = '";
  const std::size_t at = inner.find(tag);
  if (at != std::string::npos) {
    const std::size_t end = inner.find('\'', at + tag.size());
    return inner.substr(at + tag.size(), end == std::string::npos ? std::string::npos : end - at - tag.size());
  }
  return inner.empty() ? "unknown HDF5 error" : inner;
}

// An HDF5 identifier closed with its own function when it goes.
class Id {
 public:
  Id(hid_t id, herr_t (*close)(hid_t)) : id_(id), close_(close) {}
  ~Id() { release(); }
  Id(const Id&) = delete;
  Id& operator=(const Id&) = delete;
  operator hid_t() const { return id_; }
  bool valid() const { return id_ >= 0; }
  void reset(hid_t id) { release(), id_ = id; }
  herr_t release() {
    const herr_t r = id_ >= 0 ? close_(id_) : 0;
    id_ = -1;
    return r;
  }

 private:
  hid_t id_;
  herr_t (*close_)(hid_t);
};

}  // namespace psph::hdf5
