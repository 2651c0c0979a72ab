// The shapes of [[geometry]]: box, sphere (lattice or concentric layout) and grain pack.
#include <cmath>

#include "scene/shape.hpp"

namespace psph {
namespace {

class BoxShape final : public Shape {
 public:
  explicit BoxShape(const Bounds& b) : b_(b) {}
  bool contains(const double* x) const override { return b_.contains(x); }
  Bounds bounds() const override { return b_; }

 private:
  Bounds b_;
};

class SphereShape final : public Shape {
 public:
  SphereShape(const std::array<double, 3>& c, double r, bool concentric, int D)
      : c_(c), r_(r), concentric_(concentric), D_(D) {}
  bool contains(const double* x) const override {
    double r2 = 0;
    for (int k = 0; k < D_; ++k) r2 += (x[k] - c_[k]) * (x[k] - c_[k]);
    return r2 <= r_ * r_;
  }
  Bounds bounds() const override {
    Bounds b;
    b.dimension = D_;
    for (int k = 0; k < D_; ++k) b.lower[k] = c_[k] - r_, b.upper[k] = c_[k] + r_;
    return b;
  }
  bool places_points() const override { return concentric_; }
  std::vector<LayoutPoint> points(double spacing) const override {
    return concentric_ ? concentric_points(c_, r_, spacing, D_) : std::vector<LayoutPoint>{};
  }
  // Shells of one spacing: about the volume in spacings, (R / dx)^D times the unit ball's volume.
  double point_estimate(double spacing) const override {
    return concentric_ ? std::pow(r_ / spacing, D_) * unit_ball_volume(D_) : 0;
  }

 private:
  std::array<double, 3> c_;
  double r_;
  bool concentric_;
  int D_;
};

class GrainPackShape final : public Shape {
 public:
  GrainPackShape(const GrainPackSpec& spec, std::vector<Grain> grains, int D)
      : spec_(spec), grains_(std::move(grains)), D_(D) {}
  bool contains(const double* x) const override { return in_grain_pack(spec_, grains_, x, D_); }
  Bounds bounds() const override { return Bounds{D_, spec_.lower, spec_.upper}; }

 private:
  GrainPackSpec spec_;
  std::vector<Grain> grains_;
  int D_;
};

}  // namespace

std::shared_ptr<const Shape> make_box(const Bounds& box) { return std::make_shared<BoxShape>(box); }
std::shared_ptr<const Shape> make_sphere(const std::array<double, 3>& centre, double radius, bool concentric,
                                         int dimension) {
  return std::make_shared<SphereShape>(centre, radius, concentric, dimension);
}
std::shared_ptr<const Shape> make_grain_pack(const GrainPackSpec& spec, std::vector<Grain> grains, int dimension) {
  return std::make_shared<GrainPackShape>(spec, std::move(grains), dimension);
}

}  // namespace psph
