// The checks between tables, after every table is read: combinations that cannot run, and keys
// that would have no effect in this case (refused with the reason, not silently ignored).
#include <algorithm>
#include <cmath>

#include "integrate/timestep.hpp"
#include "kernels/kernel.hpp"
#include "scene/case_tables.hpp"

namespace psph {
namespace {

[[noreturn]] void fail(const CaseDraft& d, const std::string& key, const std::string& expected) {
  throw CaseError(d.file + ": " + key + ": " + expected);
}

void check_solids(const CaseDraft& d) {
  const SolverOptions& o = d.c.scene.options;
  // The displacement form sums central pair forces, whose transverse stiffness 5 mu/3 - k is
  // negative above nu = 1/4 (the Cauchy relation): a 2D plate at nu = 0.3 blew up within 1,000
  // steps, at 0.25 within 16,000 (solid/elastic_force.hpp). A 1D rod has no transverse term.
  if (d.dimension() > 1 && o.solid_formulation == SolidFormulation::Displacement)
    for (const auto& [name, nu] : d.poisson_ratio)
      if (!(nu < 0.25))
        fail(d, "materials." + name + ".poisson_ratio",
             "expected a Poisson ratio below 0.25 in 2D and 3D with [solid] formulation = \"displacement\" (central "
             "pair forces go unstable above it; the stress form takes any ratio), got " + CaseReader::fmt(nu));
  // The solid takes the reaction of each fluid pair force (solid/fluid_coupling.hpp), which needs
  // the explicit viscous sum and a per-particle (scalar) Laplacian correction.
  const bool solids_in_fluid = d.has_fluid() && (d.has_elastic || d.has_rigid);
  if (o.implicit_viscosity && o.laplacian_correction == LaplacianCorrection::Tensor)
    fail(d, "solver.laplacian_correction",
         "expected \"trace\" or \"none\" with implicit_viscosity = true (the tensor form is explicit only)");
  if (solids_in_fluid && o.implicit_viscosity)
    fail(d, "solver.implicit_viscosity", "expected false in a case with elastic or rigid solids and fluids (the solid "
                                         "takes the reaction of the explicit viscous force)");
  if (solids_in_fluid && o.laplacian_correction == LaplacianCorrection::Tensor)
    fail(d, "solver.laplacian_correction", "expected \"trace\" or \"none\" in a case with elastic or rigid solids and fluids");
}

void check_interface(const CaseDraft& d) {
  const SolverOptions& o = d.c.scene.options;
  const bool tension = o.surface_tension > 0;
  if (tension && !d.c.two_phase)
    fail(d, "interface.surface_tension", "expected a case with a liquid and a gas (materials with phase = \"gas\")");
  if (tension && !d.walls_without_angle.empty())
    fail(d, "materials." + d.walls_without_angle.front() + ".contact_angle",
         "expected the contact angle (degrees, through the liquid) of every wall in a case with surface tension");
  for (const char* key : {"interface.normal_threshold", "interface.wetting", "interface.contact_line_force"})
    d.refuse_unless(tension, key, "surface_tension > 0 for it to apply to");
  for (const char* key : {"interface.wetting", "interface.contact_line_force"})
    d.refuse_unless(d.has_walls, key, "a material with kind = \"wall\" for it to apply to");
}

// Keys of the fluid's methods, in a case with no fluid, or without what they act on.
void check_fluid_keys(const CaseDraft& d) {
  const SolverOptions& o = d.c.scene.options;
  for (const char* key : {"density", "xsph", "artificial_viscosity", "laplacian_correction", "wall_noslip",
                          "wall_pressure", "implicit_viscosity", "background_pressure", "background_pressure_rate",
                          "max_density_deviation", "on_density_deviation", "compressibility"})
    d.refuse_unless(d.has_fluid(), std::string("solver.") + key, "a material with kind = \"fluid\" for it to apply to");
  d.refuse_unless(o.density == DensityMethod::Continuity, "solver.density_diffusion",
                  "density = \"continuity\" for it to apply to (it diffuses the integrated density)");
  d.refuse_unless(o.implicit_viscosity, "solver.implicit_tolerance", "implicit_viscosity = true for it to apply to");
  for (const char* key : {"region_lower", "region_upper", "flow_axis", "percolation_distance"})
    d.refuse_unless(d.c.two_phase, std::string("monitors.") + key,
                    "a case with a liquid and a gas (the monitors region is the two-phase monitors')");
  d.refuse_unless(d.c.two_phase, "time.after_percolation", "a case with a liquid and a gas (percolation is the gas')");
}

TimeStepInputs step_inputs(const CaseDraft& d, const std::vector<Material>& props) {
  const SolverOptions& o = d.c.scene.options;
  return time_step_inputs(props.data(), int(props.size()), o.implicit_viscosity, o.surface_tension,
                          o.solid_artificial_viscosity, o.solid_artificial_viscosity_beta, d.c.scene.dimension);
}

// A fixed step against the limits known before the run: acoustic (at rest), viscous and capillary
// (Pazdniakou eqs. 50-52).
void check_fixed_step(const CaseDraft& d) {
  const SolverOptions& o = d.c.scene.options;
  if (!(o.fixed_dt > 0)) return;
  if (o.fixed_dt > d.c.end_time) fail(d, "time.end", "expected an end time of at least one fixed step (solver.dt)");
  std::vector<Material> props;
  for (const auto& m : d.c.scene.materials) props.push_back(m.props);
  const TimeStepInputs in = step_inputs(d, props);
  const double hs = o.support_radius / support_per_smoothing_length(o.kernel);
  const double limit = time_step_limits(hs, in, 0.0, 0.0, 1.0).min();
  if (o.fixed_dt > 2 * limit)
    throw CaseError(d.file + ": solver.dt: a fixed step of " + CaseReader::fmt(o.fixed_dt) +
                    " s is impossible: the acoustic/viscous/capillary stability limit is " + CaseReader::fmt(limit) + " s");
}

// A bound on the steps a run takes, from the step known before the run (at the initial speeds
// and the body forces): a run of more is refused rather than left to run for months.
constexpr double kMaxSteps = 1e9;

void check_step_count(const CaseDraft& d) {
  const SolverOptions& o = d.c.scene.options;
  double v = 0, a = 0;
  for (const auto& g : d.c.geometry) v = std::max(v, std::hypot(g.velocity[0], g.velocity[1], g.velocity[2]));
  std::vector<Material> props;
  for (const auto& m : d.c.scene.materials) {
    props.push_back(m.props);
    a = std::max(a, std::hypot(m.body_force[0], m.body_force[1], m.body_force[2]));
  }
  const TimeStepInputs in = step_inputs(d, props);
  const double hs = o.support_radius / support_per_smoothing_length(o.kernel);
  const double dt = o.fixed_dt > 0 ? o.fixed_dt : time_step_limits(hs, in, v, a, o.dt_factor).min();
  const double steps = d.c.end_time / dt;
  if (!(steps <= kMaxSteps))
    fail(d, "time.end", "expected a run of at most " + CaseReader::fmt(kMaxSteps) + " steps, got about " +
                            CaseReader::fmt(steps) + " (time.end / a step of " + CaseReader::fmt(dt) + " s" +
                            (o.fixed_dt > 0 ? ", solver.dt" : " from solver.dt_factor and the stability limits") + ")");
}

}  // namespace

// Keys without effect first: they explain a combination's error better than the combination.
void cross_check(const CaseDraft& d) {
  check_fluid_keys(d);
  check_interface(d);
  check_solids(d);
  check_fixed_step(d);
  check_step_count(d);
}

void check_output_fields(const Case& c, const std::vector<std::string>& available) {
  for (const auto& f : c.output.fields) {
    if (std::count(available.begin(), available.end(), f)) continue;
    std::string list;
    for (const auto& a : available) list += (list.empty() ? "" : ", ") + a;
    throw CaseError(c.file + ": output.fields: no particle field \"" + shown(f) + "\" in this case; expected some of: " + list);
  }
}

}  // namespace psph
