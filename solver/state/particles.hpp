#pragma once
// Particle state as a structure of arrays in a backend's memory, with every array registered by
// name. `ParticleView` is the raw-pointer view the passes receive by value.
#include <cstdint>
#include <type_traits>
#include <vector>

#include "backend/device_array.hpp"
#include "core/vec.hpp"
#include "state/fields.hpp"

namespace psph {

template <int D>
struct ParticleView {
  int n = 0;
  Vec<D>* x;          // position
  Vec<D>* v;          // velocity (prescribed for walls)
  Vec<D>* a;          // acceleration
  Vec<D>* v_xsph;     // XSPH correction added to the drift velocity
  Vec<D>* v_noslip;   // walls: velocity seen by the viscous term (no-slip extrapolation)
  Vec<D>* lap_v;      // fluids: Laplacian of the velocity from the last force pass
  Real* rho;          // density
  Real* drho;         // d rho / dt (continuity)
  Real* p;            // pressure
  Real* m;            // mass
  Real* rho0;         // per-particle reference density of the EOS
  Real* number_density;  // sum_j W_ij (for eq. 41)
  std::uint8_t* material;
  std::int32_t* id;   // particle id at creation, to follow particles across reorderings
  const std::uint8_t* near_fluid;  // 1 where a fluid particle may be within the support (neighbours/)
  // Two-fluid cases only (null otherwise): interface/surface_tension.hpp.
  Real* colour;             // smoothed colour c (eq. 58)
  Vec<D>* colour_gradient;  // n = grad c (eq. 59a)
  Real* curvature;          // kappa = -div n^ (eqs. 7, 60)
  // Elastic solids only (null otherwise): solid/elastic_force.hpp.
  Vec<D>* x0;  // reference (initial) position
  Vec<D>* u;   // displacement x - x0
  Mat<D>* strain;  // small strain (solid/strain.hpp)
  Mat<D>* stress;  // Cauchy stress
  Real* shepard;   // the gradient correction S_i, G_i, K_i of the strain pass (solid/strain.hpp)
  Vec<D>* shepard_grad;
  Mat<D>* kcorr;
  std::int32_t* mirror;       // clamps: id of the mirror partner, -1 if none (solid/clamp_partners.hpp)
  std::int32_t* index_of_id;  // current index of each id (clamps, rigid bodies)
  // Fluids with elastic solids only (null otherwise): solid/fluid_coupling.hpp.
  Real* visc_scale;  // a fluid particle's Laplacian correction D / lambda of the last force pass
  std::uint8_t* fluid_contact;  // a solid particle with fluid within its support
  Real* p_ambient;              // the fluid's pressure carried into an elastic body's surface layer
  // Rigid bodies only (null otherwise): rigid/.
  std::int32_t* body;  // the rigid body a particle belongs to, -1 if none
  // Large-strain solids only (null otherwise): solid/constitutive.hpp.
  Mat<D>* piola;    // first Piola-Kirchhoff stress P = F S
  Mat<D>* defgrad;  // deformation gradient F
  // Loaded elastic particles only (null otherwise): solid/solid_load.hpp.
  std::int32_t* load_mask;  // the [[solid_load]]s a particle belongs to, bit g for load g
};

template <class T, class B>
struct Gather {
  T* out;
  const T* in;
  const int* perm;
  PSPH_HD void operator()(int i) const { out[i] = in[perm[i]]; }
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

  ParticleView<D> view() {
    return ParticleView<D>{n_,         x.data(),    v.data(),    a.data(),  v_xsph.data(), v_noslip.data(), lap_v.data(),
                           rho.data(), drho.data(), p.data(),    m.data(),  rho0.data(),
                           number_density.data(),   material.data(), id.data(), near_fluid.data(),
                           colour.data(), colour_gradient.data(), curvature.data(), x0.data(), u.data(),
                           strain.data(), stress.data(), shepard.data(), shepard_grad.data(), kcorr.data(),
                           mirror.data(), index_of_id.data(), visc_scale.data(),
                           fluid_contact.data(), p_ambient.data(), body.data(), piola.data(), defgrad.data(),
                           load_mask.data()};
  }

  // Allocates and registers the interface fields (a case with two fluids and surface tension).
  void enable_interface() {
    if (interface_) return;
    interface_ = true;
    colour.resize(n_), colour_gradient.resize(n_), curvature.resize(n_);
    colour.zero(), colour_gradient.zero(), curvature.zero();
    reg(colour, FieldType::Real, 1, "colour", "-", "smoothed colour function, +1 liquid, -1 gas (Pazdniakou eq. 58)");
    reg(colour_gradient, FieldType::Real, D, "colour_gradient", "1/m", "interface normal n = grad c (eq. 59a)");
    reg(curvature, FieldType::Real, 1, "curvature", "1/m", "interface curvature -div n^ (eqs. 7, 60)");
  }

  // Allocates and registers the reference positions and displacements (a case with an elastic solid).
  void enable_solid() {
    if (solid_) return;
    solid_ = true;
    x0.resize(n_), u.resize(n_), strain.resize(n_), stress.resize(n_);
    shepard.resize(n_), shepard_grad.resize(n_), kcorr.resize(n_), mirror.resize(n_);
    index_of_id.resize(n_);
    u.zero(), strain.zero(), stress.zero();
    reg(x0, FieldType::Real, D, "reference_position", "m", "initial position (small-strain reference configuration)");
    reg(u, FieldType::Real, D, "displacement", "m", "displacement x - x0 of elastic solids");
    reg(strain, FieldType::Real, D * D, "strain", "-", "small strain sym(grad u) (large strain: Green-Lagrange), row-major");
    reg(stress, FieldType::Real, D * D, "stress", "Pa", "Cauchy stress (tension positive), row-major");
    reg(mirror, FieldType::Int, 1, "clamp_mirror", "-", "id of a clamp wall's mirror partner and back, -1 if none");
  }

  // A fluid with elastic solids: the fluid force pass keeps each particle's viscous correction for
  // the solid's reaction, the solid its contact and ambient pressure (solid/fluid_coupling.hpp);
  // written and read within one force evaluation: not registered.
  void enable_coupling() {
    visc_scale.resize(n_), fluid_contact.resize(n_), p_ambient.resize(n_);
    visc_scale.zero(), fluid_contact.zero(), p_ambient.zero();
  }

  // Registers the rigid body of each particle (a case with rigid bodies, rigid/); the index of each
  // id finds a body's particles after a reordering.
  void enable_rigid(const std::vector<std::int32_t>& body_of_particle) {
    body.upload(body_of_particle);
    index_of_id.resize(n_);
    reg(body, FieldType::Int, 1, "rigid_body", "-", "the rigid body a particle belongs to, -1 if none");
  }

  // Large strain (Saint Venant-Kirchhoff): the Piola stress of the strain pass (recomputed before
  // every use: not registered) and the deformation gradient (registered: the fluid reads a solid's
  // volume det F before the next strain pass, so it must follow reorderings and checkpoints).
  void enable_large_strain() {
    piola.resize(n_);
    piola.zero();
    defgrad.upload(std::vector<Mat<D>>(n_, Mat<D>::identity()));  // undeformed until the first strain pass
    reg(defgrad, FieldType::Real, D * D, "deformation_gradient", "-", "F = I + grad u (large strain), row-major");
  }

  // Registers each particle's [[solid_load]]s, bit g for load g (solid/solid_load.hpp).
  void enable_solid_loads(const std::vector<std::int32_t>& group_of_particle) {
    load_mask.upload(group_of_particle);
    reg(load_mask, FieldType::Int, 1, "solid_load_mask", "-", "the [[solid_load]]s a particle belongs to: bit g for load g");
  }

  // Reorders every registered field: field[i] <- field[perm[i]].
  void permute(const int* perm) {
    for (const auto& f : registry_.all()) f.permute(perm);
  }

  DeviceArray<Vec<D>, B> x, v, a, v_xsph, v_noslip, lap_v;
  DeviceArray<Real, B> rho, drho, p, m, rho0, number_density;
  DeviceArray<std::uint8_t, B> material;
  DeviceArray<std::int32_t, B> id;
  DeviceArray<std::uint8_t, B> near_fluid;  // not registered: recomputed after every reordering
  DeviceArray<Real, B> colour, curvature;     // empty unless enable_interface()
  DeviceArray<Vec<D>, B> colour_gradient;
  DeviceArray<Vec<D>, B> x0, u;          // empty unless enable_solid()
  DeviceArray<Mat<D>, B> strain, stress;
  DeviceArray<Real, B> shepard;  // the strain pass's correction, recomputed every step: not registered
  DeviceArray<Vec<D>, B> shepard_grad;
  DeviceArray<Mat<D>, B> kcorr;
  DeviceArray<std::int32_t, B> mirror;
  DeviceArray<std::int32_t, B> index_of_id;  // not registered: recomputed after every reordering
  DeviceArray<std::int32_t, B> body;         // empty unless enable_rigid()
  DeviceArray<std::int32_t, B> load_mask;   // empty unless enable_solid_loads()
  DeviceArray<Mat<D>, B> piola, defgrad;     // empty unless enable_large_strain()
  DeviceArray<Real, B> visc_scale, p_ambient;  // empty unless enable_coupling()
  DeviceArray<std::uint8_t, B> fluid_contact;

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
      constexpr bool real_tuple = std::is_same_v<T, Vec<D>> || std::is_same_v<T, Mat<D>>;
      const auto* raw = reinterpret_cast<const std::conditional_t<real_tuple, Real, T>*>(hv.data());
      for (std::size_t k = 0; k < out.size(); ++k) out[k] = static_cast<double>(raw[k]);
    };
    h.element_bytes = sizeof(T);
    h.to_host_bytes = [&arr](std::vector<unsigned char>& out) {
      out.resize(arr.size() * sizeof(T));
      if (!out.empty()) B::download(out.data(), arr.data(), out.size());
    };
    h.from_host_bytes = [&arr](const std::vector<unsigned char>& in) {
      arr.resize(in.size() / sizeof(T));
      if (!in.empty()) B::upload(arr.data(), in.data(), in.size());
    };
    registry_.add(std::move(h));
  }

  template <class T>
  DeviceArray<T, B>& scratch() {
    if constexpr (std::is_same_v<T, Vec<D>>) return scratch_vec_;
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
  bool interface_ = false, solid_ = false;
  FieldRegistry registry_;
  DeviceArray<Vec<D>, B> scratch_vec_;
  DeviceArray<Mat<D>, B> scratch_mat_;
  DeviceArray<Real, B> scratch_real_;
  DeviceArray<std::uint8_t, B> scratch_u8_;
  DeviceArray<std::int32_t, B> scratch_i32_;
};

}  // namespace psph
