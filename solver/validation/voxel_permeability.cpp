#include "validation/voxel_permeability.hpp"

#include <cmath>
#include <filesystem>
#include <sstream>
#include <unistd.h>

#include "engine/engine.hpp"
#include "scene/scene_builder.hpp"
#include "validation/sphere_array.hpp"

namespace psph {
namespace {

constexpr double kVoxel = 1e-5;  // m
constexpr double kNu = 1e-6;     // m^2/s, water
// Sound speed (m/s). Around bends and dead ends the pressure field that turns the flow settles by
// diffusion, with D = c^2 K / nu (Darcy flow of a compressible fluid), over the image's length L in
// L^2 nu / (pi^2 c^2 K): at 0.1 m/s that was 0.05 s in the zigzag, 17 times the time at which its
// flow rate looked steady, and K came out +59 % (+27 % at 1 m/s, where it settles in 0.5 ms). The
// step is viscous-limited at these sizes, so the faster sound costs few steps.
constexpr double kSound = 1.0;
// Body force (m/s^2): Stokes flow, (v/c)^2 ~ 1e-8 in a duct 8 voxels across, heads ~ 1e-5 of rho c^2.
constexpr double kForce = 0.1;

bool periodic_section(const std::string& kind) { return kind == "tilted_slit" || kind == "sphere_array"; }

// Q mu / G of a square duct of side a (the series solution; White, Viscous Fluid Flow, eq. 3-48).
double square_duct_flow(double a) {
  double s = 0;
  for (int n = 1; n < 200; n += 2) s += std::tanh(n * M_PI / 2) / std::pow(n, 5);
  return a * a * a * a / 12 * (1 - 192 / std::pow(M_PI, 5) * s);
}

std::string case_text(const VoxelBenchmark& g, const LabelVolume& v, const std::string& file, int per_voxel) {
  const double h = kVoxel / per_voxel, support = 2 * h;
  const bool open = !periodic_section(g.kind);
  const double margin = open ? support : 0.0;  // a rock sleeve on the closed sides
  double hi[3];
  for (int k = 0; k < 3; ++k) hi[k] = double(v.size[k]) * kVoxel + (k < 2 ? margin : 0.0);
  const double width = double(std::max(g.width, 1L)) * kVoxel, steady = 0.5 * width * width / kNu;
  std::ostringstream o;
  o.precision(17);
  o << "[case]\nname = \"voxel_" << g.kind << "\"\ndimension = 3\n\n[domain]\nlower = [" << -margin << ", " << -margin
    << ", 0.0]\nupper = [" << hi[0] << ", " << hi[1] << ", " << hi[2] << "]\nperiodic = [" << (open ? "false, false" : "true, true")
    << ", true]\n\n[discretisation]\nspacing = " << h << "\nsupport_radius = " << support
    << "\nkernel = \"cubic_spline\"\n\n[materials.water]\nkind = \"fluid\"\ndensity = 1000.0\nviscosity = " << 1000 * kNu
    << "\nsound_speed = " << kSound << "\nbody_force = [0.0, 0.0, " << kForce << "]\n\n[materials.rock]\nkind = \"wall\"\n\n[time]\nend = "
    << 20 * steady << "\n\n";
  if (open)
    o << "[[geometry]]\nshape = \"box\"\nlower = [" << -margin << ", " << -margin << ", 0.0]\nupper = [" << hi[0] << ", " << hi[1]
      << ", " << hi[2] << "]\nmaterial = \"rock\"\n\n";
  o << "[[geometry]]\nshape = \"image\"\nfile = \"" << file << "\"\nvoxel_size = " << kVoxel
    << "\norigin = [0.0, 0.0, 0.0]\nparticles_per_voxel = " << per_voxel
    << "\nlabels = { \"0\" = \"water\", \"1\" = \"rock\" }\nwall_depth = " << support << "\n";
  return o.str();
}

}  // namespace

VoxelPermeability voxel_permeability(const VoxelBenchmark& g, int per_voxel, const std::string& backend) {
  const LabelVolume v = make_voxel_benchmark(g);
  const std::filesystem::path file =
      std::filesystem::temp_directory_path() / ("poresph-voxel-" + g.kind + "-" + std::to_string(::getpid()) + ".npy");
  Case c;
  try {
    write_npy(file.string(), v);
    c = load_case_text(case_text(g, v, file.string(), per_voxel), "voxel_" + g.kind + " (validation)");
    build_particles(c);
  } catch (...) {
    std::error_code ec;
    std::filesystem::remove(file, ec);
    throw;
  }
  std::filesystem::remove(file);
  PermeabilityRun run;
  const double width = double(g.width) * kVoxel, tau = width * width / (2 * M_PI * M_PI * kNu);  // slowest mode
  run.bulk_volume = double(v.size[0] * v.size[1] * v.size[2]) * kVoxel * kVoxel * kVoxel;
  run.interval = tau, run.min_time = 8 * tau, run.max_time = 60 * tau, run.change = 1e-3;
  VoxelPermeability out;
  out.run = measure_permeability(c, backend, run);
  out.K_voxels = out.run.K / (kVoxel * kVoxel);
  return out;
}

double voxel_exact_permeability(const VoxelBenchmark& g) {
  const double w = double(g.width);
  if (g.kind == "duct") return square_duct_flow(w) / ((w + 2) * (w + 2));
  if (g.kind == "twin_ducts") return 2 * square_duct_flow(w) / ((2 * w + 3) * (w + 2));
  if (g.kind == "tilted_slit") return w * w / 12 * (w * std::sqrt(5.0) * double(g.size)) / (double(g.size) * double(g.size));
  if (g.kind == "sphere_array") {
    const double n = double(g.size), phi = 4 * M_PI * g.radius * g.radius * g.radius / (3 * n * n * n);
    return sphere_array_reference(phi) / 4e-6 * n * n;  // the reference is for L = 2 mm
  }
  return 0;
}

}  // namespace psph
