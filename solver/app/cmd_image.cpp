// `poresph image info` and `poresph image slice` (app/cmd_image.hpp).
#include "app/cmd_image.hpp"

#include <algorithm>
#include <cstdio>
#include <iostream>
#include <limits>

#include "image/image_error.hpp"
#include "image/image_report.hpp"
#include "image/png_file.hpp"
#include "image/volume_source.hpp"

namespace psph {
namespace {

// Each pore label is phase 0 (pore), every other label phase 1.
PhaseSpec pore_and_solid(const ImageInfoOptions& o) {
  PhaseSpec s;
  for (long l : o.pore_labels) s.labels.push_back({l, l, 0});
  s.labels.push_back({std::numeric_limits<std::int64_t>::min(), std::numeric_limits<std::int64_t>::max(), 1});
  s.phases = 2, s.pore_phases = 1;
  for (int k = 0; k < 3; ++k) s.coarsen[k] = o.coarsen.size() == 3 ? o.coarsen[k] : o.coarsen[0];
  if (o.crop.size() == 6)
    for (int k = 0; k < 3; ++k) s.crop_lower[k] = o.crop[k], s.crop_upper[k] = o.crop[3 + k];
  return s;
}

// Pore labels dark blue; the others a qualitative palette (Tableau 10) in label order.
const std::array<std::array<std::uint8_t, 3>, 10> kSectionColours = {{{31, 119, 180}, {255, 127, 14}, {44, 160, 44},
    {214, 39, 40}, {148, 103, 189}, {140, 86, 75}, {227, 119, 194}, {127, 127, 127}, {188, 189, 34}, {23, 190, 207}}};
const std::array<std::uint8_t, 3> kPoreColour{8, 24, 64};
const std::array<std::uint8_t, 3>& colour_of(const PhaseSpec& each, int phase, const std::vector<long>& pore) {
  const std::int64_t label = each.labels[std::size_t(phase)].lo;
  if (std::count(pore.begin(), pore.end(), label)) return kPoreColour;
  return kSectionColours[std::size_t(phase) % kSectionColours.size()];
}

// The options every image subcommand reads the file with.
void add_reading_options(CLI::App* c, ImageInfoOptions& o) {
  c->add_option("file", o.file, "the image (.raw, .tif/.tiff, .npy; a TIFF series: '#' for the page's digits)")->required();
  c->add_option("--format", o.format, "raw, tiff, npy or auto (by the extension)")
      ->check(CLI::IsMember({"auto", "raw", "tiff", "npy"}));
  c->add_option("--dimensions", o.dimensions, "raw: voxels along x, y, z")->expected(3);
  c->add_option("--type", o.type, "raw: uint8, int8, uint16, int16, uint32, int32 or float32");
  c->add_option("--byte-order", o.byte_order, "raw: little or big")->check(CLI::IsMember({"little", "big"}));
  c->add_option("--header-bytes", o.header_bytes, "raw: bytes to skip before the voxels")->check(CLI::NonNegativeNumber);
  c->add_option("--order", o.order, "raw: the axes in the file, fastest first (xyz: x fastest; zyx: C order of [x][y][z])");
  c->add_option("--first-page", o.first_page, "TIFF series: the first page's number")->check(CLI::NonNegativeNumber);
  c->add_option("--pore", o.pore_labels, "the labels of the pore space (default 0); repeatable");
}

std::unique_ptr<VolumeSource> open_described(const ImageInfoOptions& o) {
  RawSpec raw;
  const bool raw_given = !o.dimensions.empty();
  if (raw_given) {
    for (int k = 0; k < 3; ++k) raw.dimensions[k] = o.dimensions[k];
    if (!parse_voxel_type(o.type, raw.type)) throw ImageError(o.file, "--type: unknown voxel type \"" + o.type + "\"");
    raw.big_endian = o.byte_order == "big", raw.header_bytes = o.header_bytes, raw.order = o.order;
  }
  return open_volume(o.file, o.format, raw_given ? &raw : nullptr, o.first_page);
}

}  // namespace

int image_info(const ImageInfoOptions& o) {
  if (o.coarsen.size() == 2) throw ImageError(o.file, "--coarsen: expected one factor or three");
  auto src = open_described(o);
  const PhaseSpec spec = pore_and_solid(o);
  const PhaseVolume v = read_phases(*src, spec);
  const PoreComponents pores = pore_components(v, spec.pore_phases, o.connectivity, o.file);
  ImageReportInput in;
  in.file = o.file, in.format = o.format == "auto" ? format_of(o.file) : o.format;
  in.volume = &v, in.pores = &pores, in.pore_phases = spec.pore_phases;
  in.coarsen = spec.coarsen, in.connectivity = o.connectivity, in.dimension = v.size[2] == 1 ? 2 : 3;
  const nlohmann::json report = image_report(in);
  std::cout << (o.json ? report.dump(2) + "\n" : image_report_text(report));
  return 0;
}

namespace {

// One section: its labels found first, then each label its own phase and colour.
int image_slice(const ImageInfoOptions& o) {
  auto src = open_described(o);
  const int a = o.axis[0] - 'x';
  std::array<long, 3> size{};
  for (int s = 0; s < 3; ++s) size[src->storage_axes()[s]] = src->size()[s];
  if (o.index < 0 || o.index >= size[a])
    throw ImageError(o.file, "--index: expected a section from 0 to " + std::to_string(size[a] - 1) + " along " + o.axis);
  PhaseSpec all;
  all.labels = {{std::numeric_limits<std::int64_t>::min(), std::numeric_limits<std::int64_t>::max(), 0}};
  all.phases = 1;
  all.crop_lower[a] = o.index, all.crop_upper[a] = o.index + 1;
  const PhaseVolume first = read_phases(*src, all);
  if (first.label_voxels.size() > kSectionColours.size())
    throw ImageError(o.file, "expected at most " + std::to_string(kSectionColours.size()) + " labels in a section to colour");
  PhaseSpec each = all;
  each.labels.clear();
  for (const auto& [label, n] : first.label_voxels) each.labels.push_back({label, label, int(each.labels.size())});
  each.phases = int(each.labels.size());
  const PhaseVolume v = read_phases(*src, each);
  const int u = a == 0 ? 1 : 0, w = a == 2 ? 1 : 2;  // the section's axes: right, up
  const int width = int(v.size[u]) * o.scale, height = int(v.size[w]) * o.scale;
  std::vector<std::uint8_t> rgb(std::size_t(width) * height * 3);
  for (int r = 0; r < height; ++r)
    for (int c = 0; c < width; ++c) {
      std::array<long, 3> q{0, 0, 0};
      q[u] = c / o.scale, q[w] = v.size[w] - 1 - r / o.scale;
      const auto& colour = colour_of(each, v.at(q[0], q[1], q[2]), o.pore_labels);
      std::copy(colour.begin(), colour.end(), rgb.begin() + long((std::size_t(r) * width + c) * 3));
    }
  write_png(o.out, width, height, rgb);
  std::cout << o.out << ": section " << o.axis << " = " << o.index << " of " << o.file << ", " << width << " x " << height
            << " pixels (" << "xyz"[u] << " to the right, " << "xyz"[w] << " up)\n";
  for (const LabelRange& l : each.labels) {
    const auto& c = colour_of(each, l.phase, o.pore_labels);
    std::printf("  label %lld: #%02x%02x%02x, %ld voxels%s\n", static_cast<long long>(l.lo), c[0], c[1], c[2],
                first.label_voxels.at(l.lo), std::count(o.pore_labels.begin(), o.pore_labels.end(), l.lo) ? " (pore)" : "");
  }
  return 0;
}

}  // namespace

CLI::App* add_image_command(CLI::App& app, ImageInfoOptions& o) {
  auto* image = app.add_subcommand("image", "look at a segmented image (raw, TIFF, NumPy)");
  image->require_subcommand(1);
  auto* info = image->add_subcommand("info", "size, labels, porosity, pore components and percolation of an image");
  add_reading_options(info, o);
  info->add_option("--coarsen", o.coarsen, "majority coarsening: one factor, or one per axis")->expected(1, 3)
      ->check(CLI::PositiveNumber);
  info->add_option("--crop", o.crop, "voxels x0 y0 z0 x1 y1 z1 (upper bounds excluded)")->expected(6);
  info->add_option("--connectivity", o.connectivity, "pore connectivity: 6, 18 or 26")->check(CLI::IsMember({6, 18, 26}));
  info->add_flag("--json", o.json, "print the report as JSON");
  auto* slice = image->add_subcommand("slice", "a PNG of one section of an image, a colour per label");
  add_reading_options(slice, o);
  slice->add_option("--axis", o.axis, "the section's normal: x, y or z (default z)")->check(CLI::IsMember({"x", "y", "z"}));
  slice->add_option("--index", o.index, "the section's voxel along that axis (default 0)");
  slice->add_option("--out", o.out, "the PNG to write (default slice.png)");
  slice->add_option("--scale", o.scale, "pixels per voxel (default 1)")->check(CLI::Range(1, 64));
  add_generate_command(image, o);
  return image;
}

int cmd_image(const CLI::App& image, const ImageInfoOptions& o) {
  try {
    if (image.got_subcommand("generate")) return image_generate(o);
    return image.got_subcommand("slice") ? image_slice(o) : image_info(o);
  } catch (const ImageError& e) {
    std::cerr << "poresph: " << e.what() << "\n";
    return 2;
  }
}

}  // namespace psph
