#include "scene/concentric_layout.hpp"

#include <algorithm>
#include <cmath>

namespace psph {

std::vector<LayoutPoint> concentric_points(const std::array<double, 3>& centre, double radius, double dx,
                                           int D) {
  std::vector<LayoutPoint> out;
  const double golden = M_PI * (3 - std::sqrt(5.0));  // the Fibonacci spiral's turn per point
  // Shells of thickness dr = radius / round(radius / dx): the last one ends on the surface.
  const int shells = std::max(1, static_cast<int>(std::lround(radius / dx)));
  const double dr = radius / shells;
  for (int k = 0; k < shells; ++k) {
    const double r = (k + 0.5) * dr, lo = k * dr, hi = (k + 1) * dr;
    // Shell measure: 2 points (1D), the annulus pi (hi^2 - lo^2) (2D), the shell 4/3 pi (hi^3 - lo^3) (3D).
    const double shell = D == 1 ? 2 * dr : D == 2 ? M_PI * (hi * hi - lo * lo) : 4.0 / 3.0 * M_PI * (hi * hi * hi - lo * lo * lo);
    const int n = D == 1 ? 2 : std::max(1, static_cast<int>(std::lround(shell / std::pow(dx, D))));
    for (int q = 0; q < n; ++q) {
      LayoutPoint p;
      p.volume = shell / n;
      p.x = centre;
      if (D == 1) {
        p.x[0] += q == 0 ? -r : r;
      } else if (D == 2) {
        const double th = (q + 0.5 * (k % 2)) * 2 * M_PI / n;
        p.x[0] += r * std::cos(th), p.x[1] += r * std::sin(th);
      } else {
        const double z = n == 1 ? 0.0 : 1 - (2.0 * q + 1) / n, s = std::sqrt(std::max(0.0, 1 - z * z));
        const double ph = golden * q;
        p.x[0] += r * s * std::cos(ph), p.x[1] += r * s * std::sin(ph), p.x[2] += r * z;
      }
      out.push_back(p);
    }
  }
  return out;
}

}  // namespace psph
