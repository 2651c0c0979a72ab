#pragma once
// Clamps of elastic solids: a wall particle w with a mirror partner p (engine/clamp_partners.hpp)
// presents the partner's displacement mirrored through the clamp surface, u_w = 2 u_wall - u_p
// (the odd extension, as the no-slip mirror of Adami, Hu & Adams 2012 eq. 23 is for velocities);
// walls without a partner, or whose partner is a damage ghost, present their own displacement.
// A slip clamp ([materials] clamp = "slip") mirrors the normal component only, n the unit vector
// from the wall to its partner in the reference state: u_w = u_p + 2 ((u_wall - u_p) . n) n, the
// even extension of the tangential displacement, so that no shear crosses the clamp surface.
// The stress form's elastic energy is the solid's own, sum_s V_s sigma_s : eps_s / 2, with the
// walls' u_w inside eps_s; as u_w follows u_p, the partner also feels -dE/du_p through u_w
// (clamp_reaction), which keeps the forces the gradient of that energy: without this chain rule a
// clamped rod went unstable.
#include <cmath>

#include "core/material.hpp"
#include "kernels/kernel.hpp"
#include "neighbours/neighbour_list.hpp"
#include "solid/strain.hpp"
#include "state/particles.hpp"
#include "core/pass_fields.hpp"

namespace psph {

// The unit vector from wall w to its partner p in the reference state (a clamp spans one support,
// far less than any periodic length, so no image is needed).
template <int D>
PSPH_HD inline Vec<D> clamp_normal(const ParticleView<D>& s, int w, int p) {
  const Vec<D> d = to_real(s.x0[p] - s.x0[w]);
  return d * (Real(1) / sqrt(dot(d, d)));
}

// The id of a particle whose clamp partner is not on this process (-1: none); a run over several
// processes checks it after each list build.
template <int D>
struct MissingClampPartner {
  ParticleView<D> s;
  PSPH_HD int operator()(int i) const { return s.mirror[i] >= 0 && s.index_of_id[s.mirror[i]] < 0 ? int(s.id[i]) : -1; }
};

template <int D>
struct ClampDisplacementPass {
  static constexpr FieldNames neighbour_reads = kSolidPairReads;
  static constexpr FieldNames writes{"displacement"};
  ParticleView<D> s;
  MaterialTable<D> mats;
  PSPH_HD void operator()(int i) const {
    if (mats.is_dynamic(s.material[i]) || s.mirror[i] < 0) return;
    const int p = s.index_of_id[s.mirror[i]];
    if (p < 0) return;  // a halo copy whose partner another process holds (parallel/): not read
    if (is_retired_ghost(s.ghost, p)) return;  // a damage ghost's wall clamps nothing (damage/ghosts.hpp)
    if (!mats[s.material[i]].slip_clamp) {
      s.u[i] = s.u[i] * Coord(2) - s.u[p];
      return;
    }
    const Point<D> n = to_coord(clamp_normal(s, i, p));
    s.u[i] = s.u[p] + n * (Coord(2) * dot(s.u[i] - s.u[p], n));
  }
};

// dE/du_w = V_w sum_k V_k sigma_k g_kw of wall w over its elastic neighbours k (g_kw = K_k
// grad W~_kw, stored by the strain pass): with u_w = 2 u_wall - u_p it acts on the partner p as the
// force +dE/du_w, with a slip clamp's u_w as -(I - 2 n n) dE/du_w (StressForcePass adds it; the
// mirror is one to one, so each wall's is summed once).
template <int D, class NB>
PSPH_HD inline Vec<D> clamp_reaction(const NB& nb, const Kernel<D>& kern, const ParticleView<D>& s,
                                     const MaterialTable<D>& mats, int w) {
  Vec<D> f = Vec<D>::zero();
  nb.for_each(w, [&](int k, const Vec<D>& rwk, Real r) PSPH_PAIR {
    if (!mats.is_elastic(s.material[k])) return;
    const Vec<D> g_kw = corrected_gradient(s, k, kern.W(r), kern.grad(rwk, r) * Real(-1));
    f += (s.piola ? s.piola[k] : s.stress[k]) * g_kw * solid_sum_volume(s, k);
  });
  f = f * solid_sum_volume(s, w);
  if (!mats[s.material[w]].slip_clamp) return f;
  const Vec<D> n = clamp_normal(s, w, s.index_of_id[s.mirror[w]]);
  return n * (Real(2) * dot(f, n)) - f;
}

}  // namespace psph
