#include "engine/scene_units.hpp"

#include <stdexcept>

namespace psph {

namespace {

struct Scaler {
  LengthUnit u;
  // A value of length power k in place.
  template <class T>
  void operator()(T& v, int k) const {
    v = T(u.to_engine(double(v), k));
  }
  template <class T, std::size_t N>
  void operator()(std::array<T, N>& a, int k) const {
    for (T& v : a) (*this)(v, k);
  }
  template <class T>
  void operator()(std::vector<T>& a, int k) const {
    for (T& v : a) (*this)(v, k);
  }
};

void scale_options(SolverOptions& o, const Scaler& s) {
  s(o.support_radius, 1), s(o.spacing, 1);  // discretisation; jitter and skin are fractions
  s(o.fixed_dt, 1);                          // step
  s(o.background_pressure_rate, -1);         // fluid (Pa/s)
  s(o.surface_tension, 1);                   // interface (N/m)
  s(o.solid_damping_rate, -1);               // solid (1/s); its pressures and strengths are Pa
}

}  // namespace

Scene in_units(const Scene& sc, const LengthUnit& unit) {
  if (!sc.unit.si()) throw std::logic_error("in_units: the scene is not in SI");
  Scene out = sc;
  out.unit = unit;
  const Scaler s{unit};
  const int D = sc.dimension;
  s(out.lower, 1), s(out.upper, 1);
  s(out.x, 1), s(out.mass, D), s(out.body_angular_velocity, -1);  // velocities: m/s either way
  for (SceneMaterial& m : out.materials) s(m.props.viscosity, 1), s(m.body_force, -1);
  for (SceneForceRegion& r : out.force_regions) s(r.lower, 1), s(r.upper, 1), s(r.acceleration, -1), s(r.ramp_time, 1);
  for (SceneSolidLoad& l : out.solid_loads) s(l.lower, 1), s(l.upper, 1), s(l.ramp_time, 1), s(l.duration, 1);
  s(out.open_boundary.lower, 1), s(out.open_boundary.upper, 1), s(out.open_boundary.thickness, 1);
  scale_options(out.options, s);
  return out;
}

}  // namespace psph
