#include "io/particle_output.hpp"

#include "io/durable_file.hpp"
#include "io/field_staging.hpp"

#include <cstdio>
#include <filesystem>
#include <sstream>
#include <stdexcept>

#if defined(PORESPH_HAVE_VTK)
#include <vtkNew.h>
#include <vtkXMLPolyDataWriter.h>

#include "io/particle_polydata.hpp"
#endif

namespace psph {

bool particle_output_available() {
#if defined(PORESPH_HAVE_VTK)
  return true;
#else
  return false;
#endif
}

ParticleWriter::ParticleWriter(std::string directory, std::vector<std::string> fields)
    : dir_(std::move(directory)), fields_(std::move(fields)) {}

std::string ParticleWriter::write(Engine& e) {
  char name[64];
  std::snprintf(name, sizeof name, "particles_%06zu.vtp", written_.size());
  const std::string path = dir_ + "/" + name;
#if defined(PORESPH_HAVE_VTK)
  const std::vector<std::string> missing = stage_frame(e, fields_, frame_);
  if (!missing.empty()) throw std::runtime_error("output.fields: no particle field '" + missing.front() + "'");
  if (dir_.empty()) return "";  // another process of a shared run: the fields gathered, nothing written
  ParticlePolyData poly;
  vtkNew<vtkXMLPolyDataWriter> w;
  w->SetFileName((path + ".tmp").c_str());  // renamed when whole: a watcher never reads half a file
  w->SetInputData(poly.wrap(frame_));
  // Inline base64 blocks, not the appended section: VTK 9.2's readers (ParaView 5.11) cannot read
  // appended data with expat's reparse deferral (expat 2.6, backported in Debian 12's 2.5.0-1+deb12u2).
  w->SetDataModeToBinary();
  w->SetCompressorTypeToZLib();
  if (w->Write() != 1) {
    std::error_code ec;
    std::filesystem::remove(path + ".tmp", ec);
    throw WriteError(path + ": VTK could not write the extract (disk full?)");
  }
  std::error_code ec;
  if (std::filesystem::rename(path + ".tmp", path, ec), ec) throw WriteError(path + ": " + ec.message());
#else
  (void)e;
  throw std::runtime_error("particle extracts need ParaView's VTK; this poresph was built without it");
#endif
  written_.emplace_back(e.time(), name);
  write_collection();  // kept current, for ParaView and the dashboard to follow a running run
  return path;
}

void ParticleWriter::write_collection() const {
  std::ostringstream o;
  o << "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n  <Collection>\n";
  for (const auto& [t, f] : written_) o << "    <DataSet timestep=\"" << t << "\" file=\"" << f << "\"/>\n";
  o << "  </Collection>\n</VTKFile>\n";
  write_file_atomically(dir_ + "/particles.pvd", o.str());  // rewritten at every extract, as they are: no fsync
}

}  // namespace psph
