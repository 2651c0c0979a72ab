#include "validation/softening_bar.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <vector>

#include "damage/damage_pass.hpp"
#include "engine/engine.hpp"
#include "scene/embedded_cases.hpp"
#include "scene/scene_builder.hpp"
#include "validation/case_edit.hpp"

namespace psph {

namespace {

constexpr double kHalfLength = 0.1;  // L, Table 4.1
constexpr double kMargin = 5e-3;     // domain room around the strip (m)

void set_box(toml::table& t, double x_lo, double x_hi, double y_hi, double s) {
  t.insert_or_assign("lower", pair_of(x_lo - s / 2, -s / 2));
  t.insert_or_assign("upper", pair_of(x_hi + s / 2, y_hi + s / 2));
}

// The [damage] table of another model whose local peak stress lies at the same strain eps_0 (with
// nu = 0 the bar is uniaxial, w~ = E eps^2 / 2): AT-1 Y_c0 = E eps_0^2 (peak at its onset), AT-2
// Y_c0 = 3 E eps_0^2 / 2 (peak at sqrt(2 Y_c0 / 3E)), Rankine f_t = E eps_0 with eq. 20's strains
// eps_0, eps_u (Mohr-Coulomb out of reach).
toml::table damage_table(const std::string& model) {
  constexpr double E = 70.8e9, eps0 = 0.022, epsu = 0.060;
  toml::table t{{"model", model}, {"materials", toml::array{"bar"}}};
  if (model == "pcw") t.insert("elastic_limit_strain", eps0), t.insert("ultimate_strain", epsu);
  if (model == "at1") t.insert("critical_energy_release", E * eps0 * eps0);
  if (model == "at2") t.insert("critical_energy_release", 1.5 * E * eps0 * eps0);
  if (model == "rankine_mohr_coulomb") {
    t.insert("tensile_strength", E * eps0), t.insert("tensile_elastic_strain", eps0);
    t.insert("tensile_ultimate_strain", epsu), t.insert("compressive_strength", 1e12);
  }
  return t;
}

}  // namespace

Case softening_bar_case(int points, int rows, double support, const std::string& model) {
  toml::table tbl = toml::parse(embedded_case_text("softening_bar_2d"), std::string_view("cases/softening_bar_2d.toml"));
  const double s = 2 * kHalfLength / (points - 1), width = (rows - 1) * s, L = kHalfLength;
  const double grip = std::round(support / s) * s;  // the grips hold one support's depth of layers
  tbl["discretisation"].as_table()->insert_or_assign("spacing", s);
  tbl["discretisation"].as_table()->insert_or_assign("support_radius", support);
  const double x_edge = lattice_aligned(L + grip + kMargin, s);
  tbl["domain"].as_table()->insert_or_assign("lower", pair_of(-x_edge, -lattice_aligned(kMargin, s)));
  tbl["domain"].as_table()->insert_or_assign("upper", pair_of(x_edge, lattice_aligned(width + kMargin, s)));
  toml::array& geometry = *tbl["geometry"].as_array();
  toml::array& loads = *tbl["solid_load"].as_array();
  set_box(*geometry[0].as_table(), -L - grip, L + grip, width, s);
  for (toml::array* a : {&geometry, &loads}) {
    set_box(*(*a)[a == &geometry ? 1 : 0].as_table(), -L - grip, -L, width, s);
    set_box(*(*a)[a == &geometry ? 2 : 1].as_table(), L, L + grip, width, s);
  }
  if (model != "pcw") tbl.insert_or_assign("damage", damage_table(model));
  Case c = parse_case(tbl, "cases/softening_bar_2d.toml");
  build_particles(c);
  return c;
}

namespace {

struct BarFields {
  std::vector<double> x0, strain, damage, material;
};

BarFields read_fields(Engine& e) {
  return {e.field("reference_position"), e.field("strain"), e.field("damage"), e.field("material")};
}

// The median engineering strain (from the Green-Lagrange E_xx) of the bar's particles between one
// support behind the incident fronts, at |x| = L / 2, and one support before the grips.
double plateau_strain(const BarFields& f, int bar, double support) {
  std::vector<double> e;
  for (std::size_t i = 0; i < f.material.size(); ++i) {
    const double x = std::fabs(f.x0[2 * i]);
    if (int(f.material[i]) == bar && x > kHalfLength / 2 + support && x < kHalfLength - support)
      e.push_back(std::sqrt(1 + 2 * f.strain[4 * i]) - 1);
  }
  if (e.empty()) return 0;
  std::nth_element(e.begin(), e.begin() + e.size() / 2, e.end());
  return e[e.size() / 2];
}

}  // namespace

SofteningBar run_softening_bar(const Case& c, const std::string& backend) {
  const Scene& sc = c.scene;
  const auto t0 = std::chrono::steady_clock::now();
  SofteningBar out;
  out.spacing = sc.options.spacing, out.support = sc.options.support_radius;
  int bar = -1;
  for (int m = 0; m < static_cast<int>(sc.materials.size()); ++m)
    if (sc.materials[m].name == "bar") {
      const Material& b = sc.materials[m].props;
      bar = m, out.wave_speed = std::sqrt(young_modulus<double>(b.bulk_modulus, b.shear_modulus) / b.rest_density);
    }
  out.pull_speed = std::fabs(sc.solid_loads.at(1).value[0]);
  const double L = out.half_length, t_plateau = L / (2 * out.wave_speed), t_band = 3 * L / (2 * out.wave_speed);
  auto engine = make_engine(sc, backend);
  out.particles = engine->particles();
  bool plateau_done = false;
  while (engine->time() < t_band) {
    engine->step(plateau_done ? t_band : t_plateau);
    if (!plateau_done && engine->time() >= t_plateau) {
      out.plateau_strain = plateau_strain(read_fields(*engine), bar, out.support);
      plateau_done = true;
    }
    if (out.onset_time >= 0) continue;
    const std::vector<double> d = engine->field("damage");
    const auto worst = std::max_element(d.begin(), d.end());
    if (*worst > kDamaged) {
      out.onset_time = engine->time();
      out.onset_position = std::fabs(engine->field("reference_position")[2 * (worst - d.begin())]);
    }
  }
  const BarFields f = read_fields(*engine);
  int damaged = 0, rows = 0;
  for (std::size_t i = 0; i < f.material.size(); ++i) {
    if (int(f.material[i]) != bar) continue;
    if (std::fabs(f.x0[2 * i]) < out.spacing / 2) ++rows;  // the centre column
    if (std::fabs(f.x0[2 * i]) < L / 2 && f.damage[i] > kDamaged) ++damaged;
    out.peak_damage = std::max(out.peak_damage, f.damage[i]);
  }
  out.band_width = rows > 0 ? damaged * out.spacing / rows : 0;
  out.steps = engine->steps();
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

}  // namespace psph
