// NumPy .npy volumes (image/volume_source.hpp): the header (format 1.0-3.0) gives the type, byte
// order, memory order and shape; the data follow as a raw volume.
#include <cctype>
#include <fstream>

#include "image/image_error.hpp"
#include "image/volume_source.hpp"

namespace psph {
namespace {

constexpr long kMaxHeader = 65536;  // NumPy writes a few hundred bytes

// The value of `key` in the header's dict: a quoted string, a parenthesised tuple or a word
// (True, False), as text (no regular expression: a hostile header must not recurse deeply).
std::string dict_value(const std::string& header, const std::string& key, const std::string& file) {
  auto missing = [&] { return ImageError(file, "expected a NumPy header with '" + key + "'"); };
  std::size_t at = header.find("'" + key + "'");
  if (at == std::string::npos) at = header.find("\"" + key + "\"");
  if (at == std::string::npos) throw missing();
  at = header.find(':', at + key.size() + 2);
  if (at == std::string::npos) throw missing();
  at = header.find_first_not_of(" ", at + 1);
  if (at == std::string::npos) throw missing();
  const char open = header[at];
  const char close = open == '(' ? ')' : (open == '\'' || open == '"') ? open : '\0';
  const std::size_t end = close ? header.find(close, at + 1) : header.find_first_of(",}", at);
  if (end == std::string::npos) throw missing();
  return header.substr(at, end - at + (close ? 1 : 0));
}

// '<u1', '>i2', '|b1', '<f4', ...
void read_descr(std::string descr, RawSpec& spec, const std::string& file) {
  descr = descr.size() >= 2 ? descr.substr(1, descr.size() - 2) : "";
  const char order = descr.empty() ? '?' : descr[0];
  const std::string kind = descr.size() > 1 ? descr.substr(1) : "";
  const struct {
    const char* code;
    VoxelType type;
  } known[] = {{"u1", VoxelType::U8}, {"b1", VoxelType::U8}, {"i1", VoxelType::I8}, {"u2", VoxelType::U16},
               {"i2", VoxelType::I16}, {"u4", VoxelType::U32}, {"i4", VoxelType::I32}, {"f4", VoxelType::F32}};
  for (const auto& k : known)
    if (kind == k.code && (order == '<' || order == '>' || order == '|' || order == '=')) {
      spec.type = k.type;
      spec.big_endian = order == '>';
      return;
    }
  throw ImageError(file, "expected a NumPy array of uint8, int8, uint16, int16, uint32, int32, float32 or bool, got "
                         "dtype '" + descr + "'");
}

}  // namespace

std::unique_ptr<VolumeSource> open_npy_volume(const std::string& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw ImageError(file, "cannot open it for reading");
  unsigned char head[12] = {};
  in.read(reinterpret_cast<char*>(head), 10);
  if (!in || std::string(reinterpret_cast<char*>(head), 6) != "\x93NUMPY")
    throw ImageError(file, "expected a NumPy .npy file (it does not start with \\x93NUMPY)");
  const int major = head[6];
  long header_len = head[8] | head[9] << 8, prefix = 10;
  if (major >= 2) {
    in.read(reinterpret_cast<char*>(head + 10), 2);
    header_len |= long(head[10]) << 16 | long(head[11]) << 24;
    prefix = 12;
  }
  if (major < 1 || major > 3 || !in) throw ImageError(file, "expected an .npy format version 1 to 3");
  if (header_len > kMaxHeader)
    throw ImageError(file, "its NumPy header claims " + std::to_string(header_len) + " bytes; expected at most 65536");
  std::string header(std::size_t(header_len), '\0');
  if (!in.read(header.data(), header_len)) throw ImageError(file, "its NumPy header is cut short");
  RawSpec spec;
  read_descr(dict_value(header, "descr", file), spec, file);
  const bool fortran = dict_value(header, "fortran_order", file).rfind("True", 0) == 0;
  std::vector<long> shape;
  const std::string tuple = dict_value(header, "shape", file);
  for (std::size_t i = 0; i < tuple.size();) {
    if (!std::isdigit(static_cast<unsigned char>(tuple[i]))) {
      ++i;
      continue;
    }
    const std::size_t j = tuple.find_first_not_of("0123456789", i);
    const std::string digits = tuple.substr(i, j - i);
    if (digits.size() > 12) throw ImageError(file, "expected a shape of at most 1e12 voxels an axis, got " + tuple);
    shape.push_back(std::stol(digits));
    i = j == std::string::npos ? tuple.size() : j;
  }
  if (shape.size() != 2 && shape.size() != 3)
    throw ImageError(file, "expected a 2D or 3D array, got shape " + tuple);
  spec.dimensions = {shape[0], shape[1], shape.size() == 3 ? shape[2] : 1};
  spec.header_bytes = prefix + header_len;
  // [i][j][k] is (x, y, z): C order has its last index fastest.
  spec.order = fortran ? "xyz" : shape.size() == 3 ? "zyx" : "yxz";
  return open_raw_volume(file, spec);
}

}  // namespace psph
