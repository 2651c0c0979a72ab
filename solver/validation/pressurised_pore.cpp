#include "validation/pressurised_pore.hpp"

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

constexpr const char* kFile = "cases/pressurised_pore_2d.toml";
constexpr double kHalfSide = 0.03;      // the block's half side (m), the case's
constexpr double kHalfLength = 0.01225;  // the lens' centre-to-tip distance (m), the case's
constexpr double kMargin = 0.005;       // domain room around the block (m)
constexpr double kLook = 5e3;           // Pa of pressure rise between looks

// The four faces' outermost layers, in the case's order (left, right, bottom, top), and the
// traction each carries: t = -sigma n_out.
void set_confinement(toml::table& tbl, double sigma, double s) {
  const double L = kHalfSide, lo = -L - s / 2, hi = L + s / 2;
  toml::array& loads = *tbl["solid_load"].as_array();
  const double faces[4][4] = {{lo, lo, lo + s, hi}, {hi - s, lo, hi, hi}, {lo, lo, hi, lo + s}, {lo, hi - s, hi, hi}};
  const double traction[4][2] = {{sigma, 0}, {-sigma, 0}, {0, sigma}, {0, -sigma}};
  for (int f = 0; f < 4; ++f) {
    toml::table& t = *loads[f].as_table();
    t.insert_or_assign("lower", pair_of(faces[f][0], faces[f][1]));
    t.insert_or_assign("upper", pair_of(faces[f][2], faces[f][3]));
    t.insert_or_assign("traction", pair_of(traction[f][0], traction[f][1]));
  }
}

}  // namespace

Case pressurised_pore_case(double confinement, double spacing) {
  toml::table tbl = toml::parse(embedded_case_text("pressurised_pore_2d"), std::string_view(kFile));
  const double s = spacing, L = kHalfSide;
  set_case_spacing(tbl, s);
  tbl["domain"].as_table()->insert_or_assign("lower", pair_of(lattice_aligned(-L - kMargin, s), lattice_aligned(-L - kMargin, s)));
  tbl["domain"].as_table()->insert_or_assign("upper", pair_of(lattice_aligned(L + kMargin, s), lattice_aligned(L + kMargin, s)));
  toml::table& block = *tbl["geometry"].as_array()->at(0).as_table();
  block.insert_or_assign("lower", pair_of(-L - s / 2, -L - s / 2));
  block.insert_or_assign("upper", pair_of(L + s / 2, L + s / 2));
  set_confinement(tbl, confinement, s);
  Case c = parse_case(tbl, kFile);
  build_particles(c);
  return c;
}

namespace {

// What one look sees: the most damaged clay particle, the mean pore pressure, whether each tip
// has damage within a support.
struct PoreLook {
  int first = -1;
  double pressure = 0, compressive = 0;
  bool left = false, right = false;
};

PoreLook look_at(Engine& e, const Scene& sc) {
  auto is = [&](double m, MaterialKind k) { return sc.materials[int(m)].props.kind == k; };
  const double support = sc.options.support_radius;
  const std::vector<double> d = e.field("damage"), mat = e.field("material"), x0 = e.field("reference_position");
  const std::vector<double> p = e.field("pressure"), dc = e.field("compressive_damage");
  PoreLook l;
  int fluid = 0;
  for (std::size_t i = 0; i < d.size(); ++i) {
    if (is(mat[i], MaterialKind::Fluid)) l.pressure += p[i], ++fluid;
    if (!is(mat[i], MaterialKind::Elastic)) continue;
    l.compressive = std::max(l.compressive, dc[i]);
    if (d[i] <= kDamaged) continue;
    if (l.first < 0 || d[i] > d[l.first]) l.first = int(i);
    l.left |= std::hypot(x0[2 * i] + kHalfLength, x0[2 * i + 1]) <= support;
    l.right |= std::hypot(x0[2 * i] - kHalfLength, x0[2 * i + 1]) <= support;
  }
  l.pressure /= std::max(fluid, 1);
  return l;
}

}  // namespace

PoreDamage run_pressurised_pore(const Case& c, const std::string& backend) {
  const auto t0 = std::chrono::steady_clock::now();
  const Scene& sc = c.scene;
  auto engine = make_engine(sc, backend);
  PoreDamage out;
  out.particles = engine->particles();
  const double every = kLook / sc.options.background_pressure_rate;  // s between looks
  for (double t = every; t <= c.end_time + 1e-12 && out.other_tip_pressure < 0; t += every) {
    engine->run_until(std::min(t, c.end_time));
    const PoreLook l = look_at(*engine, sc);
    if (l.first < 0) {  // the damage, once it starts, turns elastic energy into kinetic: not loading
      const StepStats st = engine->stats();
      out.kinetic_over_elastic = st.elastic_energy > 0 ? st.kinetic_energy / st.elastic_energy : 0;
      continue;
    }
    if (out.onset_pressure < 0) {
      const std::vector<double> x0 = engine->field("reference_position");
      out.onset_pressure = l.pressure, out.compressive = l.compressive;
      out.onset_x = x0[2 * l.first], out.onset_y = x0[2 * l.first + 1];
      out.tip_distance = std::hypot(std::fabs(out.onset_x) - kHalfLength, out.onset_y);
    }
    if (l.left && l.right) out.other_tip_pressure = l.pressure;
  }
  out.steps = engine->steps();
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

}  // namespace psph
