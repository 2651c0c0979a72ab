// PNG files (image/png_file.hpp): signature, IHDR, one IDAT of a zlib stream in stored deflate
// blocks (RFC 1950/1951: no compression, so no library), IEND; CRC-32 and Adler-32 by hand.
#include "image/png_file.hpp"

#include <algorithm>
#include <array>

#include "image/image_error.hpp"
#include "io/durable_file.hpp"

namespace psph {
namespace {

std::uint32_t crc32(const std::uint8_t* p, std::size_t n, std::uint32_t crc = 0) {
  static const std::array<std::uint32_t, 256> table = [] {
    std::array<std::uint32_t, 256> t{};
    for (std::uint32_t i = 0; i < 256; ++i) {
      std::uint32_t c = i;
      for (int k = 0; k < 8; ++k) c = c & 1 ? 0xedb88320u ^ (c >> 1) : c >> 1;
      t[i] = c;
    }
    return t;
  }();
  crc = ~crc;
  for (std::size_t i = 0; i < n; ++i) crc = table[(crc ^ p[i]) & 0xff] ^ (crc >> 8);
  return ~crc;
}

void put32(std::vector<std::uint8_t>& out, std::uint32_t v) {
  for (int s = 24; s >= 0; s -= 8) out.push_back(std::uint8_t(v >> s));
}

void chunk(std::vector<std::uint8_t>& out, const char* type, const std::vector<std::uint8_t>& data) {
  put32(out, std::uint32_t(data.size()));
  const std::size_t start = out.size();
  out.insert(out.end(), type, type + 4);
  out.insert(out.end(), data.begin(), data.end());
  put32(out, crc32(out.data() + start, out.size() - start));
}

// zlib stream of `raw` in stored blocks of at most 65535 bytes.
std::vector<std::uint8_t> stored_zlib(const std::vector<std::uint8_t>& raw) {
  std::vector<std::uint8_t> z{0x78, 0x01};
  std::uint32_t a = 1, b = 0;
  for (std::uint8_t c : raw) a = (a + c) % 65521, b = (b + a) % 65521;
  std::size_t at = 0;
  do {
    const std::size_t n = std::min<std::size_t>(65535, raw.size() - at);
    z.push_back(at + n == raw.size() ? 1 : 0);
    z.push_back(std::uint8_t(n)), z.push_back(std::uint8_t(n >> 8));
    z.push_back(std::uint8_t(~n)), z.push_back(std::uint8_t(~n >> 8));
    z.insert(z.end(), raw.begin() + long(at), raw.begin() + long(at + n));
    at += n;
  } while (at < raw.size());
  put32(z, (b << 16) | a);
  return z;
}

}  // namespace

void write_png(const std::string& file, int width, int height, const std::vector<std::uint8_t>& rgb) {
  std::vector<std::uint8_t> raw;  // each row: filter type 0, then its pixels
  raw.reserve(std::size_t(height) * (1 + 3 * std::size_t(width)));
  for (int y = 0; y < height; ++y) {
    raw.push_back(0);
    raw.insert(raw.end(), rgb.begin() + long(3 * std::size_t(y) * width), rgb.begin() + long(3 * std::size_t(y + 1) * width));
  }
  std::vector<std::uint8_t> png{0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'}, head;
  put32(head, std::uint32_t(width)), put32(head, std::uint32_t(height));
  head.insert(head.end(), {8, 2, 0, 0, 0});  // 8 bits, RGB, deflate, adaptive filters, no interlace
  chunk(png, "IHDR", head);
  chunk(png, "IDAT", stored_zlib(raw));
  chunk(png, "IEND", {});
  try {
    write_file_atomically(file, std::string(png.begin(), png.end()));  // whole, or not at all
  } catch (const WriteError& e) {
    throw ImageError(file, e.what());
  }
}

}  // namespace psph
