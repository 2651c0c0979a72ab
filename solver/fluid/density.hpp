#pragma once
// Density passes. Sums run over all neighbours of every material (fluid and wall particles alike:
// the "virtual contribution" that removes the deficit at a material boundary, Pazdniakou §3.1.2).
#include "boundary/open_boundary.hpp"
#include "core/equation_of_state.hpp"
#include "core/fluid_table.hpp"
#include "kernels/kernel.hpp"
#include "neighbours/neighbour_list.hpp"
#include "state/particles.hpp"
#include "stage/pass_context.hpp"
#include "core/pass_fields.hpp"

namespace psph {

// n_i = sum_j W_ij, self included (Pazdniakou eq. 40).
template <int D>
struct NumberDensityPass {
  static constexpr FieldNames neighbour_reads{"position"};
  static constexpr FieldNames writes{"number_density"};
  NeighbourList<D> nb;
  Kernel<D> kern;
  ParticleView<D> s;
  bool all_particles;  // false: walls far from any fluid keep their (initial, full) number density
  PSPH_HD void operator()(int i) const {
    if (!all_particles && !s.near_fluid[i]) return;
    Real n = kern.W(Real(0));
    nb.for_each(i, [&](int, const Vec<D>&, Real r) PSPH_PAIR { n += kern.W(r); });
    s.number_density[i] = n;
  }
};

// rho_i = sum_j m_j W_ij (eq. 39), the number-density form rho_i = m_i sum_j W_ij (eq. 40: a
// particle's density does not take its neighbours' masses, so an interface between fluids of
// density ratio 1000 stays sharp; our choice, the paper does not say which form its two-phase
// tests use), or the normalised form
// rho_i = sum_j m_j W_ij / sum_j W_ij / n_j (eq. 41, needs NumberDensityPass first);
// then the pressure from the material's equation of state. Open-boundary buffer neighbours count
// with the density of their buffer's pressure (boundary/open_boundary.hpp).
template <int D>
struct DensitySummationPass {
  static constexpr FieldNames neighbour_reads = kFluidPairReads;
  static constexpr FieldNames writes{"density", "pressure"};
  PairContext<D> c;  // lists, kernel, particles, materials
  bool normalised;
  bool number;         // eq. 40 form
  bool all_particles;  // false: walls far from any fluid keep their density and pressure
  bool solids;         // the case has elastic or rigid solids
  PSPH_HD void operator()(int i) const {
    if (!all_particles && !c.s.near_fluid[i]) return;
    if (solids && c.mats.is_solid(c.s.material[i])) return;  // a solid keeps its own density
    const Real w0 = c.kern.W(Real(0));
    const Real m_i = c.s.m[i];
    Real num = m_i * w0;
    Real den = normalised ? w0 / c.s.number_density[i] : Real(1);
    const bool open = c.mats.open.active();
    c.nb.for_each(i, [&](int j, const Vec<D>&, Real r) PSPH_PAIR {
      const Real w = c.kern.W(r);
      const Real ratio = open ? buffer_density_ratio(c.mats, c.s, i, j, number) : Real(1);
      // A solid neighbour fills its volume with i's rest density (no deficit at the interface,
      // whatever the solid's own density).
      const Real m_j = number                                  ? m_i
                       : solids && c.mats.is_solid(c.s.material[j]) ? c.s.rho[i] * c.mats.volume_of(c.s, j)
                                                                : c.s.m[j];
      num += m_j * w * ratio;
      if (normalised) den += w / c.s.number_density[j];
    });
    const Real rho = num / den;
    c.s.rho[i] = rho;
    c.s.p[i] = pressure_from_density(c.mats[c.s.material[i]], rho, c.s.rho0[i]);
  }
};

// Pressure from the current density (continuity mode, where density is integrated).
template <int D>
struct EquationOfStatePass {
  static constexpr FieldNames neighbour_reads{};
  static constexpr FieldNames writes{"pressure"};
  ParticleView<D> s;
  FluidTable<D> mats;
  PSPH_HD void operator()(int i) const {
    if (mats.is_solid(s.material[i])) return;  // solid/fluid_coupling.hpp
    s.p[i] = pressure_from_density(mats[s.material[i]], s.rho[i], s.rho0[i]);
  }
};

// The walls' EOS reference: their initial summed density (and the background pressure).
template <int D>
struct SetWallRestDensity {
  static constexpr FieldNames neighbour_reads{};
  static constexpr FieldNames writes{"rest_density", "pressure"};
  ParticleView<D> s;
  FluidTable<D> mats;
  PSPH_HD void operator()(int i) const {
    if (!mats.is_fluid(s.material[i])) {
      s.rho0[i] = s.rho[i];
      s.p[i] = mats[s.material[i]].background_pressure;
    }
  }
};

}  // namespace psph
