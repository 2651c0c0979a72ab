// `poresph image generate claystone` (app/cmd_image.hpp): the synthetic claystone sample
// (image/claystone_sample.hpp) written as a NumPy file, then its report as `image info` prints it.
#include <iostream>
#include <stdexcept>

#include "app/cmd_image.hpp"
#include "image/claystone_sample.hpp"
#include "image/image_error.hpp"
#include "image/voxel_benchmarks.hpp"

namespace psph {

void add_generate_command(CLI::App* image, ImageInfoOptions& o) {
  auto* gen = image->add_subcommand("generate", "write a synthetic segmented sample");
  auto* clay = gen->add_subcommand("claystone", "a claystone-like sample: a fracture-like percolating pore, small "
                                                "disconnected pores, mineral grains (labels 0 pore, 1 clay, 2 grain)");
  gen->require_subcommand(1);
  clay->add_option("--out", o.out, "the NumPy file to write (.npy)")->required();
  clay->add_option("--size", o.size, "voxels along each axis (default 50)")->check(CLI::Range(16, 1024));
  clay->add_option("--seed", o.seed, "random seed (default 1)");
  clay->add_option("--porosity", o.porosity, "the pore fraction, fracture and small pores (default 0.128)")
      ->check(CLI::Range(0.01, 0.45));
  clay->add_option("--grains", o.grains, "the fraction of mineral grains (default 0.08)")->check(CLI::Range(0.0, 0.35));
  clay->add_option("--variant", o.variant, "one_pore (default) or two_pores (Deptulski 2021 §5.5)")
      ->check(CLI::IsMember({"one_pore", "two_pores"}));
  auto* voxel = gen->add_subcommand("voxel", "a voxel geometry with known flow along z (labels 0 pore, 1 solid): duct, "
                                             "twin_ducts, tilted_slit, sphere_array, dead_ends, zigzag");
  std::vector<std::string> kinds;
  for (const char* const* k = voxel_benchmark_kinds(); *k; ++k) kinds.push_back(*k);
  voxel->add_option("kind", o.kind, "the geometry")->required()->check(CLI::IsMember(kinds));
  voxel->add_option("--out", o.out, "the NumPy file to write (.npy)")->required();
  voxel->add_option("--width", o.width, "voxels across the duct or slit (default 4)");
  voxel->add_option("--length", o.length, "voxels along z: duct, twin_ducts, tilted_slit (default 6)");
  voxel->add_option("--size", o.size, "the periodic cell: tilted_slit, sphere_array (voxels)");
  voxel->add_option("--radius", o.radius, "the sphere's radius (voxels): sphere_array");
}

int image_generate(const ImageInfoOptions& o) {
  if (!o.kind.empty()) {
    VoxelBenchmark b;
    b.kind = o.kind, b.width = o.width, b.length = o.length, b.size = o.size, b.radius = o.radius;
    try {
      write_npy(o.out, make_voxel_benchmark(b));
    } catch (const std::invalid_argument& e) {
      throw ImageError(o.out, std::string("image generate voxel ") + o.kind + ": --" + e.what());
    }
    ImageInfoOptions info;
    info.file = o.out;
    std::cout << o.kind << " written; labels 0 pore, 1 solid; flow along z\n";
    return image_info(info);
  }
  ClaystoneSpec spec;
  spec.size = o.size, spec.seed = o.seed, spec.porosity = o.porosity, spec.grains = o.grains;
  spec.two_pores = o.variant == "two_pores";
  write_npy(o.out, make_claystone(spec));
  ImageInfoOptions info;
  info.file = o.out;
  std::cout << "claystone sample (" << o.variant << ", seed " << o.seed << ") written; labels 0 pore, 1 clay, 2 grain\n";
  return image_info(info);
}

}  // namespace psph
