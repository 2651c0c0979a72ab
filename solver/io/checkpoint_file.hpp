#pragma once
// Checkpoint files: "PORESPH-CHECKPOINT 1\n", one line of JSON (clock, sizes, field table), then
// each field's raw bytes in table order. Written to a temporary name and renamed, so that a file
// with the final name is always complete.
#include <stdexcept>
#include <string>

#include "state/checkpoint.hpp"

namespace psph {

struct CheckpointError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

void write_checkpoint_file(const std::string& path, const Checkpoint& c, const std::string& case_name);
// Throws CheckpointError naming the file and what is wrong with it.
Checkpoint read_checkpoint_file(const std::string& path);
// The newest checkpoint (highest step) in a run directory's checkpoints/ folder, or "" if none.
std::string latest_checkpoint(const std::string& run_or_checkpoint_dir);

}  // namespace psph
