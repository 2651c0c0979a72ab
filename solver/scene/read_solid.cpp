// [solid] and [[solid_load]]: the elastic solids' formulation, law, damping and coupling, and the
// loads on groups of their particles (solid/solid_load.hpp).
#include "scene/case_tables.hpp"

namespace psph {

void read_solid(CaseReader& top, CaseDraft& d) {
  SolverOptions& o = d.c.scene.options;
  CaseReader solid(top.table("solid", false), d.file, "solid");
  for (const char* key :
       {"formulation", "model", "damping_rate", "coupling", "artificial_viscosity", "artificial_viscosity_beta", "xsph", "reference_pressure", "hourglass_control"})
    if (!d.has_elastic && solid.has(key)) solid.fail(key, "expected a material with kind = \"elastic\" for it to apply to");
  // The stress form by default (solid/stress_form.hpp: any Poisson ratio, free rotations at free
  // surfaces, a per-particle stress law), or the displacement form (solid/elastic_force.hpp,
  // Pazdniakou eq. 17).
  const bool stress = solid.choice("formulation", {"stress", "displacement"}, "stress") == "stress";
  o.solid_formulation = stress ? SolidFormulation::Stress : SolidFormulation::Displacement;
  // Mass-proportional damping a -= zeta v for quasi-static loading (Pazdniakou §3.1.4's Verlet
  // parameter theta is zeta dt).
  o.solid_damping_rate = solid.non_negative("damping_rate", 0.0);
  o.solid_artificial_viscosity = solid.non_negative("artificial_viscosity", 0.0);
  o.solid_artificial_viscosity_beta = solid.non_negative("artificial_viscosity_beta", 0.0);
  o.solid_xsph = solid.non_negative("xsph", 0.0);
  if (o.solid_xsph > 1) solid.fail("xsph", "expected an XSPH epsilon in [0, 1]");
  // Small strain by default: the references' clay strains are ~1e-3 (Pazdniakou's eps_t0 =
  // 0.0013), where Saint Venant-Kirchhoff differs by O(eps) and costs fixed reference lists and
  // two more tensors per particle.
  o.solid_model = solid.choice("model", {"linear", "saint_venant_kirchhoff"}, "linear") == "linear"
                      ? SolidModel::Linear : SolidModel::SaintVenantKirchhoff;
  if (!stress && o.solid_model == SolidModel::SaintVenantKirchhoff)
    solid.fail("model", "expected \"linear\" with formulation = \"displacement\" (Saint Venant-Kirchhoff is "
                        "written in the stress form)");
  // The traction needs the stress form's boundary sums; the displacement form couples by pairs.
  const std::string cp = solid.choice("coupling", {"traction", "pair", "pair_eos"}, stress ? "traction" : "pair");
  o.solid_coupling = cp == "traction" ? SolidCoupling::Traction : cp == "pair" ? SolidCoupling::Pair : SolidCoupling::PairEos;
  if (o.solid_coupling == SolidCoupling::PairEos && o.solid_model == SolidModel::SaintVenantKirchhoff)
    solid.fail("coupling", "expected \"traction\" or \"pair\" with model = \"saint_venant_kirchhoff\" (eq. 74's "
                           "pressure -k tr(eps) is a small-strain one)");
  for (const char* key : {"coupling", "reference_pressure"})
    if (!(d.has_fluid() && d.has_elastic) && solid.has(key))
      solid.fail(key, "expected a case with both fluids and elastic solids for it to apply to");
  if (!stress && o.solid_coupling == SolidCoupling::Traction)
    solid.fail("coupling", "expected \"pair\" or \"pair_eos\" with formulation = \"displacement\" (the traction "
                           "uses the stress form's boundary sums)");
  // The pressure the solid feels as no load (solid/fluid_coupling.hpp: AmbientPressurePass), the
  // fluid's background pressure where that regularises the fluid only.
  o.solid_reference_pressure = solid.non_negative("reference_pressure", 0.0);
  if (o.solid_reference_pressure > 0 && o.solid_coupling != SolidCoupling::Traction)
    solid.fail("reference_pressure", "expected coupling = \"traction\" (the pair couplings load the solid with the "
                                     "pair forces' absolute pressures)");
  // Ganzenmüller's hourglass control (solid/hourglass.hpp; TrixiParticles' default 0.1);
  // at most 1, so that the penalty's stiffness stays below the elastic one that sets the time step.
  o.solid_hourglass = solid.non_negative("hourglass_control", 0.0);
  if (o.solid_hourglass > 1) solid.fail("hourglass_control", "expected a penalty factor alpha in [0, 1]");
  if (o.solid_hourglass > 0 && !stress)
    solid.fail("hourglass_control", "expected formulation = \"stress\" (the displacement form's pair forces have no "
                                    "zero-energy mode)");
  solid.finish();
}

namespace {

// `axes` of an imposed velocity: the names of the axes it holds, each once (default all).
unsigned read_load_axes(CaseReader& r, int dimension) {
  if (!r.has("axes")) return (1u << dimension) - 1;
  const std::vector<std::string> names = r.strings("axes", {});
  const std::string all = std::string("xyz").substr(0, dimension);
  const std::string expected = "expected a non-empty array of distinct axes among \"" + all + "\"";
  unsigned axes = 0;
  for (const std::string& a : names) {
    const std::size_t k = a.size() == 1 ? all.find(a[0]) : std::string::npos;
    if (k == std::string::npos || (axes >> k & 1u)) r.fail("axes", expected, r.node("axes"));
    axes |= 1u << k;
  }
  if (axes == 0) r.fail("axes", expected, r.node("axes"));
  return axes;
}

}  // namespace

// Tractions and imposed velocities on groups of elastic particles (solid/solid_load.hpp).
void read_solid_loads(CaseReader& top, CaseDraft& d) {
  top.each_table("solid_load", kMaxSolidLoads, "loads", [&](CaseReader& r) {
    SceneSolidLoad l;
    l.material = d.material(r, "material", MaterialKind::Elastic, "an elastic material");
    r.box(d.dimension(), l.lower, l.upper);
    if (r.has("traction") == r.has("velocity"))
      r.fail("traction", "give exactly one of traction (Pa, on each particle's share of the surface) and velocity (m/s)");
    l.velocity = r.has("velocity");
    l.value = r.vec<double>(l.velocity ? "velocity" : "traction", d.dimension());
    if (l.velocity) {
      l.duration = r.non_negative("duration", 0.0);
      l.axes = read_load_axes(r, d.dimension());
    } else {
      l.ramp_time = r.non_negative("ramp_time", 0.0);
      if (r.has("axes")) r.fail("axes", "expected velocity for it to apply to (a traction acts along every axis)", r.node("axes"));
    }
    d.c.scene.solid_loads.push_back(l);
  });
}

}  // namespace psph
