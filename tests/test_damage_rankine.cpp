// Rankine / Mohr-Coulomb damage (damage/rankine_mohr_coulomb.hpp) under homogeneous strain against
// Pazdniakou 2018 eqs. 19-24, written out here: the piecewise tensile law (20), the compressive
// law (22), the relaxation (24) with healing, and how D enters the stress.
#include <cmath>

#include <gtest/gtest.h>

#include "damage/degraded_stress.hpp"
#include "damage/rankine_mohr_coulomb.hpp"

using namespace psph;

namespace {

constexpr double kTol = 1e-10;
constexpr double kE = 3e9, kK = kE / 3, kMu = kE / 2;  // nu = 0: the bar's stress is E eps

RankineMohrCoulomb clay() {
  RankineMohrCoulomb p;
  p.tensile_strength = 3e6;  // f_t / E = 1e-3 < eps_t0: the strain law (20) decides
  p.compressive_strength = 20e6;
  p.friction_factor = (1 + std::sin(25 * M_PI / 180)) / (1 - std::sin(25 * M_PI / 180));
  p.tensile_elastic_strain = 0.0013, p.tensile_ultimate_strain = 0.0026, p.compressive_elastic_strain = 0.015;
  p.residual_tensile_strength = 0.3e6, p.residual_compressive_strength = 2e6;
  p.relaxation_rate = 0.1;  // tau = 10 steps
  return p;
}

Mat<1> bar(double e) {
  Mat<1> m;
  m.a[0][0] = e;
  return m;
}

double target(const RankineMohrCoulomb& p, double e) {
  return rankine_mohr_coulomb_target(p, principal_state(bar(e), kK, kMu), kK, kMu);
}

}  // namespace

// Eq. 20 with tensile strain magnitude e: 0 up to e_t0, 1 - f_tr / (E e) up to e_tu, then 1.
TEST(DamageRankine, TensileLawIsPiecewise) {
  const RankineMohrCoulomb p = clay();
  for (double e = 1e-4; e < 4e-3; e += 1.7e-5) {
    const double expected = e <= 0.0013 ? 0 : e <= 0.0026 ? 1 - 0.3e6 / (kE * e) : 1;
    EXPECT_NEAR(target(p, e), expected, kTol) << e;
  }
  EXPECT_EQ(target(p, -1e-3), 0.0);  // compression below eq. 21's strength
}

// Eq. 19 gates eq. 20: past e_t0 but below f_t, no damage.
TEST(DamageRankine, TensileStrengthGatesTheLaw) {
  RankineMohrCoulomb p = clay();
  p.tensile_strength = 4e6;  // f_t / E = 1.333e-3
  EXPECT_EQ(target(p, 1.32e-3), 0.0);
  EXPECT_NEAR(target(p, 1.34e-3), 1 - 0.3e6 / (kE * 1.34e-3), kTol);
}

// Eqs. 21-22 under uniaxial compressive stress s in 3D (nu = 0.2): sigma_1 = s, sigma_3 = 0, so
// the criterion is s >= f_c, and D_c = 1 - f_cr / (E eps_1) past eps_c0. No principal stress is
// tensile, so the Mazars weight of the tension is 0 although the lateral strains are extensions.
TEST(DamageRankine, MohrCoulombUnderUniaxialCompression) {
  const RankineMohrCoulomb p = clay();
  const double E = 3e9, nu = 0.2, k = E / (3 * (1 - 2 * nu)), mu = E / (2 * (1 + nu));
  for (double s : {10e6, 19.9e6, 40e6, 60e6, 90e6}) {
    Mat<3> eps = Mat<3>::zero();
    eps.a[0][0] = eps.a[1][1] = nu * s / E, eps.a[2][2] = -s / E;
    const double e1 = s / E, expected = (s >= 20e6 && e1 > 0.015) ? 1 - 2e6 / (E * e1) : 0;
    EXPECT_NEAR(rankine_mohr_coulomb_target(p, principal_state(eps, k, mu), k, mu), expected, kTol) << s;
  }
}

// Mazars weights zeta_t = sum over extensions of eps^t_i eps_i / sum of eps_i^2: in pure shear with
// nu = 0 the only extension is the tensile stress's own (1); with no tensile stress, 0; in uniaxial
// tension with nu = 0.25 the lateral contractions do not count (1).
TEST(DamageRankine, MazarsWeights) {
  PrincipalState s{{1e-3, 0, -1e-3}, {3e6, 0, -3e6}};
  EXPECT_NEAR(mazars_tensile_weight(s, kE, 0.0), 1.0, kTol);
  PrincipalState c{{0, 0, -1e-3}, {0, 0, -3e6}};
  EXPECT_EQ(mazars_tensile_weight(c, kE, 0.0), 0.0);
  const double nu = 0.25, st = 3e6;
  PrincipalState u{{st / kE, -nu * st / kE, -nu * st / kE}, {st, 0, 0}};
  EXPECT_NEAR(mazars_tensile_weight(u, kE, nu), 1.0, kTol);
}

// Eq. 24 for a constant target T from D_0: D_n = T + (D_0 - T) (1 - 1/tau)^n exactly. Reversible,
// unloading heals the point the same way towards 0; irreversible, D stays.
TEST(DamageRankine, RelaxationTrajectoryAndHealing) {
  RankineMohrCoulomb p = clay();
  const double e = 2e-3, T = 1 - 0.3e6 / (kE * e), r = 1 - 1.0 / 10;
  double d = 0;
  for (int n = 1; n <= 40; ++n) {
    d = rankine_mohr_coulomb_update(p, d, bar(e), kK, kMu);
    EXPECT_NEAR(d, T * (1 - std::pow(r, n)), kTol) << n;
  }
  const double loaded = d;
  for (int n = 1; n <= 40; ++n) {
    d = rankine_mohr_coulomb_update(p, d, bar(0.0), kK, kMu);
    EXPECT_NEAR(d, loaded * std::pow(r, n), kTol) << n;
  }
  p.irreversible = true;
  d = loaded;
  for (int n = 1; n <= 10; ++n) d = rankine_mohr_coulomb_update(p, d, bar(0.0), kK, kMu);
  EXPECT_EQ(d, loaded);
  d = rankine_mohr_coulomb_update(p, d, bar(3e-3), kK, kMu);  // still grows towards 1
  EXPECT_NEAR(d, loaded + (1 - loaded) / 10, kTol);
}

// How D enters the stress: deviatoric only (the pressure term intact, Pazdniakou §5.2.3) or all
// moduli (eq. 18); a ghost at or above its threshold.
TEST(DamageRankine, DamageInTheStress) {
  const double d = 0.6, e = 1e-4;
  Mat<2> vol = Mat<2>::identity();
  vol.a[0][0] = vol.a[1][1] = -e;  // plane strain: tr = -2e
  Mat<2> shear = Mat<2>::zero();
  shear.a[0][1] = shear.a[1][0] = e;
  for (auto how : {DamageDegrades::Deviatoric, DamageDegrades::Ghost, DamageDegrades::AllModuli}) {
    const double keep = how == DamageDegrades::AllModuli ? 1 - d : 1;
    const Mat<2> sv = rankine_mohr_coulomb_stress(how, vol, kK, kMu, d);
    // mean of the 3D stress (sxx + syy + szz) / 3 = k tr, szz = (k - 2 mu (1 - d) / 3) tr.
    const double szz = (keep * kK - 2 * kMu * (1 - d) / 3) * (-2 * e);
    EXPECT_NEAR((sv.a[0][0] + sv.a[1][1] + szz) / 3 / (-2 * e), keep * kK, kTol * kK);
    EXPECT_NEAR(rankine_mohr_coulomb_stress(how, shear, kK, kMu, d).a[0][1], 2 * kMu * (1 - d) * e, kTol * kMu * e);
  }
  EXPECT_FALSE(is_damage_ghost(DamageDegrades::Ghost, 0.99, 0.98));
  EXPECT_TRUE(is_damage_ghost(DamageDegrades::Ghost, 0.99, 0.99));
  EXPECT_FALSE(is_damage_ghost(DamageDegrades::Deviatoric, 0.99, 1.0));
}
