#pragma once
// Host-side description of a run, independent of dimension and backend: what the scene builder
// produces from a case file and what an engine is created from.
#include <algorithm>
#include <array>
#include <string>
#include <vector>

#include "boundary/wall_pressure.hpp"
#include "boundary/wall_velocity.hpp"
#include "fluid/material.hpp"
#include "kernels/kernel.hpp"
#include "kernels/laplacian_correction.hpp"

namespace psph {

enum class DensityMethod { Summation, NormalisedSummation, NumberSummation, Continuity };
enum class Integrator { Leapfrog, VelocityVerlet };
// Elastic solids: the stress form (solid/stress_form.hpp) or the displacement form (solid/elastic_force.hpp).
enum class SolidFormulation { Stress, Displacement };
// The stress form's law: small-strain linear, or large-strain Saint Venant-Kirchhoff in total
// Lagrangian form (solid/constitutive.hpp).
enum class SolidModel { Linear, SaintVenantKirchhoff };
// How fluids and elastic solids exchange forces (solid/fluid_coupling.hpp).
enum class SolidCoupling { Traction, Pair, PairEos };

struct SceneMaterial {
  std::string name;
  Material props;
  std::array<double, 3> body_force{0, 0, 0};
};

struct SceneForceRegion {
  int material = 0;
  std::array<double, 3> lower{0, 0, 0}, upper{0, 0, 0}, acceleration{0, 0, 0};
  double ramp_time = 0;  // s: the force grows linearly from zero over this time (0: full at once)
};

// A load on the elastic particles of one material inside a box (solid/solid_load.hpp).
struct SceneSolidLoad {
  int material = 0;
  std::array<double, 3> lower{0, 0, 0}, upper{0, 0, 0};
  bool velocity = false;                  // imposed velocity, else traction
  std::array<double, 3> value{0, 0, 0};   // traction (Pa) or velocity (m/s)
  double ramp_time = 0;  // s: a traction grows linearly from zero over this time
  double duration = 0;   // s: an imposed velocity stops after this time (0: never)
};

// Open pressure inlet and outlet across a periodic axis (boundary/open_boundary.hpp).
struct SceneOpenBoundary {
  int axis = -1;  // -1: none
  double lower = 0, upper = 0;  // the domain along the axis (m)
  double thickness = 0;         // of each buffer (m)
  bool inlet_at_lower = true;
  double inlet_pressure = 0, outlet_pressure = 0;  // Pa
  int inlet_material = 0;
};

struct SolverOptions {
  KernelType kernel = KernelType::CubicSpline;
  double support_radius = 0;  // m
  double spacing = 0;         // initial particle spacing (m)
  double jitter = 0;          // initial disorder: fluid positions moved by up to this fraction of the spacing
  DensityMethod density = DensityMethod::Summation;
  Integrator integrator = Integrator::VelocityVerlet;
  double xsph = 0;            // XSPH epsilon
  double artificial_viscosity = 0;  // Monaghan alpha
  double density_diffusion = 0;     // delta-SPH delta (continuity only)
  WallNoSlip wall_noslip = WallNoSlip::Curved;
  WallPressure wall_pressure = WallPressure::Extrapolated;
  LaplacianCorrection laplacian_correction = LaplacianCorrection::Trace;  // kernels/laplacian_correction.hpp
  double dt_factor = 1;       // scales every time-step limit
  double neighbour_skin = 0.1;  // Verlet-list skin as a fraction of the support radius
  double fixed_dt = 0;        // > 0: constant step instead of the adaptive one
  double min_dt_ratio = 1e-4; // a step below this fraction of the first step is a collapse
  double max_density_deviation = 0;  // > 0: |rho/rho0 - 1| of a fluid particle that stops a run
  // Backward-Euler viscous step solved by BiCGSTAB (fluid/viscosity.hpp, integrate/bicgstab.hpp):
  // no viscous time-step limit.
  bool implicit_viscosity = false;
  double implicit_tolerance = 1e-6;  // relative residual of the viscous solve
  // Two fluids ([interface]): interface/surface_tension.hpp.
  double surface_tension = 0;   // sigma (N/m); 0 = no colour, normal or curvature pass
  double normal_threshold = 0.01;  // a normal is reliable when |grad c| > this / smoothing length
  bool geometric_wetting = true;   // walls' colour extrapolated (interface/wall_wetting.hpp), else cos(theta)
  bool contact_line_force = true;  // the unbalanced Young force at contact lines (interface/contact_line.hpp)
  // Elastic solids ([solid]).
  SolidFormulation solid_formulation = SolidFormulation::Stress;
  SolidModel solid_model = SolidModel::Linear;
  double solid_damping_rate = 0;  // zeta (1/s): a -= zeta v on elastic particles
  // Monaghan artificial viscosity and XSPH on elastic solids (solid/artificial_viscosity.hpp).
  double solid_artificial_viscosity = 0, solid_artificial_viscosity_beta = 0, solid_xsph = 0;
  SolidCoupling solid_coupling = SolidCoupling::Traction;
};

struct Scene {
  int dimension = 3;
  std::array<double, 3> lower{0, 0, 0}, upper{0, 0, 0};
  std::array<bool, 3> periodic{false, false, false};
  std::vector<SceneMaterial> materials;
  std::vector<SceneForceRegion> force_regions;
  std::vector<SceneSolidLoad> solid_loads;
  SceneOpenBoundary open_boundary;
  SolverOptions options;

  // Particles, components interleaved (dimension per particle).
  std::vector<double> x, v, mass;
  std::vector<int> material;
  // Rigid bodies (rigid/): each particle's body (-1 if none) and each body's initial angular
  // velocity (rad/s, world frame; z in 2D). Particle velocities already include the rotation.
  std::vector<int> body;
  std::vector<std::array<double, 3>> body_angular_velocity;
  // Each particle's [[solid_load]]s: bit g for load g.
  std::vector<int> load_mask;

  int count() const { return static_cast<int>(material.size()); }
};

// sigma / mu_liquid, the velocity scale of capillary flow (spurious currents are measured in it);
// 0 without surface tension or a viscous liquid.
inline double capillary_speed(const Scene& sc) {
  double mu = 0;
  for (const auto& m : sc.materials)
    if (m.props.kind == MaterialKind::Fluid && m.props.colour > 0) mu = std::max(mu, double(m.props.viscosity));
  return sc.options.surface_tension > 0 && mu > 0 ? sc.options.surface_tension / mu : 0.0;
}

}  // namespace psph
