#include "io/particle_polydata.hpp"

#include <stdexcept>

#include <vtkFieldData.h>
#include <vtkFloatArray.h>
#include <vtkIdTypeArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkStringArray.h>
#include <vtkCellType.h>

#include "core/config.hpp"

namespace psph {
namespace {

vtkSmartPointer<vtkFloatArray> wrap_array(const std::vector<float>& v, int comps, const std::string& name) {
  auto a = vtkSmartPointer<vtkFloatArray>::New();
  a->SetName(name.c_str());
  a->SetNumberOfComponents(comps);
  a->SetArray(const_cast<float*>(v.data()), static_cast<vtkIdType>(v.size()), 1);  // save = 1: not owned
  return a;
}

void add_fields(const ParticleFrame& f, vtkPointData* to) {
  for (const StagedField& s : f.fields) {
    if (s.data.size() != static_cast<std::size_t>(f.n) * s.components)
      throw std::logic_error("staged field '" + s.name + "' has the wrong size");
    to->AddArray(wrap_array(s.data, s.components, s.name));
  }
}

}  // namespace

vtkSmartPointer<vtkPolyData> ParticlePolyData::wrap(const ParticleFrame& f) {
  if (f.position.size() != 3 * static_cast<std::size_t>(f.n)) throw std::logic_error("frame positions are not 3 n");
  if (f.n != verts_n_) {
    vtkNew<vtkIdTypeArray> offsets, conn;
    offsets->SetNumberOfValues(f.n + 1);
    conn->SetNumberOfValues(f.n);
    for (vtkIdType i = 0; i <= f.n; ++i) offsets->SetValue(i, i);
    for (vtkIdType i = 0; i < f.n; ++i) conn->SetValue(i, i);
    verts_ = vtkSmartPointer<vtkCellArray>::New();
    verts_->SetData(offsets, conn);
    verts_n_ = f.n;
  }
  auto poly = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> pts;
  pts->SetData(wrap_array(f.position, 3, "position"));
  poly->SetPoints(pts);
  poly->SetVerts(verts_);
  add_fields(f, poly->GetPointData());
  vtkNew<vtkStringArray> precision;  // the run's arithmetic (the extract's values are float32 in any)
  precision->SetName("precision");
  precision->InsertNextValue(precision_name());
  poly->GetFieldData()->AddArray(precision);
  return poly;
}

vtkSmartPointer<vtkUnstructuredGrid> ParticlePolyData::wrap_grid(const ParticleFrame& f) {
  const vtkSmartPointer<vtkPolyData> poly = wrap(f);
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  grid->SetPoints(poly->GetPoints());
  grid->SetCells(VTK_VERTEX, verts_);
  grid->GetPointData()->ShallowCopy(poly->GetPointData());
  grid->GetFieldData()->ShallowCopy(poly->GetFieldData());
  return grid;
}

}  // namespace psph
