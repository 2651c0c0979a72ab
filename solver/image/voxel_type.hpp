#pragma once
// The voxel types of raw and NumPy volumes, decoded to integer labels.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace psph {

enum class VoxelType { U8, I8, U16, I16, U32, I32, F32 };

// "uint8", "int8", "uint16", "int16", "uint32", "int32", "float32"; false if none of them.
bool parse_voxel_type(const std::string& name, VoxelType& type);
std::string voxel_type_name(VoxelType type);
std::size_t voxel_bytes(VoxelType type);

// Decodes `count` voxels of `type` from `bytes` (big-endian if `big_endian`) into `out`. A float
// voxel must hold an integer (a segmented image's label): false at the first that does not, its
// index in `bad`.
bool decode_labels(const unsigned char* bytes, std::size_t count, VoxelType type, bool big_endian,
                   std::vector<std::int64_t>& out, std::size_t& bad);

}  // namespace psph
