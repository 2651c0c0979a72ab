#include "io/particle_output.hpp"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <stdexcept>

#if defined(PORESPH_HAVE_VTK)
#include <vtkCellArray.h>
#include <vtkDoubleArray.h>
#include <vtkFloatArray.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkXMLPolyDataWriter.h>
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
  const int D = e.dimension();
  const int n = e.particles();
  const std::vector<double> x = e.field("position");
  vtkNew<vtkPoints> pts;
  pts->SetDataTypeToDouble();
  pts->SetNumberOfPoints(n);
  for (int i = 0; i < n; ++i) {
    double p[3] = {0, 0, 0};
    for (int k = 0; k < D; ++k) p[k] = x[static_cast<std::size_t>(i) * D + k];
    pts->SetPoint(i, p);
  }
  vtkNew<vtkPolyData> poly;
  poly->SetPoints(pts);
  vtkNew<vtkCellArray> verts;
  for (vtkIdType i = 0; i < n; ++i) verts->InsertNextCell(1, &i);
  poly->SetVerts(verts);
  for (const std::string& f : fields_) {
    const std::vector<double> v = e.field(f);
    const int comps = static_cast<int>(n > 0 ? v.size() / n : 1);
    vtkNew<vtkFloatArray> arr;
    arr->SetName(f.c_str());
    // Vectors are written with 3 components so that ParaView glyphs and streamlines work in 2D.
    const int out_comps = comps == D && D > 1 ? 3 : comps;
    arr->SetNumberOfComponents(out_comps);
    arr->SetNumberOfTuples(n);
    for (int i = 0; i < n; ++i)
      for (int k = 0; k < out_comps; ++k)
        arr->SetComponent(i, k, k < comps ? static_cast<float>(v[static_cast<std::size_t>(i) * comps + k]) : 0.f);
    poly->GetPointData()->AddArray(arr);
  }
  vtkNew<vtkXMLPolyDataWriter> w;
  w->SetFileName(path.c_str());
  w->SetInputData(poly);
  w->SetDataModeToAppended();
  w->SetCompressorTypeToZLib();
  if (w->Write() != 1) throw std::runtime_error(path + ": VTK could not write the extract");
#else
  (void)e;
  throw std::runtime_error("particle extracts need ParaView's VTK; this poresph was built without it");
#endif
  written_.emplace_back(e.time(), name);
  return path;
}

void ParticleWriter::write_collection() const {
  const std::string path = dir_ + "/particles.pvd";
  std::ofstream o(path + ".tmp");
  o << "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n  <Collection>\n";
  for (const auto& [t, f] : written_) o << "    <DataSet timestep=\"" << t << "\" file=\"" << f << "\"/>\n";
  o << "  </Collection>\n</VTKFile>\n";
  o.close();
  std::filesystem::rename(path + ".tmp", path);
}

}  // namespace psph
