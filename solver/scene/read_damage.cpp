// [damage]: the damage model of the elastic materials it names, and the model's parameters in SI
// (damage/damage_options.hpp). Keys of another model than the chosen one are refused.
#include <cmath>
#include <initializer_list>

#include "scene/case_tables.hpp"

namespace psph {
namespace {

const std::initializer_list<const char*> kRankineKeys{
    "tensile_strength", "compressive_strength", "friction_angle", "tensile_elastic_strain", "tensile_ultimate_strain",
    "compressive_elastic_strain", "residual_tensile_strength", "residual_compressive_strength", "combination",
    "relaxation_steps", "irreversible", "degraded", "ghost_threshold"};
const std::initializer_list<const char*> kThermodynamicKeys{"critical_energy_release", "damage_bound", "unilateral"};
const std::initializer_list<const char*> kPcwKeys{"critical_energy_law", "alpha", "elastic_limit_strain", "ultimate_strain"};

// A strain magnitude in (0, 1).
double strain(CaseReader& r, const std::string& key, double def) {
  const double e = r.positive(key, def);
  if (!(e < 1)) r.fail(key, "expected a strain in (0, 1), got " + CaseReader::fmt(e), r.node(key));
  return e;
}

// A number in [lo, hi] (both inclusive).
double within(CaseReader& r, const std::string& key, double def, double lo, double hi) {
  const double v = r.number(key, def);
  if (!(v >= lo && v <= hi))
    r.fail(key, "expected a number in [" + CaseReader::fmt(lo) + ", " + CaseReader::fmt(hi) + "], got " + CaseReader::fmt(v),
           r.node(key));
  return v;
}

// Bit k for each elastic material named.
unsigned read_damaged_materials(CaseReader& r, const CaseDraft& d) {
  if (!r.has("materials")) r.fail("materials", "missing required value (expected an array of elastic material names)");
  const std::vector<std::string> names = r.strings("materials", {});
  if (names.empty()) r.fail("materials", "expected at least one elastic material name", r.node("materials"));
  unsigned bits = 0;
  for (const auto& name : names) {
    const auto it = d.mat_index.find(name);
    if (it == d.mat_index.end() || d.c.scene.materials[it->second].props.kind != MaterialKind::Elastic)
      r.fail("materials", "expected names of materials with kind = \"elastic\" under [materials], got \"" + shown(name) + "\"",
             r.node("materials"));
    if (bits >> it->second & 1u) r.fail("materials", "\"" + shown(name) + "\" is named twice", r.node("materials"));
    bits |= 1u << it->second;
  }
  return bits;
}

// Pazdniakou 2018 eqs. 19-24 with Table 1's COx values by default.
void read_rankine_mohr_coulomb(CaseReader& r, DamageOptions& o) {
  o.tensile_strength = r.positive("tensile_strength", o.tensile_strength);
  o.compressive_strength = r.positive("compressive_strength", o.compressive_strength);
  const double phi = r.non_negative("friction_angle", 25.0);  // degrees, as contact_angle
  if (!(phi < 90))
    r.fail("friction_angle", "expected an angle in degrees in [0, 90), got " + CaseReader::fmt(phi), r.node("friction_angle"));
  o.friction_angle = phi * M_PI / 180;
  o.tensile_elastic_strain = strain(r, "tensile_elastic_strain", o.tensile_elastic_strain);
  o.tensile_ultimate_strain = strain(r, "tensile_ultimate_strain", 2 * o.tensile_elastic_strain);
  if (!(o.tensile_ultimate_strain > o.tensile_elastic_strain))
    r.fail("tensile_ultimate_strain", "expected a strain above tensile_elastic_strain (" +
                                          CaseReader::fmt(o.tensile_elastic_strain) + ")", r.node("tensile_ultimate_strain"));
  o.compressive_elastic_strain = strain(r, "compressive_elastic_strain", o.compressive_elastic_strain);
  // Not given in the paper: 0.1 of the strengths (Tang et al. 2002's residual coefficient).
  o.residual_tensile_strength = within(r, "residual_tensile_strength", 0.1 * o.tensile_strength, 0, o.tensile_strength);
  o.residual_compressive_strength =
      within(r, "residual_compressive_strength", 0.1 * o.compressive_strength, 0, o.compressive_strength);
  o.damage_combination = r.choice("combination", {"mazars", "max"}, "mazars") == "max" ? DamageCombination::Max
                                                                                      : DamageCombination::Mazars;
  o.relaxation_steps = r.number("relaxation_steps", o.relaxation_steps);
  if (!(o.relaxation_steps >= 1))
    r.fail("relaxation_steps", "expected a relaxation time tau >= 1 (steps; below 1 eq. 24 overshoots), got " +
                                   CaseReader::fmt(o.relaxation_steps), r.node("relaxation_steps"));
  o.damage_irreversible = r.boolean("irreversible", false);
  const std::string how = r.choice("degraded", {"deviatoric", "all_moduli", "ghost"}, "deviatoric");
  o.damage_degrades = how == "deviatoric" ? DamageDegrades::Deviatoric
                      : how == "all_moduli" ? DamageDegrades::AllModuli : DamageDegrades::Ghost;
  if (o.damage_degrades != DamageDegrades::Ghost && r.has("ghost_threshold"))
    r.fail("ghost_threshold", "expected degraded = \"ghost\" for it to apply to", r.node("ghost_threshold"));
  o.ghost_threshold = r.positive("ghost_threshold", o.ghost_threshold);
  if (o.ghost_threshold > 1) r.fail("ghost_threshold", "expected a damage in (0, 1]", r.node("ghost_threshold"));
}

// PCW (Deptulski 2021 eqs. 4.21, 4.27): beta = eps_u / eps_0 - 1 from the two strains.
void read_pcw(CaseReader& r, DamageOptions& o) {
  o.critical_energy_law = r.choice("critical_energy_law", {"constant", "linear"}, "constant") == "linear"
                              ? CriticalEnergyLaw::Linear : CriticalEnergyLaw::Constant;
  o.elastic_limit_strain = strain(r, "elastic_limit_strain", o.elastic_limit_strain);
  o.ultimate_strain = strain(r, "ultimate_strain", 2 * o.elastic_limit_strain);
  if (!(o.ultimate_strain > o.elastic_limit_strain))
    r.fail("ultimate_strain", "expected a strain above elastic_limit_strain (" + CaseReader::fmt(o.elastic_limit_strain) +
                                  "), so that beta = ultimate / elastic_limit - 1 > 0", r.node("ultimate_strain"));
  o.pcw_beta = o.ultimate_strain / o.elastic_limit_strain - 1;
  o.pcw_alpha = r.positive("alpha", 1.0);
  if (o.pcw_alpha * o.damage_bound > 1)
    r.fail("alpha", "expected alpha <= 1 / damage_bound (" + CaseReader::fmt(1 / o.damage_bound) +
                        "): the stiffness (1 - alpha D) / (1 + beta D) would turn negative below the bound", r.node("alpha"));
}

// AT-1, AT-2, PCW (Deptulski 2021 §4.1): always irreversible.
void read_thermodynamic(CaseReader& r, DamageOptions& o) {
  o.critical_energy_from_strains = o.damage_model == DamageModel::Pcw && !r.has("critical_energy_release");
  o.critical_energy_release = r.positive("critical_energy_release", o.critical_energy_release);
  o.damage_bound = r.positive("damage_bound", o.damage_bound);
  if (o.damage_bound > 1)
    r.fail("damage_bound", "expected an upper bound s_l of the damage in (0, 1]", r.node("damage_bound"));
  o.unilateral = r.boolean("unilateral", true);
  if (o.damage_model == DamageModel::Pcw) read_pcw(r, o);
}

}  // namespace

void read_damage(CaseReader& top, CaseDraft& d) {
  if (!top.has("damage")) return;
  CaseReader r(top.table("damage", false), d.file, "damage");
  DamageOptions& o = d.c.scene.options;
  const std::string model = r.choice("model", {"rankine_mohr_coulomb", "at1", "at2", "pcw"});
  if (!d.has_elastic) r.fail("model", "expected a material with kind = \"elastic\" for it to apply to", r.node("model"));
  o.damage_model = model == "rankine_mohr_coulomb" ? DamageModel::RankineMohrCoulomb
                   : model == "at1"                ? DamageModel::At1
                   : model == "at2"                ? DamageModel::At2 : DamageModel::Pcw;
  const bool rankine = o.damage_model == DamageModel::RankineMohrCoulomb;
  const std::string why = " for it to apply to (model is \"" + model + "\")";
  for (const char* key : kRankineKeys)
    if (!rankine && r.has(key)) r.fail(key, "expected model = \"rankine_mohr_coulomb\"" + why, r.node(key));
  for (const char* key : kThermodynamicKeys)
    if (rankine && r.has(key)) r.fail(key, "expected model = \"at1\", \"at2\" or \"pcw\"" + why, r.node(key));
  for (const char* key : kPcwKeys)
    if (o.damage_model != DamageModel::Pcw && r.has(key)) r.fail(key, "expected model = \"pcw\"" + why, r.node(key));
  // The damage stage degrades the stress the stress form reads and the moduli the displacement
  // form pairs; ghosts leave every list (damage/ghosts.hpp).
  o.damage_materials = read_damaged_materials(r, d);
  if (rankine) read_rankine_mohr_coulomb(r, o);
  else read_thermodynamic(r, o);
  // The displacement form's pairs stiffen across their axis by 5 mu / 3 - k (solid/elastic_force.hpp):
  // degrading mu alone turns that negative once D > 1 - 3 k0 / (5 mu0), and the solid blows up.
  // Ghosts take the deviatoric law until they drop out.
  if (rankine && o.damage_degrades != DamageDegrades::AllModuli &&
      d.c.scene.options.solid_formulation == SolidFormulation::Displacement)
    r.fail("degraded", "expected \"all_moduli\" with [solid] formulation = \"displacement\" (its central pairs go "
                       "unstable when only the shear modulus is degraded, as \"deviatoric\" and \"ghost\" do; the "
                       "stress form takes them)",
           r.has("degraded") ? r.node("degraded") : r.node("model"));
  r.finish();
}

}  // namespace psph
