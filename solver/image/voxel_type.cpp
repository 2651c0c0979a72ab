// Voxel types (image/voxel_type.hpp).
#include "image/voxel_type.hpp"

#include <cmath>
#include <cstring>

namespace psph {
namespace {

const struct {
  const char* name;
  VoxelType type;
  std::size_t bytes;
} kTypes[] = {{"uint8", VoxelType::U8, 1},   {"int8", VoxelType::I8, 1},   {"uint16", VoxelType::U16, 2},
              {"int16", VoxelType::I16, 2},  {"uint32", VoxelType::U32, 4}, {"int32", VoxelType::I32, 4},
              {"float32", VoxelType::F32, 4}};

// The unsigned value of `n` bytes at p in the given byte order.
std::uint32_t word(const unsigned char* p, std::size_t n, bool big_endian) {
  std::uint32_t w = 0;
  for (std::size_t k = 0; k < n; ++k) w |= std::uint32_t(p[big_endian ? n - 1 - k : k]) << (8 * k);
  return w;
}

}  // namespace

bool parse_voxel_type(const std::string& name, VoxelType& type) {
  for (const auto& t : kTypes)
    if (name == t.name) return type = t.type, true;
  return false;
}

std::string voxel_type_name(VoxelType type) {
  for (const auto& t : kTypes)
    if (t.type == type) return t.name;
  return "?";
}

std::size_t voxel_bytes(VoxelType type) {
  for (const auto& t : kTypes)
    if (t.type == type) return t.bytes;
  return 0;
}

bool decode_labels(const unsigned char* bytes, std::size_t count, VoxelType type, bool big_endian,
                   std::vector<std::int64_t>& out, std::size_t& bad) {
  const std::size_t n = voxel_bytes(type);
  out.resize(count);
  for (std::size_t i = 0; i < count; ++i) {
    const std::uint32_t w = word(bytes + i * n, n, big_endian);
    switch (type) {
      case VoxelType::U8: case VoxelType::U16: case VoxelType::U32: out[i] = w; break;
      case VoxelType::I8: out[i] = std::int8_t(w); break;
      case VoxelType::I16: out[i] = std::int16_t(w); break;
      case VoxelType::I32: out[i] = std::int32_t(w); break;
      case VoxelType::F32: {
        float f;
        std::memcpy(&f, &w, 4);
        if (!(f == std::floor(f)) || std::fabs(f) > 2147483647.0f) return bad = i, false;
        out[i] = std::int64_t(f);
        break;
      }
    }
  }
  return true;
}

}  // namespace psph
