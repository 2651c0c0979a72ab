#pragma once
// Particle state as a structure of arrays in a backend's memory, with every array registered by
// name. `ParticleView` is the raw-pointer view the passes receive by value.
#include <algorithm>
#include <cstdint>
#include <type_traits>
#include <vector>

#include "backend/device_array.hpp"
#include "core/damage_ghost.hpp"
#include "core/vec.hpp"
#include "state/fields.hpp"

namespace psph {

template <int D>
struct ParticleView {
  int n = 0;
  Point<D>* x = nullptr;        // position
  Vec<D>* v = nullptr;          // velocity (prescribed for walls)
  Vec<D>* a = nullptr;          // acceleration
  Vec<D>* v_xsph = nullptr;     // XSPH correction added to the drift velocity
  Vec<D>* v_noslip = nullptr;   // walls: velocity seen by the viscous term (no-slip extrapolation)
  Vec<D>* lap_v = nullptr;      // fluids: Laplacian of the velocity from the last force pass
  Real* rho = nullptr;          // density
  Real* drho = nullptr;         // d rho / dt (continuity)
  Real* p = nullptr;            // pressure
  Real* m = nullptr;            // mass
  Real* rho0 = nullptr;         // per-particle reference density of the EOS
  Real* number_density = nullptr;  // sum_j W_ij (for eq. 41)
  std::uint8_t* material = nullptr;
  std::int32_t* id = nullptr;   // particle id at creation, to follow particles across reorderings
  const std::uint8_t* near_fluid = nullptr;  // 1 where a fluid particle may be within the support (neighbours/)
  // Two-fluid cases only (null otherwise): interface/surface_tension.hpp.
  Real* colour = nullptr;             // smoothed colour c (eq. 58)
  Vec<D>* colour_gradient = nullptr;  // n = grad c (eq. 59a)
  Real* curvature = nullptr;          // kappa = -div n^ (eqs. 7, 60)
  // Elastic solids only (null otherwise): solid/elastic_force.hpp.
  Point<D>* x0 = nullptr;  // reference (initial) position
  Point<D>* u = nullptr;   // displacement x - x0
  Mat<D>* strain = nullptr;  // small strain (solid/strain.hpp)
  Mat<D>* stress = nullptr;  // Cauchy stress
  Real* shepard = nullptr;   // the gradient correction S_i, G_i, K_i of the strain pass (solid/strain.hpp)
  Vec<D>* shepard_grad = nullptr;
  Mat<D>* kcorr = nullptr;
  Mat<D>* grad_u = nullptr;  // grad u of the strain pass, for the hourglass control only (solid/hourglass.hpp)
  std::int32_t* mirror = nullptr;       // clamps: id of the mirror partner, -1 if none (engine/clamp_partners.hpp)
  std::int32_t* index_of_id = nullptr;  // current index of each id (clamps, rigid bodies)
  // Fluids with elastic solids only (null otherwise): solid/fluid_coupling.hpp.
  Real* visc_scale = nullptr;  // a fluid particle's Laplacian correction D / lambda of the last force pass
  std::uint8_t* fluid_contact = nullptr;  // a solid particle with fluid within its support
  Real* p_ambient = nullptr;              // the fluid's pressure carried into an elastic body's surface layer
  // Rigid bodies only (null otherwise): rigid/.
  std::int32_t* body = nullptr;  // the rigid body a particle belongs to, -1 if none
  // Large-strain solids only (null otherwise): solid/constitutive.hpp.
  Mat<D>* piola = nullptr;    // first Piola-Kirchhoff stress P = F S
  Mat<D>* defgrad = nullptr;  // deformation gradient F
  // Loaded elastic particles only (null otherwise): solid/solid_load.hpp.
  std::int32_t* load_mask = nullptr;  // the [[solid_load]]s a particle belongs to, bit g for load g
  // Damage with ghosts only (null otherwise): damage/damage_stage.hpp.
  std::uint8_t* ghost = nullptr;  // kGhostPending, kGhostRetired (core/damage_ghost.hpp), or 0
};

template <class T, class B>
struct Gather {
  T* out;
  const T* in;
  const int* perm;
  PSPH_HD void operator()(int i) const { out[i] = in[perm[i]]; }
};

// The same for rows of `width` values per particle: out row i <- in row perm[i].
template <class T>
struct GatherRows {
  T* out;
  const T* in;
  const int* perm;
  int width;
  PSPH_HD void operator()(int i) const {
    const std::size_t to = std::size_t(i) * width, from = std::size_t(perm[i]) * width;
    for (int k = 0; k < width; ++k) out[to + k] = in[from + k];
  }
};
// The inverse: row i of `in` to row index[i] of `out`.
template <class T>
struct ScatterRows {
  T* out;
  const T* in;
  const int* index;
  int width;
  PSPH_HD void operator()(int i) const {
    const std::size_t to = std::size_t(index[i]) * width, from = std::size_t(i) * width;
    for (int k = 0; k < width; ++k) out[to + k] = in[from + k];
  }
};

// index_of_id[id] = -1: no particle with that id here (a run shared out over processes holds
// some of them), before IndexOfIdPass.
struct ClearIndexOfId {
  std::int32_t* index;
  PSPH_HD void operator()(int k) const { index[k] = -1; }
};
// index_of_id[id[i]] = i, after every reordering (ids are unique: no write conflicts).
template <int D>
struct IndexOfIdPass {
  ParticleView<D> s;
  PSPH_HD void operator()(int i) const { s.index_of_id[s.id[i]] = i; }
};

template <int D, class B>
class ParticleState {
 public:
  ParticleState() { register_all(); }
  ParticleState(const ParticleState&) = delete;
  ParticleState& operator=(const ParticleState&) = delete;

  int size() const { return n_; }
  const FieldRegistry& fields() const { return registry_; }

  void resize(int n) {
    n_ = n;
    x.resize(n), v.resize(n), a.resize(n), v_xsph.resize(n), v_noslip.resize(n), lap_v.resize(n);
    rho.resize(n), drho.resize(n), p.resize(n), m.resize(n), rho0.resize(n), number_density.resize(n);
    material.resize(n), id.resize(n), near_fluid.resize(n);
    a.zero(), v_xsph.zero(), v_noslip.zero(), lap_v.zero(), drho.zero(), p.zero(), number_density.zero();
  }

  // Every member by name: a positional aggregate would let a pointer placed out of order take a
  // neighbour's slot of the same type.
  ParticleView<D> view() {
    ParticleView<D> v;
    v.n = n_;
    v.x = x.data(), v.v = this->v.data(), v.a = a.data(), v.v_xsph = v_xsph.data();
    v.v_noslip = v_noslip.data(), v.lap_v = lap_v.data();
    v.rho = rho.data(), v.drho = drho.data(), v.p = p.data(), v.m = m.data(), v.rho0 = rho0.data();
    v.number_density = number_density.data();
    v.material = material.data(), v.id = id.data(), v.near_fluid = near_fluid.data();
    v.colour = colour.data(), v.colour_gradient = colour_gradient.data(), v.curvature = curvature.data();
    v.x0 = x0.data(), v.u = u.data(), v.strain = strain.data(), v.stress = stress.data();
    v.shepard = shepard.data(), v.shepard_grad = shepard_grad.data(), v.kcorr = kcorr.data();
    v.grad_u = grad_u.data();
    v.mirror = mirror.data(), v.index_of_id = index_of_id.data();
    v.visc_scale = visc_scale.data(), v.fluid_contact = fluid_contact.data(), v.p_ambient = p_ambient.data();
    v.body = body.data(), v.piola = piola.data(), v.defgrad = defgrad.data(), v.load_mask = load_mask.data();
    v.ghost = ghost.data();
    return v;
  }

  // Registers an allocated array under a name: checkpoints, reorderings and outputs then carry it.
  // The stages register the fields they own (fluid/, interface/, solid/, rigid/ *_stage.hpp).
  template <class T>
  void add_field(DeviceArray<T, B>& arr, int comps, const char* name, const char* unit, const char* what) {
    constexpr FieldType type = std::is_same_v<T, std::uint8_t> ? FieldType::Byte
                               : std::is_same_v<T, std::int32_t> ? FieldType::Int : FieldType::Real;
    reg(arr, type, comps, name, unit, what);
  }

  // Registers `width` integers per particle (a row each, width fixed for the run), carried whole
  // by reorderings, migrations and checkpoints like any field.
  void add_rows(DeviceArray<std::int32_t, B>& arr, int width, const char* name, const char* unit, const char* what) {
    FieldHandle h;
    h.info = FieldInfo{name, FieldType::Int, width, unit, what};
    h.permute = [this, &arr, width](const int* perm) {
      DeviceArray<std::int32_t, B>& tmp = scratch<std::int32_t>();
      tmp.resize(arr.size());
      B::for_each(static_cast<int>(arr.size() / std::size_t(width)), GatherRows<std::int32_t>{tmp.data(), arr.data(), perm, width});
      arr.swap(tmp);
    };
    h.to_host_double = [&arr](std::vector<double>& out) {
      const std::vector<std::int32_t> hv = arr.host();
      out.assign(hv.begin(), hv.end());
    };
    h.element_bytes = sizeof(std::int32_t) * std::size_t(width);
    raw_copies(h, arr, width);
    registry_.add(std::move(h));
  }

  // A new particle count (a process's share of a run changed: parallel/particle_domain.hpp): the
  // registered fields hold their new values already; the unregistered per-particle arrays in use
  // are resized, to be recomputed before they are read.
  void set_count(int n) {
    n_ = n;
    near_fluid.resize(n);
    auto fit = [n](auto&... arrays) { ((arrays.size() ? arrays.resize(n) : void()), ...); };
    fit(shepard, shepard_grad, kcorr, grad_u, piola, visc_scale, p_ambient, fluid_contact);
  }

  // Reorders every registered field: field[i] <- field[perm[i]].
  void permute(const int* perm) {
    for (const auto& f : registry_.all()) f.permute(perm);
  }

  DeviceArray<Point<D>, B> x;
  DeviceArray<Vec<D>, B> v, a, v_xsph, v_noslip, lap_v;
  DeviceArray<Real, B> rho, drho, p, m, rho0, number_density;
  DeviceArray<std::uint8_t, B> material;
  DeviceArray<std::int32_t, B> id;
  DeviceArray<std::uint8_t, B> near_fluid;  // not registered: recomputed after every reordering
  // Empty unless a stage allocates them: the interface stage's,
  DeviceArray<Real, B> colour, curvature;
  DeviceArray<Vec<D>, B> colour_gradient;
  // the elastic stage's (solid/elastic_stage.hpp),
  DeviceArray<Point<D>, B> x0, u;
  DeviceArray<Mat<D>, B> strain, stress;
  DeviceArray<Real, B> shepard;  // the strain pass's correction (each step, or kept from the list build): not registered
  DeviceArray<Vec<D>, B> shepard_grad;
  DeviceArray<Mat<D>, B> kcorr;
  DeviceArray<Mat<D>, B> grad_u;  // the hourglass control's, recomputed each step: not registered
  DeviceArray<std::int32_t, B> mirror;
  DeviceArray<std::int32_t, B> index_of_id;  // not registered: recomputed after every reordering
  DeviceArray<Mat<D>, B> piola, defgrad;     // large strain only
  DeviceArray<std::int32_t, B> body;         // the rigid stage's (rigid/rigid_stage.hpp)
  DeviceArray<std::int32_t, B> load_mask;    // the solid loads' (solid/solid_load_stage.hpp)
  DeviceArray<Real, B> visc_scale, p_ambient;  // the fluid-solid coupling's (solid/coupling_stage.hpp)
  DeviceArray<std::uint8_t, B> fluid_contact;
  DeviceArray<std::uint8_t, B> ghost;        // the damage stage's, with ghosts (damage/ghosts.hpp)

 private:
  template <class T>
  void reg(DeviceArray<T, B>& arr, FieldType type, int comps, const char* name, const char* unit,
           const char* what) {
    FieldHandle h;
    h.info = FieldInfo{name, type, comps, unit, what};
    h.permute = [this, &arr](const int* perm) {
      DeviceArray<T, B>& tmp = scratch<T>();
      tmp.resize(arr.size());
      B::for_each(static_cast<int>(arr.size()), Gather<T, B>{tmp.data(), arr.data(), perm});
      arr.swap(tmp);
    };
    h.to_host_double = [&arr, comps](std::vector<double>& out) {
      const std::vector<T> hv = arr.host();
      out.resize(hv.size() * static_cast<std::size_t>(comps));
      const auto* raw = reinterpret_cast<const ScalarOf<T>*>(hv.data());
      for (std::size_t k = 0; k < out.size(); ++k) out[k] = static_cast<double>(raw[k]);
    };
    h.element_bytes = sizeof(T);
    raw_copies(h, arr);
    registry_.add(std::move(h));
  }

  // The array's bytes as stored (`width` values of T a particle), to and from the host
  // (checkpoints, migrations).
  template <class T>
  void raw_copies(FieldHandle& h, DeviceArray<T, B>& arr, int width = 1) {
    h.data = [&arr]() -> void* { return arr.data(); };
    h.to_host_bytes = [&arr](std::vector<unsigned char>& out) {
      out.resize(arr.size() * sizeof(T));
      if (!out.empty()) B::download(out.data(), arr.data(), out.size());
    };
    h.from_host_bytes = [&arr](const std::vector<unsigned char>& in) {
      arr.fit(in.size() / sizeof(T));
      if (!in.empty()) B::upload(arr.data(), in.data(), in.size());
    };
    h.gather_to_host = [this, &arr, width](const std::vector<int>& idx, std::vector<unsigned char>& out) {
      DeviceArray<T, B>& tmp = scratch<T>();
      tmp.resize(idx.size() * std::size_t(width));
      if (!idx.empty()) {
        picked_.upload(idx);
        B::for_each(static_cast<int>(idx.size()), GatherRows<T>{tmp.data(), arr.data(), picked_.data(), width});
      }
      out.resize(tmp.size() * sizeof(T));
      if (!out.empty()) B::download(out.data(), tmp.data(), out.size());
    };
    h.keep_first = [this, &arr, width](int n) { resize_keeping(arr, std::size_t(n) * width, std::size_t(n) * width); };
    h.place = [this, &arr, width](const std::vector<unsigned char>& in, int at) {
      const std::size_t first = std::size_t(at) * width, added = in.size() / sizeof(T);
      resize_keeping(arr, first + added, first);
      if (added) B::upload(arr.data() + first, in.data(), in.size());
    };
  }
  // `arr` holding `size` values, its first `keep` as they were: in place within its allocation,
  // otherwise copied into a larger one, with room for the next migrations' growth.
  template <class T>
  void resize_keeping(DeviceArray<T, B>& arr, std::size_t size, std::size_t keep) {
    if (size <= arr.capacity()) return arr.resize(size);
    DeviceArray<T, B>& tmp = scratch<T>();
    tmp.reserve(size + size / 8);
    tmp.resize(size);
    B::copy(tmp.data(), arr.data(), std::min({keep, size, arr.size()}) * sizeof(T));
    arr.swap(tmp);
  }

  template <class T>
  DeviceArray<T, B>& scratch() {
    if constexpr (std::is_same_v<T, Vec<D>>) return scratch_vec_;
    else if constexpr (std::is_same_v<T, Point<D>>) return scratch_point_;
    else if constexpr (std::is_same_v<T, Mat<D>>) return scratch_mat_;
    else if constexpr (std::is_same_v<T, Real>) return scratch_real_;
    else if constexpr (std::is_same_v<T, std::uint8_t>) return scratch_u8_;
    else return scratch_i32_;
  }

  void register_all() {
    reg(x, FieldType::Real, D, "position", "m", "particle position");
    reg(v, FieldType::Real, D, "velocity", "m/s", "velocity (prescribed for walls)");
    reg(a, FieldType::Real, D, "acceleration", "m/s^2", "acceleration");
    reg(v_xsph, FieldType::Real, D, "xsph_correction", "m/s", "XSPH drift correction (Pazdniakou eq. 76)");
    reg(lap_v, FieldType::Real, D, "velocity_laplacian", "1/(m s)", "Laplacian of the velocity (viscous term / nu)");
    reg(v_noslip, FieldType::Real, D, "wall_noslip_velocity", "m/s", "wall velocity seen by the viscous term");
    reg(rho, FieldType::Real, 1, "density", "kg/m^3", "mass density");
    reg(drho, FieldType::Real, 1, "density_rate", "kg/m^3/s", "continuity d rho/dt (Pazdniakou eq. 53a)");
    reg(p, FieldType::Real, 1, "pressure", "Pa", "pressure from the equation of state");
    reg(m, FieldType::Real, 1, "mass", "kg", "particle mass");
    reg(rho0, FieldType::Real, 1, "rest_density", "kg/m^3", "reference density of the EOS");
    reg(number_density, FieldType::Real, 1, "number_density", "1/m^3", "sum_j W_ij (Pazdniakou eq. 40)");
    reg(material, FieldType::Byte, 1, "material", "-", "material index");
    reg(id, FieldType::Int, 1, "id", "-", "particle id at creation");
  }

  int n_ = 0;
  FieldRegistry registry_;
  DeviceArray<Vec<D>, B> scratch_vec_;
  DeviceArray<Point<D>, B> scratch_point_;  // used where Coord is not Real (mixed precision)
  DeviceArray<Mat<D>, B> scratch_mat_;
  DeviceArray<Real, B> scratch_real_;
  DeviceArray<std::uint8_t, B> scratch_u8_;
  DeviceArray<std::int32_t, B> scratch_i32_;
  DeviceArray<int, B> picked_;  // the particles a migration gathers (gather_to_host)
};

}  // namespace psph
