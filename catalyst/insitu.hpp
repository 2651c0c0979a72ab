#pragma once
// In-situ visualisation behind a small interface of its own: initialise (make_insitu), execute
// (one output step), finalise. The legacy Catalyst implementation (ParaView 5.11, vtkCPProcessor)
// lives in legacy_catalyst.cpp; a Catalyst 2 (Conduit) one can be added beside it without
// touching the solver. Without ParaView, make_insitu throws InSituUnavailable.
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "io/particle_frame.hpp"

namespace psph {

struct InSituUnavailable : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct InSituConfig {
  std::vector<std::string> scripts;  // pipeline script paths (see pipeline_scripts.hpp)
  std::string settings_file;         // JSON the scripts read (camera, slab, ranges, output folders)
  std::string live_url;              // HOST:PORT for ParaView Live, empty = off
  // The MPI communicator (an MPI_Comm*) of the processes that render together, each its piece
  // (ParaView composites their images); null for one process.
  const void* mpi_comm = nullptr;
};

class InSitu {
 public:
  virtual ~InSitu() = default;
  // Hands one output step to every pipeline; `frame` must hold the fields the pipelines declared.
  virtual void execute(const ParticleFrame& frame, long step, double time) = 0;
  // Ends the pipelines (closes their files). Called once; the destructor calls it if needed.
  virtual void finalise() = 0;
  // One line for the log: how rendering is done (X display, own Xvfb, off-screen).
  virtual std::string note() const = 0;
};

// Whether this build has ParaView Catalyst.
bool insitu_available();
// Starts Catalyst with the given pipelines. Throws InSituUnavailable without ParaView and
// std::runtime_error when a script cannot be loaded.
std::unique_ptr<InSitu> make_insitu(const InSituConfig& config);

}  // namespace psph
