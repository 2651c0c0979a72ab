#pragma once
// Raised when a run goes unstable (NaN, a particle leaving the domain, a collapsing time step, a
// linear solve that does not converge).
#include <stdexcept>

namespace psph {

struct InstabilityError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

}  // namespace psph
