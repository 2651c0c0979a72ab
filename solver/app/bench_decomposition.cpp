#include "app/bench_decomposition.hpp"

#include <algorithm>
#include <chrono>

#include "app/bench_cases.hpp"
#include "parallel/decomposition.hpp"
#include "parallel/particle_cost.hpp"
#include "scene/scene_builder.hpp"
#include "validation/claystone_drainage.hpp"

namespace psph {

std::vector<DecompositionCount> count_decompositions(const std::string& name, const Scene& sc, double halo_width,
                                                     const std::vector<int>& processes, std::ostream* log) {
  const int dim = sc.dimension, n = sc.count();
  Box box;
  std::array<bool, 3> periodic{false, false, false};
  for (int k = 0; k < dim; ++k) box.lo[k] = sc.lower[k], box.hi[k] = sc.upper[k], periodic[k] = sc.periodic[k];
  std::vector<double> cost(n);
  for (int i = 0; i < n; ++i) cost[i] = particle_cost(sc.materials[sc.material[i]].props.kind);
  std::vector<DecompositionCount> out;
  Communicator one;
  for (int p : processes) {
    const auto t0 = std::chrono::steady_clock::now();
    Decomposition d(dim, box, periodic);
    d.bisect(sc.x, cost, p, one);
    std::vector<double> load(p, 0.0), halo(p, 0.0), owned(p, 0.0);
    std::vector<int> near;
    for (int i = 0; i < n; ++i) {
      const double* x = &sc.x[std::size_t(i) * dim];
      const int o = d.owner(x);
      load[o] += cost[i], owned[o] += 1;
      d.parts_near(x, halo_width, o, near);
      for (int r : near) halo[r] += 1;
    }
    DecompositionCount c;
    c.case_name = name, c.processes = p, c.particles = n;
    double total_load = 0, total_halo = 0;
    for (int r = 0; r < p; ++r) total_load += load[r], total_halo += halo[r];
    c.cost_imbalance = *std::max_element(load.begin(), load.end()) / (total_load / p);
    c.halo_mean = total_halo / p, c.halo_max = *std::max_element(halo.begin(), halo.end());
    c.halo_per_particle = total_halo / n, c.owned_mean = double(n) / p;
    out.push_back(c);
    if (log)
      *log << name << ": " << p << " processes, cost imbalance " << c.cost_imbalance << ", halo per process "
           << c.halo_mean << " (largest " << c.halo_max << ") against " << c.owned_mean << " owned, "
           << std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() << " s" << std::endl;
  }
  return out;
}

std::vector<DecompositionCount> decomposition_sweep(const std::vector<int>& processes, std::ostream* log) {
  std::vector<DecompositionCount> out;
  // Halo width: the lists' radius, support x (1 + skin), and what reads reach beyond it
  // (engine/scene.hpp, halo_reach).
  {
    Case c = spheric_dam_break_case(0.006);
    build_particles(c);
    const double width = c.scene.options.support_radius * (1 + c.scene.options.neighbour_skin) + halo_reach(c.scene);
    for (auto& r : count_decompositions("spheric_dam_break_3d_dp6mm", c.scene, width, processes, log)) out.push_back(r);
  }
  {
    Case c = claystone_case({"sample.image.particles_per_voxel=2", "discretisation.spacing=1e-8",
                             "discretisation.support_radius=2e-8"});
    build_particles(c);
    const SolverOptions& o = c.scene.options;
    const double width = o.support_radius * (1 + o.neighbour_skin) + halo_reach(c.scene);
    for (auto& r : count_decompositions("claystone_published_cell", c.scene, width, processes, log)) out.push_back(r);
  }
  return out;
}

}  // namespace psph
