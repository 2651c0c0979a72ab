// poresph bench: throughput of the single-phase step.
#include <cstdio>
#include <iostream>

#include <nlohmann/json.hpp>

#include "app/bench_cases.hpp"
#include "app/commands.hpp"

namespace psph {

int cmd_bench(bool json, const std::string& backend, bool quick) {
  nlohmann::json out = nlohmann::json::array();
  for (const BenchSpec& spec : bench_specs(backend, quick)) {
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
    if (!json) {
      char line[400];
      std::snprintf(line, sizeof line,
                    "%-24s %dD %8d particles (%8d fluid) %5ld steps %8.3f s  %10.4g fluid particle-steps/s  "
                    "%10.4g interactions/s (%.1f neighbours)",
                    r.name.c_str(), r.dimension, r.particles, r.fluid_particles, r.steps, r.seconds,
                    r.fluid_particle_steps_per_second, r.interactions_per_second, r.neighbours);
      std::cout << line << std::endl;
    }
  }
  if (json) std::cout << out.dump(2) << "\n";
  return 0;
}

}  // namespace psph
