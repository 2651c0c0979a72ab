#pragma once
// An elastic cube compressed by the fluid around it (Pazdniakou 2018 §4.5, eq. 83;
// cases/elastic_cube_3d.toml): the fluid of a periodic box starts at the background pressure p_b,
// the cube at rest and unstrained; once the damping has settled them, the cube's bulk modulus is
// K = -p / (dV/V) with p the fluid's pressure away from the cube and dV/V = D e, e the uniform
// strain fitted to the cube's displacements (least squares of u = e (x0 - c)).
#include <string>

#include "scene/case_file.hpp"
#include "engine/scene.hpp"

namespace psph {

// `spacing` > 0 replaces the case's (support and sizes keep their ratios to it);
// `background_pressure` > 0 replaces the load.
// `model` chooses the solid's law (small strain or Saint Venant-Kirchhoff).
Case elastic_cube_case(double spacing = 0, SolidCoupling coupling = SolidCoupling::Traction,
                       double background_pressure = 0, SolidModel model = SolidModel::Linear);

// The fluid pressure that holds a Saint Venant-Kirchhoff solid of bulk modulus k at the uniform
// stretch lambda: sigma = P F^T / J = 3 k (lambda^2 - 1) / (2 lambda) I, p = -sigma.
inline double svk_pressure(double k, double lambda) { return -3 * k * (lambda * lambda - 1) / (2 * lambda); }

struct CubeCompression {
  double bulk_modulus = 0;        // measured -p / (dV/V) (Pa)
  double bulk_modulus_exact = 0;  // E / (3 (1 - 2 nu))
  double pressure = 0;            // fluid's, away from the cube (Pa)
  double volume_strain = 0;       // dV/V of the cube
  // The same from the particles more than a support inside the cube, where the fluid's load
  // (spread over the solid's first support by the pair sums) no longer acts.
  double bulk_modulus_interior = 0, volume_strain_interior = 0;
  double pressure_spread = 0;     // (max - min) / mean of the fluid's pressure away from the cube
  double kinetic_energy = 0;      // at the end (J)
  double dissipated_energy = 0;   // by the solid's damping (J)
  long steps = 0;
  int particles = 0;
  double seconds = 0;
};

CubeCompression run_elastic_cube(const Case& c, const std::string& backend);

}  // namespace psph
