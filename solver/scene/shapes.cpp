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

// The intersection of two balls of radius R = (a^2 + b^2) / (2 b) whose centres lie R - b either
// side of the centre along `axis`: thickness 2 b along it, tips (a rim in 3D) a from the centre.
class LensShape final : public Shape {
 public:
  LensShape(const LensSpec& l, int D) : l_(l), D_(D), R_((l.half_length * l.half_length + l.half_thickness * l.half_thickness) / (2 * l.half_thickness)) {}
  bool contains(const double* x) const override {
    for (double side : {-1.0, 1.0}) {
      double r2 = 0;
      for (int k = 0; k < D_; ++k) {
        const double c = l_.center[k] + (k == l_.axis ? side * (R_ - l_.half_thickness) : 0.0);
        r2 += (x[k] - c) * (x[k] - c);
      }
      if (r2 > R_ * R_) return false;
    }
    return true;
  }
  Bounds bounds() const override {
    Bounds b;
    b.dimension = D_;
    for (int k = 0; k < D_; ++k) {
      const double half = k == l_.axis ? l_.half_thickness : l_.half_length;
      b.lower[k] = l_.center[k] - half, b.upper[k] = l_.center[k] + half;
    }
    return b;
  }

 private:
  LensSpec l_;
  int D_;
  double R_;
};

std::shared_ptr<const Shape> make_box(const Bounds& box) { return std::make_shared<BoxShape>(box); }
std::shared_ptr<const Shape> make_lens(const LensSpec& lens, int dimension) {
  return std::make_shared<LensShape>(lens, dimension);
}
std::shared_ptr<const Shape> make_sphere(const std::array<double, 3>& centre, double radius, bool concentric,
                                         int dimension) {
  return std::make_shared<SphereShape>(centre, radius, concentric, dimension);
}
std::shared_ptr<const Shape> make_grain_pack(const GrainPackSpec& spec, std::vector<Grain> grains, int dimension) {
  return std::make_shared<GrainPackShape>(spec, std::move(grains), dimension);
}

}  // namespace psph
