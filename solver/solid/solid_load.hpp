#pragma once
// Loads on groups of elastic particles (`[[solid_load]]`; groups chosen by box at the start):
//   traction: an external force t A on each particle of the group, A = spacing^(D-1) its share of
//             the surface, t in Pa: a confining stress sigma on a face is t = -sigma n_out on its
//             outermost layer (our choice: Pazdniakou 2018 §5.2 and Deptulski 2021 §5.2 apply it
//             to the lateral sides without saying how);
//   velocity: the particles move at an imposed velocity (an imposed displacement v x duration,
//             then held), along every axis or only those named (a face pulled along y and free
//             to slide along x, Deptulski 2021 eq. 4.31): they still take part in the solid's
//             sums (our choice: Deptulski 2021 does not say how he imposes displacements or clamps).
// A particle may belong to several loads (a corner to two faces' tractions): a bit per load.
// Applied after every other force (engine/simulation.hpp), so that an imposed velocity holds.
#include <array>
#include <cstdint>

#include "core/material.hpp"
#include "state/particles.hpp"
#include "core/pass_fields.hpp"

namespace psph {

constexpr int kMaxSolidLoads = 4;

// A load on the elastic particles of one material inside a box (as read from the case).
struct SceneSolidLoad {
  int material = 0;
  std::array<double, 3> lower{0, 0, 0}, upper{0, 0, 0};
  bool velocity = false;                  // imposed velocity, else traction
  std::array<double, 3> value{0, 0, 0};   // traction (Pa) or velocity (m/s)
  double ramp_time = 0;  // s: a traction grows linearly from zero over this time
  double duration = 0;   // s: an imposed velocity stops after this time (0: never)
  unsigned axes = 7u;    // bit d: the velocity is imposed along axis d (the others are free)
};

enum class SolidLoadKind : int { Traction = 0, Velocity = 1 };

template <int D>
struct SolidLoads {
  int count = 0;
  SolidLoadKind kind[kMaxSolidLoads] = {};
  Vec<D> value[kMaxSolidLoads] = {};  // force per particle (N) or velocity (m/s), at this step
  unsigned axes[kMaxSolidLoads] = {};  // imposed velocities: bit d, along axis d
};

template <int D>
struct SolidLoadPass {
  static constexpr FieldNames neighbour_reads{};
  static constexpr FieldNames writes{"acceleration", "velocity", "xsph_correction"};
  ParticleView<D> s;
  SolidLoads<D> loads;
  PSPH_HD void operator()(int i) const {
    const std::int32_t mask = s.load_mask[i];
    if (mask == 0) return;
    for (int g = 0; g < loads.count; ++g) {
      if (!(mask & (1 << g))) continue;
      if (loads.kind[g] == SolidLoadKind::Traction) s.a[i] += loads.value[g] * (Real(1) / s.m[i]);
    }
    for (int g = 0; g < loads.count; ++g)  // an imposed velocity overrides any force along its axes
      if ((mask & (1 << g)) && loads.kind[g] == SolidLoadKind::Velocity)
        for (int d = 0; d < D; ++d)
          if (loads.axes[g] >> d & 1u) s.v[i][d] = loads.value[g][d], s.a[i][d] = Real(0), s.v_xsph[i][d] = Real(0);
  }
};

}  // namespace psph
