#include "validation/plate_inclusion.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <utility>
#include <vector>

#include "damage/damage_pass.hpp"
#include "engine/engine.hpp"
#include "scene/embedded_cases.hpp"
#include "scene/scene_builder.hpp"
#include "validation/case_edit.hpp"

namespace psph {

namespace {

constexpr double kHalfSide = 0.15;     // L / 2, Table 4.2
constexpr double kRate = 30e-6 / 1.6e-3;  // imposed displacement rate (m/s), the case's
constexpr double kMargin = 0.01;       // domain room around the plate (m)

double monitor(Engine& e, const std::string& name) {
  for (const auto& m : e.monitors())
    if (m.name == name) return m.value;
  return 0;
}

// The damage at which a point of the model passes its peak stress (Deptulski eqs. 4.22-4.23:
// AT-2's uniaxial peak at w~ = Y_c0 / 3, where D = w~ / (w~ + Y_c0) = 1/4).
double peak_damage(const std::string& model) { return model == "at2" ? 0.25 : kDamaged; }

}  // namespace

Case plate_inclusion_case(const std::string& model, bool compression, double top_displacement, double spacing,
                          double support) {
  toml::table tbl =
      toml::parse(embedded_case_text("plate_inclusion_2d"), std::string_view("cases/plate_inclusion_2d.toml"));
  const double s = spacing, L = kHalfSide, grip = std::round(support / s) * s;
  const double edge = lattice_aligned(L + grip + kMargin, s);
  tbl["discretisation"].as_table()->insert_or_assign("spacing", s);
  tbl["discretisation"].as_table()->insert_or_assign("support_radius", support);
  tbl["domain"].as_table()->insert_or_assign("lower", pair_of(-edge, -edge));
  tbl["domain"].as_table()->insert_or_assign("upper", pair_of(edge, edge));
  toml::array& geometry = *tbl["geometry"].as_array();
  geometry[0].as_table()->insert_or_assign("lower", pair_of(-L - s / 2, -L - s / 2));
  geometry[0].as_table()->insert_or_assign("upper", pair_of(L + s / 2, L + grip + s / 2));
  for (toml::table* t : {geometry[1].as_table(), tbl["solid_load"].as_array()->at(0).as_table()}) {
    t->insert_or_assign("lower", pair_of(-L - s / 2, L - s / 2));
    t->insert_or_assign("upper", pair_of(L + s / 2, L + grip + s / 2));
  }
  tbl["solid_load"].as_array()->at(0).as_table()->insert_or_assign("velocity", pair_of(0.0, compression ? -kRate : kRate));
  tbl["damage"].as_table()->insert_or_assign("model", model);
  tbl["time"].as_table()->insert_or_assign("end", top_displacement / kRate);
  Case c = parse_case(tbl, "cases/plate_inclusion_2d.toml");
  build_particles(c);
  return c;
}

PlateDamage run_plate_inclusion(const Case& c, const std::string& model, const std::string& backend) {
  const auto t0 = std::chrono::steady_clock::now();
  const Scene& sc = c.scene;
  const double s = sc.options.spacing, support = sc.options.support_radius, L = kHalfSide;
  int plate = -1;
  for (int m = 0; m < static_cast<int>(sc.materials.size()); ++m)
    if (sc.materials[m].name == "plate") plate = m;
  auto engine = make_engine(sc, backend);
  PlateDamage out;
  out.particles = engine->particles();
  const double every = 0.5e-6 / kRate;  // s between looks
  std::vector<double> d, x0, mat;
  for (double t = every; t <= c.end_time + 1e-12; t += every) {
    engine->run_until(std::min(t, c.end_time));
    d = engine->field("damage"), x0 = engine->field("reference_position"), mat = engine->field("material");
    const double ubar = kRate * engine->time();
    bool left = false, right = false;
    int worst = -1;
    for (std::size_t i = 0; i < d.size(); ++i) {
      if (int(mat[i]) != plate) continue;
      if (worst < 0 || d[i] > d[worst]) worst = int(i);
      if (d[i] >= 0.9 && x0[2 * i] < -L + support) left = true;
      if (d[i] >= 0.9 && x0[2 * i] > L - support) right = true;
    }
    if (out.onset < 0 && worst >= 0 && d[worst] >= peak_damage(model)) {
      out.onset = ubar, out.onset_x = x0[2 * worst], out.onset_y = x0[2 * worst + 1];
      out.onset_driving_force = engine->field("damage_driving_force")[std::size_t(worst)];
      const StepStats st = engine->stats();
      out.kinetic_over_elastic = st.elastic_energy > 0 ? st.kinetic_energy / st.elastic_energy : 0;
    }
    if (out.complete < 0 && left && right) out.complete = ubar;
  }
  std::map<std::pair<long, long>, double> at;  // damage by lattice site
  for (std::size_t i = 0; i < d.size(); ++i)
    if (int(mat[i]) == plate) at[{std::lround(x0[2 * i] / s), std::lround(x0[2 * i + 1] / s)}] = d[i];
  double diff = 0, sum = 0;
  for (const auto& [site, value] : at) {
    const auto mirror = at.find({-site.first, site.second});
    if (mirror != at.end()) diff += std::fabs(value - mirror->second);
    sum += value;
  }
  out.asymmetry = sum > 0 ? diff / sum : 0;
  out.dissipated = monitor(*engine, "damage_energy");
  out.elastic = engine->stats().elastic_energy;
  out.steps = engine->steps();
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

}  // namespace psph
