// poresph bench: throughput of the single-phase step.
#include <algorithm>
#include <cstdio>
#include <iostream>

#include <nlohmann/json.hpp>

#include "app/bench_accuracy.hpp"
#include "app/bench_cases.hpp"
#include "app/bench_decomposition.hpp"
#include "app/bench_stability.hpp"
#include "app/commands.hpp"
#include "app/profile_report.hpp"

namespace psph {

namespace {

// Halo copies and cost balance of the real geometries over 2 ... 4,096 processes (--quick: up to 64).
int decomposition_counts(bool json, bool quick) {
  std::vector<int> p;
  for (int n = 2; n <= (quick ? 64 : 4096); n *= 2) p.push_back(n);
  const auto recs = decomposition_sweep(p, json ? &std::cerr : &std::cout);
  nlohmann::json out = nlohmann::json::array();
  for (const auto& r : recs)
    out.push_back({{"case", r.case_name}, {"processes", r.processes}, {"particles", r.particles},
                   {"cost_imbalance", r.cost_imbalance}, {"halo_mean", r.halo_mean}, {"halo_max", r.halo_max},
                   {"halo_per_particle", r.halo_per_particle}, {"owned_mean", r.owned_mean}});
  if (json) std::cout << out.dump(2) << "\n";
  return 0;
}

int accuracy(bool json, const std::string& backend, bool quick) {
  const auto recs = accuracy_sweep(backend, !quick, json ? &std::cerr : &std::cout);
  nlohmann::json out = nlohmann::json::array();
  for (const auto& r : recs)
    out.push_back({{"case", r.case_name},
                   {"kernel", r.kernel},
                   {"support_per_spacing", r.support_per_spacing},
                   {"particles", r.particles},
                   {"steps", r.steps},
                   {"seconds", r.seconds},
                   {"error", r.error},
                   {"backend", backend}});
  if (json) std::cout << out.dump(2) << "\n";
  return 0;
}

int stability(bool json, const std::string& backend, bool quick, const std::vector<std::string>& names) {
  const auto recs = stability_sweep(backend, quick, json ? &std::cerr : &std::cout, names);
  nlohmann::json out = nlohmann::json::array();
  for (const auto& r : recs)
    out.push_back({{"case", r.case_name},
                   {"dt_factor", r.dt_factor},
                   {"jitter", r.jitter},
                   {"stable", r.stable},
                   {"diagnostic", r.diagnostic},
                   {"end_time", r.end_time},
                   {"steps", r.steps},
                   {"density_deviation_max", r.density_deviation_max},
                   {"seconds", r.seconds}});
  if (json) std::cout << out.dump(2) << "\n";
  // The largest factor below which every run of a (case, jitter) was stable.
  if (!json)
    for (std::size_t k = 0; k < recs.size();) {
      double largest = 0;
      bool ok = true;
      std::size_t m = k;
      for (; m < recs.size() && recs[m].case_name == recs[k].case_name && recs[m].jitter == recs[k].jitter; ++m) {
        ok = ok && recs[m].stable;
        if (ok) largest = recs[m].dt_factor;
      }
      std::cout << recs[k].case_name << " jitter " << recs[k].jitter << ": largest stable dt_factor " << largest << "\n";
      k = m;
    }
  return 0;
}

}  // namespace

int cmd_bench(const std::vector<std::string>& names, bool json, const std::string& backend, bool quick,
              bool accuracy_sweep, bool stability_sweep_, bool profile, bool decomposition) {
  if (accuracy_sweep) return accuracy(json, backend, quick);
  if (decomposition) return decomposition_counts(json, quick);
  if (stability_sweep_) return stability(json, backend, quick, names);
  std::vector<BenchSpec> specs;
  for (const BenchSpec& spec : bench_specs(backend, quick))
    if (names.empty() || std::find(names.begin(), names.end(), spec.name) != names.end()) specs.push_back(spec);
  for (const auto& n : names)
    if (std::none_of(specs.begin(), specs.end(), [&](const BenchSpec& s) { return s.name == n; })) {
      std::cerr << "poresph bench: unknown benchmark '" << n << "'; expected one of:";
      for (const BenchSpec& spec : bench_specs(backend, quick)) std::cerr << " " << spec.name;
      std::cerr << "\n";
      return 2;
    }
  nlohmann::json out = nlohmann::json::array();
  for (const BenchSpec& spec : specs) {
    BenchResult r;
    try {
      r = run_bench(spec, backend, json ? &std::cerr : &std::cout);
    } catch (const std::exception& e) {
      std::cerr << "poresph bench: " << spec.name << ": " << e.what() << "\n";
      return 1;
    }
    out.push_back({{"case", r.name},
                   {"backend", r.backend},
                   {"device", r.device},
                   {"precision", r.precision},
                   {"dimension", r.dimension},
                   {"particles", r.particles},
                   {"fluid_particles", r.fluid_particles},
                   {"steps", r.steps},
                   {"seconds", r.seconds},
                   {"particle_steps_per_second", r.particle_steps_per_second},
                   {"fluid_particle_steps_per_second", r.fluid_particle_steps_per_second},
                   {"neighbours_per_particle", r.neighbours},
                   {"interactions_per_second", r.interactions_per_second},
                   {"threads", r.threads}});
    const bool cell = r.name == "claystone_drainage";
    if (cell) out.back()["published_cell_hours"] = published_cell_hours(r.particle_steps_per_second);
    PassProfile none;
    if (profile) out.back()["profile"] = profile_json(r.profile, none, r.seconds);
    if (!json) {
      char line[400];
      std::snprintf(line, sizeof line,
                    "%-24s %dD %8d particles (%8d fluid) %5ld steps %8.3f s  %10.4g fluid particle-steps/s  "
                    "%10.4g particle-steps/s  %10.4g interactions/s (%.1f neighbours)",
                    r.name.c_str(), r.dimension, r.particles, r.fluid_particles, r.steps, r.seconds,
                    r.fluid_particle_steps_per_second, r.particle_steps_per_second, r.interactions_per_second,
                    r.neighbours);
      std::cout << line << std::endl;
      if (cell) {
        std::snprintf(line, sizeof line, "  the published drainage cell (%.2g particles, %.2g steps) at this rate: %.1f h",
                      kPublishedCellParticles, kPublishedCellSteps, published_cell_hours(r.particle_steps_per_second));
        std::cout << line << "\n";
      }
      if (profile)
        for (const std::string& l : profile_lines(r.profile, none, r.seconds, 12)) std::cout << l << "\n";
    }
  }
  if (json) std::cout << out.dump(2) << "\n";
  return 0;
}

}  // namespace psph
