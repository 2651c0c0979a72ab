// The shape of an image's phases (scene/image_shape.hpp).
#include "scene/image_shape.hpp"

#include <cmath>

namespace psph {
namespace {

// The coarse voxel holding x (false outside the image).
bool voxel_of(const ImageGrid& g, const double* x, long q[3]) {
  q[2] = g.slice;
  for (int k = 0; k < g.dimension; ++k) {
    q[k] = long(std::floor((x[k] - g.origin[k]) / g.voxel[k]));
    if (q[k] < 0 || q[k] >= g.volume.size[k]) return false;
  }
  return true;
}

Bounds voxel_box(const ImageGrid& g, const std::array<long, 3>& lower, const std::array<long, 3>& upper) {
  Bounds b;
  b.dimension = g.dimension;
  for (int k = 0; k < g.dimension; ++k)
    b.lower[k] = g.origin[k] + double(lower[k]) * g.voxel[k], b.upper[k] = g.origin[k] + double(upper[k]) * g.voxel[k];
  return b;
}

class ImagePhases final : public Shape {
 public:
  ImagePhases(std::shared_ptr<const ImageGrid> g, unsigned phases) : g_(std::move(g)), phases_(phases) {}

  bool contains(const double* x) const override {
    long q[3];
    return voxel_of(*g_, x, q) && (phases_ >> g_->volume.at(q[0], q[1], q[2]) & 1u);
  }
  Bounds bounds() const override { return voxel_box(*g_, {0, 0, 0}, g_->volume.size); }

 private:
  std::shared_ptr<const ImageGrid> g_;
  unsigned phases_;
};

class ImageInclusion final : public Shape {
 public:
  ImageInclusion(std::shared_ptr<const ImageGrid> g, std::int32_t index, const std::array<long, 3>& lower,
                 const std::array<long, 3>& upper)
      : g_(std::move(g)), index_(index), box_(voxel_box(*g_, lower, upper)) {}

  bool contains(const double* x) const override {
    long q[3];
    if (!voxel_of(*g_, x, q)) return false;  // (the builder tests the bounds first)
    return g_->inclusion[std::size_t((q[2] * g_->volume.size[1] + q[1]) * g_->volume.size[0] + q[0])] == index_;
  }
  Bounds bounds() const override { return box_; }

 private:
  std::shared_ptr<const ImageGrid> g_;
  std::int32_t index_;
  Bounds box_;
};

}  // namespace

std::shared_ptr<const Shape> make_image_phases(std::shared_ptr<const ImageGrid> grid, unsigned phases) {
  return std::make_shared<ImagePhases>(std::move(grid), phases);
}

std::shared_ptr<const Shape> make_image_inclusion(std::shared_ptr<const ImageGrid> grid, std::int32_t index,
                                                  const std::array<long, 3>& lower, const std::array<long, 3>& upper) {
  return std::make_shared<ImageInclusion>(std::move(grid), index, lower, upper);
}

}  // namespace psph
