// In-situ visualisation through ParaView 5.11's legacy Catalyst (vtkCPProcessor) and version-2
// Python pipeline scripts. Particles go to the channel "particles" as a vtkPolyData of vertices
// whose arrays wrap the frame's host buffers (no copy).
#include <cstdlib>
#include <stdexcept>

#include <vtkCPDataDescription.h>
#include <vtkCPInputDataDescription.h>
#include <vtkCPProcessor.h>
#include <vtkCPPythonPipeline.h>
#include <vtkNew.h>
#include <vtkSmartPointer.h>

#include "catalyst/headless_display.hpp"
#include "catalyst/insitu.hpp"
#include "io/particle_polydata.hpp"

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
    dd->GetInputDescriptionByName("particles")->SetGrid(poly_.wrap(f));
    processor_->CoProcess(dd);
  }

  void finalise() override {
    if (done_) return;
    done_ = true;
    processor_->Finalize();
  }

 private:
  std::unique_ptr<HeadlessDisplay> display_;  // first member: outlives the processor
  std::string note_;
  vtkNew<vtkCPProcessor> processor_;
  ParticlePolyData poly_;
  bool done_ = false;
};

}  // namespace

bool insitu_available() { return true; }

std::unique_ptr<InSitu> make_insitu(const InSituConfig& config) { return std::make_unique<LegacyCatalyst>(config); }

}  // namespace psph
