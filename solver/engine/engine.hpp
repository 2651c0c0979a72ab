#pragma once
// Backend- and dimension-independent handle on a running simulation.
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/instability.hpp"
#include "core/pass_profile.hpp"
#include "engine/density_watch.hpp"
#include "rigid/rigid_bodies.hpp"
#include "engine/scene.hpp"
#include "parallel/communicator.hpp"
#include "parallel/particle_cost.hpp"
#include "stage/monitor_value.hpp"
#include "state/checkpoint.hpp"

namespace psph {

struct StepStats {
  double v_max = 0, a_max = 0, kinetic_energy = 0, density_deviation_max = 0;
  double elastic_energy = 0;  // elastic solids (solid/elastic_force.hpp)
  double dissipated_energy = 0;  // by the solids' damping since the start (solid/damping.hpp)
  std::string dt_limit;  // which limit set the last step
  int linear_iterations = 0;  // BiCGSTAB iterations of the last implicit viscous step (0 if explicit)
};

// A run shared out over processes (parallel/): how many, how often the domain was cut anew, the
// slowest process's step time over the mean at the last list build, and the halo's size.
struct SharingStats {
  int processes = 1;
  int rebalances = 0;
  double imbalance = 1;
  long long halo_particles = 0;
  long long halo_bytes = 0;  // sent by every process in halo refreshes, to the last statistics (stats())
  long long refreshes = 0;   // halo refreshes of one process, likewise
  ClassCosts class_costs;    // what the cuts weigh each particle class (parallel/particle_cost.hpp)
};

class Engine {
 public:
  virtual ~Engine() = default;
  virtual int dimension() const = 0;
  virtual int particles() const = 0;
  virtual double time() const = 0;
  virtual long steps() const = 0;
  virtual double last_dt() const = 0;
  // Advances one step, never past `t_stop`.
  virtual void step(double t_stop) = 0;
  virtual StepStats stats() = 0;
  // The fluid's largest density deviation so far, and its first step past the case's bound.
  virtual const DensityWatch& density_watch() const = 0;
  // A registered field by name, copied to the host, components interleaved.
  virtual std::vector<double> field(const std::string& name) = 0;
  // Over several processes, this process's slice of field(name): consecutive particles of one
  // process's order, the slices in process order (every process calls); one process: field(name).
  virtual std::vector<double> field_slice(const std::string& name) { return field(name); }
  virtual std::vector<std::string> field_names() const = 0;
  // What a field of field_names() is: its type, components and SI unit (the registry's, state/fields.hpp).
  virtual FieldInfo field_info(const std::string& name) const = 0;
  virtual std::string backend() const = 0;
  virtual std::string device() const = 0;
  // Mean number of neighbours (r < support) per fluid or elastic particle.
  virtual double mean_neighbours() = 0;
  // The whole state, for a restart (see state/checkpoint.hpp); over several processes, this
  // process's slice of it (every process calls). Rebuilds the neighbour lists first.
  virtual Checkpoint checkpoint() = 0;
  // Continues from a checkpoint of the same scene; throws std::invalid_argument naming what differs.
  virtual void restore(const Checkpoint& c) = 0;
  // The stages' monitors at the current state (elastic energy, rigid bodies' motion...), named:
  // the same names, in the same order, at every call of a run.
  virtual std::vector<MonitorValue> monitors() = 0;
  // Where the steps' and monitors' time went, by pass and stage, since the engine was made
  // (core/pass_profile.hpp).
  virtual PassProfile& profile() = 0;
  virtual SharingStats sharing() const { return {}; }
  // The rigid bodies' motion (rigid/rigid_bodies.hpp), in the case's order of their geometries.
  virtual std::vector<RigidBodyState> rigid_bodies() const { return {}; }
  // Runs to t_end (exactly).
  void run_until(double t_end) {
    while (time() < t_end) step(t_end);
  }
};

// Over the processes of `comm` (parallel/communicator.hpp): by default those that mpirun
// started, or this one alone. In a float build the engine runs in a length unit near the support
// radius (engine/unit_scaled_engine.hpp); everything it hands out is in SI.
std::unique_ptr<Engine> make_cpu_engine(const Scene& scene, Communicator& comm = world());
std::unique_ptr<Engine> make_cuda_engine(const Scene& scene, Communicator& comm = world());  // throws without CUDA
bool cuda_available();  // built with CUDA and a device present

inline std::unique_ptr<Engine> make_engine(const Scene& scene, const std::string& backend, Communicator& comm = world()) {
  if (backend == "cuda") return make_cuda_engine(scene, comm);
  return make_cpu_engine(scene, comm);
}

}  // namespace psph
