#pragma once
// Clamps of elastic solids: a wall particle w with a mirror partner p (solid/clamp_partners.hpp)
// presents the partner's displacement mirrored through the clamp surface, u_w = 2 u_wall - u_p
// (the odd extension, as the no-slip mirror of Adami, Hu & Adams 2012 eq. 23 is for velocities);
// walls without a partner present their own displacement. The stress form's elastic energy is the
// solid's own, sum_s V_s sigma_s : eps_s / 2, with the walls' u_w inside eps_s; as u_w follows u_p,
// the partner also feels -dE/du_p through u_w (ClampReactionPass, MirrorReactionPass), which keeps
// the forces the gradient of that energy: without this chain rule a clamped rod went unstable.
#include "fluid/material.hpp"
#include "kernels/kernel.hpp"
#include "neighbours/neighbour_list.hpp"
#include "solid/strain.hpp"
#include "state/particles.hpp"

namespace psph {

// index_of_id[id[i]] = i, after every reordering (ids are unique: no write conflicts).
template <int D>
struct IndexOfIdPass {
  ParticleView<D> s;
  PSPH_HD void operator()(int i) const { s.index_of_id[s.id[i]] = i; }
};

template <int D>
struct ClampDisplacementPass {
  ParticleView<D> s;
  MaterialTable<D> mats;
  PSPH_HD void operator()(int i) const {
    if (mats.is_dynamic(s.material[i]) || s.mirror[i] < 0) return;
    s.u[i] = s.u[i] * Real(2) - s.u[s.index_of_id[s.mirror[i]]];
  }
};

// On a wall with a partner: dE/du_w = V_w sum_k V_k sigma_k g_kw over its elastic neighbours k
// (g_kw = K_k grad W~_kw, stored by the strain pass), kept in the wall's acceleration slot.
template <int D>
struct ClampReactionPass {
  NeighbourList<D> nb;
  Kernel<D> kern;
  ParticleView<D> s;
  MaterialTable<D> mats;
  PSPH_HD void operator()(int w) const {
    if (mats.is_dynamic(s.material[w]) || s.mirror[w] < 0) return;
    Vec<D> f = Vec<D>::zero();
    nb.for_each(w, [&](int k, const Vec<D>& rwk, Real r) PSPH_PAIR {
      if (!mats.is_elastic(s.material[k])) return;
      const Vec<D> g_kw = corrected_gradient(s, k, kern.W(r), kern.grad(rwk, r) * Real(-1));
      f += s.stress[k] * g_kw * (s.m[k] / s.rho[k]);
    });
    s.a[w] = f * (s.m[w] / s.rho[w]);
  }
};

// On the partner: a_p += dE/du_w / m_p (u_w = 2 u_wall - u_p).
template <int D>
struct MirrorReactionPass {
  ParticleView<D> s;
  MaterialTable<D> mats;
  PSPH_HD void operator()(int i) const {
    if (!mats.is_elastic(s.material[i]) || s.mirror[i] < 0) return;
    s.a[i] += s.a[s.index_of_id[s.mirror[i]]] * (Real(1) / s.m[i]);
  }
};

// Walls keep no acceleration (the slot served the reaction above).
template <int D>
struct ZeroWallAcceleration {
  ParticleView<D> s;
  MaterialTable<D> mats;
  PSPH_HD void operator()(int i) const {
    if (!mats.is_dynamic(s.material[i])) s.a[i] = Vec<D>::zero();
  }
};

}  // namespace psph
