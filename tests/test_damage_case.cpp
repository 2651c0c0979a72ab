// The [damage] table (scene/read_damage.cpp): a good table of each model is read into the options;
// each bad value, a key of another model, and a material that is not elastic are refused with the
// file, the key and what was expected.
#include <cmath>

#include <gtest/gtest.h>

#include "case_text.hpp"
#include "scene/embedded_cases.hpp"

using namespace psph;
using test::error_of;
using test::replaced;

namespace {

// An elastic plate clamped by a wall (materials "plate" and "clamp"), with a [damage] table.
std::string with_damage(const std::string& table) {
  return replaced(embedded_case_text("oscillating_plate_2d"), "[time]", "[damage]\n" + table + "\n\n[time]");
}

DamageOptions options_of(const std::string& table) {
  return load_case_text(with_damage(table), "ok.toml").scene.options;
}

void expect_refused(const std::string& table, std::initializer_list<const char*> parts) {
  const std::string msg = error_of(with_damage(table));
  ASSERT_FALSE(msg.empty()) << "accepted: " << table;
  EXPECT_NE(msg.find("bad.toml"), std::string::npos) << msg;
  for (const char* p : parts) EXPECT_NE(msg.find(p), std::string::npos) << "'" << p << "' not in: " << msg;
}

const char* kPlate = "materials = [\"plate\"]\n";

}  // namespace

TEST(DamageCase, GoodTablesAreRead) {
  EXPECT_EQ(load_case_text(embedded_case_text("oscillating_plate_2d"), "ok.toml").scene.options.damage_model,
            DamageModel::None);
  const DamageOptions r = options_of(std::string("model = \"rankine_mohr_coulomb\"\n") + kPlate +
                                     "friction_angle = 30.0\ntensile_strength = 5e6\ncombination = \"max\"\n"
                                     "degraded = \"all_moduli\"\nirreversible = true");
  EXPECT_EQ(r.damage_model, DamageModel::RankineMohrCoulomb);
  EXPECT_EQ(r.damage_materials, 1u << 1);  // "plate" (index 1) follows "clamp" in key order
  EXPECT_NEAR(r.friction_angle, M_PI / 6, 1e-15);
  EXPECT_EQ(r.residual_tensile_strength, 0.5e6);  // 0.1 f_t by default
  EXPECT_EQ(r.damage_combination, DamageCombination::Max);
  EXPECT_EQ(r.damage_degrades, DamageDegrades::AllModuli);
  EXPECT_TRUE(r.damage_irreversible);

  const DamageOptions a = options_of(std::string("model = \"at2\"\n") + kPlate + "critical_energy_release = 2.5e3\n"
                                     "damage_bound = 0.95\nunilateral = false");
  EXPECT_EQ(a.damage_model, DamageModel::At2);
  EXPECT_EQ(a.damage_bound, 0.95);
  EXPECT_FALSE(a.unilateral);
  EXPECT_FALSE(a.critical_energy_from_strains);

  const DamageOptions p = options_of(std::string("model = \"pcw\"\n") + kPlate +
                                     "elastic_limit_strain = 0.022\nultimate_strain = 0.060");
  EXPECT_NEAR(p.pcw_beta, 0.060 / 0.022 - 1, 1e-15);
  EXPECT_TRUE(p.critical_energy_from_strains);
  EXPECT_EQ(p.critical_energy_law, CriticalEnergyLaw::Constant);
  // The displacement form takes damage (and nu < 0.25: the plate's 0.3975 is the stress form's).
  const std::string displacement = replaced(replaced(with_damage(std::string("model = \"at2\"\n") + kPlate), "[damage]",
                                            "[solid]\nformulation = \"displacement\"\n\n[damage]"),
                                            "poisson_ratio = 0.3975", "poisson_ratio = 0.2");
  EXPECT_EQ(load_case_text(displacement, "ok.toml").scene.options.damage_model, DamageModel::At2);
  EXPECT_TRUE(options_of(std::string("model = \"at1\"\n") + kPlate).damages(1));
  EXPECT_FALSE(options_of(std::string("model = \"at1\"\n") + kPlate).damages(0));
}

TEST(DamageCase, BadValuesAreRefusedByKey) {
  const std::string rmc = std::string("model = \"rankine_mohr_coulomb\"\n") + kPlate;
  const std::string at = std::string("model = \"at1\"\n") + kPlate, pcw = std::string("model = \"pcw\"\n") + kPlate;
  expect_refused(std::string("model = \"mazars\"\n") + kPlate, {"damage.model", "\"at2\""});
  expect_refused(rmc + "tensile_strength = -1.0", {"damage.tensile_strength", "> 0"});
  expect_refused(rmc + "friction_angle = 90.0", {"damage.friction_angle", "[0, 90)"});
  expect_refused(rmc + "tensile_elastic_strain = 1.5", {"damage.tensile_elastic_strain", "(0, 1)"});
  expect_refused(rmc + "tensile_ultimate_strain = 0.001", {"damage.tensile_ultimate_strain", "above tensile_elastic_strain"});
  expect_refused(rmc + "residual_tensile_strength = 5e6", {"damage.residual_tensile_strength", "[0, 4e+06]"});
  expect_refused(rmc + "relaxation_steps = 0.5", {"damage.relaxation_steps", "tau >= 1"});
  expect_refused(rmc + "combination = \"sum\"", {"damage.combination", "\"mazars\""});
  expect_refused(rmc + "degraded = \"ghost\"\nghost_threshold = 1.5", {"damage.ghost_threshold", "(0, 1]"});
  expect_refused(rmc + "ghost_threshold = 0.9", {"damage.ghost_threshold", "degraded = \"ghost\""});
  expect_refused(rmc + "irreversible = 1", {"damage.irreversible", "true or false"});
  expect_refused(at + "critical_energy_release = 0.0", {"damage.critical_energy_release", "> 0"});
  expect_refused(at + "damage_bound = 1.5", {"damage.damage_bound", "(0, 1]"});
  expect_refused(pcw + "ultimate_strain = 0.001", {"damage.ultimate_strain", "beta"});
  expect_refused(pcw + "alpha = 2.0", {"damage.alpha", "1 / damage_bound"});
  expect_refused(pcw + "critical_energy_law = \"quadratic\"", {"damage.critical_energy_law", "\"linear\""});
  expect_refused(at + "damage_bund = 0.9", {"damage.damage_bund", "unknown key"});
}

TEST(DamageCase, KeysOfAnotherModelAreRefused) {
  expect_refused(std::string("model = \"at1\"\n") + kPlate + "tensile_strength = 4e6",
                 {"damage.tensile_strength", "model = \"rankine_mohr_coulomb\"", "model is \"at1\""});
  expect_refused(std::string("model = \"rankine_mohr_coulomb\"\n") + kPlate + "damage_bound = 0.9",
                 {"damage.damage_bound", "\"at1\", \"at2\" or \"pcw\""});
  expect_refused(std::string("model = \"at2\"\n") + kPlate + "alpha = 1.0", {"damage.alpha", "model = \"pcw\""});
}

TEST(DamageCase, MaterialsMustBeElastic) {
  expect_refused("model = \"at1\"\nmaterials = [\"clamp\"]", {"damage.materials", "kind = \"elastic\"", "\"clamp\""});
  expect_refused("model = \"at1\"\nmaterials = [\"rock\"]", {"damage.materials", "\"rock\""});
  expect_refused("model = \"at1\"\nmaterials = []", {"damage.materials", "at least one"});
  expect_refused("model = \"at1\"", {"damage.materials", "missing required"});
  expect_refused("model = \"at1\"\nmaterials = [\"plate\", \"plate\"]", {"damage.materials", "twice"});
  // A case without elastic solids has nothing to damage.
  const std::string water = replaced(embedded_case_text("poiseuille_2d"), "[time]",
                                     "[damage]\nmodel = \"at1\"\nmaterials = [\"water\"]\n\n[time]");
  const std::string msg = error_of(water);
  EXPECT_NE(msg.find("damage.model"), std::string::npos) << msg;
  EXPECT_NE(msg.find("kind = \"elastic\""), std::string::npos) << msg;
}

// What the damage stage does not apply yet is refused, never accepted without effect.
// Rankine-Mohr-Coulomb degrading the shear modulus alone makes the displacement form's pairs
// unstable: refused there, taken with all moduli degraded.
TEST(DamageCase, TheDisplacementFormTakesRankineMohrCoulombWithAllModuli) {
  const std::string rmc = replaced(replaced(with_damage(std::string("model = \"rankine_mohr_coulomb\"\n") + kPlate),
                                            "[damage]", "[solid]\nformulation = \"displacement\"\n\n[damage]"),
                                   "poisson_ratio = 0.3975", "poisson_ratio = 0.2");
  const std::string msg = error_of(rmc);
  EXPECT_NE(msg.find("damage.degraded"), std::string::npos) << msg;
  EXPECT_NE(msg.find("expected \"all_moduli\""), std::string::npos) << msg;
  EXPECT_EQ(load_case_text(replaced(rmc, "materials = [", "degraded = \"all_moduli\"\nmaterials = ["), "ok.toml")
                .scene.options.damage_degrades,
            DamageDegrades::AllModuli);
}

// Ghosts take their threshold; the displacement form refuses them as it refuses "deviatoric".
TEST(DamageCase, GhostsTakeTheirThresholdInTheStressFormOnly) {
  const std::string ghost = std::string("model = \"rankine_mohr_coulomb\"\n") + kPlate + "degraded = \"ghost\"\n";
  const DamageOptions o = options_of(ghost + "ghost_threshold = 0.95");
  EXPECT_EQ(o.damage_degrades, DamageDegrades::Ghost);
  EXPECT_EQ(o.ghost_threshold, 0.95);
  EXPECT_EQ(options_of(ghost).ghost_threshold, 0.99);
  const std::string msg = error_of(replaced(replaced(with_damage(ghost), "[damage]", "[solid]\nformulation = \"displacement\"\n\n[damage]"),
                                            "poisson_ratio = 0.3975", "poisson_ratio = 0.2"));
  EXPECT_NE(msg.find("damage.degraded"), std::string::npos) << msg;
  EXPECT_NE(msg.find("\"ghost\""), std::string::npos) << msg;
}
