#pragma once
// Checkpoints in HDF5 (built where HDF5 is found; parallel HDF5 in a build with MPI). One file per
// checkpoint, written together by every process of a run, each its slice of one process's particle
// order (state/checkpoint.hpp), so that the file is the same for any number of processes:
//   /                 attributes: format = "poresph checkpoint", format_version, poresph_version,
//                     case, dimension, particles, precision, time, last_dt, first_dt, steps
//   /case             the resolved case file (TOML text)
//   /fields/<name>    one dataset per registered field, in the registry's order: (particles) or
//                     (particles, components) of its type, with attributes unit, description
//   /extras/...       the stages' own data (dissipated_energy, rigid_bodies)
// Readable with h5py: h5py.File(path)["fields/position"][:].
#include <string>

#include "io/checkpoint_file.hpp"
#include "parallel/communicator.hpp"

namespace psph {

// Every process calls it (collective); a failure on any process is a WriteError on all, and
// `path` is then the file it was before (written to PATH.partial, renamed when complete).
void write_hdf5_checkpoint(const std::string& path, const Checkpoint& c, const CheckpointOrigin& o, Communicator& comm);
// The whole checkpoint, on the calling process alone. Throws CheckpointError naming the file.
Checkpoint read_hdf5_checkpoint(const std::string& path);

}  // namespace psph
