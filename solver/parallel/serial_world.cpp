// A build without MPI: one process, whatever launched it.
#include "parallel/communicator.hpp"

namespace psph {

Communicator& world() {
  static Communicator one;
  return one;
}
void finalise_world() {}

}  // namespace psph
