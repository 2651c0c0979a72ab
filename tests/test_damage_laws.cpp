// The local damage laws (damage/) under homogeneous strain, against closed forms derived here from
// the references' equations, independently of the implementation: AT-1, AT-2 and PCW (Deptulski
// 2021 eqs. 4.17-4.23) and Rankine-Mohr-Coulomb (Pazdniakou 2018 eqs. 19-24).
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "damage/degraded_stress.hpp"
#include "damage/rankine_mohr_coulomb.hpp"
#include "damage/thermodynamic_update.hpp"

using namespace psph;

namespace {

constexpr double kTol = 1e-10;
// A 1D bar with nu = 0: k0 + 4 mu0 / 3 = E, so uniaxial strain is uniaxial stress.
constexpr double kE = 12e9, kK = kE / 3, kMu = kE / 2, kYc = 2.5e3;

Mat<1> bar(double e) {
  Mat<1> m;
  m.a[0][0] = e;
  return m;
}

ThermodynamicDamage model(Degradation g, bool linear, double yc = kYc) {
  ThermodynamicDamage m;
  m.degradation = g, m.linear_critical_energy = linear, m.critical_energy = yc, m.bound = 0.99;
  return m;
}

// Drives the bar monotonically through `strains`; returns the stress at each (and the damage in d).
std::vector<double> drive(const ThermodynamicDamage& m, const std::vector<double>& strains, std::vector<double>& d) {
  std::vector<double> s;
  double damage = 0;
  for (double e : strains) {
    damage = thermodynamic_damage_update(m, damage, bar(e), kK, kMu);
    d.push_back(damage);
    s.push_back(thermodynamic_stress(m, bar(e), kK, kMu, damage).a[0][0]);
  }
  return s;
}

std::vector<double> ramp(double from, double to, int n) {
  std::vector<double> e;
  for (int i = 0; i <= n; ++i) e.push_back(from + (to - from) * i / n);
  return e;
}

double stress_at(const ThermodynamicDamage& m, double e) {
  std::vector<double> d;
  return drive(m, ramp(0, e, 200), d).back();
}

}  // namespace

// AT-1: f = 2 (1 - D) E e^2 / 2 - Y_c0 = 0. Elastic up to e_p = sqrt(Y_c0 / E), where the stress
// peaks at sqrt(E Y_c0); then D = 1 - Y_c0 / (E e^2) and sigma = (1 - D)^2 E e = Y_c0^2 / (E e^3).
TEST(DamageLaws, At1OnsetPeakAndPostPeak) {
  const ThermodynamicDamage m = model(Degradation::Quadratic, false);
  const double ep = std::sqrt(kYc / kE), sp = std::sqrt(kE * kYc);
  std::vector<double> d;
  const auto e = ramp(0, 3 * ep, 300);
  const auto s = drive(m, e, d);
  for (std::size_t i = 0; i < e.size(); ++i) {
    const bool elastic = e[i] <= ep;
    const double dd = elastic ? 0 : 1 - kYc / (kE * e[i] * e[i]);
    EXPECT_NEAR(d[i], dd, kTol) << e[i];
    EXPECT_NEAR(s[i], elastic ? kE * e[i] : kYc * kYc / (kE * std::pow(e[i], 3)), kTol * sp) << e[i];
  }
  EXPECT_EQ(thermodynamic_damage_update(m, 0.0, bar(ep * (1 - 1e-9)), kK, kMu), 0.0);
  EXPECT_GT(thermodynamic_damage_update(m, 0.0, bar(ep * (1 + 1e-6)), kK, kMu), 0.0);
  EXPECT_NEAR(stress_at(m, ep), sp, kTol * sp);
  EXPECT_LT(stress_at(m, ep * 1.001), sp);
}

// AT-2: 2 (1 - D) w = 2 D Y_c0 with w = E e^2 / 2: D = w / (w + Y_c0), damage from the first
// strain, sigma = E e (Y_c0 / (w + Y_c0))^2. d sigma / de = 0 at w = Y_c0 / 3: e_p = sqrt(2 Y_c0 /
// (3 E)), sigma_p = (3/4)^2 E e_p.
TEST(DamageLaws, At2OnsetPeakAndPostPeak) {
  const ThermodynamicDamage m = model(Degradation::Quadratic, true);
  const double ep = std::sqrt(2 * kYc / (3 * kE)), sp = 9.0 / 16.0 * kE * ep;
  std::vector<double> d;
  const auto e = ramp(0, 4 * ep, 400);
  const auto s = drive(m, e, d);
  for (std::size_t i = 0; i < e.size(); ++i) {
    const double w = 0.5 * kE * e[i] * e[i];
    EXPECT_NEAR(d[i], w / (w + kYc), kTol) << e[i];
    EXPECT_NEAR(s[i], kE * e[i] * std::pow(kYc / (w + kYc), 2), kTol * sp) << e[i];
  }
  EXPECT_GT(thermodynamic_damage_update(m, 0.0, bar(1e-9 * ep), kK, kMu), 0.0);
  EXPECT_NEAR(stress_at(m, ep), sp, kTol * sp);
  EXPECT_LT(stress_at(m, ep * 0.999), sp);
  EXPECT_LT(stress_at(m, ep * 1.001), sp);
}

// PCW with alpha = 1, beta = e_u / e_0 - 1, Y_c0 = E e_0 e_u / 2: (1 + beta) w / (1 + beta D)^2 =
// Y_c0 gives D = (e - e_0) / (e_u - e_0), so sigma = (1 - D) / (1 + beta D) E e = E e_0 (e_u - e) /
// (e_u - e_0): elastic to the peak E e_0 at e_0, linear softening (the bar of Deptulski Table 4.1),
// until D reaches s_l at e_l = e_0 + s_l (e_u - e_0); beyond, sigma = g(s_l) E e.
TEST(DamageLaws, PcwOnsetPeakLinearSofteningAndBound) {
  const double e0 = 0.022, eu = 0.060, sl = 0.99, beta = eu / e0 - 1;
  ThermodynamicDamage m = model(Degradation::Pcw, false, 0.5 * kE * e0 * eu);
  m.alpha = 1, m.beta = beta, m.bound = sl;
  const double el = e0 + sl * (eu - e0);
  std::vector<double> d;
  const auto e = ramp(0, 1.2 * eu, 600);
  const auto s = drive(m, e, d);
  for (std::size_t i = 0; i < e.size(); ++i) {
    double dd = 0, ss = kE * e[i];
    if (e[i] > el) dd = sl, ss = (1 - sl) / (1 + beta * sl) * kE * e[i];
    else if (e[i] > e0) dd = (e[i] - e0) / (eu - e0), ss = kE * e0 * (eu - e[i]) / (eu - e0);
    EXPECT_NEAR(d[i], dd, kTol) << e[i];
    EXPECT_NEAR(s[i], ss, kTol * kE * e0) << e[i];
  }
  EXPECT_EQ(thermodynamic_damage_update(m, 0.0, bar(e0 * (1 - 1e-9)), kK, kMu), 0.0);
  EXPECT_GT(thermodynamic_damage_update(m, 0.0, bar(e0 * (1 + 1e-6)), kK, kMu), 0.0);
  EXPECT_NEAR(stress_at(m, e0), kE * e0, kTol * kE * e0);
}

// The closed-form roots solve f = Y(D) - Y_c(D) = 0 with Y = -g'(D) w~ (Deptulski eq. 4.19), g' by
// the quotient rule here, for PCW with alpha != 1 and either Y_c, over ten decades of w~.
TEST(DamageLaws, PcwRootsSolveTheLoadingFunction) {
  for (bool linear : {false, true}) {
    ThermodynamicDamage m = model(Degradation::Pcw, linear);
    m.alpha = 0.7, m.beta = 1.9;
    for (double w = 1e-6 * kYc; w < 1e4 * kYc; w *= 3.7) {
      const double dd = threshold_damage(m, w);
      if (!linear && dd == 0) {  // below the onset (alpha + beta) w = Y_c0
        EXPECT_LE((m.alpha + m.beta) * w, kYc);
        continue;
      }
      const double q = 1 + m.beta * dd;
      const double slope = (-m.alpha * q - m.beta * (1 - m.alpha * dd)) / (q * q);
      const double yc = linear ? 2 * dd * kYc : kYc;
      EXPECT_NEAR(-slope * w, yc, 1e-12 * yc) << w;
    }
  }
}

// Irreversible: unloading keeps D; reloading below the largest strain adds none.
TEST(DamageLaws, ThermodynamicDamageNeverDecreases) {
  const ThermodynamicDamage m = model(Degradation::Quadratic, true);
  const double big = thermodynamic_damage_update(m, 0.0, bar(1e-3), kK, kMu);
  EXPECT_EQ(thermodynamic_damage_update(m, big, bar(0.0), kK, kMu), big);
  EXPECT_EQ(thermodynamic_damage_update(m, big, bar(5e-4), kK, kMu), big);
  EXPECT_EQ(thermodynamic_damage_update(m, big, bar(-1e-3), kK, kMu), big);
  EXPECT_EQ(thermodynamic_damage_update(m, 0.0, bar(1.0), kK, kMu), 0.99);  // s_l
}

// Energy balance of monotone loading: the work of the stress, integral of sigma de, is the free
// energy sigma e / 2 plus the dissipated energy (Deptulski eq. 4.26b; Y_c0 D^2 with Y_c = 2 D Y_c0).
// Under PCW's bilinear law the work is a triangle and a trapezoid, and at e_u all of it,
// Y_c0 = E e0 e_u / 2, is dissipated.
TEST(DamageLaws, DissipatedEnergyClosesTheWorkBalance) {
  const ThermodynamicDamage at2 = model(Degradation::Quadratic, true);
  const double ep = std::sqrt(2 * kYc / (3 * kE)), e = 3 * ep;
  const int n = 20000;  // Simpson on the closed-form AT-2 stress
  double work = 0;
  for (int i = 0; i <= n; ++i) {
    const double x = e * i / n, w = 0.5 * kE * x * x;
    work += (i == 0 || i == n ? 1 : i % 2 ? 4 : 2) * kE * x * std::pow(kYc / (w + kYc), 2);
  }
  work *= e / n / 3;
  const double d = thermodynamic_damage_update(at2, 0.0, bar(e), kK, kMu);
  const double psi = half_contraction(thermodynamic_stress(at2, bar(e), kK, kMu, d), bar(e));
  EXPECT_NEAR(psi + dissipated_energy_density(at2, d), work, 1e-10 * work);

  const double e0 = 0.022, eu = 0.060;
  ThermodynamicDamage pcw = model(Degradation::Pcw, false, 0.5 * kE * e0 * eu);
  pcw.beta = eu / e0 - 1, pcw.bound = 1;
  const double x = 0.04;  // on the softening branch: triangle to e0, trapezoid e0..x
  const double sx = kE * e0 * (eu - x) / (eu - e0);
  const double w_pcw = 0.5 * kE * e0 * e0 + 0.5 * (kE * e0 + sx) * (x - e0);
  const double dx = thermodynamic_damage_update(pcw, 0.0, bar(x), kK, kMu);
  const double psi_x = half_contraction(thermodynamic_stress(pcw, bar(x), kK, kMu, dx), bar(x));
  EXPECT_NEAR(psi_x + dissipated_energy_density(pcw, dx), w_pcw, kTol * w_pcw);
  EXPECT_NEAR(dissipated_energy_density(pcw, 1.0), 0.5 * kE * e0 * eu, kTol * kE * e0 * eu);
}

// Crack closure (Deptulski eq. 4.17): a point damaged in extension, then compressed
// isotropically, has exactly the intact bulk modulus; in extension its bulk modulus is g(D) k0.
// Without the split, compression finds it degraded too.
TEST(DamageLaws, UnilateralSwitchRestoresTheIntactBulkModulus) {
  const double k = 8e9, mu = 4.8e9, e = 4e-4;
  const Mat<3> open = [&] { Mat<3> m = Mat<3>::identity(); for (int i = 0; i < 3; ++i) m.a[i][i] = e; return m; }();
  Mat<3> closed = open;
  for (int i = 0; i < 3; ++i) closed.a[i][i] = -e;
  ThermodynamicDamage m = model(Degradation::Quadratic, true);
  const double d = thermodynamic_damage_update(m, 0.0, open, k, mu);
  ASSERT_GT(d, 0.5);
  EXPECT_EQ(thermodynamic_damage_update(m, d, closed, k, mu), d);
  const Mat<3> sc = thermodynamic_stress(m, closed, k, mu, d), so = thermodynamic_stress(m, open, k, mu, d);
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(sc.a[i][i] / (-3 * e), k, kTol * k);
    EXPECT_NEAR(so.a[i][i] / (3 * e), (1 - d) * (1 - d) * k, kTol * k);
    for (int j = 0; j < 3; ++j)
      if (i != j) {
        EXPECT_EQ(sc.a[i][j], 0.0);
      }
  }
  m.unilateral = false;
  EXPECT_NEAR(thermodynamic_stress(m, closed, k, mu, d).a[0][0] / (-3 * e), (1 - d) * (1 - d) * k, kTol * k);
  // In compression only the deviatoric energy drives damage: mu0 eps^d : eps^d.
  Mat<3> squeeze = Mat<3>::zero();
  squeeze.a[2][2] = -e;
  EXPECT_NEAR(driving_energy(squeeze, k, mu, true), mu * (2.0 / 3.0) * e * e, kTol * mu * e * e);
  EXPECT_NEAR(driving_energy(squeeze, k, mu, false), 0.5 * (k + 4 * mu / 3) * e * e, kTol * mu * e * e);
}

// In 2D the point is in plane strain: the 2D deviator norm counts eps_zz^d = -tr(eps)/3, the same
// as the 3D strain with a zero third row.
TEST(DamageLaws, PlaneStrainDeviatorCountsTheOutOfPlaneComponent) {
  Mat<2> e2;
  e2.a[0][0] = 3e-4, e2.a[0][1] = e2.a[1][0] = -1e-4, e2.a[1][1] = -5e-5;
  Mat<3> e3 = Mat<3>::zero();
  for (int r = 0; r < 2; ++r)
    for (int c = 0; c < 2; ++c) e3.a[r][c] = e2.a[r][c];
  const double tr = 2.5e-4, dd = 9e-8 + 2e-8 + 2.5e-9 - tr * tr / 3;  // eps : eps - tr^2 / 3
  EXPECT_NEAR(deviator_norm2(e2), dd, 1e-12 * dd);
  EXPECT_NEAR(deviator_norm2(e3), dd, 1e-12 * dd);
}
