#pragma once
// The plate with a rigid inclusion of Deptulski 2021 §4.3 (cases/plate_inclusion_2d.toml): its top
// edge pulled up or pushed down at a fixed rate until `top_displacement`. Measured every 0.5 um of
// imposed displacement: the onset (the first particle past its law's peak stress: D >= 1/4 with
// AT-2, D > 1e-3 with AT-1 and PCW, whose peak is at their onset) and where it lies, and when a
// crack (D >= 0.9) reaches both lateral edges; the kinetic against the elastic energy at the onset,
// the left-right asymmetry of the damage, the energy dissipated by damage.
#include <string>

#include "scene/case_file.hpp"

namespace psph {

// `model`: at1, at2 or pcw; `compression`: the top edge pushed down; `spacing`, `support`: the
// case's 5 mm and 25 mm, or the thesis' 1 mm and 5 mm.
Case plate_inclusion_case(const std::string& model, bool compression, double top_displacement, double spacing = 5e-3,
                          double support = 25e-3);

struct PlateDamage {
  double onset = -1;        // imposed displacement (m) at the onset; -1: none
  double onset_x = 0, onset_y = 0;  // reference position of the particle past its peak first (m)
  double complete = -1;     // imposed displacement (m) when a crack reaches both lateral edges; -1: none
  double kinetic_over_elastic = 0;  // at the onset
  double onset_driving_force = 0;   // Y of the onset's particle then (Pa)
  double asymmetry = 0;     // sum |D(x, y) - D(-x, y)| / sum D at the end (0: symmetric)
  double dissipated = 0;    // energy dissipated by damage at the end (J per m of thickness)
  double elastic = 0;       // elastic energy at the end (J/m)
  long steps = 0;
  int particles = 0;
  double seconds = 0;
};

PlateDamage run_plate_inclusion(const Case& c, const std::string& model, const std::string& backend);

}  // namespace psph
