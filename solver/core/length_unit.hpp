#pragma once
// The engine's unit of length (engine/unit_scaled_engine.hpp). A float build runs its engine with
// lengths in a power of two L near the support radius: the kernel's (dW/dr)/r grows as R^-(D+2)
// (3e38 1/m^5 at the claystone cell's R = 4e-8 m, float ends at 3.4e38), in units of L it is of
// order one. Time is scaled by the same L (seconds) and mass by L^D (a particle's mass per unit
// depth^(3-D)), so that densities, velocities, pressures, stresses, moduli and strains keep their SI
// numbers. A power of two makes every conversion exact while the values stay normal numbers.
#include <cmath>
#include <stdexcept>
#include <string>

#include "core/config.hpp"

namespace psph {

struct LengthUnit {
  int exponent = 0;  // L = 2^exponent m (and s)
  int dimension = 3;

  bool si() const { return exponent == 0; }
  double metres() const { return std::ldexp(1.0, exponent); }
  // A quantity of length power k (an SI value is its engine value times L^k).
  double to_engine(double si, int k) const { return std::ldexp(si, -k * exponent); }
  double to_si(double engine, int k) const { return std::ldexp(engine, k * exponent); }
  // Either way: into SI (`into_si`) or into this unit.
  double convert(double v, int k, bool into_si) const { return into_si ? to_si(v, k) : to_engine(v, k); }
};

// The length power of a unit as the field registry and the monitors write it; throws
// std::logic_error for a unit it does not know (a new unit belongs in this table).
inline int length_power(const std::string& unit, int dimension) {
  const int D = dimension;
  struct Entry {
    const char* unit;
    int power;
  };
  const Entry table[] = {{"", 0},       {"-", 0},        {"rad", 0},      {"kg/m^3", 0},    {"Pa", 0},
                         {"m/s", 0},    {"m", 1},        {"s", 1},        {"Pa s", 1},      {"N/m", 1},
                         {"m/s^2", -1}, {"1/s", -1},     {"rad/s", -1},   {"1/m", -1},      {"Pa/s", -1},
                         {"kg/m^3/s", -1}, {"1/(m s)", -2}, {"1/m^3", -D}, {"kg", D},      {"J", D},
                         {"N", D - 1}};
  for (const Entry& e : table)
    if (unit == e.unit) return e.power;
  throw std::logic_error("length_power: unit '" + unit + "' is not in core/length_unit.hpp's table");
}

// The engine's length unit for a case of this support radius: SI in a double build (validated
// so), else the power of two nearest R.
inline LengthUnit engine_length_unit(double support_radius, int dimension) {
  LengthUnit u;
  u.dimension = dimension;
  if (sizeof(Real) < 8 && support_radius > 0 && std::isfinite(support_radius))
    u.exponent = int(std::lround(std::log2(support_radius)));
  return u;
}

}  // namespace psph
