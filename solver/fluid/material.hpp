#pragma once
// Material table: each particle carries a material index; the table says what the material is
// (its kind) and holds its constants. Passed by value to the passes, so it lives in registers or
// constant cache on the GPU.
#include "core/vec.hpp"

namespace psph {

enum class MaterialKind : int { Fluid = 0, Wall = 1 };
enum class EquationOfState : int { Linear = 0, Tait = 1 };

struct Material {
  MaterialKind kind = MaterialKind::Fluid;
  EquationOfState eos = EquationOfState::Linear;
  Real rest_density = 1000;  // kg/m^3 (the EOS reference; walls use their per-particle value)
  Real sound_speed = 1;      // m/s
  Real viscosity = 0;        // dynamic viscosity (Pa s); walls take the fluid's (see momentum.hpp)
  Real tait_gamma = 7;
  Real background_pressure = 0;  // Pa, added by the EOS (fluid/eos.hpp); one value for all materials
  // Colour of the continuum surface force (interface/surface_tension.hpp, Pazdniakou eqs. 6, 10):
  // +1 liquid, -1 gas, cos(contact angle) for a wall.
  Real colour = 1;
};

constexpr int kMaxMaterials = 8;

template <int D>
struct MaterialTable {
  int count = 0;
  Material m[kMaxMaterials];
  Vec<D> body_force[kMaxMaterials];  // m/s^2, per material

  PSPH_HD const Material& operator[](int k) const { return m[k]; }
  PSPH_HD bool is_fluid(int k) const { return m[k].kind == MaterialKind::Fluid; }
};

}  // namespace psph
