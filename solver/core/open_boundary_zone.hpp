#pragma once
// Where the open pressure boundaries of a case are (boundary/open_boundary.hpp): two buffer
// layers across one periodic axis, the inlet at one end and the outlet at the other.
#include "core/vec.hpp"

namespace psph {

// As read from the case.
struct SceneOpenBoundary {
  int axis = -1;  // -1: none
  double lower = 0, upper = 0;  // the domain along the axis (m)
  double thickness = 0;         // of each buffer (m)
  bool inlet_at_lower = true;
  double inlet_pressure = 0, outlet_pressure = 0;  // Pa
  int inlet_material = 0;
};

enum class BufferZone : int { None = 0, Inlet = 1, Outlet = 2 };

template <int D>
struct OpenBoundaryZone {
  int axis = -1;  // -1: no open boundary
  Coord inlet_lower = 0, inlet_upper = 0, outlet_lower = 0, outlet_upper = 0;  // along the axis (m)
  Real inlet_pressure = 0, outlet_pressure = 0;  // Pa, on the scale of the pressure field
  int inlet_material = 0;                        // what the inlet injects
  Coord face_band = 0;     // width of the interior band next to each buffer: one support radius (m)
  Coord domain_lower = 0;  // the domain's lower end along the axis (m)
  Real lattice_volume = 0;  // a lattice particle's volume m / rho0 = 1 / Kernel::lattice_sum (m^D)

  PSPH_HD bool active() const { return axis >= 0; }
  PSPH_HD BufferZone zone(const Point<D>& x) const {
    if (axis < 0) return BufferZone::None;
    const Coord c = x[axis];
    if (c >= inlet_lower && c < inlet_upper) return BufferZone::Inlet;
    if (c >= outlet_lower && c < outlet_upper) return BufferZone::Outlet;
    return BufferZone::None;
  }
  PSPH_HD Real pressure(BufferZone z) const { return z == BufferZone::Inlet ? inlet_pressure : outlet_pressure; }
  // For x in a buffer: the point one face_band into the interior from the buffer's inner face, at
  // x's transverse position, where the buffer particle at x reads the fluid's velocity.
  PSPH_HD Point<D> mirror(Point<D> x) const {
    const BufferZone z = zone(x);
    if (z == BufferZone::None) return x;
    const bool inlet = z == BufferZone::Inlet;
    const Coord lo = inlet ? inlet_lower : outlet_lower, hi = inlet ? inlet_upper : outlet_upper;
    x[axis] = inward(z) > 0 ? hi + face_band : lo - face_band;
    return x;
  }
  // The direction along the axis from buffer z into the interior: +1 for the buffer at the domain's
  // lower end, -1 for the one at its upper end.
  PSPH_HD Real inward(BufferZone z) const {
    return (z == BufferZone::Inlet ? inlet_lower : outlet_lower) <= domain_lower ? Real(1) : Real(-1);
  }
  // Whether an interior point lies within face_band of buffer z's inner face.
  PSPH_HD bool in_band(const Point<D>& x, BufferZone z) const {
    if (axis < 0 || zone(x) != BufferZone::None) return false;
    const Coord c = x[axis];
    const bool inlet = z == BufferZone::Inlet;
    const Coord lo = inlet ? inlet_lower : outlet_lower, hi = inlet ? inlet_upper : outlet_upper;
    const Coord d = inward(z) > 0 ? c - hi : lo - c;
    return d >= Coord(0) && d < face_band;
  }
};

}  // namespace psph
