#pragma once
// Channel flows between walls at x = 0 and x = L = 1e-3 m (plane Poiseuille, Poiseuille-Couette):
// the error against the transient series of Pazdniakou 2018 eq. 77 at given times.
#include <ostream>
#include <string>
#include <vector>

#include "scene/case_file.hpp"

namespace psph {

struct ChannelErrors {
  std::vector<double> times, errors;  // max |v - v_exact| / v_peak over fluid particles, per time
  std::vector<double> peaks;          // v_peak per time (m/s)
  long steps = 0;
  int particles = 0;
  double seconds = 0;                 // wall time of the run
};

// `c` must have its particles built; the flow is along the last axis, the walls normal to x.
ChannelErrors channel_flow_errors(const Case& c, const std::string& backend, const std::vector<double>& times);

// Two-phase layered Poiseuille flow (Pazdniakou 2018 §4.3): the steady profile of eq. 82 at the
// case's end time. Walls at x = -l and l (l from the fluid's extent), gas at x < 0.
struct TwoPhaseChannelErrors {
  double error_of_gas_peak = 0;       // max |v - v_exact| over all fluid particles / gas peak
  double error_of_liquid_peak = 0;    // max |v - v_exact| over the liquid / liquid peak (at x = 0)
  double gas_peak = 0, liquid_peak = 0;  // exact (m/s)
  long steps = 0;
  int particles = 0;
  double seconds = 0;
};
TwoPhaseChannelErrors two_phase_channel_errors(const Case& c, const std::string& backend);

// Pressure-driven channel through open boundaries (cases/open_channel_2d.toml): the steady profile
// u(x) = G x (W - x) / (2 mu), G = (p_inlet - p_outlet) / L over the interior length L between the
// buffers. The flow rate wavers as particle rows recycle through the buffers, so the velocities are
// averaged over `samples` states evenly spread over the second half of the run.
struct OpenChannelErrors {
  double profile_error = 0;  // max |<u>(x) - u(x)| / u_peak, bins of one spacing, middle half of the interior
  double flux_error = 0;     // <mean interior velocity> / (2/3 u_peak) - 1, signed
  double flux_spread = 0;    // max |mean interior velocity / <mean> - 1| over the samples
  double peak = 0;           // u_peak (m/s)
  long steps = 0;
  int particles = 0;
  double seconds = 0;
};
OpenChannelErrors open_channel_errors(const Case& c, const std::string& backend);

}  // namespace psph
