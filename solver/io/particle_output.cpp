#include "io/particle_output.hpp"

#include "io/durable_file.hpp"
#include "io/field_staging.hpp"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#if defined(PORESPH_HAVE_VTK)
#include <vtkXMLPPolyDataWriter.h>
#include <vtkXMLPUnstructuredGridWriter.h>
#include <vtkXMLPolyDataWriter.h>
#include <vtkXMLUnstructuredGridWriter.h>

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

ParticleWriter::ParticleWriter(std::string directory, std::vector<std::string> fields, Communicator& comm,
                               std::string format)
    : dir_(std::move(directory)), fields_(std::move(fields)), comm_(comm), format_(std::move(format)) {
  if (format_ != "vtp" && format_ != "vtu") throw std::invalid_argument("extract format '" + format_ + "'");
}

std::string ParticleWriter::write(Engine& e) {
  const bool pieces = comm_.parallel();
  char name[64];
  std::snprintf(name, sizeof name, "particles_%06zu.%s%s", written_.size(), pieces ? "p" : "", format_.c_str());
  const std::string path = dir_ + "/" + name;
#if defined(PORESPH_HAVE_VTK)
  const std::vector<std::string> missing = stage_frame(e, fields_, frame_, pieces);
  if (!missing.empty()) throw std::runtime_error("output.fields: no particle field '" + missing.front() + "'");
  std::string why;
  if (pieces) {
    agree_components(frame_, comm_);
    why = first_message(comm_, write_piece(path));  // the first process's failure
  } else {
    why = write_whole(path);
  }
  if (!why.empty()) throw WriteError(path + ": " + why);
#else
  (void)e;
  throw std::runtime_error("particle extracts need ParaView's VTK; this poresph was built without it");
#endif
  written_.emplace_back(e.time(), name);
  if (comm_.rank() == 0) write_collection();  // kept current, for ParaView and the dashboard to follow a running run
  return path;
}

#if defined(PORESPH_HAVE_VTK)
namespace {

// Inline base64 blocks, not the appended section: VTK 9.2's readers (ParaView 5.11) cannot read
// appended data with expat's reparse deferral (expat 2.6, backported in Debian 12's 2.5.0-1+deb12u2).
void encode(vtkXMLWriter* w) {
  w->SetDataModeToBinary();
  w->SetCompressorTypeToZLib();
}

// The writer of the extract's format (Base: the serial or the parallel writers'), its input `f`.
template <class Base, class PolyWriter, class GridWriter>
vtkSmartPointer<Base> writer_of(const std::string& format, ParticlePolyData& data, const ParticleFrame& f) {
  if (format == "vtu") {
    auto g = vtkSmartPointer<GridWriter>::New();
    g->SetInputData(data.wrap_grid(f));
    return g;
  }
  auto p = vtkSmartPointer<PolyWriter>::New();
  p->SetInputData(data.wrap(f));
  return p;
}

}  // namespace

// VTK's summary file, written without a controller, lists the first process's piece only: every
// piece named as VTK names them (folder/name_<process>.ext) in its place.
std::string list_every_piece(const std::string& path, int pieces) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  const std::string s = text.str(), tag = "<Piece Source=\"";
  const std::size_t at = s.find(tag), end = s.find("/>", at);
  const std::size_t digit = s.rfind("_0.", end);
  if (at == std::string::npos || end == std::string::npos || digit == std::string::npos || digit < at)
    return "VTK's summary file has no piece to list";
  std::string pieces_text;
  for (int r = 0; r < pieces; ++r)
    pieces_text += (r ? "\n    " : "") + s.substr(at, digit + 1 - at) + std::to_string(r) + s.substr(digit + 2, end + 2 - digit - 2);
  try {
    write_file_atomically(path, s.substr(0, at) + pieces_text + s.substr(end + 2));
  } catch (const WriteError& e) {
    return e.what();
  }
  return "";
}

// One process: the whole extract, written to PATH.tmp and renamed when whole (a watcher never reads
// half a file).
std::string ParticleWriter::write_whole(const std::string& path) {
  ParticlePolyData data;
  const auto w = writer_of<vtkXMLWriter, vtkXMLPolyDataWriter, vtkXMLUnstructuredGridWriter>(format_, data, frame_);
  w->SetFileName((path + ".tmp").c_str());
  encode(w);
  std::error_code ec;
  if (w->Write() != 1) {
    std::filesystem::remove(path + ".tmp", ec);
    return "VTK could not write the extract (disk full?)";
  }
  if (std::filesystem::rename(path + ".tmp", path, ec), ec) return ec.message();
  return "";
}

// Several: this process's piece, PATH's folder/PATH's name_<process>.vtp (.vtu); the first process
// also writes PATH, which lists every piece. The collection names PATH only once every piece is
// written.
std::string ParticleWriter::write_piece(const std::string& path) {
  ParticlePolyData data;
  const auto w =
      writer_of<vtkXMLPDataObjectWriter, vtkXMLPPolyDataWriter, vtkXMLPUnstructuredGridWriter>(format_, data, frame_);
  w->SetController(nullptr);  // each process writes its own piece; none waits for another here
  w->SetNumberOfPieces(comm_.size());
  w->SetStartPiece(comm_.rank());
  w->SetEndPiece(comm_.rank());
  w->SetUseSubdirectory(true);
  w->SetWriteSummaryFile(comm_.rank() == 0);
  w->SetFileName(path.c_str());
  encode(w);
  if (w->Write() != 1) return "VTK could not write the piece of process " + std::to_string(comm_.rank()) + " (disk full?)";
  return comm_.rank() == 0 ? list_every_piece(path, comm_.size()) : "";
}

#endif

void ParticleWriter::write_collection() const {
  std::ostringstream o;
  o << "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n  <Collection>\n";
  for (const auto& [t, f] : written_) o << "    <DataSet timestep=\"" << t << "\" file=\"" << f << "\"/>\n";
  o << "  </Collection>\n</VTKFile>\n";
  write_file_atomically(dir_ + "/particles.pvd", o.str());  // rewritten at every extract, as they are: no fsync
}

}  // namespace psph
