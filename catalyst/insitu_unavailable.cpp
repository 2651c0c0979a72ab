// Builds without ParaView: in-situ visualisation is unavailable and says so.
#include "catalyst/insitu.hpp"

namespace psph {

bool insitu_available() { return false; }

std::unique_ptr<InSitu> make_insitu(const InSituConfig&) {
  throw InSituUnavailable(
      "ParaView Catalyst is not available: this poresph was built without ParaView (solver-only). "
      "Install paraview-dev and python3-paraview (scripts/install-deps.sh) and rebuild, or run without --pipeline");
}

}  // namespace psph

#include <ostream>

#include "catalyst/figures.hpp"

namespace psph {

int render_figures(const std::string&, const std::vector<std::string>&, std::ostream& log) {
  log << "poresph: figures needs ParaView (pvbatch and Catalyst); this poresph was built without it\n";
  return 2;
}

}  // namespace psph
