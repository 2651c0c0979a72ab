// The shape of an image's phases (scene/image_shape.hpp).
#include "scene/image_shape.hpp"

#include <cmath>

namespace psph {
namespace {

class ImagePhases final : public Shape {
 public:
  ImagePhases(std::shared_ptr<const ImageGrid> g, unsigned phases) : g_(std::move(g)), phases_(phases) {}

  bool contains(const double* x) const override {
    long q[3] = {0, 0, g_->slice};
    for (int k = 0; k < g_->dimension; ++k) {
      q[k] = long(std::floor((x[k] - g_->origin[k]) / g_->voxel[k]));
      if (q[k] < 0 || q[k] >= g_->volume.size[k]) return false;
    }
    return phases_ >> g_->volume.at(q[0], q[1], q[2]) & 1u;
  }
  Bounds bounds() const override {
    Bounds b;
    b.dimension = g_->dimension;
    for (int k = 0; k < g_->dimension; ++k)
      b.lower[k] = g_->origin[k], b.upper[k] = g_->origin[k] + double(g_->volume.size[k]) * g_->voxel[k];
    return b;
  }

 private:
  std::shared_ptr<const ImageGrid> g_;
  unsigned phases_;
};

}  // namespace

std::shared_ptr<const Shape> make_image_phases(std::shared_ptr<const ImageGrid> grid, unsigned phases) {
  return std::make_shared<ImagePhases>(std::move(grid), phases);
}

}  // namespace psph
