// In-situ visualisation through ParaView 5.11's legacy Catalyst (vtkCPProcessor) and version-2
// Python pipeline scripts. Particles go to the channel "particles" as a vtkPolyData of vertices
// whose arrays wrap the frame's host buffers (no copy).
#include <cstdlib>
#include <stdexcept>

#include <vtkCPDataDescription.h>
#include <vtkCPInputDataDescription.h>
#include <vtkCPProcessor.h>
#include <vtkCPPythonPipeline.h>
#include <vtkCellArray.h>
#include <vtkFloatArray.h>
#include <vtkIdTypeArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include "catalyst/headless_display.hpp"
#include "catalyst/insitu.hpp"

namespace psph {
namespace {

class LegacyCatalyst final : public InSitu {
 public:
  explicit LegacyCatalyst(const InSituConfig& cfg) {
    display_ = HeadlessDisplay::ensure(note_);
    // The scripts read their settings (camera, slab, ranges, folders, Live URL) from this file.
    setenv("PORESPH_VIS_SETTINGS", cfg.settings_file.c_str(), 1);
    processor_->Initialize();
    for (const std::string& s : cfg.scripts) {
      vtkSmartPointer<vtkCPPythonPipeline> p = vtkCPPythonPipeline::CreateAndInitializePipeline(s.c_str());
      if (!p) throw std::runtime_error(s + ": Catalyst could not load this pipeline script");
      processor_->AddPipeline(p);
    }
  }
  ~LegacyCatalyst() override { finalise(); }
  std::string note() const override { return note_; }

  void execute(const ParticleFrame& f, long step, double time) override {
    vtkNew<vtkCPDataDescription> dd;
    dd->AddInput("particles");
    dd->SetTimeData(time, step);
    dd->ForceOutputOn();  // the solver decides the output steps
    if (!processor_->RequestDataDescription(dd)) return;
    dd->GetInputDescriptionByName("particles")->SetGrid(grid(f));
    processor_->CoProcess(dd);
  }

  void finalise() override {
    if (done_) return;
    done_ = true;
    processor_->Finalize();
  }

 private:
  // VTK arrays over the frame's buffers (save = 1: VTK never frees or writes them).
  static vtkSmartPointer<vtkFloatArray> wrap(const std::vector<float>& v, int comps, const std::string& name) {
    auto a = vtkSmartPointer<vtkFloatArray>::New();
    a->SetName(name.c_str());
    a->SetNumberOfComponents(comps);
    a->SetArray(const_cast<float*>(v.data()), static_cast<vtkIdType>(v.size()), 1);
    return a;
  }

  vtkSmartPointer<vtkPolyData> grid(const ParticleFrame& f) {
    if (f.position.size() != 3 * static_cast<std::size_t>(f.n)) throw std::logic_error("frame positions are not 3 n");
    if (f.n != verts_n_) {  // vertex cells, rebuilt only when the particle count changes
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
    pts->SetData(wrap(f.position, 3, "position"));
    poly->SetPoints(pts);
    poly->SetVerts(verts_);
    for (const StagedField& s : f.fields) {
      if (s.data.size() != static_cast<std::size_t>(f.n) * s.components)
        throw std::logic_error("staged field '" + s.name + "' has the wrong size");
      poly->GetPointData()->AddArray(wrap(s.data, s.components, s.name));
    }
    return poly;
  }

  std::unique_ptr<HeadlessDisplay> display_;  // first member: outlives the processor
  std::string note_;
  vtkNew<vtkCPProcessor> processor_;
  vtkSmartPointer<vtkCellArray> verts_;
  int verts_n_ = -1;
  bool done_ = false;
};

}  // namespace

bool insitu_available() { return true; }

std::unique_ptr<InSitu> make_insitu(const InSituConfig& config) { return std::make_unique<LegacyCatalyst>(config); }

}  // namespace psph
