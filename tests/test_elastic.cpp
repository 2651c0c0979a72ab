// Elastic solids (solid/): the Navier operator on a lattice, the case keys, a clamped rod that
// conserves its energy, its strain and stress fields, and the stress law with damage.
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "case_text.hpp"
#include "engine/engine.hpp"
#include "neighbours/host_neighbours.hpp"
#include "scene/embedded_cases.hpp"
#include "solid/constitutive.hpp"
#include "solid/elastic_force.hpp"
#include "validation/oscillating_plate.hpp"
#include "validation/vibrating_rod.hpp"

using namespace psph;
using psph::test::error_of;
using psph::test::expect_refused;
using psph::test::replaced;

namespace {

// rho a at the centre of a lattice (support 4 spacings) for the displacement field u(x), from the
// pair terms the elastic pass sums. Each Hessian component of eq. 61 carries a lattice anisotropy
// error (our computation, not in the paper: ~30 % at support 2 spacings, ~1 % at 4 in 3D); in
// 2D at 4 spacings the d2u_y/dx2 term reads 3.6 % low while their sum, the Laplacian, is within
// 0.1 %.
template <int D, class U>
Vec<D> navier_at_centre(const U& u, Real k, Real mu) {
  const int n = 13;
  const Real dx = Real(0.1), support = 4 * dx;
  std::vector<Point<D>> pts;
  int total = 1;
  for (int d = 0; d < D; ++d) total *= n;
  for (int s = 0; s < total; ++s) {
    Point<D> p;
    for (int d = 0, r = s; d < D; ++d, r /= n) p[d] = Coord((r % n - n / 2) * dx);
    pts.push_back(p);
  }
  Coord lo[D], hi[D];
  bool per[D];
  for (int d = 0; d < D; ++d) lo[d] = -(n / 2 + 1) * dx, hi[d] = (n / 2 + 1) * dx, per[d] = false;
  HostNeighbours<D> nb(pts, lo, hi, per, support);
  const Kernel<D> kern = Kernel<D>::make(KernelType::CubicSpline, support);
  int centre = 0;
  for (int i = 0; i < total; ++i)
    if (norm(nb.x[i]) < dx / 10) centre = i;
  const Real V = std::pow(dx, D);
  Vec<D> f = Vec<D>::zero();
  nb.view().for_each(centre, [&](int j, const Vec<D>& rij, Real r) {
    f += navier_pair<D>(u(to_real(nb.x[centre])) - u(to_real(nb.x[j])), rij * (Real(1) / r), k, mu) * (V * kern.F(r));
  });
  return f;
}

template <int D>
void check_navier() {
  const Real k = 5, mu = 2, A = 3;
  auto ex = [](int d) {
    Vec<D> e = Vec<D>::zero();
    e[d] = 1;
    return e;
  };
  // u = (A x^2 / 2) e_x: mu lap u + (k + mu/3) grad div u = (k + 4 mu/3) A e_x.
  Vec<D> f = navier_at_centre<D>([&](const Vec<D>& x) { return ex(0) * (A * x[0] * x[0] / 2); }, k, mu);
  EXPECT_NEAR(f[0], (k + 4 * mu / 3) * A, 0.05 * (k + 4 * mu / 3) * A);
  for (int d = 1; d < D; ++d) EXPECT_NEAR(f[d], 0, 1e-9);
  // The Laplacian alone (k = -mu/3: lambda + mu = 0) is accurate: mu A.
  f = navier_at_centre<D>([&](const Vec<D>& x) { return ex(1) * (A * (x[0] * x[0] + x[D - 1] * x[D - 1]) / 2); },
                          -mu / 3, mu);
  EXPECT_NEAR(f[1], 2 * mu * A, 0.002 * mu * A);
  // u = (A x^2 / 2) e_y (divergence-free): mu A e_y.
  f = navier_at_centre<D>([&](const Vec<D>& x) { return ex(1) * (A * x[0] * x[0] / 2); }, k, mu);
  EXPECT_NEAR(f[1], mu * A, 0.05 * mu * A);
  EXPECT_NEAR(f[0], 0, 1e-9);
  // u = (A x y) e_x: lap u = 0, grad div u = A e_y, so (k + mu/3) A e_y.
  f = navier_at_centre<D>([&](const Vec<D>& x) { return ex(0) * (A * x[0] * x[1]); }, k, mu);
  EXPECT_NEAR(f[1], (k + mu / 3) * A, 0.05 * (k + mu / 3) * A);
  EXPECT_NEAR(f[0], 0, 1e-9);
  // A uniform strain exerts no force inside the solid.
  f = navier_at_centre<D>([&](const Vec<D>& x) { return x * Real(0.01) + ex(0) * (Real(0.02) * x[D - 1]); }, k, mu);
  EXPECT_LT(norm(f), 1e-9);
}

const std::string rod = embedded_case_text("vibrating_rod_1d");

}  // namespace

TEST(Elastic, NavierOperatorOnALattice2D) { check_navier<2>(); }
TEST(Elastic, NavierOperatorOnALattice3D) { check_navier<3>(); }

TEST(Elastic, CaseKeys) {
  EXPECT_EQ(error_of(rod), "");
  expect_refused(rod, "poisson_ratio = 0.0", "poisson_ratio = 0.5", "bad.toml: materials.steel.poisson_ratio: expected a Poisson ratio in (-1, 0.5), got 0.5");
  expect_refused(rod, "young_modulus = 2.0e11\n", "", "materials.steel.young_modulus: missing");
  // Above nu = 1/4 the central pair forces of the displacement form have a negative transverse
  // stiffness: refused in 2D with it; the stress form (the default) takes any ratio.
  const std::string plate = embedded_case_text("oscillating_plate_2d");  // nu = 0.3975
  EXPECT_EQ(error_of(plate), "");
  const std::string displacement_form = plate + "\n[solid]\nformulation = \"displacement\"\n";
  EXPECT_NE(error_of(displacement_form).find("materials.plate.poisson_ratio: expected a Poisson ratio below 0.25 in 2D and 3D"),
            std::string::npos) << error_of(displacement_form);
  expect_refused(rod + "\n[solid]\nformulation = \"stress\"\n", "formulation = \"stress\"", "formulation = \"strain\"",
                 "solid.formulation");
  EXPECT_EQ(error_of(rod + "\n[solid]\nformulation = \"displacement\"\n"), "");
  expect_refused(rod, "young_modulus = 2.0e11", "young_modulus = -1.0", "materials.steel.young_modulus");
  // Damping and the fluid coupling.
  expect_refused(rod + "\n[solid]\ndamping_rate = 10.0\n", "damping_rate = 10.0", "damping_rate = -1.0", "solid.damping_rate");
  expect_refused(rod + "\n[solid]\ncoupling = \"pair\"\n", "", "",
                 "solid.coupling: expected a case with both fluids and elastic solids");
  const std::string cube = embedded_case_text("elastic_cube_3d");
  EXPECT_EQ(error_of(cube), "");
  expect_refused(cube, "[solid]", "[solid]\ncoupling = \"summation\"", "solid.coupling");
  expect_refused(cube, "[solid]", "[solid]\nformulation = \"displacement\"\ncoupling = \"traction\"",
                 "solid.coupling: expected \"pair\" or \"pair_eos\" with formulation = \"displacement\"");
  EXPECT_EQ(error_of(replaced(cube, "[solid]", "[solid]\nformulation = \"displacement\"")), "");
  // Saint Venant-Kirchhoff with eq. 74's small-strain pressure: refused whichever key comes first.
  for (const char* keys : {"model = \"saint_venant_kirchhoff\"\ncoupling = \"pair_eos\"",
                           "coupling = \"pair_eos\"\nmodel = \"saint_venant_kirchhoff\""})
    expect_refused(cube, "[solid]", std::string("[solid]\n") + keys,
                   "solid.coupling: expected \"traction\" or \"pair\" with model = \"saint_venant_kirchhoff\"");
  EXPECT_EQ(error_of(replaced(cube, "[solid]", "[solid]\nmodel = \"saint_venant_kirchhoff\"\ncoupling = \"pair\"")), "");
  // The reference pressure: the traction's, with fluids about.
  expect_refused(rod + "\n[solid]\nreference_pressure = 1.0\n", "", "",
                 "solid.reference_pressure: expected a case with both fluids and elastic solids");
  EXPECT_EQ(error_of(replaced(cube, "[solid]", "[solid]\nreference_pressure = 1.0")), "");
  expect_refused(cube, "[solid]", "[solid]\nreference_pressure = -1.0", "solid.reference_pressure");
  expect_refused(cube, "[solid]", "[solid]\ncoupling = \"pair\"\nreference_pressure = 1.0",
                 "solid.reference_pressure: expected coupling = \"traction\"");
  // The hourglass control: the stress form's, alpha in [0, 1].
  EXPECT_EQ(error_of(replaced(cube, "[solid]", "[solid]\nhourglass_control = 0.1")), "");
  expect_refused(cube, "[solid]", "[solid]\nhourglass_control = 2.0", "solid.hourglass_control: expected a penalty factor alpha in [0, 1]");
  expect_refused(cube, "[solid]", "[solid]\nformulation = \"displacement\"\ncoupling = \"pair\"\nhourglass_control = 0.1",
                 "solid.hourglass_control: expected formulation = \"stress\"");
  expect_refused(cube, "[solver]", "[solver]\nimplicit_viscosity = true", "solver.implicit_viscosity: expected false");
  expect_refused(cube, "[solver]", "[solver]\nlaplacian_correction = \"tensor\"", "solver.laplacian_correction");
  const std::string water = embedded_case_text("poiseuille_2d");
  expect_refused(water, "[time]", "[solid]\ndamping_rate = 1.0\n\n[time]",
                 "solid.damping_rate: expected a material with kind = \"elastic\"");
  expect_refused(rod, "lower = [0.0]\nupper = [0.1333]\nmaterial = \"steel\"", "lower = [0.0]\nupper = [0.1333]\nmaterial = \"clamp\"",
          "no fluid, elastic or rigid particles");
}

// A rod at rest stays at rest; a rod set vibrating passes its kinetic energy to the elastic one and
// back, their sum conserved by the symmetric pair forces.
TEST(Elastic, AClampedRodConservesItsEnergy) {
  Case c = load_case_text(replaced(rod, "end = 1.6e-4", "end = 2.0e-5"), "rod.toml");
  build_particles(c);
  auto still = make_engine(c.scene, "cpu");
  still->run_until(2e-5);
  EXPECT_EQ(still->stats().v_max, 0.0);
  const double c_sound = std::sqrt(2e11 / 7833.0), L = 0.1333, omega = M_PI * c_sound / L;
  for (int i = 0; i < c.scene.count(); ++i)
    if (c.scene.materials[c.scene.material[i]].props.kind == MaterialKind::Elastic)
      c.scene.v[i] = L / 2000 * omega * std::sin(M_PI * c.scene.x[i] / L);
  auto e = make_engine(c.scene, "cpu");
  const StepStats s0 = e->stats();
  EXPECT_GT(s0.kinetic_energy, 0);
  EXPECT_EQ(s0.elastic_energy, 0);
  e->run_until(13.2e-6);  // a quarter period: the energy has moved into the spring
  const StepStats s1 = e->stats();
  EXPECT_GT(s1.elastic_energy, 0.9 * s0.kinetic_energy);
  EXPECT_NEAR(s1.kinetic_energy + s1.elastic_energy, s0.kinetic_energy, 0.01 * s0.kinetic_energy);
}

// A quarter period into the first clamped-clamped mode, u = C2 sin(pi x / L): the strain is
// C2 pi / L cos(pi x / L) and, with nu = 0, the stress E times it; the principal stress is the stress.
// The clamps present the mirrored displacement, so the sine continues through them and the strain
// is within 0.005 % of the peak everywhere (with a kernel-averaged mirror it was 6 % off next to
// the clamps).
TEST(Elastic, StrainAndStressOfAVibratingRod) {
  Case c = vibrating_rod_case(1, false);
  auto e = make_engine(c.scene, "cpu");
  const double L = 0.1333, C2 = L / 2000, E = 2e11, quarter = c.end_time / 12;  // end: three periods
  const double support = c.scene.options.support_radius;
  e->run_until(quarter);
  const std::vector<double> x0 = e->field("reference_position"), eps = e->field("strain"), sigma = e->field("stress"),
                            p = e->field("principal_stress"), mat = e->field("material");
  const double peak = C2 * M_PI / L;
  double inside = 0, near_clamps = 0;
  int n = 0;
  for (int i = 0; i < e->particles(); ++i) {
    if (c.scene.materials[static_cast<int>(mat[i])].props.kind != MaterialKind::Elastic) continue;
    ++n;
    const double err = std::fabs(eps[i] - peak * std::cos(M_PI * x0[i] / L)) / peak;
    double& worst = x0[i] > support && x0[i] < L - support ? inside : near_clamps;
    worst = std::max(worst, err);
    EXPECT_NEAR(sigma[i], E * eps[i], 1e-9 * E * peak);
    EXPECT_NEAR(p[3 * i], sigma[i], 1e-9 * E * peak);
  }
  EXPECT_EQ(n, 200);
  std::printf("strain of the rod a quarter period in: max error %.4f %% of the peak inside, %.4f %% near the clamps\n",
              100 * inside, 100 * near_clamps);
  EXPECT_LT(inside, 0.001);
  EXPECT_LT(near_clamps, 0.001);
}

// The intact stress law (constitutive.hpp): isotropic Hooke with the 3D deviator. Damaged laws:
// tests/test_damage_laws.cpp.
TEST(Elastic, SmallStrainStressIsIsotropicHooke) {
  const Real k = 10, mu = 6;
  Mat<3> eps = Mat<3>::zero();
  eps.a[0][0] = Real(1e-3), eps.a[0][1] = eps.a[1][0] = Real(2e-4);
  const Mat<3> s = small_strain_stress(eps, k, mu);
  const Real lambda = k - 2 * mu / 3;
  EXPECT_NEAR(s.a[0][0], (lambda + 2 * mu) * 1e-3, 1e-12);
  EXPECT_NEAR(s.a[1][1], lambda * 1e-3, 1e-12);
  EXPECT_NEAR(s.a[0][1], 2 * mu * 2e-4, 1e-12);
}

// A solid run past its stable time step stops with a diagnostic: the displacement-form plate at
// dt_factor 4 (stable up to 3.5, BENCHMARKS.md) grows its energy by orders of magnitude before
// anything overflows; the health check stops it once a particle outruns the P-wave speed.
TEST(Elastic, AnUnstableSolidStopsWithADiagnostic) {
  Case c = oscillating_plate_case(0.001, 0, SolidFormulation::Displacement);
  c.scene.options.dt_factor = 4;
  auto e = make_engine(c.scene, "cpu");
  std::string what;
  try {
    e->run_until(1.0);
  } catch (const InstabilityError& err) {
    what = err.what();
  }
  std::printf("stopped at t = %.4f s after %ld steps: %s\n", e->time(), e->steps(), what.c_str());
  EXPECT_NE(what.find("faster than its P-wave speed"), std::string::npos) << what;
  EXPECT_LT(e->time(), 1.0);
}
