#pragma once
// Open pressure inlet and outlet (ours: the references drive a drainage by a body force on the
// reservoir gas, Pazdniakou 2018 §5.2; this is the alternative with imposed pressures). Two buffer
// layers, each at least one support radius thick, lie across the ends of a periodic axis
// (core/open_boundary_zone.hpp). Their particles are not moved by forces: they carry their
// buffer's pressure (and the density the equation of state gives it) and move along the axis with
// the fluid's velocity at a mirror point inside, corrected by the outgoing characteristic so that
// mass flows in or out until the fluid next to each buffer has its pressure. Fluid that leaves
// through the outlet crosses the periodic seam into the inlet buffer and becomes the injected fluid
// there, so the particle count stays fixed. Validated in cases/open_channel_2d.toml (VALIDATION.md).
#include "core/equation_of_state.hpp"
#include "core/fluid_table.hpp"
#include "kernels/kernel.hpp"
#include "neighbours/cell_grid.hpp"
#include "neighbours/neighbour_list.hpp"
#include "state/particles.hpp"
#include "core/pass_fields.hpp"

namespace psph {

// The factor on what neighbour j presents to i in a density sum: 1, or for a buffer particle the
// ratio rho_b / rho0_j at its buffer's pressure (BufferMass gives it the mass of the volume it stands
// for). The number-density form (eq. 40) counts every neighbour at i's mass (equal volumes), so
// there a buffer particle's own volume enters too: m_j rho0_i / (rho0_j m_i). Without the ratio the
// flow fell to 30-60 % of the exact one in open_channel_2d.
template <int D>
PSPH_HD inline Real buffer_density_ratio(const FluidTable<D>& mats, const ParticleView<D>& s, int i, int j, bool number) {
  const int k = s.material[j];
  const BufferZone z = mats.open.zone(s.x[j]);
  if (z == BufferZone::None || !mats.is_fluid(k)) return Real(1);
  const Real ratio = density_from_pressure(mats[k], mats.open.pressure(z), s.rho0[j]) / s.rho0[j];
  return number ? ratio * s.m[j] * s.rho0[i] / (s.rho0[j] * s.m[i]) : ratio;
}

// Each step, a buffer particle takes the mass of the volume it stands for, m_i = rho0_i V / n_i,
// n_i = sum_j W_ij V_j (self included) with V_j = V, a lattice particle's volume (m / rho0 as the
// scene gives it), or m_j / rho_j for interior fluid: a full lattice gives n_i = 1 and m_i the
// scene's mass. It keeps that mass as it crosses into the interior: the inlet is a mass source at
// its density, whatever the spacing of what comes round through the seam. (With a fixed mass per
// particle, buffers that gave the interior the mass its pressure and its sheared arrangement need
// thinned by 5 %; a thin buffer lowered the pressure beside it, the characteristic correction then
// drew more fluid in through both faces, and particles crossing the inlet face summed 4.9 % low:
// open_channel_2d.)
template <int D>
struct BufferMass {
  static constexpr FieldNames neighbour_reads{"position", "material", "mass", "density"};
  static constexpr FieldNames writes{"mass"};
  ParticleView<D> s;
  FluidTable<D> mats;
  NeighbourList<D> nb;
  Kernel<D> kern;
  PSPH_HD void operator()(int i) const {
    if (!mats.is_fluid(s.material[i]) || mats.open.zone(s.x[i]) == BufferZone::None) return;
    const Real vl = mats.open.lattice_volume;
    Real n = kern.W(Real(0)) * vl;
    nb.for_each(i, [&](int j, const Vec<D>&, Real r) PSPH_PAIR {
      const bool interior = mats.is_fluid(s.material[j]) && mats.open.zone(s.x[j]) == BufferZone::None;
      n += kern.W(r) * (interior ? s.m[j] / s.rho[j] : vl);
    });
    s.m[i] = s.rho0[i] * vl / n;
  }
};

// Sums over the interior band next to each buffer (OpenBoundaryZone::in_band), both buffers in one
// reduction: [buffer][count, axial velocity, pressure, impedance rho c]. (A weight vanishing at the
// band's edges, to smooth the means as particle rows cross the face, made the flow oscillate by
// +-60 % instead of +-10 %.)
struct BandSums {
  Real q[2][4];
  PSPH_HD BandSums& operator+=(const BandSums& o) {
    for (int b = 0; b < 2; ++b)
      for (int k = 0; k < 4; ++k) q[b][k] += o.q[b][k];
    return *this;
  }
  PSPH_HD friend BandSums operator+(BandSums a, const BandSums& o) { return a += o; }
};
template <int D>
struct BandSum {
  ParticleView<D> s;
  FluidTable<D> mats;
  PSPH_HD BandSums operator()(int i) const {
    BandSums out{};
    const int k = s.material[i];
    if (!mats.is_fluid(k)) return out;
    for (int b = 0; b < 2; ++b) {
      if (!mats.open.in_band(s.x[i], b == 0 ? BufferZone::Inlet : BufferZone::Outlet)) continue;
      out.q[b][0] = Real(1);
      out.q[b][1] = s.v[i][mats.open.axis];
      out.q[b][2] = s.p[i];
      out.q[b][3] = s.rho[i] * mats[k].sound_speed;
    }
    return out;
  }
};

// At the start of a step: each buffer particle takes, along the axis, the fluid's velocity at its
// mirror point (Shepard average over the interior fluid within the support there, so the buffers
// carry the developed profile; the band's mean where no fluid is in reach) plus its buffer's
// characteristic correction du (OpenBoundaryStage::buffer_velocity). Its drift correction (the XSPH
// field, unused in buffers) shifts it down the gradient of the particle concentration,
// dx = -shift R^2 sum_j V_j grad W_ij per step (particle shifting, Lind et al. 2012, J. Comput.
// Phys. 231:1499): rows coming round through the seam at the outlet's speed would otherwise pile
// onto the inlet's rows, where no force separates them.
// The shift coefficient. Measured: 0 lets drainage_open_2d blow up at 0.03 s, when the first rows
// of water have come round as gas; 0.01 runs it to the end; 0.03 lowers open_channel_2d's flow rate
// from -1.8 % to -3.9 % of the exact one.
constexpr Real kBufferShift = Real(0.01);

template <int D>
struct SetBufferVelocity {
  static constexpr FieldNames neighbour_reads{"position", "material", "velocity", "mass", "density"};
  static constexpr FieldNames writes{"velocity", "xsph_correction"};
  ParticleView<D> s;
  FluidTable<D> mats;
  NeighbourView<D> cells;
  NeighbourList<D> nb;
  Kernel<D> kern;
  Real u_band[2], du[2];  // inlet, outlet
  Real shift_per_dt;      // shift / dt
  PSPH_HD void operator()(int i) const {
    if (!mats.is_fluid(s.material[i])) return;
    const BufferZone z = mats.open.zone(s.x[i]);
    if (z == BufferZone::None) return;
    const int b = z == BufferZone::Inlet ? 0 : 1;
    const int axis = mats.open.axis;
    Real sum = 0, weight = 0;
    cells.for_each_fluid_near(mats.open.mirror(s.x[i]), [&](int j, const Vec<D>&, Real r) PSPH_PAIR {
      if (mats.open.zone(s.x[j]) != BufferZone::None) return;
      const Real w = kern.W(r);
      sum += w * s.v[j][axis], weight += w;
    });
    Vec<D> v = Vec<D>::zero();
    v[axis] = (weight > Real(0) ? sum / weight : u_band[b]) + du[b];
    s.v[i] = v;
    Vec<D> grad_c = Vec<D>::zero();
    nb.for_each(i, [&](int j, const Vec<D>& rij, Real r) PSPH_PAIR {
      if (r > Real(0)) grad_c += rij * (s.m[j] / s.rho[j] * kern.F(r));
    });
    s.v_xsph[i] = grad_c * (-shift_per_dt * kern.support * kern.support);
  }
};

// Before the lists: a fluid particle in the inlet buffer (one that came round through the seam)
// becomes the inlet's material (its mass follows: BufferMass).
template <int D>
struct ConvertInletFluid {
  static constexpr FieldNames neighbour_reads{};
  static constexpr FieldNames writes{"rest_density", "material"};
  ParticleView<D> s;
  FluidTable<D> mats;
  PSPH_HD void operator()(int i) const {
    const int k = s.material[i], to = mats.open.inlet_material;
    if (k == to || !mats.is_fluid(k) || mats.open.zone(s.x[i]) != BufferZone::Inlet) return;
    s.rho0[i] = mats[to].rest_density;
    s.material[i] = static_cast<std::uint8_t>(to);
  }
};

// After the density pass: every buffer particle takes its buffer's pressure and the density at it.
template <int D>
struct SetBufferState {
  static constexpr FieldNames neighbour_reads{};
  static constexpr FieldNames writes{"pressure", "density"};
  ParticleView<D> s;
  FluidTable<D> mats;
  PSPH_HD void operator()(int i) const {
    const int k = s.material[i];
    if (!mats.is_fluid(k)) return;
    const BufferZone z = mats.open.zone(s.x[i]);
    if (z == BufferZone::None) return;
    const Real p = mats.open.pressure(z);
    s.p[i] = p;
    s.rho[i] = density_from_pressure(mats[k], p, s.rho0[i]);
  }
};

}  // namespace psph
