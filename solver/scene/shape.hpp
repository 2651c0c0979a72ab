#pragma once
// The shapes of [[geometry]]: what a shape contains, its bounding box, and optionally the particles
// it places itself (a body-fitted layout instead of the domain's lattice). scene/scene_builder.cpp
// gives each lattice site the material of the last shape that contains it. A new shape (a
// segmented image, say) is one new class here.
#include <array>
#include <cmath>
#include <memory>
#include <vector>

#include "scene/concentric_layout.hpp"
#include "scene/grain_pack.hpp"

namespace psph {

// The most particles a case may place (lattice sites, or a concentric sphere's points): at
// ~0.5 kB a particle, 200 GB.
constexpr double kMaxParticles = 4e8;

// The volume of the unit ball: 2 in 1D, pi in 2D, 4 pi / 3 in 3D.
inline double unit_ball_volume(int dimension) {
  return dimension == 1 ? 2 : dimension == 2 ? M_PI : 4 * M_PI / 3;
}

// An axis-aligned box [lower, upper] in `dimension` components.
struct Bounds {
  int dimension = 3;
  std::array<double, 3> lower{0, 0, 0}, upper{0, 0, 0};
  bool contains(const double* x) const {
    for (int k = 0; k < dimension; ++k)
      if (x[k] < lower[k] || x[k] > upper[k]) return false;
    return true;
  }
};

class Shape {
 public:
  virtual ~Shape() = default;
  // x has the case's dimension of components.
  virtual bool contains(const double* x) const = 0;
  virtual Bounds bounds() const = 0;
  // A shape with its own layout places its particles itself (points inside it, each with the
  // volume it stands for); the others take the lattice sites they contain.
  virtual bool places_points() const { return false; }
  virtual std::vector<LayoutPoint> points(double /*spacing*/) const { return {}; }
  // How many points `points` would place, before placing them.
  virtual double point_estimate(double /*spacing*/) const { return 0; }
};

std::shared_ptr<const Shape> make_box(const Bounds& box);
// A symmetric biconvex lens (a lens-shaped pore or crack): thickness 2 half_thickness along `axis`,
// its tips half_length from the centre across it.
struct LensSpec {
  std::array<double, 3> center{0, 0, 0};
  double half_length = 0, half_thickness = 0;
  int axis = 1;
};
std::shared_ptr<const Shape> make_lens(const LensSpec& lens, int dimension);
// layout "concentric" (scene/concentric_layout.hpp) or the lattice.
std::shared_ptr<const Shape> make_sphere(const std::array<double, 3>& centre, double radius, bool concentric,
                                         int dimension);
std::shared_ptr<const Shape> make_grain_pack(const GrainPackSpec& spec, std::vector<Grain> grains, int dimension);

}  // namespace psph
