#pragma once
// Checkpoint files: HDF5 where poresph is built with it (io/checkpoint_hdf5.hpp), otherwise the
// raw format "PORESPH-CHECKPOINT 1\n", one line of JSON (clock, sizes, field table), then each
// field's raw bytes in table order. Both read back; both are written durably (a file with the final
// name is always complete; a failed write is a WriteError, io/durable_file.hpp).
#include <stdexcept>
#include <string>
#include <vector>

#include "parallel/communicator.hpp"
#include "state/checkpoint.hpp"

namespace psph {

struct CheckpointError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Where a checkpoint comes from, stored beside the state.
struct CheckpointOrigin {
  std::string case_name, resolved_case;  // the case's name and its resolved TOML text
};

// Every process of a run calls it with its slice (Engine::checkpoint()); one file.
void write_checkpoint_file(const std::string& path, const Checkpoint& c, const CheckpointOrigin& o, Communicator& comm);
// One process's whole checkpoint.
void write_checkpoint_file(const std::string& path, const Checkpoint& c, const std::string& case_name);
// The raw format (a whole checkpoint): what a build without HDF5 writes.
void write_raw_checkpoint_file(const std::string& path, const Checkpoint& c, const std::string& case_name);
// The file name's extension this build writes: ".h5" or ".ckpt".
const char* checkpoint_extension();
// Either format, whole. Throws CheckpointError naming the file and what is wrong with it.
Checkpoint read_checkpoint_file(const std::string& path);
// Where a restart from a run directory starts: its newest checkpoint (step_*.h5 or step_*.ckpt)
// that reads whole (`path`
// empty if none); the newer ones that do not, each with why; the stale .partial files (writes
// cut short by a kill) it removed.
struct RestartCheckpoint {
  std::string path;
  Checkpoint data;
  std::vector<std::string> skipped, removed;
};
RestartCheckpoint newest_intact_checkpoint(const std::string& run_or_checkpoint_dir);

}  // namespace psph
