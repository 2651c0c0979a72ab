// The damage stage in a run (damage/damage_stage.hpp): a rod clamped at one end and stretched by
// its other end (AT-1, onset at half the final strain) damages, never heals, stays below the bound,
// carries less stress than the intact rod, reports its monitors, and restarts bitwise from a
// checkpoint with its damage: in the stress form and in the displacement form, whose pair forces
// take the degraded moduli (fields damaged_bulk_modulus, damaged_shear_modulus).
#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "case_text.hpp"
#include "stretched_rod.hpp"
#include "engine/engine.hpp"
#include "scene/scene_builder.hpp"

using namespace psph;

namespace {

// tests/stretched_rod.hpp, 1D, E = 1e6 Pa, nu = 0: the end moves 50 um in 5 ms, a strain of
// ~5e-4 over the 0.1 m rod.
// AT-1's onset 2 w~ = Y_c0 with w~ = E eps^2 / 2: eps = sqrt(Y_c0 / E) = 2.5e-4 for Y_c0 = 0.0625 Pa.
const std::string kDamage = "[damage]\nmodel = \"at1\"\nmaterials = [\"steel\"]\ncritical_energy_release = 0.0625\n\n";

const char* kForms[] = {"stress", "displacement"};

std::string damaged_rod(const std::string& form) {
  return test::replaced(test::replaced(test::replaced(test::stretched_rod_case(), "[time]", kDamage + "[time]"),
                                       "end = 0.05", "end = 0.02"),
                        "[solid]\n", "[solid]\nformulation = \"" + form + "\"\n");
}

std::unique_ptr<Engine> engine_of(const std::string& text) {
  Case c = load_case_text(text, "rod.toml");
  build_particles(c);
  return make_engine(c.scene, "cpu");
}

// The damage of each particle id.
std::vector<double> damage_by_id(Engine& e) {
  const auto d = e.field("damage"), id = e.field("id");
  std::vector<double> out(d.size());
  for (std::size_t i = 0; i < d.size(); ++i) out[static_cast<std::size_t>(id[i])] = d[i];
  return out;
}

double monitor(Engine& e, const std::string& name) {
  for (const auto& m : e.monitors())
    if (m.name == name) return m.value;
  ADD_FAILURE() << "no monitor " << name;
  return 0;
}

}  // namespace

TEST(DamageStage, AStretchedRodDamagesIrreversiblyAndCarriesLess) {
  for (const char* form : kForms) {
    SCOPED_TRACE(form);
    auto e = engine_of(damaged_rod(form));
    const std::vector<double> start = damage_by_id(*e);
    EXPECT_EQ(*std::max_element(start.begin(), start.end()), 0.0);
    e->run_until(0.004);  // the end has moved 40 um: past the onset
    const std::vector<double> before = damage_by_id(*e);
    e->run_until(0.02);
    const std::vector<double> after = damage_by_id(*e);
    double most = 0;
    for (std::size_t k = 0; k < after.size(); ++k) {
      EXPECT_GE(after[k], before[k]) << "particle " << k << " healed";
      EXPECT_LE(after[k], 0.99 + 1e-12) << "particle " << k << " passed the bound";
      most = std::max(most, after[k]);
    }
    EXPECT_GT(most, 0.1);
    EXPECT_GT(monitor(*e, "damaged_particles"), 0);
    EXPECT_GT(monitor(*e, "total_damage"), most - 1e-12);
    EXPECT_GT(monitor(*e, "damage_energy"), 0);
    // The intact rod, stretched the same way, stores more elastic energy.
    auto intact = engine_of(test::replaced(damaged_rod(form), kDamage, ""));
    intact->run_until(0.02);
    EXPECT_LT(monitor(*e, "elastic_energy"), 0.9 * monitor(*intact, "elastic_energy"));
  }
}

// The displacement form's pairs take each particle's degraded moduli: AT-1 in tension degrades both
// by (1 - D)^2 (the rod is stretched: tr eps > 0), and the stress it reports is the degraded one.
TEST(DamageStage, TheDisplacementFormTakesTheDegradedModuli) {
  auto e = engine_of(damaged_rod("displacement"));
  e->run_until(0.02);
  const auto d = e->field("damage"), k = e->field("damaged_bulk_modulus"), mu = e->field("damaged_shear_modulus");
  const auto eps = e->field("strain"), sigma = e->field("stress"), mat = e->field("material");
  const double k0 = 1e6 / 3, mu0 = 1e6 / 2;  // E = 1e6 Pa, nu = 0
  int damaged = 0;
  for (std::size_t i = 0; i < d.size(); ++i) {
    if (mat[i] != 1) continue;  // "steel" (materials in key order: the wall "clamp" is 0)
    const double g = (1 - d[i]) * (1 - d[i]);
    EXPECT_NEAR(k[i], (eps[i] < 0 ? 1 : g) * k0, 1e-9 * k0) << i;
    EXPECT_NEAR(mu[i], g * mu0, 1e-9 * mu0) << i;
    EXPECT_NEAR(sigma[i], (k[i] + 4 * mu[i] / 3) * eps[i], 1e-9 * k0 * std::fabs(eps[i]) + 1e-15) << i;
    damaged += d[i] > 0.1;
  }
  EXPECT_GT(damaged, 0);
  auto stress_form = engine_of(damaged_rod("stress"));
  const auto names = stress_form->field_names();
  EXPECT_EQ(names.end(), std::find(names.begin(), names.end(), "damaged_bulk_modulus"));  // only the displacement form's
}

// Rankine-Mohr-Coulomb reports its parts (eq. 23): the stretched rod (f_t at half the final
// strain) has tensile damage and no compressive damage, and once the rod is held its reversible D
// has relaxed (eq. 24) onto the tensile part. AT-1 has no such parts.
TEST(DamageStage, RankineMohrCoulombReportsItsTensileAndCompressiveParts) {
  const std::string rmc = test::replaced(test::replaced(damaged_rod("stress"), kDamage,
                                                        "[damage]\nmodel = \"rankine_mohr_coulomb\"\nmaterials = [\"steel\"]\n"
                                                        "tensile_strength = 250.0\ntensile_elastic_strain = 2.5e-4\n"
                                                        "tensile_ultimate_strain = 1e-3\ncompressive_strength = 1e12\n\n"),
                                         "end = 0.02", "end = 0.05");
  auto e = engine_of(rmc);
  e->run_until(0.05);
  const auto d = e->field("damage"), dt = e->field("tensile_damage"), dc = e->field("compressive_damage");
  const auto mat = e->field("material");
  double most = 0;
  for (std::size_t i = 0; i < d.size(); ++i) {
    if (mat[i] != 1) continue;
    EXPECT_EQ(dc[i], 0.0) << i;
    EXPECT_NEAR(d[i], dt[i], 1e-3) << i;
    most = std::max(most, dt[i]);
  }
  EXPECT_GT(most, 0.1);
  const auto names = engine_of(damaged_rod("stress"))->field_names();
  EXPECT_EQ(names.end(), std::find(names.begin(), names.end(), "tensile_damage"));
}

TEST(DamageStage, ARestartCarriesTheDamageBitwise) {
  for (const char* form : kForms) {
    SCOPED_TRACE(form);
    auto e = engine_of(damaged_rod(form));
    e->run_until(0.006);
    const Checkpoint ck = e->checkpoint();
    e->run_until(0.01);
    auto r = engine_of(damaged_rod(form));
    r->restore(ck);
    r->run_until(0.01);
    EXPECT_EQ(damage_by_id(*r), damage_by_id(*e));
    EXPECT_EQ(r->field("position"), e->field("position"));
  }
}
