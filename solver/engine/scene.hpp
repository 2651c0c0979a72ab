#pragma once
// Host-side description of a run, independent of dimension and backend: what the scene builder
// produces from a case file and what an engine is created from.
#include <algorithm>
#include <array>
#include <string>
#include <vector>

#include "core/length_unit.hpp"
#include "core/open_boundary_zone.hpp"
#include "fluid/fluid_options.hpp"
#include "fluid/body_force_region.hpp"
#include "core/material.hpp"
#include "damage/damage_options.hpp"
#include "integrate/step_options.hpp"
#include "interface/interface_options.hpp"
#include "kernels/kernel.hpp"
#include "solid/solid_load.hpp"
#include "solid/solid_options.hpp"

namespace psph {

struct SceneMaterial {
  std::string name;
  Material props;
  std::array<double, 3> body_force{0, 0, 0};
};

// Every stage's options: the discretisation's here, the others' in their stage's folder.
struct DiscretisationOptions {
  KernelType kernel = KernelType::CubicSpline;
  double support_radius = 0;  // m
  double spacing = 0;         // initial particle spacing (m)
  double jitter = 0;          // initial disorder: fluid positions moved by up to this fraction of the spacing
  double neighbour_skin = 0.1;  // Verlet-list skin as a fraction of the support radius
};
struct SolverOptions : DiscretisationOptions, StepOptions, FluidOptions, InterfaceOptions, SolidOptions, DamageOptions {};

struct Scene {
  int dimension = 3;
  std::array<double, 3> lower{0, 0, 0}, upper{0, 0, 0};
  std::array<bool, 3> periodic{false, false, false};
  std::vector<SceneMaterial> materials;
  std::vector<SceneForceRegion> force_regions;
  std::vector<SceneSolidLoad> solid_loads;
  SceneOpenBoundary open_boundary;
  SolverOptions options;
  // What its lengths, times and masses are in: SI, or an engine's unit (engine/scene_units.hpp).
  LengthUnit unit;

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

// How far beyond its lists' radius a process of a shared run reads (parallel/): an open
// boundary's buffer reads around its mirror point (the buffer's thickness and two support radii
// further), a clamp its partner up to two support radii away and the partner's neighbours, a
// large-strain solid its neighbours of t = 0 however far the strain took them (two support radii
// more; beyond, the run stops naming the particle).
inline double halo_reach(const Scene& sc) {
  const double h = sc.options.support_radius;
  bool walls = false, elastic = false;
  for (const auto& m : sc.materials)
    walls |= m.props.kind == MaterialKind::Wall, elastic |= m.props.kind == MaterialKind::Elastic;
  const double open = sc.open_boundary.axis >= 0 ? sc.open_boundary.thickness + 2 * h : 0;
  const bool large_strain = elastic && sc.options.solid_model == SolidModel::SaintVenantKirchhoff;
  return std::max(open, (walls && elastic) || large_strain ? 2 * h : 0.0);
}

// sigma / mu_liquid, the velocity scale of capillary flow (spurious currents are measured in it);
// 0 without surface tension or a viscous liquid.
inline double capillary_speed(const Scene& sc) {
  double mu = 0;
  for (const auto& m : sc.materials)
    if (m.props.kind == MaterialKind::Fluid && m.props.colour > 0) mu = std::max(mu, double(m.props.viscosity));
  return sc.options.surface_tension > 0 && mu > 0 ? sc.options.surface_tension / mu : 0.0;
}

}  // namespace psph
