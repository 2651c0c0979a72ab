#pragma once
// Particle extracts: one VTK file per output time through ParaView's VTK (polydata of vertices,
// .vtp, or an unstructured grid of vertex cells, .vtu: `output.extract_format`), plus a .pvd
// collection that ParaView opens as a time series. Over several processes each writes its piece
// (consecutive particles of one process's order, so that the pieces in order are one process's
// extract) and the first a .pvtp or .pvtu that gathers them. Without ParaView, no extracts.
#include <string>
#include <vector>

#include "engine/engine.hpp"
#include "io/particle_frame.hpp"
#include "parallel/communicator.hpp"

namespace psph {

bool particle_output_available();

class ParticleWriter {
 public:
  // Every process of a run makes one, with the same arguments. `format`: "vtp" or "vtu".
  ParticleWriter(std::string directory, std::vector<std::string> fields, Communicator& comm,
                 std::string format = "vtp");
  // Writes extracts/particles_NNNNNN.vtp (.vtu; .pvtp or .pvtu and its pieces over several
  // processes) for the engine's current state, every process together; returns the file's path.
  std::string write(Engine& e);
  // Writes particles.pvd listing every extract written so far (the first process).
  void write_collection() const;

 private:
  std::string write_whole(const std::string& path);
  std::string write_piece(const std::string& path);

  std::string dir_;
  std::vector<std::string> fields_;
  Communicator& comm_;
  std::string format_;
  ParticleFrame frame_;  // staging buffers, reused from extract to extract
  std::vector<std::pair<double, std::string>> written_;
};

}  // namespace psph
