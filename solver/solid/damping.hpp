#pragma once
// Mass-proportional damping of elastic solids, a -= zeta v (in the solid force passes), for
// quasi-static loading: Pazdniakou (2018) §3.1.4 damps the solid with a parameter theta in its
// Verlet update, v <- (1 - theta) v per step, which is zeta = theta / dt. The paper gives no value;
// we choose zeta near the lowest mode's angular frequency, which damps it within a period.
#include "core/material.hpp"
#include "state/particles.hpp"

namespace psph {

// The power zeta m |v|^2 that the damping takes from elastic particle i.
template <int D>
struct DampingPowerOf {
  ParticleView<D> s;
  MaterialTable<D> mats;
  Real zeta;
  PSPH_HD Real operator()(int i) const {
    return mats.is_elastic(s.material[i]) ? zeta * s.m[i] * norm2(s.v[i]) : Real(0);
  }
};

}  // namespace psph
