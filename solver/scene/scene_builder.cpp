#include "scene/scene_builder.hpp"

#include <algorithm>
#include <cmath>
#include <random>

#include "engine/rigid_scene.hpp"
#include "scene/case_reader.hpp"
#include "scene/concentric_layout.hpp"

namespace psph {
namespace {

template <int D>
double lattice_sum(KernelType type, double support, double spacing) {
  return Kernel<D>::make(type, Real(support)).lattice_sum(spacing);
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

namespace {

// What the builder knows while it places particles.
class Builder {
 public:
  explicit Builder(Case& c)
      : c_(c), sc_(c.scene), D_(c.scene.dimension), dx_(c.scene.options.spacing),
        n_sum_(lattice_kernel_sum(D_, sc_.options.kernel, sc_.options.support_radius, dx_)),
        jitter_(-sc_.options.jitter * dx_, sc_.options.jitter * dx_) {
    sc_.x.clear(), sc_.v.clear(), sc_.mass.clear(), sc_.material.clear(), sc_.body.clear();
    sc_.body_angular_velocity.clear();
    // Each geometry of a rigid material is one body.
    body_of_geometry_.assign(c.geometry.size(), -1);
    for (std::size_t g = 0; g < c.geometry.size(); ++g) {
      const int m = c.geometry[g].material;
      if (m >= 0 && sc_.materials[m].props.kind == MaterialKind::Rigid) {
        body_of_geometry_[g] = static_cast<int>(sc_.body_angular_velocity.size());
        sc_.body_angular_velocity.push_back(c.geometry[g].angular_velocity);
      }
    }
    body_count_.assign(sc_.body_angular_velocity.size(), 0);
    for (const GeometryShape& g : c.geometry) {
      Bounds b = g.shape->bounds();
      for (int k = 0; k < D_; ++k) {  // a margin: a shape's bounds need not hold its surface exactly
        const double m = 1e-9 * (std::fabs(b.lower[k]) + std::fabs(b.upper[k])) + 1e-12;
        b.lower[k] -= m, b.upper[k] += m;
      }
      box_.push_back(b);
    }
  }

  // The last geometry holding x owns it (-1: none). The bounding boxes first: an image's
  // inclusions are many small shapes.
  int owner_of(const double* x) const {
    for (std::size_t g = c_.geometry.size(); g-- > 0;)
      if (box_[g].contains(x) && c_.geometry[g].shape->contains(x)) return static_cast<int>(g);
    return -1;
  }

  // A particle of geometry g at x standing for `volume` (a lattice site: dx^D).
  void add(const double* x, int g, double volume) {
    const GeometryShape& owner = c_.geometry[g];
    const SceneMaterial& m = sc_.materials[owner.material];
    const bool is_fluid = m.props.kind == MaterialKind::Fluid;
    for (int k = 0; k < D_; ++k) {
      double xk = x[k] + (is_fluid && sc_.options.jitter > 0 ? jitter_(rng_) : 0.0);
      const double L = sc_.upper[k] - sc_.lower[k];
      if (sc_.periodic[k]) xk = xk < sc_.lower[k] ? xk + L : xk >= sc_.upper[k] ? xk - L : xk;
      sc_.x.push_back(xk), sc_.v.push_back(owner.velocity[k]);
    }
    // The lattice's mass (its summed density is the rest density) in proportion to the volume.
    sc_.mass.push_back(m.props.rest_density / n_sum_ * volume / std::pow(dx_, D_));
    sc_.material.push_back(owner.material);
    const int b = body_of_geometry_[g];
    sc_.body.push_back(b);
    if (b >= 0) ++body_count_[b];
    if (m.props.kind != MaterialKind::Wall) ++moving_;
  }

  int body_of(std::size_t g) const { return body_of_geometry_[g]; }
  long body_count(int b) const { return body_count_[b]; }
  long moving() const { return moving_; }

 private:
  Case& c_;
  Scene& sc_;
  const int D_;
  const double dx_, n_sum_;
  std::vector<int> body_of_geometry_;
  std::vector<long> body_count_;
  std::vector<Bounds> box_;  // each geometry's bounding box
  long moving_ = 0;  // fluid, elastic and rigid particles: what the forces move
  std::mt19937_64 rng_{12345};  // fixed seed: the same disorder on every run
  std::uniform_real_distribution<double> jitter_;
};

std::string geometry_name(const Case& c, std::size_t g) {
  return c.geometry[g].name.empty() ? "geometry[" + std::to_string(g) + "]" : c.geometry[g].name;
}

// In double: the product of counts overflows an integer before it is checked.
double lattice_sites(const Scene& sc) {
  double sites = 1;
  for (int k = 0; k < sc.dimension; ++k) sites *= std::floor((sc.upper[k] - sc.lower[k]) / sc.options.spacing + 1e-6);
  return sites;
}

bool in_part(const Bounds& part, const double* x, int dimension) {
  for (int k = 0; k < dimension; ++k)
    if (x[k] < part.lower[k] || x[k] >= part.upper[k]) return false;
  return true;
}

// The domain's lattice sites in `part`, each given to the last shape containing it.
void place_lattice(Case& c, Builder& b, const Bounds& part) {
  const Scene& sc = c.scene;
  const int D = sc.dimension;
  const double dx = sc.options.spacing;
  // The sites' index range around the part (one site wider: in_part below decides).
  int lo[3] = {0, 0, 0}, hi[3] = {1, 1, 1};
  const double sites = lattice_sites(sc);
  if (!(sites <= kMaxParticles))
    throw CaseError(c.file + ": discretisation.spacing: the domain holds " + CaseReader::fmt(sites) +
                    " lattice sites; expected at most 4e8 (at ~0.5 kB a particle, " + CaseReader::fmt(sites * 5e-7) +
                    " GB)");
  for (int k = 0; k < D; ++k) {
    const int n = static_cast<int>(std::floor((sc.upper[k] - sc.lower[k]) / dx + 1e-6));
    lo[k] = std::clamp(static_cast<int>(std::floor((part.lower[k] - sc.lower[k]) / dx - 0.5)), 0, n);
    hi[k] = std::clamp(static_cast<int>(std::ceil((part.upper[k] - sc.lower[k]) / dx - 0.5)) + 1, lo[k], n);
  }
  for (int k = 0; k < D; ++k)
    if (hi[k] == lo[k]) return;
  int idx[3] = {lo[0], lo[1], lo[2]};
  for (;;) {
    double x[3];
    for (int k = 0; k < D; ++k) x[k] = sc.lower[k] + (idx[k] + 0.5) * dx;
    const int g = in_part(part, x, D) ? b.owner_of(x) : -1;
    if (g >= 0 && c.geometry[g].material >= 0 && !c.geometry[g].shape->places_points()) b.add(x, g, std::pow(dx, D));
    int d = 0;
    while (d < D && ++idx[d] >= hi[d]) idx[d] = lo[d], ++d;
    if (d == D) break;
  }
}

// Shapes with their own layout place their points, kept where no later geometry (nor the
// domain's edge) takes them.
void place_own_points(Case& c, Builder& b, const Bounds& part) {
  const Scene& sc = c.scene;
  for (std::size_t g = 0; g < c.geometry.size(); ++g) {
    const GeometryShape& gs = c.geometry[g];
    if (!gs.shape->places_points() || gs.material < 0) continue;
    for (const LayoutPoint& p : gs.shape->points(sc.options.spacing)) {
      bool inside = true;
      for (int k = 0; k < sc.dimension; ++k) {
        inside = inside && p.x[k] >= sc.lower[k] && p.x[k] < sc.upper[k];
        // Across a periodic seam its shells would land on lattice sites the other side owns.
        if (sc.periodic[k] && !inside)
          throw CaseError(c.file + ": " + geometry_name(c, g) + ": a concentric sphere must lie inside the "
                          "domain along its periodic axes; expected a centre and radius that keep it off the seam");
      }
      if (inside && in_part(part, p.x.data(), sc.dimension) && b.owner_of(p.x.data()) == static_cast<int>(g))
        b.add(p.x.data(), static_cast<int>(g), p.volume);
    }
  }
}

// Every rigid body holds particles and can turn: in 2D a moment of inertia about z, in 3D a
// regular inertia tensor (not a single particle, not a line of them).
void check_rigid_bodies(const Case& c, const Builder& b) {
  const Scene& sc = c.scene;
  const int D = sc.dimension;
  const double dx = sc.options.spacing;
  for (std::size_t g = 0; g < c.geometry.size(); ++g)
    if (b.body_of(g) >= 0 && b.body_count(b.body_of(g)) == 0)
      throw CaseError(c.file + ": " + geometry_name(c, g) +
                      ": this rigid body holds no particle (later geometries cover it, or it is smaller than a spacing)");
  const SceneRigidBodies rb = rigid_bodies_of(sc);
  for (std::size_t g = 0; g < c.geometry.size(); ++g) {
    const int body = b.body_of(g);
    if (body < 0 || D == 1) continue;
    const Mat3d& I = rb.state[body].inertia0;
    const double det = I[0] * (I[4] * I[8] - I[5] * I[7]) - I[1] * (I[3] * I[8] - I[5] * I[6]) + I[2] * (I[3] * I[7] - I[4] * I[6]);
    const double scale = rb.state[body].mass * dx * dx;
    if (D == 2 ? !(I[8] > 1e-9 * scale) : !(det > 1e-9 * scale * scale * scale))
      throw CaseError(c.file + ": " + geometry_name(c, g) + ": this rigid body's " +
                      std::to_string(b.body_count(body)) + " particles " +
                      (D == 2 ? "have no moment of inertia" : "lie on a line") + "; expected a body at least two spacings across");
  }
}

bool has_rigid_geometry(const Case& c) {
  for (const auto& g : c.geometry)
    if (g.material >= 0 && c.scene.materials[g.material].props.kind == MaterialKind::Rigid) return true;
  return false;
}

// Each [[solid_load]] takes the particles of its material inside its box (`check`: some).
void assign_solid_loads(Case& c, bool check) {
  Scene& sc = c.scene;
  const int D = sc.dimension;
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
    if (check && taken == 0)
      throw CaseError(c.file + ": solid_load[" + std::to_string(l) + "]: the box holds no particle of its material");
  }
}

}  // namespace

double particle_work_estimate(const Case& c) {
  double points = lattice_sites(c.scene);
  for (const auto& g : c.geometry) points += g.shape->point_estimate(c.scene.options.spacing);
  return points;
}

Bounds domain_bounds(const Scene& sc) { return Bounds{sc.dimension, sc.lower, sc.upper}; }

void build_particles(Case& c) { build_particles(c, domain_bounds(c.scene)); }

void build_particles(Case& c, const Bounds& part) {
  const Scene& sc = c.scene;
  bool whole = true;
  for (int k = 0; k < sc.dimension; ++k) whole &= part.lower[k] <= sc.lower[k] && part.upper[k] >= sc.upper[k];
  // A share's rigid bodies need the other shares' particles (mass, centre, inertia), and the
  // disorder is drawn in lattice order from the first site: neither is built by parts yet.
  if (!whole && (sc.options.jitter > 0 || has_rigid_geometry(c)))
    throw std::invalid_argument(c.file + ": a share of the domain is built only for cases without rigid bodies and "
                                "without discretisation.jitter");
  Builder b(c);
  place_lattice(c, b, part);
  place_own_points(c, b, part);
  assign_solid_loads(c, whole);
  if (!whole) return;  // the checks below are over the whole case
  check_rigid_bodies(c, b);
  add_rigid_rotation(c.scene);
  if (b.moving() == 0)
    throw CaseError(c.file + ": geometry: the geometry yields no fluid, elastic or rigid particles (" +
                    std::to_string(c.scene.material.size()) + " particles in all); check the shapes and the domain");
}

}  // namespace psph
