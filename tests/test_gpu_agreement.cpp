// CPU and CUDA agree, one case per physics family: a fixed number of steps on both backends, then
// the particle order (ids) and named fields compared. Both run the same double-precision code; the
// GPU's fused multiply-adds, libm and reduction order differ in the last bits, and the dynamics
// amplify that, so each field has its own tolerance on max|cpu - other| / max|cpu|.
//   gpu_tests CASE|--all [--against cuda|cpu|cpu-ulp] [--steps N]
// --against cuda (the default) exits 77 (skipped) where no GPU is visible. --against cpu runs the
// other side on the CPU too: it must agree exactly (0). --against cpu-ulp starts the other side
// with every position moved by about one ulp, to see how far the dynamics carry last-bit noise.
// --steps replaces each case's number of steps (a quick run of the harness).
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <functional>
#include <limits>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "engine/engine.hpp"
#include "ghost_strip.hpp"
#include "scene/case_file.hpp"
#include "scene/embedded_cases.hpp"
#include "scene/scene_builder.hpp"
#include "validation/oscillating_plate.hpp"

using namespace psph;

namespace {

struct Compared {
  const char* field;  // an engine field, "time", or a rigid-body quantity ("body_centre", ...)
  double tolerance;
};

struct AgreementCase {
  const char* name;
  std::function<Case()> build;  // particles built
  int steps;
  std::vector<Compared> fields;
};

Case embedded(const char* name) {
  Case c = load_case_text(embedded_case_text(name), std::string("cases/") + name + ".toml");
  build_particles(c);
  return c;
}

Case plate(SolidFormulation form, SolidModel model) {
  Case c = oscillating_plate_case(0.001, 0, form);  // the first bending mode's initial velocity
  c.scene.options.solid_model = model;
  return c;
}

// `text` with `from` replaced by `to`; the case text must contain `from`.
std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const auto p = text.find(from);
  if (p == std::string::npos) throw std::runtime_error("case text has no '" + from + "'");
  return text.replace(p, from.size(), to);
}

// Tolerances: at least 10 x steps x the drift that one-ulp initial positions leave on the CPU
// (gpu_tests --all --against cpu-ulp: 1e-16 to 2e-9), since FMA and libm differ at every step, not
// only at the start; a wrong or racing GPU pass differs by orders of magnitude more.
const std::vector<AgreementCase>& agreement_cases() {
  static const std::vector<AgreementCase> cases = {
      // 3D viscous low-Mach channel: smooth; pressure = c^2 (rho - rho0) loses digits to cancellation.
      {"poiseuille_couette", [] { return embedded("poiseuille_couette"); }, 100,
       {{"time", 1e-9}, {"position", 1e-9}, {"velocity", 1e-9}, {"density", 1e-9}, {"pressure", 1e-5}}},
      // Two fluids, surface tension, geometric wetting on a 60-degree wall and the contact-line
      // force: curvature divides by |grad c| and the normal switches at a threshold, so it drifts most.
      {"two_phase_wetting", [] { return embedded("sessile_drop_2d"); }, 200,
       {{"time", 1e-9}, {"position", 1e-9}, {"velocity", 1e-6}, {"density", 1e-9}, {"pressure", 1e-6},
        {"colour", 1e-7}, {"curvature", 1e-5}}},
      // Elastic plate in its first bending mode, stress form (corrected gradients, linear law):
      // stress is a difference of nearly equal neighbour sums, the most sensitive field.
      {"elastic_stress", [] { return plate(SolidFormulation::Stress, SolidModel::Linear); }, 300,
       {{"time", 1e-9}, {"position", 1e-9}, {"velocity", 1e-5}, {"displacement", 1e-7}, {"stress", 1e-5}}},
      // The displacement form (one kernel sum): as the stress form.
      {"elastic_displacement", [] { return plate(SolidFormulation::Displacement, SolidModel::Linear); }, 300,
       {{"time", 1e-9}, {"position", 1e-9}, {"velocity", 1e-5}, {"displacement", 1e-7}, {"stress", 1e-5}}},
      // Saint Venant-Kirchhoff (total Lagrangian): as the stress form; F = I + grad u is near 1.
      {"elastic_svk", [] { return plate(SolidFormulation::Stress, SolidModel::SaintVenantKirchhoff); }, 300,
       {{"time", 1e-9}, {"position", 1e-9}, {"velocity", 1e-5}, {"displacement", 1e-7}, {"stress", 1e-5},
        {"deformation_gradient", 1e-8}}},
      // A spinning rigid disc settling in a viscous fluid: the body's force and torque are sums over
      // its particles, in another order on the GPU.
      {"rigid_bodies", [] {
         Case c = load_case_text(replaced(embedded_case_text("settling_cylinder_2d"), "material = \"grain\"",
                                          "material = \"grain\"\nangular_velocity = 0.05"), "cases/settling_cylinder_2d.toml");
         build_particles(c);
         return c;
       }, 200,
       {{"time", 1e-9}, {"position", 1e-9}, {"velocity", 1e-7}, {"pressure", 1e-6}, {"body_centre", 1e-9},
        {"body_velocity", 1e-7}, {"body_angular_momentum", 1e-7}}},
      // Pressure inlet and outlet: buffer particles recycled through the periodic seam, their
      // velocity extrapolated from the fluid next to them.
      {"open_boundary", [] { return embedded("open_channel_2d"); }, 300,
       {{"time", 1e-9}, {"position", 1e-9}, {"velocity", 1e-7}, {"density", 1e-9}, {"pressure", 1e-6}}},
      // PCW damage in the softening bar (Saint Venant-Kirchhoff, artificial viscosity), past the
      // onset at the centre (step 504): the damage passes and their closed-form update.
      {"damage_pcw", [] { return embedded("softening_bar_2d"); }, 600,
       {{"time", 1e-9}, {"position", 1e-9}, {"velocity", 1e-6}, {"strain", 1e-6}, {"damage", 1e-6},
        {"damage_driving_force", 1e-6}}},
      // Rankine-Mohr-Coulomb with ghosts: the notched strip breaks (6 ghosts by 1.1 ms, each a list
      // build of its own); which particle is a ghost must agree exactly.
      {"damage_ghosts", [] {
         Case c = load_case_text(test::ghost_strip_case(), "ghost_strip.toml");
         build_particles(c);
         return c;
       }, 6500,
       {{"time", 1e-9}, {"position", 1e-9}, {"velocity", 1e-5}, {"damage", 1e-6}, {"damage_ghost", 0}}},
  };
  return cases;
}

// A field in id order (components interleaved), a rigid-body quantity, or the time.
std::vector<double> values(Engine& e, const std::string& name, const std::vector<double>& id) {
  if (name == "time") return {e.time()};
  if (name.rfind("body_", 0) == 0) {
    std::vector<double> out;
    for (const RigidBodyState& b : e.rigid_bodies()) {
      const Vec3d& q = name == "body_centre" ? b.centre : name == "body_velocity" ? b.velocity : b.angular_momentum;
      out.insert(out.end(), q.begin(), q.end());
    }
    return out;
  }
  const std::vector<double> f = e.field(name);
  const std::size_t n = id.size(), k = n ? f.size() / n : 0;
  std::vector<double> out(f.size());
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t c = 0; c < k; ++c) out[static_cast<std::size_t>(id[i]) * k + c] = f[i * k + c];
  return out;
}

// Runs one case on the CPU and on `against`; returns the number of failed comparisons.
int compare(const AgreementCase& ac, const std::string& against, int steps) {
  Case c = ac.build();
  auto ref = make_cpu_engine(c.scene);
  Scene other_scene = c.scene;
  if (against == "cpu-ulp")  // about one ulp up or down, alternating (0 stays 0)
    for (std::size_t i = 0; i < other_scene.x.size(); ++i) other_scene.x[i] *= 1 + (i % 2 ? 1 : -1) * std::ldexp(1.0, -52);
  auto other = make_engine(other_scene, against == "cuda" ? "cuda" : "cpu");
  for (int s = 0; s < steps; ++s) ref->step(1e30), other->step(1e30);
  std::printf("%s: %d particles, %d steps, cpu against %s (%s)\n", ac.name, ref->particles(), steps,
              against.c_str(), other->device().c_str());
  int failures = 0;
  const std::vector<double> ida = ref->field("id"), idb = other->field("id");
  const int n = ref->particles();
  bool ids_ok = other->particles() == n && ida.size() == idb.size();
  std::vector<int> seen(2 * std::size_t(n), 0);  // each id once on each side
  for (std::size_t i = 0; ids_ok && i < ida.size(); ++i)
    ids_ok = ida[i] >= 0 && ida[i] < n && idb[i] >= 0 && idb[i] < n && !seen[int(ida[i])]++ && !seen[n + int(idb[i])]++;
  if (!ids_ok) {
    std::printf("  FAIL particle count or ids differ (each of 0..%d once)\n", n - 1);
    return 1;
  }
  // Both sort stably by the same cell keys, so the order is normally the same; a last-bit
  // difference in a position on a cell face may reorder a few particles (and their sums): reported,
  // not failed, since the fields are compared by id.
  const bool same_order = ida == idb;
  std::printf("  %-22s %s\n", "particle order (ids)", same_order ? "same" : "differs (fields compared by id)");
  // The profiles (core/pass_profile.hpp) name the same passes under the same stages.
  auto passes = [](Engine& e) {
    std::set<std::string> out;
    for (const PassTime& t : e.profile().passes()) out.insert(t.stage + ": " + t.pass);
    return out;
  };
  const bool same_passes = passes(*ref) == passes(*other);
  std::printf("  %-22s %s\n", "profiled passes", same_passes ? "same" : "FAIL (they differ)");
  failures += !same_passes;
  for (const Compared& f : ac.fields) {
    const auto a = values(*ref, f.field, ida), b = values(*other, f.field, idb);
    double scale = 0, diff = a.size() == b.size() ? 0 : std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < a.size() && i < b.size(); ++i)
      scale = std::max(scale, std::fabs(a[i])), diff = std::max(diff, std::fabs(a[i] - b[i]));
    const double rel = scale > 0 ? diff / scale : diff;
    const bool ok = !a.empty() && rel <= f.tolerance;  // NaN fails too
    std::printf("  %-22s max|cpu - %s| / max|cpu| = %.3e (tolerance %.0e) %s\n", f.field, against.c_str(), rel,
                f.tolerance, ok ? "ok" : a.empty() ? "FAIL (no such field)" : "FAIL");
    failures += !ok;
  }
  return failures;
}

}  // namespace

int main(int argc, char** argv) {
  std::string name, against = "cuda";
  int steps = 0;  // 0: each case's own
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--against") && i + 1 < argc) against = argv[++i];
    else if (!std::strcmp(argv[i], "--steps") && i + 1 < argc) steps = std::atoi(argv[++i]), steps = steps > 0 ? steps : -1;
    else if (name.empty()) name = argv[i];
    else name = "?";
  }
  const auto& cases = agreement_cases();
  std::vector<const AgreementCase*> chosen;
  for (const auto& ac : cases)
    if (name == "--all" || name == ac.name) chosen.push_back(&ac);
  if (chosen.empty() || steps < 0 || (against != "cuda" && against != "cpu" && against != "cpu-ulp")) {
    std::fprintf(stderr, "usage: gpu_tests CASE|--all [--against cuda|cpu|cpu-ulp] [--steps N > 0]; cases:");
    for (const auto& ac : cases) std::fprintf(stderr, " %s", ac.name);
    std::fprintf(stderr, "\n");
    return 2;
  }
  if (against == "cuda" && !cuda_available()) {
    std::printf("no CUDA device: skipped\n");
    return 77;
  }
  int failed = 0;
  for (const AgreementCase* ac : chosen) {
    int f = 0;
    try {
      f = compare(*ac, against, steps ? steps : ac->steps);
    } catch (const std::exception& e) {  // an instability or a device error: a failure, named
      std::printf("  FAIL %s\n", e.what());
      f = 1;
    }
    std::printf("%s: %s\n", ac->name, f ? "FAILED" : "passed");
    failed += f > 0;
  }
  return failed ? 1 : 0;
}
