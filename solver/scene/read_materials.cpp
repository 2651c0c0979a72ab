// [materials.*]: each material's kind and constants, in file order of their names (toml tables
// are ordered by key); then the defaults that depend on the other materials.
#include <algorithm>
#include <cmath>

#include "scene/case_tables.hpp"

namespace psph {
namespace {

void read_elastic(CaseReader& r, CaseDraft& d, SceneMaterial& m) {
  // Isotropic moduli from E and nu (Pazdniakou §2.2.1); in 2D, plane strain with these moduli.
  const double E = r.positive("young_modulus"), nu = r.number("poisson_ratio");
  if (!(nu > -1 && nu < 0.5)) r.fail("poisson_ratio", "expected a Poisson ratio in (-1, 0.5), got " + CaseReader::fmt(nu));
  d.poisson_ratio[m.name] = nu;
  m.props.bulk_modulus = Real(E / (3 * (1 - 2 * nu)));
  m.props.shear_modulus = Real(E / (2 * (1 + nu)));
  m.props.sound_speed = Real(std::sqrt((m.props.bulk_modulus + 4 * m.props.shear_modulus / 3) / m.props.rest_density));
  d.has_elastic = true;
}

void read_fluid(CaseReader& r, CaseDraft& d, SceneMaterial& m) {
  m.props.viscosity = Real(r.non_negative("viscosity"));
  m.props.sound_speed = Real(r.positive("sound_speed"));
  m.props.eos = r.choice("equation_of_state", {"linear", "tait"}, "linear") == "tait" ? EquationOfState::Tait
                                                                                       : EquationOfState::Linear;
  if (m.props.eos != EquationOfState::Tait && r.has("tait_gamma"))
    r.fail("tait_gamma", "expected equation_of_state = \"tait\" for it to apply to");
  m.props.tait_gamma = Real(r.positive("tait_gamma", 7.0));
  m.body_force = r.vec<double>("body_force", d.dimension(), std::array<double, 3>{0, 0, 0});
  const bool gas = r.choice("phase", {"liquid", "gas"}, "liquid") == "gas";
  m.props.colour = gas ? Real(-1) : Real(1);  // Pazdniakou eq. 6
  (gas ? d.has_gas : d.has_liquid) = true;
}

SceneMaterial read_material(const std::string& name, const toml::node& v, CaseReader& top, CaseDraft& d) {
  if (name == "empty") top.fail("materials.empty", "\"empty\" is reserved for removing particles");
  if (!v.is_table()) top.fail("materials." + name, "expected a table", &v);
  CaseReader r(*v.as_table(), d.file, "materials." + name);
  SceneMaterial m;
  m.name = name;
  const std::string kind = r.choice("kind", {"fluid", "wall", "elastic", "rigid"});
  m.props.kind = kind == "fluid"     ? MaterialKind::Fluid
                 : kind == "elastic" ? MaterialKind::Elastic
                 : kind == "rigid"   ? MaterialKind::Rigid
                                     : MaterialKind::Wall;
  // A wall's density is optional: by default it is the densest fluid's (set below).
  m.props.rest_density = (kind != "wall" || r.has("density")) ? Real(r.positive("density")) : Real(0);
  if (kind == "elastic") read_elastic(r, d, m);
  if (kind == "rigid") {
    // Each [[geometry]] of this material is one body (rigid/). Its sound speed sets the contact
    // stiffness (rigid/rigid_body.hpp); by default Pazdniakou's eq. 74 with 8x the elastic bulk
    // modulus, set below.
    m.props.sound_speed = r.has("sound_speed") ? Real(r.positive("sound_speed")) : Real(0);
    m.body_force = r.vec<double>("body_force", d.dimension(), std::array<double, 3>{0, 0, 0});
    d.has_rigid = true;
  }
  if (kind == "wall") {
    d.has_walls = true;
    // How the wall clamps an elastic solid (solid/clamp.hpp): "stick" (every displacement
    // component held) or "slip" (the normal one only: a lubricated platen, no shear traction).
    m.props.slip_clamp = r.choice("clamp", {"stick", "slip"}, "stick") == "slip";
  } else if (r.has("clamp")) {
    r.fail("clamp", "expected kind = \"wall\" for it to apply to");
  }
  if (kind == "fluid") {
    read_fluid(r, d, m);
  } else if (r.has("contact_angle")) {
    // Walls and solids. Measured through the liquid: 0 = fully wetted by the liquid (Pazdniakou eq. 10).
    const double theta = r.non_negative("contact_angle");
    if (theta > 180) r.fail("contact_angle", "expected an angle in degrees between 0 and 180");
    m.props.colour = Real(std::cos(theta * M_PI / 180));
  } else {
    d.walls_without_angle.push_back(name);
  }
  r.finish();
  return m;
}

// A rigid material's default sound speed: c = sqrt(8 K_elastic / rho) (Pazdniakou §3.3, eq. 74),
// or without elastic solids the fluids' largest. Walls take the density of the densest fluid
// unless given, and the largest sound speed (our choice: Pazdniakou 2018 §3.3, eq. 74, gives
// immobile walls neither). The densest: a wall's volume m/rho follows its pressure through
// rho0 + p/c^2, so a wall under water with a gas's rest density would shrink by the water's head
// over 1 kg/m^3. Without fluids, walls only clamp an elastic solid and take its density.
void set_defaults(CaseReader& top, CaseDraft& d) {
  std::vector<SceneMaterial>& mats = d.c.scene.materials;
  const MaterialKind bulk = d.has_fluid() ? MaterialKind::Fluid : d.has_elastic ? MaterialKind::Elastic : MaterialKind::Rigid;
  const SceneMaterial* densest = nullptr;
  for (const auto& m : mats)
    if (m.props.kind == bulk && (!densest || m.props.rest_density > densest->props.rest_density)) densest = &m;
  if (!densest) top.fail("materials", "expected at least one material with kind = \"fluid\", \"elastic\" or \"rigid\"");
  Real k_elastic = 0, c_fluid = 0;
  for (const auto& m : mats) {
    if (m.props.kind == MaterialKind::Elastic) k_elastic = std::max(k_elastic, m.props.bulk_modulus);
    if (m.props.kind == MaterialKind::Fluid) c_fluid = std::max(c_fluid, m.props.sound_speed);
  }
  for (auto& m : mats)
    if (m.props.kind == MaterialKind::Rigid && m.props.sound_speed == Real(0)) {
      if (k_elastic == Real(0) && c_fluid == Real(0))
        top.fail("materials." + m.name + ".sound_speed",
                 "expected the sound speed (m/s) that sets a rigid material's contact stiffness in a case "
                 "without fluids or elastic solids");
      m.props.sound_speed = k_elastic > Real(0) ? std::sqrt(8 * k_elastic / m.props.rest_density) : c_fluid;
    }
  Real c_max = 0;
  for (const auto& m : mats)
    if (m.props.kind == bulk) c_max = std::max(c_max, m.props.sound_speed);
  for (auto& m : mats)
    if (m.props.kind == MaterialKind::Wall) {
      if (m.props.rest_density == Real(0)) m.props.rest_density = densest->props.rest_density;
      m.props.sound_speed = c_max;
    }
}

}  // namespace

void read_materials(CaseReader& top, CaseDraft& d) {
  const toml::table& mt = top.table("materials", true);
  if (mt.empty()) top.fail("materials", "expected at least one material");
  for (const auto& [k, v] : mt) {
    const std::string name(k.str());
    d.mat_index[name] = static_cast<int>(d.c.scene.materials.size());
    d.c.scene.materials.push_back(read_material(name, v, top, d));
  }
  if (d.c.scene.materials.size() > static_cast<std::size_t>(kMaxMaterials))
    top.fail("materials", "expected at most " + std::to_string(kMaxMaterials) + " materials");
  d.c.two_phase = d.has_liquid && d.has_gas;
  set_defaults(top, d);
}

}  // namespace psph
