#include "app/bench_stability.hpp"

#include <chrono>

#include "engine/engine.hpp"
#include "scene/embedded_cases.hpp"
#include "scene/scene_builder.hpp"

namespace psph {

std::vector<StabilityRecord> stability_sweep(const std::string& backend, bool quick, std::ostream* log) {
  struct Target {
    const char* name;
    double end;  // simulated time per run (s)
    bool jittered;  // also from disordered starts
  };
  // The dam break through the collapse of the column (the front crosses half the tank by 1 s); the
  // channel to near steady state; the 2D bubble (R = 12 spacings) through its relaxation; the
  // drainage until the gas has entered the grain pack.
  const std::vector<Target> targets = {{"poiseuille_2d", 0.5, true},
                                       {"dam_break_3d", quick ? 0.3 : 1.0, true},
                                       {"laplace_bubble_2d", quick ? 0.05 : 0.1, false},
                                       {"drainage_2d", quick ? 0.02 : 0.05, false}};
  const std::vector<double> factors = quick ? std::vector<double>{1, 2, 4} : std::vector<double>{1, 1.5, 2, 2.5, 3, 3.5, 4};
  const std::vector<double> all_jitters = quick ? std::vector<double>{0, 0.2} : std::vector<double>{0, 0.1, 0.2};
  std::vector<StabilityRecord> out;
  for (const Target& tg : targets)
    for (double jit : tg.jittered ? all_jitters : std::vector<double>{0.0})
      for (double f : factors) {
        toml::table tbl = toml::parse(embedded_case_text(tg.name), std::string_view(tg.name));
        set_case_value(tbl, "solver.dt_factor", toml::value<double>(f));
        set_case_value(tbl, "discretisation.jitter", toml::value<double>(jit));
        Case c = parse_case(tbl, tg.name);
        build_particles(c);
        StabilityRecord r;
        r.case_name = tg.name, r.dt_factor = f, r.jitter = jit;
        const auto t0 = std::chrono::steady_clock::now();
        auto e = make_engine(c.scene, backend);
        try {
          e->run_until(tg.end);
          // A weakly compressible run that "survives" with > 10 % density error is not a result.
          r.stable = e->stats().density_deviation_max < 0.1;
          if (!r.stable) r.diagnostic = "ended with a fluid density more than 10 % off its reference";
        } catch (const InstabilityError& err) {
          r.diagnostic = err.what();
        }
        r.density_deviation_max = e->stats().density_deviation_max;
        r.end_time = e->time(), r.steps = e->steps();
        r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        out.push_back(r);
        if (log)
          *log << tg.name << " dt_factor " << f << " jitter " << jit << ": " << (r.stable ? "stable" : "UNSTABLE")
               << " (t = " << r.end_time << " s, " << r.steps << " steps, max |rho/rho0 - 1| = "
               << r.density_deviation_max << ")" << (r.diagnostic.empty() ? "" : " " + r.diagnostic) << std::endl;
      }
  return out;
}

}  // namespace psph
