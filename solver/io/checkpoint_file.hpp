#pragma once
// Checkpoint files: "PORESPH-CHECKPOINT 1\n", one line of JSON (clock, sizes, field table), then
// each field's raw bytes in table order. Written durably (io/durable_file.hpp): a file with the
// final name is always complete; a failed write is a WriteError.
#include <stdexcept>
#include <string>
#include <vector>

#include "state/checkpoint.hpp"

namespace psph {

struct CheckpointError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

void write_checkpoint_file(const std::string& path, const Checkpoint& c, const std::string& case_name);
// Throws CheckpointError naming the file and what is wrong with it.
Checkpoint read_checkpoint_file(const std::string& path);
// Where a restart from a run directory starts: its newest checkpoint that reads whole (`path`
// empty if none); the newer ones that do not, each with why; the stale .partial files (writes
// cut short by a kill) it removed.
struct RestartCheckpoint {
  std::string path;
  Checkpoint data;
  std::vector<std::string> skipped, removed;
};
RestartCheckpoint newest_intact_checkpoint(const std::string& run_or_checkpoint_dir);

}  // namespace psph
