#include "scene/scene_builder.hpp"

#include <cmath>
#include <random>

#include "rigid/rigid_scene.hpp"
#include "scene/concentric_layout.hpp"

namespace psph {
namespace {

bool contains(const GeometryShape& s, const double* x, int D) {
  if (s.kind == GeometryShape::Kind::GrainPack) return in_grain_pack(s.pack, s.grains, x, D);
  if (s.kind == GeometryShape::Kind::Box) {
    for (int k = 0; k < D; ++k)
      if (x[k] < s.lower[k] || x[k] > s.upper[k]) return false;
    return true;
  }
  double r2 = 0;
  for (int k = 0; k < D; ++k) r2 += (x[k] - s.center[k]) * (x[k] - s.center[k]);
  return r2 <= s.radius * s.radius;
}

template <int D>
double lattice_sum(KernelType type, double support, double spacing) {
  const Kernel<D> k = Kernel<D>::make(type, Real(support));
  const int n = static_cast<int>(std::ceil(support / spacing));
  double sum = 0;
  int idx[3] = {-n, -n, -n};
  for (;;) {
    double r2 = 0;
    for (int d = 0; d < D; ++d) r2 += (idx[d] * spacing) * (idx[d] * spacing);
    sum += k.W(Real(std::sqrt(r2)));
    int d = 0;
    while (d < D && ++idx[d] > n) idx[d++] = -n;
    if (d == D) break;
  }
  return sum;
}

}  // namespace

double lattice_kernel_sum(int dimension, KernelType kernel, double support, double spacing) {
  switch (dimension) {
    case 1: return lattice_sum<1>(kernel, support, spacing);
    case 2: return lattice_sum<2>(kernel, support, spacing);
    default: return lattice_sum<3>(kernel, support, spacing);
  }
}

Scene shear_box_scene(const ShearBox& b) {
  const int D = b.dimension;
  const double dx = b.length / b.per_axis;
  Scene sc;
  sc.dimension = D;
  for (int k = 0; k < D; ++k) sc.lower[k] = 0, sc.upper[k] = b.length, sc.periodic[k] = true;
  SceneMaterial fluid;
  fluid.name = "fluid";
  fluid.props.kind = MaterialKind::Fluid;
  fluid.props.rest_density = Real(b.density);
  fluid.props.viscosity = Real(b.viscosity);
  fluid.props.sound_speed = Real(b.sound_speed);
  sc.materials.push_back(fluid);
  sc.options.spacing = dx;
  sc.options.support_radius = b.support_per_spacing * dx;
  const double mass = b.density / lattice_kernel_sum(D, sc.options.kernel, sc.options.support_radius, dx);
  long n = 1;
  for (int k = 0; k < D; ++k) n *= b.per_axis;
  sc.x.resize(n * D), sc.v.assign(n * D, 0.0), sc.mass.assign(n, mass), sc.material.assign(n, 0);
  for (long i = 0; i < n; ++i) {
    long r = i;
    for (int k = 0; k < D; ++k) {
      sc.x[i * D + k] = (r % b.per_axis + 0.5) * dx;
      r /= b.per_axis;
    }
    sc.v[i * D] = b.amplitude * std::sin(2 * M_PI * sc.x[i * D + (D > 1 ? 1 : 0)] / b.length);
  }
  return sc;
}

void build_particles(Case& c) {
  Scene& sc = c.scene;
  const int D = sc.dimension;
  const double dx = sc.options.spacing;
  int n[3] = {1, 1, 1};
  long total = 1;
  for (int k = 0; k < D; ++k) {
    n[k] = static_cast<int>(std::floor((sc.upper[k] - sc.lower[k]) / dx + 1e-6));
    total *= n[k];
  }
  if (total > 400'000'000L)
    throw CaseError(c.file + ": discretisation.spacing: the domain holds " + std::to_string(total) +
                    " lattice sites; expected at most 4e8");
  const double n_sum = lattice_kernel_sum(D, sc.options.kernel, sc.options.support_radius, dx);
  sc.x.clear(), sc.v.clear(), sc.mass.clear(), sc.material.clear(), sc.body.clear();
  sc.body_angular_velocity.clear();
  // Each geometry of a rigid material is one body.
  std::vector<int> body_of_geometry(c.geometry.size(), -1);
  for (std::size_t g = 0; g < c.geometry.size(); ++g) {
    const int m = c.geometry[g].material;
    if (m >= 0 && sc.materials[m].props.kind == MaterialKind::Rigid) {
      body_of_geometry[g] = static_cast<int>(sc.body_angular_velocity.size());
      sc.body_angular_velocity.push_back(c.geometry[g].angular_velocity);
    }
  }
  std::vector<long> body_count(sc.body_angular_velocity.size(), 0);
  long moving = 0;  // fluid, elastic and rigid particles: what the forces move
  int idx[3] = {0, 0, 0};
  std::mt19937_64 rng(12345);  // fixed seed: the same disorder on every run
  std::uniform_real_distribution<double> jitter(-sc.options.jitter * dx, sc.options.jitter * dx);
  // The last geometry holding x owns it (-1: none).
  auto owner_of = [&](const double* x) {
    int owner = -1;
    for (std::size_t g = 0; g < c.geometry.size(); ++g)
      if (contains(c.geometry[g], x, D)) owner = static_cast<int>(g);
    return owner;
  };
  // A particle of geometry g at x standing for `volume` (a lattice site: dx^D).
  auto add = [&](const double* x, int g, double volume) {
    const GeometryShape& owner = c.geometry[g];
    const SceneMaterial& m = sc.materials[owner.material];
    const bool is_fluid = m.props.kind == MaterialKind::Fluid;
    for (int k = 0; k < D; ++k) {
      double xk = x[k] + (is_fluid && sc.options.jitter > 0 ? jitter(rng) : 0.0);
      if (sc.periodic[k]) xk = xk < sc.lower[k] ? xk + (sc.upper[k] - sc.lower[k]) : xk >= sc.upper[k] ? xk - (sc.upper[k] - sc.lower[k]) : xk;
      sc.x.push_back(xk), sc.v.push_back(owner.velocity[k]);
    }
    // The lattice's mass (its summed density is the rest density) in proportion to the volume.
    sc.mass.push_back(m.props.rest_density / n_sum * volume / std::pow(dx, D));
    sc.material.push_back(owner.material);
    const int b = body_of_geometry[g];
    sc.body.push_back(b);
    if (b >= 0) ++body_count[b];
    if (m.props.kind != MaterialKind::Wall) ++moving;
  };
  for (long s = 0; s < total; ++s) {
    double x[3];
    for (int k = 0; k < D; ++k) x[k] = sc.lower[k] + (idx[k] + 0.5) * dx;
    const int g = owner_of(x);
    if (g >= 0 && c.geometry[g].material >= 0 && !c.geometry[g].concentric) add(x, g, std::pow(dx, D));
    int d = 0;
    while (d < D && ++idx[d] >= n[d]) idx[d++] = 0;
  }
  // Concentric spheres place their own points, kept where no later geometry (nor the domain's
  // edge) takes them.
  for (std::size_t g = 0; g < c.geometry.size(); ++g) {
    const GeometryShape& gs = c.geometry[g];
    if (!gs.concentric || gs.material < 0) continue;
    for (const LayoutPoint& p : concentric_points(gs.center, gs.radius, dx, D)) {
      bool inside = true;
      for (int k = 0; k < D; ++k) {
        inside = inside && p.x[k] >= sc.lower[k] && p.x[k] < sc.upper[k];
        // Across a periodic seam its shells would land on lattice sites the other side owns.
        if (sc.periodic[k] && !inside)
          throw CaseError(c.file + ": geometry[" + std::to_string(g) + "]: a concentric sphere must lie inside the "
                          "domain along its periodic axes; expected a centre and radius that keep it off the seam");
      }
      if (inside && owner_of(p.x.data()) == static_cast<int>(g)) add(p.x.data(), static_cast<int>(g), p.volume);
    }
  }
  for (std::size_t g = 0; g < c.geometry.size(); ++g)
    if (body_of_geometry[g] >= 0 && body_count[body_of_geometry[g]] == 0)
      throw CaseError(c.file + ": geometry[" + std::to_string(g) +
                      "]: this rigid body holds no particle (later geometries cover it, or it is smaller than a spacing)");
  // A body must be able to turn: in 2D a moment of inertia about z, in 3D a regular inertia tensor
  // (not a single particle, not a line of them).
  const SceneRigidBodies rb = rigid_bodies_of(sc);
  for (std::size_t g = 0; g < c.geometry.size(); ++g) {
    const int b = body_of_geometry[g];
    if (b < 0 || D == 1) continue;
    const Mat3d& I = rb.state[b].inertia0;
    const double det = I[0] * (I[4] * I[8] - I[5] * I[7]) - I[1] * (I[3] * I[8] - I[5] * I[6]) + I[2] * (I[3] * I[7] - I[4] * I[6]);
    const double scale = rb.state[b].mass * dx * dx;
    if (D == 2 ? !(I[8] > 1e-9 * scale) : !(det > 1e-9 * scale * scale * scale))
      throw CaseError(c.file + ": geometry[" + std::to_string(g) + "]: this rigid body's " +
                      std::to_string(body_count[b]) + " particles " + (D == 2 ? "have no moment of inertia" : "lie on a line") +
                      "; expected a body at least two spacings across");
  }
  add_rigid_rotation(sc);
  // Each [[solid_load]] takes the particles of its material inside its box.
  sc.load_mask.assign(sc.material.size(), 0);
  for (std::size_t l = 0; l < sc.solid_loads.size(); ++l) {
    const SceneSolidLoad& ld = sc.solid_loads[l];
    long taken = 0;
    for (int i = 0; i < sc.count(); ++i) {
      if (sc.material[i] != ld.material) continue;
      bool in = true;
      for (int k = 0; k < D; ++k) in = in && sc.x[i * D + k] >= ld.lower[k] && sc.x[i * D + k] <= ld.upper[k];
      if (in) sc.load_mask[i] |= 1 << l, ++taken;
    }
    if (taken == 0)
      throw CaseError(c.file + ": solid_load[" + std::to_string(l) + "]: the box holds no particle of its material");
  }
  if (moving == 0)
    throw CaseError(c.file + ": geometry: the geometry yields no fluid, elastic or rigid particles (" +
                    std::to_string(sc.material.size()) + " particles in all); check the shapes and the domain");
}

}  // namespace psph
