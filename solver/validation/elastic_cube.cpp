#include "validation/elastic_cube.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "engine/engine.hpp"
#include "scene/embedded_cases.hpp"
#include "scene/scene_builder.hpp"

namespace psph {

constexpr const char* kFile = "cases/elastic_cube_3d.toml";

Case elastic_cube_case(double spacing, SolidCoupling coupling, double background_pressure, SolidModel model) {
  toml::table tbl = toml::parse(embedded_case_text("elastic_cube_3d"), std::string_view(kFile));
  if (spacing > 0) set_case_spacing(tbl, spacing);  // the same box and cube, more particles
  if (coupling != SolidCoupling::Traction)
    tbl["solid"].as_table()->insert_or_assign("coupling", coupling == SolidCoupling::Pair ? "pair" : "pair_eos");
  if (background_pressure > 0) tbl["solver"].as_table()->insert_or_assign("background_pressure", background_pressure);
  if (model == SolidModel::SaintVenantKirchhoff) tbl["solid"].as_table()->insert_or_assign("model", "saint_venant_kirchhoff");
  Case c = parse_case(tbl, kFile);
  build_particles(c);
  return c;
}

CubeCompression run_elastic_cube(const Case& c, const std::string& backend) {
  const Scene& sc = c.scene;
  const int D = sc.dimension;
  const Material* solid = nullptr;
  for (const auto& m : sc.materials)
    if (m.props.kind == MaterialKind::Elastic) solid = &m.props;
  if (!solid) throw std::logic_error("elastic cube without an elastic material");
  CubeCompression out;
  out.bulk_modulus_exact = solid->bulk_modulus;
  // The cube's box and centre from its particles.
  std::vector<double> lo(D, 1e300), hi(D, -1e300);
  for (int i = 0; i < sc.count(); ++i)
    if (sc.materials[sc.material[i]].props.kind == MaterialKind::Elastic)
      for (int k = 0; k < D; ++k) lo[k] = std::min(lo[k], sc.x[i * D + k]), hi[k] = std::max(hi[k], sc.x[i * D + k]);

  const auto t0 = std::chrono::steady_clock::now();
  auto engine = make_engine(sc, backend);
  out.particles = engine->particles();
  engine->run_until(c.end_time);
  out.steps = engine->steps();
  const StepStats st = engine->stats();
  out.kinetic_energy = st.kinetic_energy, out.dissipated_energy = st.dissipated_energy;

  const std::vector<double> mat = engine->field("material"), x = engine->field("position");
  const std::vector<double> x0 = engine->field("reference_position"), u = engine->field("displacement");
  const std::vector<double> p = engine->field("pressure");
  double num = 0, den = 0, num_in = 0, den_in = 0, psum = 0, pmin = 1e300, pmax = -1e300;
  int fluid = 0;
  const double away = sc.options.support_radius;
  for (int i = 0; i < engine->particles(); ++i) {
    if (sc.materials[static_cast<int>(mat[i])].props.kind == MaterialKind::Elastic) {
      double depth = 1e300;  // from the cube's surface
      for (int k = 0; k < D; ++k) depth = std::min(depth, std::min(x0[i * D + k] - lo[k], hi[k] - x0[i * D + k]));
      for (int k = 0; k < D; ++k) {
        const double r = x0[i * D + k] - 0.5 * (lo[k] + hi[k]), ur = u[i * D + k] * r;
        num += ur, den += r * r;
        if (depth >= away) num_in += ur, den_in += r * r;
      }
      continue;
    }
    double gap = 0;  // distance from the cube's box
    for (int k = 0; k < D; ++k) gap = std::max(gap, std::max(lo[k] - x[i * D + k], x[i * D + k] - hi[k]));
    if (gap <= away) continue;
    psum += p[i], ++fluid;
    pmin = std::min(pmin, p[i]), pmax = std::max(pmax, p[i]);
  }
  if (fluid == 0 || den == 0) throw std::logic_error("elastic cube: no fluid away from the cube, or no cube");
  out.pressure = psum / fluid;
  out.pressure_spread = (pmax - pmin) / out.pressure;
  out.volume_strain = D * num / den;
  out.bulk_modulus = -out.pressure / out.volume_strain;
  if (den_in > 0) {
    out.volume_strain_interior = D * num_in / den_in;
    out.bulk_modulus_interior = -out.pressure / out.volume_strain_interior;
  }
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

}  // namespace psph
