#include "validation/sessile_drop.hpp"

#include <chrono>
#include <cmath>

#include "engine/engine.hpp"
#include "scene/embedded_cases.hpp"
#include "scene/scene_builder.hpp"

namespace psph {

Case sessile_drop_case(double contact_angle_deg, double initial_angle_deg, double radius_spacings) {
  toml::table tbl = toml::parse(embedded_case_text("sessile_drop_2d"), std::string_view("cases/sessile_drop_2d.toml"));
  set_case_value(tbl, "materials.wall.contact_angle", toml::value<double>(contact_angle_deg));
  // A cap of angle a and radius R has the area R^2 (a - sin a cos a); the half-disc's is pi R0^2 / 2.
  const double a = initial_angle_deg * M_PI / 180, R0 = radius_spacings * 1e-4, wall = 6e-4;
  const double R = R0 * std::sqrt(M_PI / 2 / (a - std::sin(a) * std::cos(a)));
  auto& geometry = *tbl["geometry"].as_array();
  auto& drop = *geometry.at(1).as_table();
  drop.insert_or_assign("radius", R);
  drop.insert_or_assign("center", toml::array{3.2e-3, wall - R * std::cos(a)});
  Case c = parse_case(tbl, "cases/sessile_drop_2d.toml");
  build_particles(c);
  return c;
}

std::vector<double> fit_circle(const std::vector<double>& xy) {
  // Minimise sum (x^2 + y^2 + a x + b y + c)^2: 3x3 normal equations, solved by Cramer's rule
  // about the points' mean (for conditioning).
  const std::size_t n = xy.size() / 2;
  double mx = 0, my = 0;
  for (std::size_t i = 0; i < n; ++i) mx += xy[2 * i] / n, my += xy[2 * i + 1] / n;
  double M[3][3] = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}}, r[3] = {0, 0, 0};
  for (std::size_t i = 0; i < n; ++i) {
    const double x = xy[2 * i] - mx, y = xy[2 * i + 1] - my, z = -(x * x + y * y);
    const double row[3] = {x, y, 1};
    for (int a = 0; a < 3; ++a) {
      r[a] += row[a] * z;
      for (int b = 0; b < 3; ++b) M[a][b] += row[a] * row[b];
    }
  }
  auto det = [](double A[3][3]) {
    return A[0][0] * (A[1][1] * A[2][2] - A[1][2] * A[2][1]) - A[0][1] * (A[1][0] * A[2][2] - A[1][2] * A[2][0]) +
           A[0][2] * (A[1][0] * A[2][1] - A[1][1] * A[2][0]);
  };
  const double d = det(M);
  double sol[3];
  for (int k = 0; k < 3; ++k) {
    double A[3][3];
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) A[a][b] = b == k ? r[a] : M[a][b];
    sol[k] = det(A) / d;
  }
  const double cx = -sol[0] / 2, cy = -sol[1] / 2;
  return {cx + mx, cy + my, std::sqrt(cx * cx + cy * cy - sol[2])};
}

ContactAngle measure_contact_angle(const Case& c, const std::string& backend) {
  const Scene& sc = c.scene;
  const int D = sc.dimension;
  const auto t0 = std::chrono::steady_clock::now();
  auto engine = make_engine(sc, backend);
  ContactAngle out;
  out.particles = engine->particles();
  out.capillary_speed = capillary_speed(sc);
  const double support = sc.options.support_radius;
  const int samples = 10;
  for (int k = 0; k <= samples; ++k) {
    engine->run_until(c.end_time * (0.8 + 0.2 * k / samples));
    const std::vector<double> x = engine->field("position"), colour = engine->field("colour");
    const std::vector<double> mat = engine->field("material"), v = engine->field("velocity");
    // The wall plane: half a spacing above the top wall layer.
    double wall = -1e300;
    for (int i = 0; i < engine->particles(); ++i)
      if (sc.materials[static_cast<int>(mat[i])].props.kind == MaterialKind::Wall) wall = std::max(wall, x[i * D + 1]);
    wall += 0.5 * sc.options.spacing;
    // The interface band (|c| < 1/2) clear of the wall's influence.
    std::vector<double> band;
    double speed = 0;
    for (int i = 0; i < engine->particles(); ++i) {
      if (sc.materials[static_cast<int>(mat[i])].props.kind != MaterialKind::Fluid) continue;
      speed = std::max(speed, std::hypot(v[i * D], v[i * D + 1]));
      if (std::fabs(colour[i]) < 0.5 && x[i * D + 1] > wall + support) band.push_back(x[i * D]), band.push_back(x[i * D + 1]);
    }
    const std::vector<double> circle = fit_circle(band);
    // cos(theta) = (y_wall - y_centre) / R, theta through the liquid inside the circle.
    const double cos_theta = std::clamp((wall - circle[1]) / circle[2], -1.0, 1.0);
    out.angle += std::acos(cos_theta) * 180 / M_PI / (samples + 1);
    out.radius += circle[2] / (samples + 1);
    out.spurious_speed = speed;
  }
  out.steps = engine->steps();
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

}  // namespace psph
