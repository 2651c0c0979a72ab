// The contact-line force (interface/contact_line.hpp) on a lattice: a straight interface meets a flat
// wall at theta_d; summed over the fluid, the force per unit length must be the unbalanced Young
// force sigma (cos theta_s - cos theta_d), pointing into the gas when the liquid should spread, and
// vanish when theta_d = theta_s.
#include <cmath>

#include <gtest/gtest.h>

#include "interface/contact_line.hpp"

using namespace psph;

namespace {

struct LineForce {
  Vec<2> total = Vec<2>::zero();  // sum_i V_i rho_i a_i: force per unit length of contact line
  double angle_error = 0;          // degrees: theta_d from the fluid's corrected colour gradient, interface-weighted
};

// Wall y < 0, fluid y > 0 on a unit lattice (volume 1); the interface passes through the origin with
// the liquid on the side of n = (-sin t, -cos t) (gas -> liquid), so that cos(theta_d) = -n . e_y.
// The colour is a smooth step across it, c = tanh(d / 1.5), d the signed distance along n.
LineForce line_force(double theta_d_deg, double theta_s_deg, double sigma) {
  const double t = theta_d_deg * M_PI / 180, hs = 3;
  const Kernel<2> kern = Kernel<2>::make(KernelType::QuinticSpline, Real(hs));
  Vec<2> n;
  n[0] = -std::sin(t), n[1] = -std::cos(t);
  auto colour = [&](double x, double y) { return std::tanh((x * n[0] + y * n[1]) / 1.5); };
  LineForce out;
  double weight = 0;
  for (int ix = -30; ix < 30; ++ix)
    for (int iy = 0; iy < 4; ++iy) {  // rows within one support of the wall
      const double xi = ix + 0.5, yi = iy + 0.5, ci = colour(xi, yi);
      ContactLineSum<2> sum;
      for (int jx = ix - 3; jx <= ix + 3; ++jx)
        for (int jy = -6; jy <= iy + 3; ++jy) {
          Vec<2> rij;
          rij[0] = xi - (jx + 0.5), rij[1] = yi - (jy + 0.5);
          const Real r = norm(rij);
          if (!(r > 0) || r >= hs) continue;
          if (jy < 0) sum.add(1, rij, kern.F(r), kern.W(r), Real(std::cos(theta_s_deg * M_PI / 180)));
          else sum.add_fluid(1, rij, kern.F(r), Real(colour(jx + 0.5, jy + 0.5) - ci));
        }
      const double gx = (1 - ci * ci) / 1.5;  // |grad c| of the step
      Vec<2> grad_c = n * Real(gx);
      out.total += sum.acceleration(grad_c, Real(sigma), 1000) * Real(1000);
      Mat<2> K;
      if (norm2(sum.grad_wall) > 0 && invert(sum.moment, K, Real(1e-6))) {
        const Vec<2> g = K * sum.colour_sum;
        const double angle = std::acos(std::clamp(-double(g[1]) / double(norm(g)), -1.0, 1.0)) * 180 / M_PI;
        out.angle_error += gx * (angle - theta_d_deg), weight += gx;
      }
    }
  out.angle_error /= weight;
  return out;
}

}  // namespace

TEST(ContactLine, TheForceIsTheUnbalancedYoungForce) {
  const double sigma = 1e-3;
  for (double theta_d : {60.0, 90.0, 120.0}) {
    for (double theta_s : {30.0, 90.0, 150.0}) {
      const LineForce f = line_force(theta_d, theta_s, sigma);
      const double young = sigma * (std::cos(theta_s * M_PI / 180) - std::cos(theta_d * M_PI / 180));
      // Along the wall, towards the gas (+x here) when the liquid should spread (young > 0).
      EXPECT_NEAR(f.total[0], young, 0.1 * std::fabs(young) + 1e-12) << theta_d << " on a " << theta_s << " wall";
      EXPECT_NEAR(f.total[1], 0.0, 1e-12);
      EXPECT_LT(std::fabs(f.angle_error), 2.0) << theta_d;
    }
  }
  // At rest at its own angle the line feels (almost) nothing: the residual of the discrete
  // theta_d is below sigma (cos 121.5 - cos 120), 1.5 degrees.
  for (double theta : {30.0, 90.0, 120.0, 150.0})
    EXPECT_LT(std::fabs(line_force(theta, theta, sigma).total[0]), 0.025 * sigma) << theta;
}
