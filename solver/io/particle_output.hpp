#pragma once
// Particle extracts: one VTP file per output time through ParaView's VTK, plus a .pvd collection
// that ParaView opens as a time series. Without ParaView, extracts are not written.
#include <string>
#include <vector>

#include "engine/engine.hpp"
#include "io/particle_frame.hpp"

namespace psph {

bool particle_output_available();

class ParticleWriter {
 public:
  // An empty directory: another process of a shared run, which gathers the fields and writes nothing.
  ParticleWriter(std::string directory, std::vector<std::string> fields);
  // Writes extracts/particles_NNNNNN.vtp for the engine's current state; returns the file path.
  std::string write(Engine& e);
  // Writes particles.pvd listing every extract written so far.
  void write_collection() const;

 private:
  std::string dir_;
  std::vector<std::string> fields_;
  ParticleFrame frame_;  // staging buffers, reused from extract to extract
  std::vector<std::pair<double, std::string>> written_;
};

}  // namespace psph
