// Strict case-file reader: each table's keys are consumed as they are read; what is left over is
// an unknown key and rejected.
#include "scene/case_file.hpp"

#include "integrate/timestep.hpp"
#include "scene/case_reader.hpp"
#include "scene/visualisation_options.hpp"
#include "solid/solid_load.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

namespace psph {
namespace {


KernelType kernel_from(const std::string& s) {
  return s == "wendland_c2" ? KernelType::WendlandC2 : s == "quintic_spline" ? KernelType::QuinticSpline
                                                                              : KernelType::CubicSpline;
}

}  // namespace

Case parse_case(const toml::table& tbl, const std::string& file) {
  Case c;
  c.file = file;
  CaseReader top(tbl, file, "");
  Scene& sc = c.scene;

  {
    CaseReader r(top.table("case", true), file, "case");
    c.name = r.string("name");
    if (c.name.empty() || c.name.find_first_of("/\\ \t") != std::string::npos)
      r.fail("name", "expected a non-empty name without spaces or slashes");
    c.description = r.string("description", "");
    const long dim = r.integer("dimension");
    if (dim < 1 || dim > 3) r.fail("dimension", "expected 1, 2 or 3, got " + std::to_string(dim));
    sc.dimension = static_cast<int>(dim);
    r.finish();
  }
  const int D = sc.dimension;
  {
    CaseReader r(top.table("domain", true), file, "domain");
    r.box(D, sc.lower, sc.upper);
    sc.periodic = r.vec<bool>("periodic", D, std::array<bool, 3>{false, false, false});
    r.finish();
  }
  SolverOptions& o = sc.options;
  {
    CaseReader r(top.table("discretisation", true), file, "discretisation");
    o.spacing = r.positive("spacing");
    o.jitter = r.non_negative("jitter", 0.0);
    if (o.jitter > 0.5) r.fail("jitter", "expected a fraction of the spacing in [0, 0.5]");
    o.kernel = kernel_from(r.choice("kernel", {"cubic_spline", "wendland_c2", "quintic_spline"}, "cubic_spline"));
    const bool has_R = r.has("support_radius"), has_h = r.has("smoothing_length");
    if (has_R == has_h) r.fail("support_radius", "give exactly one of support_radius and smoothing_length");
    o.support_radius = has_R ? r.positive("support_radius")
                             : r.positive("smoothing_length") * support_per_smoothing_length(o.kernel);
    if (o.support_radius < o.spacing)
      r.fail(has_R ? "support_radius" : "smoothing_length", "expected a support radius of at least one spacing");
    for (int k = 0; k < D; ++k) {
      const double cells = (sc.upper[k] - sc.lower[k]) / o.spacing;
      if (sc.periodic[k] && std::fabs(cells - std::round(cells)) > 1e-6 * cells)
        r.fail("spacing", "expected the periodic domain length along axis " + std::to_string(k) +
                              " to be a whole number of spacings (got " + CaseReader::fmt(cells) + ")");
      if (sc.periodic[k] && sc.upper[k] - sc.lower[k] < 3 * o.support_radius)
        r.fail("support_radius", "periodic axis " + std::to_string(k) + " is shorter than 3 support radii");
    }
    r.finish();
  }
  // Materials, in file order of their names (toml tables are ordered by key).
  std::map<std::string, int> mat_index;
  std::vector<std::string> walls_without_angle;
  bool has_liquid = false, has_gas = false, has_elastic = false, has_rigid = false, coupled = false;
  bool solids_in_fluid = false;
  // Elastic solids: the stress form by default (solid/stress_form.hpp: any Poisson ratio, free
  // rotations at free surfaces, a per-particle stress law), or the displacement form
  // (solid/elastic_force.hpp, Pazdniakou eq. 17).
  CaseReader solid(top.table("solid", false), file, "solid");
  o.solid_formulation = solid.choice("formulation", {"stress", "displacement"}, "stress") == "stress"
                            ? SolidFormulation::Stress : SolidFormulation::Displacement;
  {
    const toml::table& mt = top.table("materials", true);
    if (mt.empty()) top.fail("materials", "expected at least one material");
    for (const auto& [k, v] : mt) {
      const std::string name(k.str());
      if (name == "empty") top.fail("materials.empty", "\"empty\" is reserved for removing particles");
      if (!v.is_table()) top.fail("materials." + name, "expected a table", &v);
      CaseReader r(*v.as_table(), file, "materials." + name);
      SceneMaterial m;
      m.name = name;
      const std::string kind = r.choice("kind", {"fluid", "wall", "elastic", "rigid"});
      m.props.kind = kind == "fluid"     ? MaterialKind::Fluid
                     : kind == "elastic" ? MaterialKind::Elastic
                     : kind == "rigid"   ? MaterialKind::Rigid
                                         : MaterialKind::Wall;
      // A wall's density is optional: by default it is the densest fluid's (set below).
      m.props.rest_density = (kind != "wall" || r.has("density")) ? Real(r.positive("density")) : Real(0);
      if (kind == "elastic") {
        // Isotropic moduli from E and nu (Pazdniakou §2.2.1); in 2D, plane strain with these moduli.
        const double E = r.positive("young_modulus"), nu = r.number("poisson_ratio");
        if (!(nu > -1 && nu < 0.5)) r.fail("poisson_ratio", "expected a Poisson ratio in (-1, 0.5), got " + CaseReader::fmt(nu));
        // The displacement form sums central pair forces, whose transverse stiffness 5 mu/3 - k is
        // negative above nu = 1/4 (the Cauchy relation): a 2D plate at nu = 0.3 blew up within
        // 1,000 steps, at 0.25 within 16,000 (solid/elastic_force.hpp). A 1D rod has no transverse term.
        if (D > 1 && o.solid_formulation == SolidFormulation::Displacement && !(nu < 0.25))
          r.fail("poisson_ratio", "expected a Poisson ratio below 0.25 in 2D and 3D with [solid] formulation = "
                                  "\"displacement\" (central pair forces go unstable above it; the stress form takes "
                                  "any ratio), got " + CaseReader::fmt(nu));
        m.props.bulk_modulus = Real(E / (3 * (1 - 2 * nu)));
        m.props.shear_modulus = Real(E / (2 * (1 + nu)));
        m.props.sound_speed =
            Real(std::sqrt((m.props.bulk_modulus + 4 * m.props.shear_modulus / 3) / m.props.rest_density));
        has_elastic = true;
      }
      if (kind == "rigid") {
        // Each [[geometry]] of this material is one body (rigid/). Its sound speed sets the
        // contact stiffness (rigid/rigid_body.hpp); by default Pazdniakou's eq. 74 with 8x the
        // elastic bulk modulus, set below.
        m.props.sound_speed = r.has("sound_speed") ? Real(r.positive("sound_speed")) : Real(0);
        m.body_force = r.vec<double>("body_force", D, std::array<double, 3>{0, 0, 0});
        has_rigid = true;
      }
      if (kind == "fluid") {
        m.props.viscosity = Real(r.non_negative("viscosity"));
        m.props.sound_speed = Real(r.positive("sound_speed"));
        m.props.eos = r.choice("equation_of_state", {"linear", "tait"}, "linear") == "tait" ? EquationOfState::Tait
                                                                                             : EquationOfState::Linear;
        m.props.tait_gamma = Real(r.positive("tait_gamma", 7.0));
        m.body_force = r.vec<double>("body_force", D, std::array<double, 3>{0, 0, 0});
        const bool gas = r.choice("phase", {"liquid", "gas"}, "liquid") == "gas";
        m.props.colour = gas ? Real(-1) : Real(1);  // Pazdniakou eq. 6
        (gas ? has_gas : has_liquid) = true;
      } else if (r.has("contact_angle")) {
        // Walls and elastic solids. Measured through the liquid: 0 = fully wetted by the liquid
        // (Pazdniakou eq. 10).
        const double theta = r.non_negative("contact_angle");
        if (theta > 180) r.fail("contact_angle", "expected an angle in degrees between 0 and 180");
        m.props.colour = Real(std::cos(theta * M_PI / 180));
      } else {
        walls_without_angle.push_back(name);
      }
      r.finish();
      mat_index[name] = static_cast<int>(sc.materials.size());
      sc.materials.push_back(m);
    }
    if (sc.materials.size() > static_cast<std::size_t>(kMaxMaterials))
      top.fail("materials", "expected at most " + std::to_string(kMaxMaterials) + " materials");
    // Walls take the density of the densest fluid unless given, and the largest sound speed (our
    // choice: Pazdniakou 2018 §3.3, eq. 74, gives immobile walls neither). The densest: a wall's
    // volume m/rho follows its pressure through rho0 + p/c^2, so a wall under water with a gas's
    // rest density would shrink by the water's head over 1 kg/m^3.
    // Without fluids, walls only clamp an elastic solid and take its density.
    for (const char* key :
         {"formulation", "model", "damping_rate", "coupling", "artificial_viscosity", "artificial_viscosity_beta", "xsph"})
      if (!has_elastic && solid.has(key))
        solid.fail(key, "expected a material with kind = \"elastic\" for it to apply to");
    const bool has_fluid = has_liquid || has_gas;
    coupled = has_fluid && has_elastic;
    solids_in_fluid = has_fluid && (has_elastic || has_rigid);
    // Mass-proportional damping a -= zeta v for quasi-static loading (Pazdniakou §3.1.4's Verlet
    // parameter theta is zeta dt).
    o.solid_damping_rate = solid.non_negative("damping_rate", 0.0);
    o.solid_artificial_viscosity = solid.non_negative("artificial_viscosity", 0.0);
    o.solid_artificial_viscosity_beta = solid.non_negative("artificial_viscosity_beta", 0.0);
    o.solid_xsph = solid.non_negative("xsph", 0.0);
    if (o.solid_xsph > 1) solid.fail("xsph", "expected an XSPH epsilon in [0, 1]");
    // The traction needs the stress form's boundary sums; the displacement form couples by pairs.
    const bool stress = o.solid_formulation == SolidFormulation::Stress;
    // Small strain by default: the references' clay strains are ~1e-3 (Pazdniakou's eps_t0 =
    // 0.0013), where Saint Venant-Kirchhoff differs by O(eps) and costs fixed reference lists and
    // two more tensors per particle.
    o.solid_model = solid.choice("model", {"linear", "saint_venant_kirchhoff"}, "linear") == "linear"
                        ? SolidModel::Linear : SolidModel::SaintVenantKirchhoff;
    if (!stress && o.solid_model == SolidModel::SaintVenantKirchhoff)
      solid.fail("model", "expected \"linear\" with formulation = \"displacement\" (Saint Venant-Kirchhoff is "
                          "written in the stress form)");
    const std::string cp = solid.choice("coupling", {"traction", "pair", "pair_eos"}, stress ? "traction" : "pair");
    o.solid_coupling = cp == "traction" ? SolidCoupling::Traction : cp == "pair" ? SolidCoupling::Pair : SolidCoupling::PairEos;
    if (o.solid_coupling == SolidCoupling::PairEos && o.solid_model == SolidModel::SaintVenantKirchhoff)
      solid.fail("coupling", "expected \"traction\" or \"pair\" with model = \"saint_venant_kirchhoff\" (eq. 74's "
                             "pressure -k tr(eps) is a small-strain one)");
    if (!coupled && solid.has("coupling"))
      solid.fail("coupling", "expected a case with both fluids and elastic solids for it to apply to");
    if (!stress && o.solid_coupling == SolidCoupling::Traction)
      solid.fail("coupling", "expected \"pair\" or \"pair_eos\" with formulation = \"displacement\" (the traction "
                             "uses the stress form's boundary sums)");
    solid.finish();
    const MaterialKind bulk = has_fluid ? MaterialKind::Fluid : has_elastic ? MaterialKind::Elastic : MaterialKind::Rigid;
    const SceneMaterial* densest = nullptr;
    for (const auto& m : sc.materials)
      if (m.props.kind == bulk && (!densest || m.props.rest_density > densest->props.rest_density)) densest = &m;
    if (!densest) top.fail("materials", "expected at least one material with kind = \"fluid\", \"elastic\" or \"rigid\"");
    // A rigid material's default sound speed: c = sqrt(8 K_elastic / rho) (Pazdniakou §3.3, eq. 74),
    // or without elastic solids the fluids' largest.
    Real k_elastic = 0, c_fluid = 0;
    for (const auto& m : sc.materials) {
      if (m.props.kind == MaterialKind::Elastic) k_elastic = std::max(k_elastic, m.props.bulk_modulus);
      if (m.props.kind == MaterialKind::Fluid) c_fluid = std::max(c_fluid, m.props.sound_speed);
    }
    for (auto& m : sc.materials)
      if (m.props.kind == MaterialKind::Rigid && m.props.sound_speed == Real(0)) {
        if (k_elastic == Real(0) && c_fluid == Real(0))
          top.fail("materials." + m.name + ".sound_speed",
                   "expected the sound speed (m/s) that sets a rigid material's contact stiffness in a case "
                   "without fluids or elastic solids");
        m.props.sound_speed = k_elastic > Real(0) ? std::sqrt(8 * k_elastic / m.props.rest_density) : c_fluid;
      }
    Real c_max = 0;
    for (const auto& m : sc.materials)
      if (m.props.kind == bulk) c_max = std::max(c_max, m.props.sound_speed);
    for (auto& m : sc.materials)
      if (m.props.kind == MaterialKind::Wall) {
        if (m.props.rest_density == Real(0)) m.props.rest_density = densest->props.rest_density;
        m.props.sound_speed = c_max;
      }
  }
  if (const toml::node* g = top.node("body_force_region")) {
    // Body forces on one fluid inside a box (e.g. the reservoir gas of a drainage).
    const toml::array* arr = g->as_array();
    if (!arr || !arr->is_array_of_tables()) top.fail("body_force_region", "expected an array of tables [[body_force_region]]", g);
    if (arr->size() > static_cast<std::size_t>(kMaxForceRegions))
      top.fail("body_force_region", "expected at most " + std::to_string(kMaxForceRegions) + " regions", g);
    int idx = 0;
    for (const auto& e : *arr) {
      CaseReader r(*e.as_table(), file, "body_force_region[" + std::to_string(idx++) + "]");
      SceneForceRegion f;
      const std::string mname = r.string("material");
      if (!mat_index.count(mname) || sc.materials[mat_index[mname]].props.kind != MaterialKind::Fluid)
        r.fail("material", "expected the name of a fluid under [materials], got \"" + mname + "\"");
      f.material = mat_index[mname];
      r.box(D, f.lower, f.upper);
      f.acceleration = r.vec<double>("body_force", D);
      f.ramp_time = r.non_negative("ramp_time", 0.0);
      r.finish();
      sc.force_regions.push_back(f);
    }
  }
  if (const toml::node* g = top.node("solid_load")) {
    // Tractions and imposed velocities on groups of elastic particles (solid/solid_load.hpp).
    const toml::array* arr = g->as_array();
    if (!arr || !arr->is_array_of_tables()) top.fail("solid_load", "expected an array of tables [[solid_load]]", g);
    if (arr->size() > static_cast<std::size_t>(kMaxSolidLoads))
      top.fail("solid_load", "expected at most " + std::to_string(kMaxSolidLoads) + " loads", g);
    int idx = 0;
    for (const auto& e : *arr) {
      CaseReader r(*e.as_table(), file, "solid_load[" + std::to_string(idx++) + "]");
      SceneSolidLoad l;
      const std::string mname = r.string("material");
      if (!mat_index.count(mname) || sc.materials[mat_index[mname]].props.kind != MaterialKind::Elastic)
        r.fail("material", "expected the name of an elastic material under [materials], got \"" + mname + "\"");
      l.material = mat_index[mname];
      r.box(D, l.lower, l.upper);
      if (r.has("traction") == r.has("velocity"))
        r.fail("traction", "give exactly one of traction (Pa, on each particle's share of the surface) and velocity (m/s)");
      l.velocity = r.has("velocity");
      l.value = r.vec<double>(l.velocity ? "velocity" : "traction", D);
      if (l.velocity) l.duration = r.non_negative("duration", 0.0);
      else l.ramp_time = r.non_negative("ramp_time", 0.0);
      r.finish();
      sc.solid_loads.push_back(l);
    }
  }
  if (top.has("open_boundary")) {
    // Pressure inlet and outlet buffers across a periodic axis (boundary/open_boundary.hpp).
    CaseReader r(top.table("open_boundary", false), file, "open_boundary");
    SceneOpenBoundary& ob = sc.open_boundary;
    ob.axis = r.axis("axis", D);
    if (!sc.periodic[ob.axis])
      r.fail("axis", "expected an axis declared periodic under [domain]: the fluid leaving through the outlet "
                     "comes back through the inlet as the injected fluid");
    ob.lower = sc.lower[ob.axis], ob.upper = sc.upper[ob.axis];
    ob.inlet_at_lower = r.choice("inlet_side", {"lower", "upper"}, "lower") == "lower";
    auto pressure = [&](const char* key) {
      const double p = r.number(key);
      if (!std::isfinite(p)) r.fail(key, "expected a finite pressure (Pa)", r.node(key));
      return p;
    };
    ob.inlet_pressure = pressure("inlet_pressure");
    ob.outlet_pressure = pressure("outlet_pressure");
    const std::string mname = r.string("inlet_material");
    if (!mat_index.count(mname) || sc.materials[mat_index[mname]].props.kind != MaterialKind::Fluid)
      r.fail("inlet_material", "expected the name of a fluid under [materials], got \"" + mname + "\"");
    ob.inlet_material = mat_index[mname];
    ob.thickness = r.positive("thickness", o.support_radius);
    if (ob.thickness < o.support_radius * (1 - 1e-9))
      r.fail("thickness", "expected a buffer at least one support radius (" + CaseReader::fmt(o.support_radius) +
                              " m) thick, got " + CaseReader::fmt(ob.thickness));
    if (2 * ob.thickness + 2 * o.support_radius > ob.upper - ob.lower)
      r.fail("thickness", "expected the two buffers to leave at least two support radii of domain between them");
    r.finish();
  }
  {
    CaseReader r(top.table("interface", false), file, "interface");
    o.surface_tension = r.non_negative("surface_tension", 0.0);
    o.normal_threshold = r.positive("normal_threshold", 0.01);
    o.geometric_wetting = r.choice("wetting", {"geometric", "wall_colour"}, "geometric") == "geometric";
    o.contact_line_force = r.boolean("contact_line_force", true);
    if (o.surface_tension > 0 && !(has_liquid && has_gas))
      r.fail("surface_tension", "expected a case with a liquid and a gas (materials with phase = \"gas\")");
    if (o.surface_tension > 0 && !walls_without_angle.empty())
      top.fail("materials." + walls_without_angle.front() + ".contact_angle",
               "expected the contact angle (degrees, through the liquid) of every wall in a case with surface tension");
    r.finish();
  }
  {
    CaseReader r(top.table("solver", false), file, "solver");
    // Fluids of different densities: the number-density form keeps the interface sharp (eq. 40).
    bool ratio = false;
    double first_fluid = 0;
    for (const auto& m : sc.materials)
      if (m.props.kind == MaterialKind::Fluid) {
        if (first_fluid == 0) first_fluid = m.props.rest_density;
        ratio |= m.props.rest_density != first_fluid;
      }
    const std::string d = r.choice("density", {"summation", "number_summation", "normalised_summation", "continuity"},
                                   ratio ? "number_summation" : "summation");
    o.density = d == "continuity"             ? DensityMethod::Continuity
                : d == "normalised_summation" ? DensityMethod::NormalisedSummation
                : d == "number_summation"     ? DensityMethod::NumberSummation
                                              : DensityMethod::Summation;
    o.integrator = r.choice("integrator", {"velocity_verlet", "leapfrog"}, "velocity_verlet") == "leapfrog"
                       ? Integrator::Leapfrog : Integrator::VelocityVerlet;
    const std::string ns = r.choice("wall_noslip", {"curved", "mirror", "prescribed", "free_slip"}, "curved");
    o.wall_noslip = ns == "prescribed" ? WallNoSlip::Prescribed
                    : ns == "mirror"   ? WallNoSlip::Mirror
                    : ns == "free_slip" ? WallNoSlip::FreeSlip
                                        : WallNoSlip::Curved;
    {
      const std::string lc = r.choice("laplacian_correction", {"trace", "tensor", "none"}, "trace");
      o.laplacian_correction = lc == "tensor" ? LaplacianCorrection::Tensor
                               : lc == "none" ? LaplacianCorrection::None
                                              : LaplacianCorrection::Trace;
    }
    o.wall_pressure = r.choice("wall_pressure", {"extrapolated", "summation"}, "extrapolated") == "summation"
                          ? WallPressure::Summation : WallPressure::Extrapolated;
    o.xsph = r.non_negative("xsph", 0.0);
    o.artificial_viscosity = r.non_negative("artificial_viscosity", 0.0);
    o.density_diffusion = r.non_negative("density_diffusion", 0.0);
    if (o.xsph > 1) r.fail("xsph", "expected an XSPH epsilon in [0, 1]");
    o.dt_factor = r.positive("dt_factor", 1.0);
    if (o.dt_factor > 4) r.fail("dt_factor", "expected a factor in (0, 4]");
    o.fixed_dt = r.non_negative("dt", 0.0);
    o.neighbour_skin = r.non_negative("neighbour_skin", 0.1);
    o.max_density_deviation = r.non_negative("max_density_deviation", 0.0);
    o.implicit_viscosity = r.boolean("implicit_viscosity", false);
    o.implicit_tolerance = r.positive("implicit_tolerance", 1e-6);
    if (o.implicit_tolerance >= 1) r.fail("implicit_tolerance", "expected a relative residual in (0, 1)");
    if (o.implicit_viscosity && o.laplacian_correction == LaplacianCorrection::Tensor)
      r.fail("laplacian_correction", "expected \"trace\" or \"none\" with implicit_viscosity = true (the tensor form is explicit only)");
    // The solid takes the reaction of each fluid pair force (solid/fluid_coupling.hpp), which needs
    // the explicit viscous sum and a per-particle (scalar) Laplacian correction.
    if (solids_in_fluid && o.implicit_viscosity)
      r.fail("implicit_viscosity", "expected false in a case with elastic or rigid solids and fluids (the solid "
                                   "takes the reaction of the explicit viscous force)");
    if (solids_in_fluid && o.laplacian_correction == LaplacianCorrection::Tensor)
      r.fail("laplacian_correction", "expected \"trace\" or \"none\" in a case with elastic or rigid solids and fluids");
    const double p_b = r.non_negative("background_pressure", 0.0);
    for (auto& m : sc.materials) m.props.background_pressure = Real(p_b);
    if (o.neighbour_skin > 1) r.fail("neighbour_skin", "expected a fraction of the support radius in [0, 1]");
    r.finish();
  }
  {
    CaseReader r(top.table("time", true), file, "time");
    c.end_time = r.positive("end");
    if (o.fixed_dt > c.end_time) r.fail("end", "expected an end time of at least one fixed step (solver.dt)");
    r.finish();
    if (o.fixed_dt > 0) {
      // The limits known before the run: acoustic (at rest) and viscous (Pazdniakou eqs. 50-52).
      std::vector<Material> props;
      for (const auto& m : sc.materials) props.push_back(m.props);
      const TimeStepInputs in = time_step_inputs(props.data(), int(props.size()), o.implicit_viscosity, o.surface_tension);
      const double hs = o.support_radius / support_per_smoothing_length(o.kernel);
      const TimeStepLimits lim = time_step_limits(hs, in, 0.0, 0.0, 1.0);
      const double limit = lim.min();
      if (o.fixed_dt > 2 * limit)
        throw CaseError(file + ": solver.dt: a fixed step of " + CaseReader::fmt(o.fixed_dt) +
                        " s is impossible: the acoustic/viscous/capillary stability limit is " + CaseReader::fmt(limit) + " s");
    }
  }
  {
    CaseReader r(top.table("output", false), file, "output");
    c.output.monitor_interval = r.non_negative("monitor_interval", 0.0);
    c.output.extract_interval = r.non_negative("extract_interval", 0.0);
    c.output.checkpoint_interval = r.non_negative("checkpoint_interval", 0.0);
    c.output.checkpoint_keep = static_cast<int>(r.positive_integer("checkpoint_keep", c.output.checkpoint_keep));
    c.output.fields = r.strings("fields", c.output.fields);
    r.finish();
  }
  c.visualisation = parse_visualisation(top.table("visualisation", false), file);
  c.two_phase = has_liquid && has_gas;
  {
    CaseReader r(top.table("monitors", false), file, "monitors");
    MonitorRegion& m = c.monitor_region;
    m.lower = r.vec<double>("region_lower", D, sc.lower);
    m.upper = r.vec<double>("region_upper", D, sc.upper);
    for (int k = 0; k < D; ++k)
      if (!(m.upper[k] > m.lower[k]) || m.lower[k] < sc.lower[k] || m.upper[k] > sc.upper[k])
        r.fail("region_upper", "expected region_lower < region_upper inside the domain on every axis (axis " +
                                   std::to_string(k) + ")");
    m.flow_axis = r.axis("flow_axis", D, std::string(1, "xyz"[D - 1]));
    // Lattice neighbours (1 and sqrt(2) spacings) connect; a one-particle water film (2) does not.
    m.percolation_distance = r.positive("percolation_distance", 1.5 * o.spacing);
    if (!c.two_phase && r.has("percolation_distance"))
      r.fail("percolation_distance", "expected a case with a liquid and a gas");
    r.finish();
  }
  {
    const toml::node* g = top.node("geometry");
    if (!g) top.fail("geometry", "missing required array of tables [[geometry]]");
    const toml::array* arr = g->as_array();
    if (!arr || arr->empty() || !arr->is_array_of_tables()) top.fail("geometry", "expected an array of tables [[geometry]]", g);
    int idx = 0;
    for (const auto& e : *arr) {
      CaseReader r(*e.as_table(), file, "geometry[" + std::to_string(idx++) + "]");
      GeometryShape s;
      const std::string shape = r.choice("shape", {"box", "sphere", "grain_pack"});
      s.kind = shape == "sphere" ? GeometryShape::Kind::Sphere
               : shape == "grain_pack" ? GeometryShape::Kind::GrainPack : GeometryShape::Kind::Box;
      if (s.kind == GeometryShape::Kind::GrainPack) {
        GrainPackSpec& p = s.pack;
        r.box(D, p.lower, p.upper);
        p.grain_radius = r.positive("grain_radius");
        p.radius_spread = r.non_negative("radius_spread", 0.2);
        if (p.radius_spread >= 1) r.fail("radius_spread", "expected a fraction of the radius in [0, 1)");
        p.min_gap = r.non_negative("min_gap", 2 * o.spacing);
        p.solid_fraction = r.positive("solid_fraction");
        if (p.solid_fraction > 0.9) r.fail("solid_fraction", "expected a fraction in (0, 0.9]");
        const long seed = r.integer("seed", 1);
        if (seed < 0) r.fail("seed", "expected an integer >= 0");
        p.seed = static_cast<std::uint64_t>(seed);
        try {
          s.grains = generate_grain_pack(p, D).grains;
        } catch (const std::invalid_argument& e) {
          r.fail("solid_fraction", e.what());
        }
      } else if (s.kind == GeometryShape::Kind::Box) {
        s.lower = r.vec<double>("lower", D);
        s.upper = r.vec<double>("upper", D);
      } else {
        s.center = r.vec<double>("center", D);
        s.radius = r.positive("radius");
        // "lattice": the domain's lattice sites inside; "concentric": shells fitted to the surface.
        s.concentric = r.choice("layout", {"lattice", "concentric"}, "lattice") == "concentric";
      }
      if (s.kind != GeometryShape::Kind::Sphere && r.has("layout"))
        r.fail("layout", "expected a layout only on a sphere (boxes and grain packs take the lattice)");
      const std::string mname = r.string("material");
      if (mname == "empty") s.material = -1;
      else if (mat_index.count(mname)) s.material = mat_index[mname];
      else r.fail("material", "expected \"empty\" or the name of a table under [materials], got \"" + mname + "\"");
      if (s.kind == GeometryShape::Kind::GrainPack && s.material >= 0 &&
          sc.materials[s.material].props.kind == MaterialKind::Rigid)
        r.fail("material", "expected a box or a sphere for a rigid material (each geometry is one rigid body: a "
                           "grain pack would move as one clump)");
      s.velocity = r.vec<double>("velocity", D, std::array<double, 3>{0, 0, 0});
      // A rigid body's initial angular velocity (rad/s) about its centre of mass: a number in 2D
      // (about z), a vector in 3D.
      if (r.has("angular_velocity")) {
        if (s.material < 0 || sc.materials[s.material].props.kind != MaterialKind::Rigid)
          r.fail("angular_velocity", "expected a geometry of a material with kind = \"rigid\" for it to apply to");
        if (D == 1) r.fail("angular_velocity", "expected no rotation in 1D");
        if (D == 2) s.angular_velocity[2] = r.number("angular_velocity");
        else s.angular_velocity = r.vec<double>("angular_velocity", 3);
      }
      r.finish();
      c.geometry.push_back(s);
    }
  }
  top.finish();
  std::ostringstream os;
  os << tbl;
  c.source_text = os.str();
  return c;
}

Case load_case_text(const std::string& text, const std::string& file) {
  toml::table tbl;
  try {
    tbl = toml::parse(text, file);
  } catch (const toml::parse_error& e) {
    throw CaseError(file + " (line " + std::to_string(e.source().begin.line) + "): not valid TOML: " +
                    std::string(e.description()));
  }
  return parse_case(tbl, file);
}

Case load_case_file(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw CaseError(path + ": cannot open the case file");
  std::stringstream ss;
  ss << in.rdbuf();
  return load_case_text(ss.str(), path);
}

void set_case_value(toml::table& tbl, const std::string& dotted_key, const toml::node& value) {
  toml::table* t = &tbl;
  std::size_t start = 0;
  for (;;) {
    const std::size_t dot = dotted_key.find('.', start);
    const std::string part = dotted_key.substr(start, dot == std::string::npos ? std::string::npos : dot - start);
    if (dot == std::string::npos) {
      value.visit([&](auto&& v) { t->insert_or_assign(part, v); });
      return;
    }
    toml::node* next = t->get(part);
    if (!next) {
      t->insert(part, toml::table{});
      next = t->get(part);
    }
    if (!next->is_table()) throw std::logic_error("set_case_value: " + dotted_key + " crosses a non-table");
    t = next->as_table();
    start = dot + 1;
  }
}

void set_case_spacing(toml::table& tbl, double spacing) {
  toml::table& disc = *tbl["discretisation"].as_table();
  const double f = spacing / *disc["spacing"].value<double>();
  for (const char* key : {"support_radius", "smoothing_length"})
    if (const auto v = disc[key].value<double>()) disc.insert_or_assign(key, *v * f);
  disc.insert_or_assign("spacing", spacing);
}

}  // namespace psph
