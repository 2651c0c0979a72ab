#pragma once
// A reduction's terms from the particles this process owns (parallel/particle_domain.hpp): its
// halo copies count zero in a sum and nothing in a maximum. `owned` null: every particle.
#include <cstdint>
#include <limits>

#include "core/config.hpp"

namespace psph {

// A pass on the particles this process owns only: a halo copy's results would be its owner's,
// brought before any pass reads them (stage/step_context.hpp: launch).
template <class F>
struct OwnedPass {
  using named_as = F;
  F f;
  const std::uint8_t* owned;
  PSPH_HD void operator()(int i) const {
    if (owned[i]) f(i);
  }
};

template <class T, class F>
struct OwnedTerm {
  using named_as = F;  // profiled as the pass it wraps
  F f;
  const std::uint8_t* owned;
  PSPH_HD T operator()(int i) const { return !owned || owned[i] ? f(i) : T{}; }
};

template <class T, class F>
struct OwnedMax {
  using named_as = F;
  F f;
  const std::uint8_t* owned;
  PSPH_HD T operator()(int i) const { return !owned || owned[i] ? f(i) : std::numeric_limits<T>::lowest(); }
};

}  // namespace psph
