// In-situ visualisation through ParaView 5.11's legacy Catalyst (vtkCPProcessor) and version-2
// Python pipeline scripts. Particles go to the channel "particles" as a vtkPolyData of vertices
// whose arrays wrap the frame's host buffers (no copy); over several processes each hands its
// piece and Catalyst runs over their communicator.
#define OMPI_SKIP_MPICXX 1  // ParaView's MPI headers include MPI's: its C API only
#define MPICH_SKIP_MPICXX 1
#include <cstdlib>
#include <stdexcept>
#include <string>

#include <vtkCallbackCommand.h>
#include <vtkCPDataDescription.h>
#include <vtkCPInputDataDescription.h>
#include <vtkCPProcessor.h>
#include <vtkMPI.h>
#include <vtkCPPythonPipeline.h>
#include <vtkNew.h>
#include <vtkPythonInterpreter.h>
#include <vtkSmartPointer.h>

#include "catalyst/headless_display.hpp"
#include "catalyst/insitu.hpp"
#include "io/particle_polydata.hpp"

namespace psph {
namespace {

// Catalyst reports a pipeline script that raises (on import or at an output step) only by printing
// the Python traceback and carrying on. Its Python stderr is watched instead, so that a run that
// asked for figures stops with the script's error rather than finish without them.
class PythonErrors {
 public:
  PythonErrors() {
    auto cb = vtkSmartPointer<vtkCallbackCommand>::New();
    cb->SetClientData(this);
    cb->SetCallback([](vtkObject*, unsigned long, void* self, void* text) {
      if (text) static_cast<PythonErrors*>(self)->text_ += static_cast<const char*>(text);
    });
    interpreter_->AddObserver(vtkCommand::ErrorEvent, cb);
  }
  void raise_if_failed(const std::string& where) {
    drop_logging_errors();
    const auto tb = text_.find("Traceback (most recent call last)");
    if (tb == std::string::npos) return text_.clear();  // warnings only
    std::string last = text_.substr(tb);                // its last non-empty line names the error
    while (!last.empty() && (last.back() == '\n' || last.back() == ' ')) last.pop_back();
    last = last.substr(last.find_last_of('\n') + 1);
    text_.clear();
    throw std::runtime_error("a Catalyst pipeline script failed at " + where + ": " + last +
                             " (traceback above)");
  }

 private:
  // Python's report of a log record its handler could not emit ("--- Logging error ---", a
  // traceback, then "Arguments: ..."): not a script's failure. ParaView 5.11's handler raises on
  // the debug records that Catalyst logs on every process but the first (vtkLogger has no
  // VERBOSITY_DEBUG in its VTK).
  void drop_logging_errors() {
    for (std::size_t at; (at = text_.find("--- Logging error ---")) != std::string::npos;) {
      const std::size_t args = text_.find("\nArguments:", at);
      const std::size_t end = args == std::string::npos ? std::string::npos : text_.find('\n', args + 1);
      text_.erase(at, end == std::string::npos ? std::string::npos : end + 1 - at);
    }
  }

  vtkNew<vtkPythonInterpreter> interpreter_;  // an instance receives the interpreter's stderr events
  std::string text_;
};

class LegacyCatalyst final : public InSitu {
 public:
  explicit LegacyCatalyst(const InSituConfig& cfg) {
    display_ = HeadlessDisplay::ensure(note_);
    // The scripts read their settings (camera, slab, ranges, folders, Live URL) from this file.
    setenv("PORESPH_VIS_SETTINGS", cfg.settings_file.c_str(), 1);
    if (cfg.mpi_comm) {
      // ParaView's log handler fails on the debug records Catalyst writes on every process but the
      // first (drop_logging_errors): those records are not asked for.
      vtkPythonInterpreter::Initialize();
      vtkPythonInterpreter::RunSimpleString("import logging, paraview\nparaview.logger.setLevel(logging.WARNING)\n");
      vtkMPICommunicatorOpaqueComm comm(static_cast<MPI_Comm*>(const_cast<void*>(cfg.mpi_comm)));
      processor_->Initialize(comm);
    } else {
      processor_->Initialize();
    }
    for (const std::string& s : cfg.scripts) {
      vtkSmartPointer<vtkCPPythonPipeline> p = vtkCPPythonPipeline::CreateAndInitializePipeline(s.c_str());
      if (!p) throw std::runtime_error(s + ": Catalyst could not load this pipeline script");
      processor_->AddPipeline(p);
    }
    python_errors_.raise_if_failed("start-up");
  }
  ~LegacyCatalyst() override { finalise(); }
  std::string note() const override { return note_; }

  void execute(const ParticleFrame& f, long step, double time) override {
    vtkNew<vtkCPDataDescription> dd;
    dd->AddInput("particles");
    dd->SetTimeData(time, step);
    dd->ForceOutputOn();  // the solver decides the output steps
    processor_->RequestDataDescription(dd);
    dd->GetInputDescriptionByName("particles")->SetGrid(poly_.wrap(f));
    processor_->CoProcess(dd);
    python_errors_.raise_if_failed("output " + std::to_string(step));
  }

  void finalise() override {
    if (done_) return;
    done_ = true;
    processor_->Finalize();
  }

 private:
  std::unique_ptr<HeadlessDisplay> display_;  // first member: outlives the processor
  PythonErrors python_errors_;
  std::string note_;
  vtkNew<vtkCPProcessor> processor_;
  ParticlePolyData poly_;
  bool done_ = false;
};

}  // namespace

bool insitu_available() { return true; }

std::unique_ptr<InSitu> make_insitu(const InSituConfig& config) { return std::make_unique<LegacyCatalyst>(config); }

}  // namespace psph
