#pragma once
// Runs another program (pvbatch, ffmpeg, python3) and waits for it.
#include <string>
#include <vector>

namespace psph {

// Runs argv[0] (searched in PATH); returns its exit status, 127 when it cannot start.
int run_program(const std::vector<std::string>& args);

}  // namespace psph
