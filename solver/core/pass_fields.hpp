#pragma once
// What a pass reads of its neighbours and what it writes, by registered field name
// (state/fields.hpp). A run shared out over processes brings a field's halo values from their
// owners before a pass that reads it, once after each pass that wrote it
// (stage/step_context.hpp: launch). In a pass:
//   static constexpr FieldNames neighbour_reads{"position", "density"};
//   static constexpr FieldNames writes{"pressure"};
// A pass that declares neither refreshes every field written since the last refresh and counts
// as writing every field. A reduction that reads neighbours declares neighbour_reads alone.
// Names of fields that a case does not register are skipped.
#include <type_traits>

namespace psph {

struct FieldNames {
  static constexpr int kMax = 20;
  const char* names[kMax] = {};
  int count = 0;
  template <class... S>
  constexpr FieldNames(S... s) : names{s...}, count(int(sizeof...(S))) {}
};

// What the fluid's pair passes may read of a neighbour (fluid/, boundary/, interface/): a
// superset, which costs nothing where a field has not changed since it was last brought.
// (An elastic neighbour's volume reads its strain or deformation gradient: core/material.hpp.)
inline constexpr FieldNames kFluidPairReads{"position",        "velocity",       "density",
                                            "pressure",        "mass",           "material",
                                            "rest_density",    "number_density", "wall_noslip_velocity",
                                            "velocity_laplacian", "colour",      "colour_gradient",
                                            "curvature",       "strain",         "deformation_gradient"};

// What the elastic solids' pair passes may read of a neighbour (solid/, the clamps' partners and
// their neighbours included), a superset likewise.
inline constexpr FieldNames kSolidPairReads{"position",     "reference_position",   "material",
                                            "displacement", "mass",                 "rest_density",
                                            "density",      "velocity",             "stress",
                                            "strain",       "deformation_gradient", "damage_ghost",
                                            "damaged_bulk_modulus", "damaged_shear_modulus"};

template <class F, class = void>
struct DeclaresReads : std::false_type {};
template <class F>
struct DeclaresReads<F, std::void_t<decltype(F::neighbour_reads)>> : std::true_type {};

template <class F, class = void>
struct DeclaresFields : std::false_type {};
template <class F>
struct DeclaresFields<F, std::void_t<decltype(F::neighbour_reads), decltype(F::writes)>> : std::true_type {};

}  // namespace psph
