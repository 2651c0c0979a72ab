#pragma once
// The elastic solids' options ([solid]).

namespace psph {

// The stress form (solid/stress_form.hpp) or the displacement form (solid/elastic_force.hpp).
enum class SolidFormulation { Stress, Displacement };
// The stress form's law: small-strain linear, or large-strain Saint Venant-Kirchhoff in total
// Lagrangian form (solid/constitutive.hpp).
enum class SolidModel { Linear, SaintVenantKirchhoff };
// How fluids and elastic solids exchange forces (solid/fluid_coupling.hpp).
enum class SolidCoupling { Traction, Pair, PairEos };

struct SolidOptions {
  SolidFormulation solid_formulation = SolidFormulation::Stress;
  SolidModel solid_model = SolidModel::Linear;
  double solid_damping_rate = 0;  // zeta (1/s): a -= zeta v on elastic particles
  // Monaghan artificial viscosity and XSPH on elastic solids (solid/artificial_viscosity.hpp).
  double solid_artificial_viscosity = 0, solid_artificial_viscosity_beta = 0, solid_xsph = 0;
  SolidCoupling solid_coupling = SolidCoupling::Traction;
  // Pa: the fluid pressure that loads an elastic solid with nothing (the traction coupling: the
  // solid feels p - p_ref, Terzaghi's effective stress; solid/fluid_coupling.hpp).
  double solid_reference_pressure = 0;
  // Ganzenmüller's hourglass control of the stress form (solid/hourglass.hpp): alpha, 0 for none.
  double solid_hourglass = 0;
};

}  // namespace psph
