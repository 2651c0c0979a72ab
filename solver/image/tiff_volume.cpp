// TIFF stacks through libtiff (image/volume_source.hpp): one multi-page file, or a numbered
// series of single-page files; pages along z. libtiff swaps 16- and 32-bit samples of either byte
// order to the machine's. The labels are the stored sample values whatever the photometric
// interpretation (WhiteIsZero only changes how a viewer shows them: ImageJ's inverted LUTs).
#include <tiffio.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "image/image_error.hpp"
#include "image/volume_source.hpp"

namespace psph {
namespace {

constexpr double kMaxPagePixels = 2147483648.0;

struct TiffCloser {
  void operator()(TIFF* t) const { TIFFClose(t); }
};
using TiffFile = std::unique_ptr<TIFF, TiffCloser>;

// libtiff's own messages are kept for the error, not printed.
thread_local std::string tiff_message;
void keep_message(const char* module, const char* fmt, va_list ap) {
  char b[512];
  std::vsnprintf(b, sizeof b, fmt, ap);
  tiff_message = std::string(module ? module : "libtiff") + ": " + b;
}

TiffFile open_tiff(const std::string& file) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(file, ec)) throw ImageError(file, "expected a regular TIFF file");
  TIFFSetErrorHandler(keep_message);
  TIFFSetWarningHandler(nullptr);
  tiff_message.clear();
  TiffFile t(TIFFOpen(file.c_str(), "r"));
  if (!t) throw ImageError(file, "expected a readable TIFF file" + (tiff_message.empty() ? "" : " (" + tiff_message + ")"));
  return t;
}

// One page's layout, checked.
struct Page {
  std::uint32_t width = 0, height = 0;
  std::uint16_t bits = 0, photometric = PHOTOMETRIC_MINISBLACK;
  bool tiled = false;
};

Page page_of(TIFF* t, const std::string& where) {
  Page p;
  std::uint16_t samples = 1, format = SAMPLEFORMAT_UINT, planar = PLANARCONFIG_CONTIG;
  TIFFGetField(t, TIFFTAG_IMAGEWIDTH, &p.width);
  TIFFGetField(t, TIFFTAG_IMAGELENGTH, &p.height);
  TIFFGetFieldDefaulted(t, TIFFTAG_BITSPERSAMPLE, &p.bits);
  TIFFGetFieldDefaulted(t, TIFFTAG_SAMPLESPERPIXEL, &samples);
  TIFFGetFieldDefaulted(t, TIFFTAG_SAMPLEFORMAT, &format);
  TIFFGetFieldDefaulted(t, TIFFTAG_PLANARCONFIG, &planar);
  if (!TIFFGetField(t, TIFFTAG_PHOTOMETRIC, &p.photometric)) p.photometric = PHOTOMETRIC_MINISBLACK;
  p.tiled = TIFFIsTiled(t);
  if (samples != 1) throw ImageError(where, "expected one sample per pixel (a label image), got " + std::to_string(samples));
  if (format != SAMPLEFORMAT_UINT) throw ImageError(where, "expected unsigned integer samples (labels)");
  if (p.bits != 1 && p.bits != 8 && p.bits != 16 && p.bits != 32)
    throw ImageError(where, "expected 1, 8, 16 or 32 bits per sample, got " + std::to_string(p.bits));
  if (double(p.width) * double(p.height) > kMaxPagePixels)
    throw ImageError(where, "expected pages of at most 2^31 pixels, got " + std::to_string(p.width) + " x " +
                                std::to_string(p.height));
  if (p.photometric != PHOTOMETRIC_MINISBLACK && p.photometric != PHOTOMETRIC_MINISWHITE)
    throw ImageError(where, "expected a grey-level image (BlackIsZero or WhiteIsZero), got photometric " +
                                std::to_string(p.photometric));
  return p;
}

// Sample k of a decoded row or tile row of `bits` per sample.
std::int64_t sample(const unsigned char* row, std::uint32_t k, int bits) {
  switch (bits) {
    case 1: return row[k / 8] >> (7 - k % 8) & 1;
    case 8: return row[k];
    case 16: return reinterpret_cast<const std::uint16_t*>(row)[k];
    default: return reinterpret_cast<const std::uint32_t*>(row)[k];
  }
}

// The page t is on, into labels (width x height, rows of x).
void read_page(TIFF* t, const Page& p, std::vector<std::int64_t>& labels, const std::string& where) {
  labels.assign(std::size_t(p.width) * p.height, 0);
  auto put = [&](std::uint32_t x, std::uint32_t y, std::int64_t v) { labels[std::size_t(y) * p.width + x] = v; };
  auto failed = [&] { return ImageError(where, "could not decode a page" + (tiff_message.empty() ? "" : " (" + tiff_message + ")")); };
  if (p.tiled) {
    std::uint32_t tw = 0, th = 0;
    TIFFGetField(t, TIFFTAG_TILEWIDTH, &tw);
    TIFFGetField(t, TIFFTAG_TILELENGTH, &th);
    // A tiny file may claim tiles of 2^30 x 2^30: bound their width, decode only their rows in the page.
    if (double(tw) > std::max(16.0 * std::ceil(p.width / 16.0), 1024.0))
      throw ImageError(where, "expected tiles at most as wide as the page (rounded up to 16 pixels) or 1024 pixels, got " +
                                  std::to_string(tw) + " x " + std::to_string(th));
    const tmsize_t row_bytes = TIFFTileRowSize(t);
    std::vector<unsigned char> tile;
    for (std::uint32_t y0 = 0; y0 < p.height; y0 += th)
      for (std::uint32_t x0 = 0; x0 < p.width; x0 += tw) {
        tile.resize(std::size_t(row_bytes) * std::min(th, p.height - y0));
        if (TIFFReadEncodedTile(t, TIFFComputeTile(t, x0, y0, 0, 0), tile.data(), tmsize_t(tile.size())) < 0)
          throw failed();
        for (std::uint32_t y = y0; y < std::min(y0 + th, p.height); ++y)
          for (std::uint32_t x = x0; x < std::min(x0 + tw, p.width); ++x)
            put(x, y, sample(tile.data() + (y - y0) * row_bytes, x - x0, p.bits));
      }
    return;
  }
  std::vector<unsigned char> row(TIFFScanlineSize(t));
  for (std::uint32_t y = 0; y < p.height; ++y) {
    if (TIFFReadScanline(t, row.data(), y, 0) < 0) throw failed();
    for (std::uint32_t x = 0; x < p.width; ++x) put(x, y, sample(row.data(), x, p.bits));
  }
}

// "#" runs: the file of page number k.
std::string numbered(const std::string& pattern, long k) {
  const auto a = pattern.find('#'), b = pattern.find_first_not_of('#', a);
  std::string digits = std::to_string(k);
  const std::size_t width = (b == std::string::npos ? pattern.size() : b) - a;
  if (digits.size() < width) digits.insert(0, width - digits.size(), '0');
  return pattern.substr(0, a) + digits + (b == std::string::npos ? "" : pattern.substr(b));
}

class TiffVolume final : public VolumeSource {
 public:
  TiffVolume(const std::string& file, long first) : file_(file), first_(first) {
    if (file.find('#') != std::string::npos) {
      for (long k = first; std::filesystem::exists(numbered(file, k)); ++k) ++pages_;
      if (pages_ == 0) throw ImageError(file, "expected a numbered series of files, from " + numbered(file, first));
      open_page(0);
    } else {
      if (first != 0) throw ImageError(file, "expected a numbered series ('#' in the name) for a first page to apply to");
      tif_ = open_tiff(file);
      pages_ = TIFFNumberOfDirectories(tif_.get());
      if (pages_ < 1) throw ImageError(file, "expected at least one page");
      page_ = page_of(tif_.get(), file);
    }
    first_page_ = page_;
  }
  std::array<long, 3> size() const override { return {long(first_page_.width), long(first_page_.height), pages_}; }
  std::array<int, 3> storage_axes() const override { return {0, 1, 2}; }
  std::string file() const override { return file_; }

  void read_slice(long s, std::vector<std::int64_t>& labels) override {
    const std::string where = series() ? numbered(file_, first_ + s) : file_ + " (page " + std::to_string(s) + ")";
    if (series()) open_page(s);
    else if (s != current_ && !(s == current_ + 1 ? TIFFReadDirectory(tif_.get()) : TIFFSetDirectory(tif_.get(), tdir_t(s))))
      throw ImageError(where, "could not find the page");
    current_ = s;
    page_ = page_of(tif_.get(), where);
    if (page_.width != first_page_.width || page_.height != first_page_.height)
      throw ImageError(where, "expected every page of " + std::to_string(first_page_.width) + " x " +
                                  std::to_string(first_page_.height) + " pixels, got " + std::to_string(page_.width) +
                                  " x " + std::to_string(page_.height));
    read_page(tif_.get(), page_, labels, where);
  }

 private:
  bool series() const { return file_.find('#') != std::string::npos; }
  void open_page(long s) {
    tif_ = open_tiff(numbered(file_, first_ + s));
    page_ = page_of(tif_.get(), numbered(file_, first_ + s));
    current_ = s;
  }

  std::string file_;
  long first_ = 0, pages_ = 0, current_ = 0;
  TiffFile tif_;
  Page page_, first_page_;
};

}  // namespace

std::unique_ptr<VolumeSource> open_tiff_volume(const std::string& file, long first) {
  return std::make_unique<TiffVolume>(file, first);
}
bool tiff_available() { return true; }

}  // namespace psph
