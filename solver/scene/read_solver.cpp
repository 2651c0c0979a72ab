// [solver] and [interface]: how the fluid is discretised and stepped, and its surface tension.
#include "scene/case_tables.hpp"

namespace psph {
namespace {

// Fluids of different densities: the number-density form keeps the interface sharp (eq. 40).
std::string default_density(const std::vector<SceneMaterial>& materials) {
  bool ratio = false;
  double first_fluid = 0;
  for (const auto& m : materials)
    if (m.props.kind == MaterialKind::Fluid) {
      if (first_fluid == 0) first_fluid = m.props.rest_density;
      ratio |= m.props.rest_density != first_fluid;
    }
  return ratio ? "number_summation" : "summation";
}

// The [solver] keys that choose a method.
void read_methods(CaseReader& r, CaseDraft& d, SolverOptions& o) {
  const std::string dm = r.choice("density", {"summation", "number_summation", "normalised_summation", "continuity"},
                                  default_density(d.c.scene.materials));
  o.density = dm == "continuity"             ? DensityMethod::Continuity
              : dm == "normalised_summation" ? DensityMethod::NormalisedSummation
              : dm == "number_summation"     ? DensityMethod::NumberSummation
                                             : DensityMethod::Summation;
  o.integrator = r.choice("integrator", {"velocity_verlet", "leapfrog"}, "velocity_verlet") == "leapfrog"
                     ? Integrator::Leapfrog : Integrator::VelocityVerlet;
  const std::string ns = r.choice("wall_noslip", {"curved", "mirror", "prescribed", "free_slip"}, "curved");
  o.wall_noslip = ns == "prescribed"  ? WallNoSlip::Prescribed
                  : ns == "mirror"    ? WallNoSlip::Mirror
                  : ns == "free_slip" ? WallNoSlip::FreeSlip
                                      : WallNoSlip::Curved;
  const std::string lc = r.choice("laplacian_correction", {"trace", "tensor", "none"}, "trace");
  o.laplacian_correction = lc == "tensor" ? LaplacianCorrection::Tensor
                           : lc == "none" ? LaplacianCorrection::None
                                          : LaplacianCorrection::Trace;
  o.wall_pressure = r.choice("wall_pressure", {"extrapolated", "summation"}, "extrapolated") == "summation"
                        ? WallPressure::Summation : WallPressure::Extrapolated;
  o.implicit_viscosity = r.boolean("implicit_viscosity", false);
}

}  // namespace

void read_solver(CaseReader& top, CaseDraft& d) {
  SolverOptions& o = d.c.scene.options;
  const toml::table& t = top.table("solver", false);
  d.note(t, "solver");
  CaseReader r(t, d.file, "solver");
  read_methods(r, d, o);
  o.xsph = r.non_negative("xsph", 0.0);
  if (o.xsph > 1) r.fail("xsph", "expected an XSPH epsilon in [0, 1]");
  o.artificial_viscosity = r.non_negative("artificial_viscosity", 0.0);
  o.density_diffusion = r.non_negative("density_diffusion", 0.0);
  o.dt_factor = r.positive("dt_factor", 1.0);
  if (o.dt_factor > 4) r.fail("dt_factor", "expected a factor in (0, 4]");
  o.fixed_dt = r.non_negative("dt", 0.0);
  o.neighbour_skin = r.non_negative("neighbour_skin", 0.1);
  if (o.neighbour_skin > 1) r.fail("neighbour_skin", "expected a fraction of the support radius in [0, 1]");
  o.rebalance_imbalance = r.positive("rebalance_imbalance", 1.2);
  if (o.rebalance_imbalance < 1) r.fail("rebalance_imbalance", "expected a ratio of step times >= 1 (1: at every list build)");
  o.max_density_deviation = r.non_negative("max_density_deviation", 0.03);
  o.stop_on_density_deviation = r.choice("on_density_deviation", {"warn", "stop"}, "warn") == "stop";
  if (o.stop_on_density_deviation && !(o.max_density_deviation > 0))
    r.fail("max_density_deviation", "expected a bound > 0 with on_density_deviation = \"stop\"");
  d.c.compressibility_strict = r.choice("compressibility", {"warn", "strict"}, "warn") == "strict";
  o.implicit_tolerance = r.positive("implicit_tolerance", 1e-6);
  if (o.implicit_tolerance >= 1) r.fail("implicit_tolerance", "expected a relative residual in (0, 1)");
  const double p_b = r.non_negative("background_pressure", 0.0);
  for (auto& m : d.c.scene.materials) m.props.background_pressure = Real(p_b);
  o.background_pressure_rate = r.non_negative("background_pressure_rate", 0.0);
  if (o.background_pressure_rate > 0 && d.c.scene.open_boundary.axis >= 0)
    r.fail("background_pressure_rate", "expected no [open_boundary]: its buffers hold absolute pressures, which a "
                                       "rising background pressure would leave behind");
  r.finish();
}

void read_interface(CaseReader& top, CaseDraft& d) {
  SolverOptions& o = d.c.scene.options;
  const toml::table& t = top.table("interface", false);
  d.note(t, "interface");
  CaseReader r(t, d.file, "interface");
  o.surface_tension = r.non_negative("surface_tension", 0.0);
  o.normal_threshold = r.positive("normal_threshold", 0.01);
  o.geometric_wetting = r.choice("wetting", {"geometric", "wall_colour"}, "geometric") == "geometric";
  o.contact_line_force = r.boolean("contact_line_force", true);
  r.finish();
}

}  // namespace psph
