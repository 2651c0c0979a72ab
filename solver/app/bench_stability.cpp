#include "app/bench_stability.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "engine/engine.hpp"
#include "scene/embedded_cases.hpp"
#include "scene/scene_builder.hpp"
#include "validation/oscillating_plate.hpp"
#include "validation/softening_bar.hpp"

namespace psph {

namespace {

// How a run that reaches its end is judged: weakly compressible flow must end with every fluid
// density within 10 % of its reference (a run that "survives" beyond is not a result); an
// undamped solid must keep its kinetic + elastic energy within 1 %.
// A damaging solid takes energy, so it is stable when it ends without a diagnostic.
enum class Criterion { FluidDensity, Energy, NoDiagnostic };

double mechanical_energy(Engine& e) {
  const StepStats s = e.stats();
  return s.kinetic_energy + s.elastic_energy;
}

StabilityRecord run_one(const std::string& name, const Case& c, double jitter, double end, Criterion criterion,
                        const std::string& backend, std::ostream* log) {
  StabilityRecord r;
  r.case_name = name, r.dt_factor = c.scene.options.dt_factor, r.jitter = jitter;
  const auto t0 = std::chrono::steady_clock::now();
  auto e = make_engine(c.scene, backend);
  const double e0 = criterion == Criterion::Energy ? mechanical_energy(*e) : 0.0;
  try {
    e->run_until(end);
    if (criterion == Criterion::FluidDensity && !(e->stats().density_deviation_max < 0.1))
      r.diagnostic = "ended with a fluid density more than 10 % off its reference";
    if (criterion == Criterion::Energy) {
      const double drift = std::fabs(mechanical_energy(*e) / e0 - 1);
      if (!(drift < 0.01)) r.diagnostic = "kinetic + elastic energy off by " + std::to_string(100 * drift) + " %";
    }
    r.stable = r.diagnostic.empty();
  } catch (const InstabilityError& err) {
    r.diagnostic = err.what();
  }
  r.density_deviation_max = e->stats().density_deviation_max;
  r.end_time = e->time(), r.steps = e->steps();
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (log)
    *log << name << " dt_factor " << r.dt_factor << " jitter " << jitter << ": " << (r.stable ? "stable" : "UNSTABLE")
         << " (t = " << r.end_time << " s, " << r.steps << " steps, max |rho/rho0 - 1| = " << r.density_deviation_max
         << ")" << (r.diagnostic.empty() ? "" : " " + r.diagnostic) << std::endl;
  return r;
}

}  // namespace

std::vector<StabilityRecord> stability_sweep(const std::string& backend, bool quick, std::ostream* log,
                                             const std::vector<std::string>& only) {
  auto wanted = [&](const std::string& name) {
    return only.empty() || std::find(only.begin(), only.end(), name) != only.end();
  };
  struct Target {
    const char* name;
    double end;  // simulated time per run (s)
    bool jittered;  // also from disordered starts
  };
  // The dam break through the collapse of the column (the front crosses half the tank by 1 s); the
  // channel to near steady state; the 2D bubble (R = 12 spacings) through its relaxation; the
  // drainage until the gas has entered the grain pack; the cube in water until it has settled.
  const std::vector<Target> targets = {{"poiseuille_2d", 0.5, true},
                                       {"dam_break_3d", quick ? 0.3 : 1.0, true},
                                       {"laplace_bubble_2d", quick ? 0.05 : 0.1, false},
                                       {"drainage_2d", quick ? 0.02 : 0.05, false},
                                       {"elastic_cube_3d", quick ? 0.002 : 0.01, false},
                                       {"settling_cylinder_2d", quick ? 0.05 : 0.3, false}};
  const std::vector<double> factors = quick ? std::vector<double>{1, 2, 4} : std::vector<double>{1, 1.5, 2, 2.5, 3, 3.5, 4};
  const std::vector<double> all_jitters = quick ? std::vector<double>{0, 0.2} : std::vector<double>{0, 0.1, 0.2};
  std::vector<StabilityRecord> out;
  for (const Target& tg : targets) {
    if (!wanted(tg.name)) continue;
    for (double jit : tg.jittered ? all_jitters : std::vector<double>{0.0})
      for (double f : factors) {
        toml::table tbl = toml::parse(embedded_case_text(tg.name), std::string_view(tg.name));
        set_case_value(tbl, "solver.dt_factor", toml::value<double>(f));
        set_case_value(tbl, "discretisation.jitter", toml::value<double>(jit));
        Case c = parse_case(tbl, tg.name);
        build_particles(c);
        out.push_back(run_one(tg.name, c, jit, tg.end, Criterion::FluidDensity, backend, log));
      }
  }
  // Elastic solids: the cantilever plate vibrating in its first mode (tip speed 1e-3 c_P) for a
  // fifth of a period, in each formulation and law.
  if (wanted("oscillating_plate_2d"))
    for (int variant = 0; variant < 3; ++variant)
      for (double f : factors) {
        Case c = oscillating_plate_case(0.001, 0, variant == 1 ? SolidFormulation::Displacement : SolidFormulation::Stress);
        if (variant == 2) c.scene.options.solid_model = SolidModel::SaintVenantKirchhoff;
        c.scene.options.dt_factor = f;
        const char* name = variant == 0   ? "oscillating_plate_2d (stress)"
                           : variant == 1 ? "oscillating_plate_2d (displacement)"
                                          : "oscillating_plate_2d (stress, Saint Venant-Kirchhoff)";
        out.push_back(run_one(name, c, 0.0, quick ? 0.01 : 0.05, Criterion::Energy, backend, log));
      }
  // Damage: the softening bar (101 x 5, validation/softening_bar.cpp) pulled until its centre has
  // cracked, 3 L / (2 c_e), with each model: the fully damaged particles must not fly apart.
  if (wanted("softening_bar_2d"))
    for (const char* model : {"pcw", "at1", "at2", "rankine_mohr_coulomb"})
      for (double f : factors) {
        Case c = softening_bar_case(101, 5, 5e-3, model);
        c.scene.options.dt_factor = f;
        out.push_back(run_one(std::string("softening_bar_2d (") + model + ")", c, 0.0, c.end_time,
                              Criterion::NoDiagnostic, backend, log));
      }
  return out;
}

}  // namespace psph
