#include "validation/lame_cylinder.hpp"

#include <chrono>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "engine/engine.hpp"
#include "scene/embedded_cases.hpp"
#include "scene/scene_builder.hpp"

namespace psph {

namespace {
constexpr const char* kFile = "cases/lame_cylinder_2d.toml";
}

Case lame_cylinder_case(double spacing) {
  toml::table tbl = toml::parse(embedded_case_text("lame_cylinder_2d"), std::string_view(kFile));
  if (spacing > 0) set_case_spacing(tbl, spacing);
  Case c = parse_case(tbl, kFile);
  build_particles(c);
  return c;
}

LameComparison run_lame_cylinder(const Case& c, const std::string& backend) {
  const Scene& sc = c.scene;
  if (sc.dimension != 2) throw std::logic_error("the Lame cylinder is a 2D case");
  const double dx = sc.options.spacing, R = sc.options.support_radius;
  auto kind = [&](int m) { return sc.materials[m].props.kind; };
  // Areas from the particles' volumes (scene/scene_builder.hpp): V = m n_sum dx^2 / rho0.
  const double n_sum = lattice_kernel_sum(2, sc.options.kernel, R, dx);
  double fluid_area = 0, solid_area = 0;
  for (int i = 0; i < sc.count(); ++i) {
    const int m = sc.material[i];
    const double V = sc.mass[i] * n_sum * dx * dx / sc.materials[m].props.rest_density;
    fluid_area += kind(m) == MaterialKind::Fluid ? V : 0, solid_area += kind(m) == MaterialKind::Elastic ? V : 0;
  }
  LameComparison out;
  out.inner = std::sqrt(fluid_area / M_PI);
  out.outer = std::sqrt((fluid_area + solid_area) / M_PI);
  const double a = out.inner, b = out.outer;

  const auto t0 = std::chrono::steady_clock::now();
  auto engine = make_engine(sc, backend);
  out.particles = engine->particles();
  engine->run_until(c.end_time);
  out.steps = engine->steps();
  out.kinetic_energy = engine->stats().kinetic_energy;
  const std::vector<double> mat = engine->field("material"), x0 = engine->field("reference_position");
  const std::vector<double> p = engine->field("pressure"), s = engine->field("stress");
  double psum = 0;
  int nf = 0;
  for (int i = 0; i < engine->particles(); ++i)
    if (kind(static_cast<int>(mat[i])) == MaterialKind::Fluid && std::hypot(x0[2 * i], x0[2 * i + 1]) < a - R)
      psum += p[i], ++nf;
  if (nf == 0) throw std::logic_error("Lame cylinder: no fluid a support away from the wall");
  out.pressure = psum / nf;
  const double A = out.pressure * a * a / (b * b - a * a), B = A * b * b;
  double srr2 = 0, stt2 = 0;
  for (int i = 0; i < engine->particles(); ++i) {
    if (kind(static_cast<int>(mat[i])) != MaterialKind::Elastic) continue;
    const double x = x0[2 * i], y = x0[2 * i + 1], r = std::hypot(x, y);
    if (r < a + R || r > b - R) continue;
    const double c_ = x / r, s_ = y / r;
    const double sxx = s[4 * i], sxy = s[4 * i + 1], syy = s[4 * i + 3];
    const double srr = c_ * c_ * sxx + 2 * c_ * s_ * sxy + s_ * s_ * syy;
    const double stt = s_ * s_ * sxx - 2 * c_ * s_ * sxy + c_ * c_ * syy;
    const double err_r = std::fabs(srr - (A - B / (r * r))) / out.pressure;
    const double err_t = std::fabs(stt - (A + B / (r * r))) / out.pressure;
    out.radial_error = std::max(out.radial_error, err_r), out.hoop_error = std::max(out.hoop_error, err_t);
    srr2 += err_r * err_r, stt2 += err_t * err_t, ++out.compared;
  }
  if (out.compared == 0) throw std::logic_error("Lame cylinder: no solid particle a support from both surfaces");
  out.radial_rms = std::sqrt(srr2 / out.compared), out.hoop_rms = std::sqrt(stt2 / out.compared);
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

}  // namespace psph
