#pragma once
// Material table: each particle carries a material index; the table says what the material is
// (its kind) and holds its constants. Passed by value to the passes, so it lives in registers or
// constant cache on the GPU.
#include "core/vec.hpp"

namespace psph {

enum class MaterialKind : int { Fluid = 0, Wall = 1, Elastic = 2, Rigid = 3 };
enum class EquationOfState : int { Linear = 0, Tait = 1 };

struct Material {
  MaterialKind kind = MaterialKind::Fluid;
  EquationOfState eos = EquationOfState::Linear;
  Real rest_density = 1000;  // kg/m^3 (the EOS reference; walls use their per-particle value)
  Real sound_speed = 1;      // m/s
  Real viscosity = 0;        // dynamic viscosity (Pa s); walls take the fluid's (see momentum.hpp)
  Real tait_gamma = 7;
  Real background_pressure = 0;  // Pa, added by the EOS (core/equation_of_state.hpp); one value for all materials
  // Elastic solids (solid/elastic_force.hpp): small-strain isotropic moduli, sigma = k tr(eps) I +
  // 2 mu dev(eps) (Deptulski eq. 2.84); sound_speed is then the P-wave speed sqrt((k + 4 mu/3)/rho).
  Real bulk_modulus = 0;   // k (Pa)
  Real shear_modulus = 0;  // mu (Pa)
  // Colour of the continuum surface force (interface/surface_tension.hpp, Pazdniakou eqs. 6, 10):
  // +1 liquid, -1 gas, cos(contact angle) for a wall.
  Real colour = 1;
  // Walls that clamp an elastic solid (solid/clamp.hpp): false, they hold every component of its
  // displacement (a bonded plate); true, the normal one only (a lubricated plate, free to slip).
  bool slip_clamp = false;
};

// Young's modulus and Poisson ratio of the moduli k, mu: E = 9 k mu / (3 k + mu),
// nu = (3 k - 2 mu) / (2 (3 k + mu)).
template <class T>
PSPH_HD inline T young_modulus(T k, T mu) {
  return T(9) * k * mu / (T(3) * k + mu);
}
template <class T>
PSPH_HD inline T poisson_ratio(T k, T mu) {
  return (T(3) * k - T(2) * mu) / (T(2) * (T(3) * k + mu));
}
// Both with one division (per-particle laws).
template <class T>
PSPH_HD inline void young_and_poisson(T k, T mu, T& young, T& poisson) {
  const T inv = T(1) / (T(3) * k + mu);
  young = T(9) * k * mu * inv, poisson = T(0.5) * (T(3) * k - T(2) * mu) * inv;
}

constexpr int kMaxMaterials = 8;
template <int D>
struct MaterialTable {
  int count = 0;
  Material m[kMaxMaterials];
  Vec<D> body_force[kMaxMaterials];  // m/s^2, per material (fluids: plus their regions, core/fluid_table.hpp)

  PSPH_HD const Material& operator[](int k) const { return m[k]; }
  PSPH_HD bool is_fluid(int k) const { return m[k].kind == MaterialKind::Fluid; }
  PSPH_HD bool is_elastic(int k) const { return m[k].kind == MaterialKind::Elastic; }
  PSPH_HD bool is_rigid(int k) const { return m[k].kind == MaterialKind::Rigid; }
  // Elastic and rigid solids: bodies with their own density, which present their volume and an
  // extrapolated pressure to the fluid (solid/fluid_coupling.hpp) and keep their density.
  PSPH_HD bool is_solid(int k) const { return is_elastic(k) || is_rigid(k); }
  // The volume neighbour j presents to the fluid's sums: m / rho, and for an elastic particle (whose
  // rho stays the reference one, solid/) its current volume V0 (1 + tr eps) in small strain: with
  // the reference volume a solid compressed by 1e-3 looked 1e-3 denser to the fluid's density sum,
  // a spurious pressure of K_fluid 1e-3 / 2 at its surface.
  // In large strain (Saint Venant-Kirchhoff, s.defgrad set) the current volume is V0 det F.
  template <class View>
  PSPH_HD PSPH_PAIR Real volume_of(const View& s, int j) const {
    const Real v = s.m[j] / s.rho[j];
    if (!is_elastic(s.material[j])) return v;
    return v * (s.defgrad ? determinant(s.defgrad[j]) : Real(1) + trace(s.strain[j]));
  }
  // Particles that the forces move (the others are walls, moved only by their prescribed velocity).
  PSPH_HD bool is_dynamic(int k) const { return m[k].kind != MaterialKind::Wall; }
  // Particles kicked by their own acceleration: a rigid particle moves with its body (rigid/).
  PSPH_HD bool is_kicked(int k) const { return is_dynamic(k) && !is_rigid(k); }
};

}  // namespace psph
