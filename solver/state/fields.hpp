#pragma once
// Field registry: every per-particle array is registered with its name, type and unit, so that
// reordering, output and checkpoints ask for fields by name and get exactly those.
#include <cstdint>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

namespace psph {

enum class FieldType { Real, Int, Byte };

struct FieldInfo {
  std::string name;
  FieldType type;
  int components;    // 1 for scalars, D for vectors
  std::string unit;  // SI
  std::string description;
};

// Host-side, type-erased handle on one registered array.
struct FieldHandle {
  FieldInfo info;
  std::function<void(const int* perm)> permute;             // out[i] = in[perm[i]]
  std::function<void(std::vector<double>&)> to_host_double;  // components interleaved
  // Raw copies for checkpoints: `element_bytes` per particle, exactly as stored.
  std::size_t element_bytes = 0;
  std::function<void(std::vector<unsigned char>&)> to_host_bytes;
  std::function<void(const std::vector<unsigned char>&)> from_host_bytes;  // size = n * element_bytes
  std::function<void*()> data;  // the array in the backend's memory
  // Migrations between processes (parallel/particle_domain.hpp): the values of the particles
  // `idx` on the host, `element_bytes` each; only the first n particles kept; `count` particles'
  // values placed from particle `at` on (those before kept, the array ending after them).
  std::function<void(const std::vector<int>& idx, std::vector<unsigned char>&)> gather_to_host;
  std::function<void(int n)> keep_first;
  std::function<void(const std::vector<unsigned char>&, int at)> place;
};

class FieldRegistry {
 public:
  void add(FieldHandle h) {
    for (const auto& f : fields_)
      if (f.info.name == h.info.name) throw std::logic_error("field registered twice: " + h.info.name);
    fields_.push_back(std::move(h));
  }
  const FieldHandle& get(const std::string& name) const {
    for (const auto& f : fields_)
      if (f.info.name == name) return f;
    throw std::invalid_argument("unknown particle field '" + name + "'");
  }
  bool has(const std::string& name) const {
    for (const auto& f : fields_)
      if (f.info.name == name) return true;
    return false;
  }
  const std::vector<FieldHandle>& all() const { return fields_; }

 private:
  std::vector<FieldHandle> fields_;
};

}  // namespace psph
