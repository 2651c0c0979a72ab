#pragma once
// `poresph image info FILE`: a segmented image's size, labels, porosity and pore components
// (image/image_report.hpp), without building particles; `poresph image slice FILE`: a PNG of one
// section, a colour per label (the legend printed); `poresph image generate claystone`: the seeded
// synthetic claystone sample as a NumPy file (app/cmd_image_generate.cpp).
#include <CLI/CLI.hpp>
#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace psph {

struct ImageInfoOptions {
  std::string file, format = "auto", type = "uint8", byte_order = "little", order = "xyz";
  std::vector<long> dimensions;  // raw: x, y, z
  long header_bytes = 0, first_page = 0;
  std::vector<long> pore_labels{0};
  std::vector<int> coarsen{1};   // one factor, or one per axis
  std::vector<long> crop;        // x0 y0 z0 x1 y1 z1 (voxels, upper exclusive)
  int connectivity = 6;
  bool json = false;
  // slice
  std::string axis = "z", out = "slice.png";
  long index = 0;
  int scale = 1;  // pixels per voxel
  // generate (image/claystone_sample.hpp)
  long size = 50;
  std::uint64_t seed = 1;
  double porosity = 0.128, grains = 0.08;
  std::string variant = "one_pore";
  std::string kind;  // generate voxel (image/voxel_benchmarks.hpp)
  long width = 4, length = 6;
  double radius = 14;
};

// The `image` command and its `info` and `slice` subcommands on `app`.
CLI::App* add_image_command(CLI::App& app, ImageInfoOptions& o);
// `image generate claystone` on `image`, and what it runs (writes the file, prints its report).
void add_generate_command(CLI::App* image, ImageInfoOptions& o);
int image_generate(const ImageInfoOptions& o);
int image_info(const ImageInfoOptions& o);
// Exit 0, or 2 when the image cannot be read as described (the message names the file).
int cmd_image(const CLI::App& image, const ImageInfoOptions& o);

}  // namespace psph
