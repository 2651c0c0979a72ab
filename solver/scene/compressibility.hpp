#pragma once
// How far a case's fluids will be compressed, estimated before it runs from what the case states
// (GUIDE §3): weakly compressible SPH is right only while Δρ/ρ ≈ Δp/(ρ c²) + (v/c)² stays about
// 1 %, where Δp gathers body forces over the fluid's extent, imposed pressures, capillary
// pressures and loads on the solids around it. `poresph check` and `poresph run` print it.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "scene/case_file.hpp"

namespace psph {

struct CompressibilityTerm {
  std::string fluid;  // the material it compresses
  std::string what;   // "body force", "pressure drive", "capillary pressure", "confinement", "speed", "impact"
  std::string keys;   // the case keys that make it
  std::string detail; // how it was counted
  double pressure = 0;  // Δp (Pa); 0 for the speed term
  double value = 0;     // its share of Δρ/ρ
  double drive_power = 0;  // how it scales with the drive (body forces, imposed pressures): as drive^this (0: it does not)
  // How it scales with the sound speed c: as 1/c^sound_power, or, where > 0, as pressure / max(rho c^2, this)
  // (the solids' bulk modulus: past it, a faster sound no longer helps).
  double stiffness = 0;
  double sound_power = 2;  // otherwise as 1/c^this: 2 for a pressure or (v/c)^2, 1 for an impact's rho c v
};

struct CompressibilityEstimate {
  double limit = 0.01;  // what weak compressibility allows
  double total = 0;     // the largest fluid's sum of terms
  std::string fluid;    // that fluid
  std::vector<CompressibilityTerm> terms;  // every fluid's
  double sound_speed = 0, sound_speed_needed = 0;  // that fluid's, and the one that would hold `limit` (0: none can)
  double drive_factor = 0;  // the drives times this hold `limit` (0: no drive can: the other terms pass it alone)
  bool exceeds() const { return total > limit; }
  // Where a body force drives a fluid along a periodic axis through pores: the pressure field that
  // turns the flow settles by diffusion, D = c^2 K / nu (Darcy flow of a compressible fluid), over
  // the length L in L^2 nu / (pi^2 c^2 K), K an upper bound from the sections (scene/pore_grid.hpp),
  // so the time a lower bound. Until then a flow rate is too high where the flow turns.
  double settle_time = 0, end_time = 0;  // s; 0: no such drive
  std::string settle_fluid, settle_detail;
  double settle_sound_speed = 0;         // the fluid's, and the one that settles within a third of the run
  double settle_sound_speed_needed = 0;
  bool settles_late() const { return settle_time > end_time / 3; }
};

// From a case whose particles are built (scene/scene_builder.hpp).
CompressibilityEstimate estimate_compressibility(const Case& c);
// The estimate as lines for `check` and the run's log; a warning, naming the file and keys, when it
// exceeds the limit.
std::string compressibility_text(const CompressibilityEstimate& e, const std::string& file);
nlohmann::json to_json(const CompressibilityEstimate& e);

}  // namespace psph
