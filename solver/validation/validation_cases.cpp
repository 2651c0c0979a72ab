#include "validation/validation_cases.hpp"

#include <cmath>
#include <map>
#include <sstream>

#include "scene/case_file.hpp"
#include "scene/embedded_cases.hpp"
#include "scene/scene_builder.hpp"
#include "validation/capillary_entry.hpp"
#include "validation/channel_flow.hpp"
#include "validation/claystone_drainage.hpp"
#include "validation/damage_validations.hpp"
#include "validation/elastic_cube.hpp"
#include "validation/lame_cylinder.hpp"
#include "validation/rigid_motion.hpp"
#include "validation/rock_drainage.hpp"
#include "validation/rock_permeability.hpp"
#include "validation/laplace_bubble.hpp"
#include "validation/operator_checks.hpp"
#include "validation/oscillating_plate.hpp"
#include "validation/sessile_drop.hpp"
#include "validation/sphere_array.hpp"
#include "validation/vibrating_rod.hpp"
#include "validation/voxel_permeability.hpp"
#include "validation/voxel_references.hpp"

namespace psph {

ValidationRecord make_record(const std::string& case_name, const std::string& metric, double value,
                             double reference, double error, double tolerance) {
  ValidationRecord r;
  r.case_name = case_name, r.metric = metric, r.value = value, r.reference = reference;
  r.error = error, r.tolerance = tolerance, r.passed = std::isfinite(error) && error <= tolerance;
  return r;
}

namespace {

// Error of the velocity profile relative to its peak, at each time.
std::vector<ValidationRecord> channel_profile(const ValidationContext& ctx, const std::string& name,
                                              const std::vector<double>& times, double tolerance) {
  Case c = load_case_text(embedded_case_text(name), "cases/" + name + ".toml");
  build_particles(c);
  const ChannelErrors e = channel_flow_errors(c, ctx.backend, times);
  std::vector<ValidationRecord> out;
  for (std::size_t k = 0; k < times.size(); ++k) {
    std::ostringstream metric;
    metric << "max |v - v_exact| / v_peak at t = " << times[k] << " s";
    out.push_back(make_record(name, metric.str(), e.errors[k], 0.0, e.errors[k], tolerance));
    if (ctx.log)
      *ctx.log << "  " << name << " t = " << times[k] << " s: max error " << 100 * e.errors[k] << " % of v_peak "
               << e.peaks[k] << " m/s\n";
  }
  if (ctx.log) *ctx.log << "  " << e.particles << " particles, " << e.steps << " steps, " << e.seconds << " s\n";
  return out;
}

// Pazdniakou 2018 §4.3: paper < 1 % of the profile. The liquid moves 13x slower than the gas peak,
// so its error is also given relative to its own peak (the interface velocity). Run with explicit
// viscosity (the gas's viscous limit sets the step) and with the implicit viscous step.
std::vector<ValidationRecord> two_phase_poiseuille(const ValidationContext& ctx) {
  const std::string name = "two_phase_poiseuille_2d";
  std::vector<ValidationRecord> out;
  for (bool implicit : {false, true}) {
    toml::table tbl = toml::parse(embedded_case_text(name), std::string_view("cases/" + name + ".toml"));
    set_case_value(tbl, "solver.implicit_viscosity", toml::value<bool>(implicit));
    Case c = parse_case(tbl, "cases/" + name + ".toml");
    build_particles(c);
    const TwoPhaseChannelErrors e = two_phase_channel_errors(c, ctx.backend);
    const std::string how = implicit ? " (implicit viscosity)" : "";
    if (ctx.log)
      *ctx.log << "  " << (implicit ? "implicit" : "explicit") << " viscosity, t = " << c.end_time << " s: max error "
               << 100 * e.error_of_gas_peak << " % of the gas peak " << e.gas_peak << " m/s; liquid max error "
               << 100 * e.error_of_liquid_peak << " % of its peak " << e.liquid_peak << " m/s; " << e.particles
               << " particles, " << e.steps << " steps, " << e.seconds << " s\n";
    out.push_back(make_record(name, "max |v - v_exact| / v_gas_peak" + how, e.error_of_gas_peak, 0.0,
                              e.error_of_gas_peak, 0.01));
    out.push_back(make_record(name, "max |v - v_exact| / v_liquid_peak, liquid" + how, e.error_of_liquid_peak, 0.0,
                              e.error_of_liquid_peak, 0.03));
  }
  return out;
}

// The paper's own error magnitude (Table 2 refined, Table 3), the bound we must stay within.
double paper_error(double phi, double support_per_spacing) {
  if (support_per_spacing < 2.5) return phi < 0.4 ? 0.3103 : phi < 0.5 ? 0.3011 : 0.3366;
  if (support_per_spacing < 3.5) return phi < 0.4 ? 0.0832 : phi < 0.5 ? 0.0924 : 0.0980;
  return 0.0397;
}

std::vector<ValidationRecord> sphere_permeability(const ValidationContext& ctx) {
  std::vector<std::pair<double, double>> runs;  // (solid fraction, support / spacing)
  if (ctx.full) {
    for (double ratio : {2.0, 3.0})
      for (double phi : {0.343, 0.45, 0.5236}) runs.emplace_back(phi, ratio);
    runs.emplace_back(0.45, 4.0);
  } else {
    runs.emplace_back(0.45, 2.0);
  }
  std::vector<ValidationRecord> out;
  for (const auto& [phi, ratio] : runs) {
    const Case c = sphere_array_case(phi, ratio);
    const Permeability p = measure_permeability(c, ctx.backend);
    const double ref = sphere_array_reference(phi), err = p.K / ref - 1;
    std::ostringstream metric;
    metric << "|K/K_a - 1|, solid fraction " << phi << ", spacing R/" << ratio << " (refined)";
    out.push_back(make_record("sphere_permeability", metric.str(), p.K, ref, std::fabs(err), paper_error(phi, ratio)));
    if (ctx.log)
      *ctx.log << "  solid fraction " << phi << ", spacing R/" << ratio << ", " << p.particles << " particles: K = "
               << p.K << " m^2, error " << 100 * err << " % (paper -" << 100 * paper_error(phi, ratio)
               << " %), steady at t = " << p.time << " s, " << p.steps << " steps, " << p.seconds << " s\n";
  }
  return out;
}

// A rock crop's permeability against the lattice-Boltzmann reference on the same voxels
// (tests/reference/voxel_lbm; VALIDATION.md "Permeability of a Berea crop", "... of a Ketton
// crop"): CI at one particle per voxel, whose throats a few particles wide it over-predicts (the
// measured excess with a margin); --full at 1, 2 and 3 per voxel, the finest within 5 % (6 % for
// Ketton: +5.7 % measured), and the two methods' extrapolations within 3 %.
std::vector<ValidationRecord> rock_permeability_records(const RockCrop& rock, const ValidationContext& ctx) {
  std::vector<int> per_voxel = ctx.full ? std::vector<int>{1, 2, 3} : std::vector<int>{1};
  std::vector<double> h, K;
  for (int n : per_voxel) {
    const Permeability p = rock_permeability(rock, n, ctx.backend);
    h.push_back(1.0 / n), K.push_back(p.K);
    if (ctx.log)
      *ctx.log << "  " << n << " particle(s) per voxel, " << p.particles << " particles: K = " << p.K << " m^2 ("
               << p.K / 9.869233e-16 << " mD, " << p.K / (rock.voxel * rock.voxel) << " voxel^2), "
               << 100 * (p.K / rock.lattice_boltzmann - 1) << " % from the lattice Boltzmann's, steady at t = " << p.time
               << " s, " << p.steps << " steps, " << p.seconds << " s\n";
  }
  auto against = [&](std::size_t k, double tol) {
    return make_record(rock.case_name, "|K(" + std::to_string(per_voxel[k]) + " per voxel)/K_lattice_Boltzmann - 1|", K[k],
                       rock.lattice_boltzmann, std::fabs(K[k] / rock.lattice_boltzmann - 1), tol);
  };
  std::vector<ValidationRecord> out{against(0, rock.coarse_excess + 0.02)};
  if (!ctx.full) return out;
  const Richardson r = richardson(h, K);
  if (ctx.log)
    *ctx.log << "  Richardson: K -> " << r.limit << " m^2 (" << r.limit / 9.869233e-16 << " mD), order " << r.order
             << (r.order > 0.5 && r.order < 3 ? "\n" : " (not asymptotic)\n");
  out.push_back(against(2, rock.finest_tolerance));
  // Both methods' limits: SPH's Richardson extrapolation against the lattice Boltzmann's own.
  const double limit = rock.lattice_boltzmann_limit;
  out.push_back(make_record(rock.case_name, "|K_Richardson/K_lattice_Boltzmann_extrapolated - 1|", r.limit, limit,
                            std::fabs(r.limit / limit - 1), 0.03));
  return out;
}
std::vector<ValidationRecord> berea_permeability_records(const ValidationContext& ctx) {
  return rock_permeability_records(berea_crop(), ctx);
}
std::vector<ValidationRecord> ketton_permeability_records(const ValidationContext& ctx) {
  return rock_permeability_records(ketton_crop(), ctx);
}

// Gas drainage of Berea crops: gas percolates before the end, and the capillary pressure at breakthrough is below the driving pressure (gas enters only the throats
// that Delta P opens). CI: a 12 x 12 x 16 crop; --full: the case's 24 x 24 x 32 crop and a
// 48 x 48 x 64 one (GPU-sized: ~200,000 particles).
std::vector<ValidationRecord> berea_drainage_records(const ValidationContext& ctx) {
  struct Crop {
    std::array<long, 3> lower, size;
    double end;
  };
  std::vector<Crop> crops{{{22, 34, 20}, {12, 12, 16}, 0.006}};
  if (ctx.full) crops = {{{10, 30, 20}, {24, 24, 32}, 0.008}, {{10, 30, 20}, {48, 48, 64}, 0.03}};
  std::vector<ValidationRecord> out;
  for (const Crop& k : crops) {
    const RockDrainage r = run_rock_drainage(berea_drainage_case(k.lower, k.size, k.end), ctx.backend);
    const std::string crop = std::to_string(k.size[0]) + "x" + std::to_string(k.size[1]) + "x" + std::to_string(k.size[2]);
    if (ctx.log)
      *ctx.log << "  crop " << crop << ", " << r.particles << " particles: "
               << (r.percolation_time >= 0 ? "gas percolates at " + std::to_string(r.percolation_time) + " s"
                                           : std::string("no percolation"))
               << ", gas saturation " << r.saturation_gas << ", capillary pressure " << r.capillary_pressure << " Pa (Delta P "
               << r.driving_pressure << " Pa), " << r.steps << " steps, " << r.seconds << " s\n";
    const double tp = r.percolation_time >= 0 ? r.percolation_time : NAN;
    out.push_back(make_record("berea_drainage", "percolation time / end time, crop " + crop, tp, k.end, tp / k.end, 1.0));
    out.push_back(make_record("berea_drainage", "capillary pressure at percolation / Delta P, crop " + crop,
                              r.capillary_pressure, r.driving_pressure, r.capillary_pressure / r.driving_pressure, 1.0));
  }
  return out;
}

// Laplace law at several radii (in spacings; the quintic spline's smoothing length is one
// spacing, its support three). In 3D the run ends at 0.15 s (the jump has settled by 0.1 s).
std::vector<ValidationRecord> laplace(const ValidationContext& ctx, int dimension, const std::vector<double>& radii) {
  const std::string name = dimension == 3 ? "laplace_bubble_3d" : "laplace_bubble_2d";
  const char* law = dimension == 3 ? "2 sigma/R" : "sigma/R";
  std::vector<ValidationRecord> out;
  for (double r : radii) {
    Case c = laplace_bubble_case(r, "quintic_spline", 3, dimension);
    if (dimension == 3) c.end_time = 0.15;
    const BubbleMeasurement b = measure_bubble(c, ctx.backend);
    const double err = b.jump / b.jump_exact - 1;
    std::ostringstream metric, spurious;
    metric << "|dp / (" << law << ") - 1|, R = " << r << " spacings";
    out.push_back(make_record(name, metric.str(), b.jump, b.jump_exact, std::fabs(err), 0.02));
    spurious << "max |v| / (sigma/mu) at rest, R = " << r << " spacings";
    const double vs = b.spurious_speed / b.capillary_speed;
    out.push_back(make_record(name, spurious.str(), vs, 0.0, vs, 0.01));
    if (ctx.log)
      *ctx.log << "  R = " << r << " spacings (" << b.radius << " m from the gas volume), " << b.particles
               << " particles: p_gas - p_liquid = " << b.jump << " Pa against " << law << " = " << b.jump_exact
               << " Pa, error " << 100 * err << " %; spurious speed " << vs << " sigma/mu; " << b.steps << " steps, "
               << b.seconds << " s\n";
  }
  return out;
}

// Static contact angle of a 2D drop on a flat wall (ours: the references give no figure): the
// error is the absolute difference in degrees (GUIDE §5). Each drop starts 15 degrees towards 90
// and must relax to the wall's angle. The 150-degree drop has twice the radius: at 10 spacings its
// base is 7 spacings wide, two contact lines within a support of each other, and it hops off the
// wall; the 30-degree drop spreads slowly and runs twice as long.
std::vector<ValidationRecord> contact_angle_2d(const ValidationContext& ctx) {
  struct Drop {
    double theta, radius_spacings, end_time;
  };
  const std::vector<Drop> drops = ctx.full ? std::vector<Drop>{{30, 10, 1.2}, {60, 10, 0.6}, {90, 10, 0.6},
                                                               {120, 10, 0.6}, {150, 20, 0.6}}
                                           : std::vector<Drop>{{60, 10, 0.6}, {120, 10, 0.6}};
  std::vector<ValidationRecord> out;
  for (const Drop& d : drops) {
    const double theta = d.theta;
    Case c = sessile_drop_case(theta, theta + (theta < 90 ? 15 : -15), d.radius_spacings);
    c.end_time = d.end_time;
    const ContactAngle a = measure_contact_angle(c, ctx.backend);
    std::ostringstream metric, spurious;
    metric << "|angle - theta| (degrees), theta = " << theta;
    out.push_back(make_record("sessile_drop_2d", metric.str(), a.angle, theta, std::fabs(a.angle - theta), 5.0));
    if (ctx.log)
      *ctx.log << "  theta = " << theta << " deg: measured " << a.angle << " deg (circle radius " << a.radius
               << " m), speed at the end " << a.spurious_speed / a.capillary_speed << " sigma/mu; " << a.particles
               << " particles, " << a.steps << " steps, " << a.seconds << " s\n";
  }
  return out;
}

// Pressure-driven channel through open boundaries (ours): the time-averaged profile in the middle
// half of the channel and the mean velocity (the flow rate the imposed pressure drop drives).
std::vector<ValidationRecord> open_channel(const ValidationContext& ctx) {
  const std::string name = "open_channel_2d";
  Case c = load_case_text(embedded_case_text(name), "cases/" + name + ".toml");
  build_particles(c);
  const OpenChannelErrors e = open_channel_errors(c, ctx.backend);
  if (ctx.log)
    *ctx.log << "  profile " << 100 * e.profile_error << " % of u_peak " << e.peak << " m/s, mean velocity "
             << 100 * e.flux_error << " % (samples within " << 100 * e.flux_spread << " % of their mean); "
             << e.particles << " particles, " << e.steps << " steps, " << e.seconds << " s\n";
  return {make_record(name, "max |<v> - v_exact| / v_peak, middle half of the channel, time-averaged", e.profile_error,
                      0.0, e.profile_error, 0.03),
          make_record(name, "<mean velocity> / exact mean (flow rate from the imposed pressure drop)",
                      1 + e.flux_error, 1.0, std::fabs(e.flux_error), 0.03)};
}

// Capillary entry (ours): below the Young-Laplace entry pressure the meniscus bulges into the slit
// by at most w/2 (a half-disc) plus a spacing; above it the gas runs into the slit, past w. The
// bracket 0.9 / 1.1 is the issue's 10 %. Recorded as the depth reached over the slit width.
std::vector<ValidationRecord> capillary_entry(const ValidationContext& ctx) {
  std::vector<ValidationRecord> out;
  for (double ratio : {0.9, 1.1}) {
    const Case c = capillary_entry_case(ratio);
    const EntryResult r = run_capillary_entry(c, ctx.backend);
    const double depth = r.depth / r.width;
    std::ostringstream metric;
    metric << "gas depth in the slit / w at " << ratio << " x the entry pressure ("
           << (ratio < 1 ? "stays out: <= 0.5 + 1 spacing" : "enters: > 1") << ")";
    const double bound = 0.5 + c.scene.options.spacing / r.width;
    // The error is how far the depth is on the wrong side of its bound (in widths; 0 passes).
    const double err = std::max(0.0, ratio < 1 ? depth - bound : 1 - depth);
    out.push_back(make_record("capillary_entry_2d", metric.str(), depth, ratio < 1 ? bound : 1.0, err, 0.0));
    if (ctx.log)
      *ctx.log << "  drive " << r.drive << " Pa = " << ratio << " x entry pressure " << r.entry_pressure
               << " Pa: gas reached " << depth << " w into the slit; " << r.particles << " particles, " << r.steps
               << " steps, " << r.seconds << " s\n";
  }
  return out;
}

// Longitudinal modes of a 1D rod (Deptulski 2021 Ch. 3, Tables 2-3), with the total energy
// (kinetic + elastic) within 1 % over the run: the stress form (the default) against the thesis'
// own TLSPH beta^2, which carries the same non-local softening (within 0.5 % at lambda/L = 0.05,
// 3 % at 0.5); the displacement form against the local continuum (k pi)^2, ((2k - 1) pi / 2)^2 at
// lambda/L = 0.05. At lambda/L = 0.5 the
// clamped-free modes 2 and 3 are left out: the initial sine is no eigenmode of the wide-support
// rod there, and the period read moves by several % with the run length (VALIDATION.md).
std::vector<ValidationRecord> vibrating_rod(const ValidationContext& ctx) {
  std::vector<ValidationRecord> out;
  struct Run {
    SolidFormulation form;
    double support_over_length;
    bool clamped_free;
    int k;
    double thesis, tolerance;  // thesis SPH beta^2 (0: compare with the local continuum)
  };
  const std::vector<Run> runs = {
      {SolidFormulation::Stress, 0.05, false, 1, 9.85, 0.005},  {SolidFormulation::Stress, 0.05, false, 2, 39.16, 0.005},
      {SolidFormulation::Stress, 0.05, false, 3, 87.19, 0.005}, {SolidFormulation::Stress, 0.05, true, 1, 2.47, 0.005},
      {SolidFormulation::Stress, 0.05, true, 2, 22.10, 0.005},  {SolidFormulation::Stress, 0.05, true, 3, 60.98, 0.005},
      {SolidFormulation::Stress, 0.5, false, 1, 8.03, 0.03},    {SolidFormulation::Stress, 0.5, false, 2, 17.04, 0.03},
      {SolidFormulation::Stress, 0.5, false, 3, 12.71, 0.03},   {SolidFormulation::Stress, 0.5, true, 1, 2.34, 0.03},
      {SolidFormulation::Displacement, 0.05, false, 1, 0, 0.005}, {SolidFormulation::Displacement, 0.05, false, 2, 0, 0.005},
      {SolidFormulation::Displacement, 0.05, false, 3, 0, 0.005}, {SolidFormulation::Displacement, 0.05, true, 1, 0, 0.005},
      {SolidFormulation::Displacement, 0.05, true, 2, 0, 0.005},  {SolidFormulation::Displacement, 0.05, true, 3, 0, 0.005},
  };
  for (const Run& run : runs) {
    const Case c = vibrating_rod_case(run.k, run.clamped_free, run.form, run.support_over_length);
    const RodVibration r = run_vibrating_rod(c, run.k, run.clamped_free, ctx.backend);
    std::ostringstream mode;
    mode << (run.form == SolidFormulation::Stress ? "stress form, " : "displacement form, ") << "lambda/L = "
         << run.support_over_length << ", " << (run.clamped_free ? "clamped-free" : "clamped-clamped") << " mode " << run.k;
    const double reference = run.thesis > 0 ? run.thesis : r.beta2_local;
    const std::string against = run.thesis > 0 ? " (against the thesis' SPH)" : " (against the local continuum)";
    out.push_back(make_record("vibrating_rod_1d", "beta^2, " + mode.str() + against, r.beta2, reference,
                              std::fabs(r.beta2 / reference - 1), run.tolerance));
    out.push_back(make_record("vibrating_rod_1d", "max |E / E0 - 1| over the run, " + mode.str(), r.energy_drift, 0.0,
                              r.energy_drift, 0.01));
    if (ctx.log)
      *ctx.log << "  " << mode.str() << ": beta^2 = " << r.beta2 << " (reference " << reference << ", local continuum "
               << r.beta2_local << "), energy within " << 100 * r.energy_drift << " %; " << r.particles << " particles, "
               << r.steps << " steps, " << r.seconds << " s\n";
  }
  return out;
}

// First bending frequency of a cantilever plate (Gray, Monaghan & Swift 2001) against the
// Euler-Bernoulli value, and the energy over the run: with --full at 1 mm spacing (H = 20 spacings)
// within the issue's 3 %; at the case's 2 mm (H = 10), which CI runs, the bending is softer by the
// truncated supports of the free surfaces (VALIDATION.md) and the bound is 4 %.
std::vector<ValidationRecord> oscillating_plate(const ValidationContext& ctx) {
  const double spacing = ctx.full ? 1e-3 : 0;
  const PlateVibration r = run_oscillating_plate(oscillating_plate_case(0.001, spacing), ctx.backend);
  if (ctx.log)
    *ctx.log << "  omega = " << r.omega << " rad/s against Euler-Bernoulli " << r.omega_exact << " rad/s; tip amplitude "
             << r.tip_amplitude << " m; energy within " << 100 * r.energy_drift << " %; " << r.particles << " particles, "
             << r.steps << " steps, " << r.seconds << " s\n";
  return {make_record("oscillating_plate_2d", "first bending frequency / Euler-Bernoulli", r.omega / r.omega_exact, 1.0,
                      std::fabs(r.omega / r.omega_exact - 1), ctx.full ? 0.03 : 0.04),
          make_record("oscillating_plate_2d", "max |E / E0 - 1| (kinetic + elastic)", r.energy_drift, 0.0, r.energy_drift,
                      0.01)};
}

// Bulk modulus of an elastic cube loaded by the fluid around it (Pazdniakou 2018 §4.5, eq. 83;
// paper: 0.33 % at small, 11.4 % at large volume changes). The traction coupling (the default)
// holds a uniform pressure exactly, so K is the constitutive one at any resolution in small
// strain; at dV/V ~ 8 % the small-strain model itself departs. --full also reports the pair
// couplings (Pazdniakou's action and reaction), not asserted: 4-6 % stiff at 10 spacings.
std::vector<ValidationRecord> elastic_cube(const ValidationContext& ctx) {
  std::vector<ValidationRecord> out;
  auto run = [&](const char* what, const Case& c, double tolerance, bool assert_it) {
    const CubeCompression r = run_elastic_cube(c, ctx.backend);
    const double ratio = r.bulk_modulus / r.bulk_modulus_exact;
    std::ostringstream metric;
    metric << "bulk modulus / E / (3 (1 - 2 nu)), " << what << ", dV/V = " << r.volume_strain;
    if (assert_it)
      out.push_back(make_record("elastic_cube_3d", metric.str(), ratio, 1.0, std::fabs(ratio - 1), tolerance));
    if (ctx.log)
      *ctx.log << "  " << what << ": K = " << r.bulk_modulus << " Pa (" << 100 * (ratio - 1) << " %; inside "
               << 100 * (r.bulk_modulus_interior / r.bulk_modulus_exact - 1) << " %), p = " << r.pressure
               << " Pa, dV/V = " << r.volume_strain << ", kinetic energy left " << r.kinetic_energy << " J; "
               << r.particles << " particles, " << r.steps << " steps, " << r.seconds << " s\n";
  };
  run("small strain", elastic_cube_case(ctx.full ? 0.5e-3 : 0), 0.005, true);
  run("large strain (p_b = 40 kPa)", elastic_cube_case(0, SolidCoupling::Traction, 4e4), 0.12, true);
  {  // Saint Venant-Kirchhoff at the same load: the pressure against its own law at the stretch reached
    const CubeCompression r =
        run_elastic_cube(elastic_cube_case(0, SolidCoupling::Traction, 4e4, SolidModel::SaintVenantKirchhoff), ctx.backend);
    const double ratio = r.pressure / svk_pressure(r.bulk_modulus_exact, 1 + r.volume_strain / 3);
    std::ostringstream metric;
    metric << "p / Saint Venant-Kirchhoff p(lambda), large strain, dV/V = " << r.volume_strain;
    out.push_back(make_record("elastic_cube_3d", metric.str(), ratio, 1.0, std::fabs(ratio - 1), 0.02));
    if (ctx.log)
      *ctx.log << "  large strain, Saint Venant-Kirchhoff: p = " << r.pressure << " Pa against "
               << svk_pressure(r.bulk_modulus_exact, 1 + r.volume_strain / 3) << " Pa (" << 100 * (ratio - 1)
               << " %) at dV/V = " << r.volume_strain << "; " << r.steps << " steps, " << r.seconds << " s\n";
  }
  if (ctx.full) {
    run("pair coupling", elastic_cube_case(0, SolidCoupling::Pair), 0, false);
    run("pair coupling, eq. 74 pressure", elastic_cube_case(0, SolidCoupling::PairEos), 0, false);
  }
  return out;
}

// Radial and hoop stress of a ring pressurised by the water inside it against Lame, relative to
// the pressure, over the particles a support and more from both surfaces (both bodies on
// concentric shells: a lattice's staircase makes the ring ~10 % too soft, VALIDATION.md).
std::vector<ValidationRecord> lame_cylinder(const ValidationContext& ctx) {
  const LameComparison r = run_lame_cylinder(lame_cylinder_case(ctx.full ? 0.25e-3 : 0), ctx.backend);
  if (ctx.log)
    *ctx.log << "  p = " << r.pressure << " Pa, a = " << r.inner << " m, b = " << r.outer << " m; |error| / p: radial rms "
             << r.radial_rms << " (max " << r.radial_error << "), hoop rms " << r.hoop_rms << " (max " << r.hoop_error
             << ") over " << r.compared << " particles; kinetic energy left " << r.kinetic_energy << " J; "
             << r.particles << " particles, " << r.steps << " steps, " << r.seconds << " s\n";
  return {make_record("lame_cylinder_2d", "rms |sigma_rr - Lame| / p, a support from both surfaces", r.radial_rms, 0.0,
                      r.radial_rms, 0.03),
          make_record("lame_cylinder_2d", "rms |sigma_tt - Lame| / p, a support from both surfaces", r.hoop_rms, 0.0,
                      r.hoop_rms, 0.03)};
}

// A torque-free symmetric top falling freely: every particle against the analytical motion
// (Newton-Euler, Pazdniakou eqs. 62-69), angular momentum and rotational energy kept.
std::vector<ValidationRecord> rigid_top(const ValidationContext& ctx) {
  const TopTrajectory r = run_rigid_top(rigid_case("rigid_top_3d"), ctx.backend);
  if (ctx.log)
    *ctx.log << "  particles within " << r.position_error << " of the body's length of the analytical trajectory, centre "
             << r.centre_error << " of the fall; |L| kept to " << r.momentum_drift << ", rotational energy to "
             << r.energy_drift << "; " << r.precession_turns << " turns of precession; " << r.particles
             << " particles, " << r.steps << " steps, " << r.seconds << " s\n";
  return {make_record("rigid_top_3d", "max |x - x_exact| / body length (every particle, 10 samples)", r.position_error,
                      0.0, r.position_error, 1e-4),
          make_record("rigid_top_3d", "max |X - X_exact| / distance fallen", r.centre_error, 0.0, r.centre_error, 1e-9),
          make_record("rigid_top_3d", "max | |L| / |L0| - 1 |", r.momentum_drift, 0.0, r.momentum_drift, 1e-9),
          make_record("rigid_top_3d", "max |E_rot / E_rot0 - 1|", r.energy_drift, 0.0, r.energy_drift, 1e-5)};
}

// A cylinder settling through a periodic square array at Re << 1: the drag at its terminal
// velocity against Sangani & Acrivos (1982) at the lattice's solid fraction; --full at half the
// spacing (14 spacings in the radius).
std::vector<ValidationRecord> settling_cylinder(const ValidationContext& ctx) {
  const SettlingDrag r = run_settling_cylinder(rigid_case("settling_cylinder_2d", ctx.full ? 0.5e-3 : 0), ctx.backend);
  if (ctx.log)
    *ctx.log << "  solid fraction " << r.solid_fraction << ": F / (mu U) = " << r.drag << " against " << r.drag_reference
             << " (" << 100 * (r.drag / r.drag_reference - 1) << " %), changed by " << r.drag_change
             << " over the last tenth; Re = " << r.reynolds << ", omega = " << r.angular_velocity << " rad/s; "
             << r.particles << " particles, " << r.steps << " steps, " << r.seconds << " s\n";
  return {make_record("settling_cylinder_2d", "drag F / (mu U) at the terminal velocity / Sangani-Acrivos", r.drag / r.drag_reference,
                      1.0, std::fabs(r.drag / r.drag_reference - 1), 0.02),
          make_record("settling_cylinder_2d", "relative change of the drag over the run's last tenth", r.drag_change, 0.0,
                      r.drag_change, 0.002)};
}

// Voxel geometries with known flow (VALIDATION.md "Flow through voxel images"): each at 1 and 2
// particles per voxel (--full: up to 4), against the lattice-Boltzmann reference on the same
// voxels and, for square ducts, the exact series; two ducts one voxel apart also against the single
// duct (what leaks through the wall between them).
std::vector<ValidationRecord> voxel_permeability_records(const ValidationContext& ctx) {
  std::vector<ValidationRecord> out;
  std::map<std::pair<long, int>, double> duct;  // a square duct's K by width and resolution
  for (const VoxelReference& ref : voxel_references()) {
    const int finest = ctx.full ? ref.finest : std::min(ref.finest, 2);
    for (int n = 1; n <= finest; ++n) {
      const VoxelPermeability p = voxel_permeability(ref.geometry, n, ctx.backend);
      const double exact = voxel_exact_permeability(ref.geometry), tol = ref.tolerance[std::size_t(n - 1)];
      if (ctx.log)
        *ctx.log << "  " << ref.name << ", " << n << " per voxel, " << p.run.particles << " particles: K = " << p.K_voxels
                 << " voxel^2, " << 100 * (p.K_voxels / ref.lbm - 1) << " % from the lattice Boltzmann's " << ref.lbm
                 << " (ideal shape " << exact << "), steady at t = " << p.run.time << " s, " << p.run.steps << " steps, "
                 << p.run.seconds << " s\n";
      const std::string at = ref.name + ", " + std::to_string(n) + " per voxel";
      out.push_back(make_record("voxel_permeability", "|K/K_lattice_Boltzmann - 1|, " + at, p.K_voxels, ref.lbm,
                                std::fabs(p.K_voxels / ref.lbm - 1), tol));
      if (ref.exact)
        out.push_back(make_record("voxel_permeability", "|K/K_exact - 1|, " + at, p.K_voxels, exact,
                                  std::fabs(p.K_voxels / exact - 1), tol));
      const long w = ref.geometry.width;
      if (ref.geometry.kind == "duct") duct[{w, n}] = p.K_voxels;
      if (ref.geometry.kind == "twin_ducts" && duct.count({w, n})) {
        // Each duct carries the single duct's flow: K_twin = 2 (w+2)^2 / ((2w+3)(w+2)) K_duct.
        const double alone = duct[{w, n}] * 2 * double(w + 2) / double(2 * w + 3);
        out.push_back(make_record("voxel_permeability", "flow through the wall: |K_twin / (2 K_duct A_duct/A_twin) - 1|, " + at,
                                  p.K_voxels, alone, std::fabs(p.K_voxels / alone - 1), n == 1 ? 0.06 : 0.005));
      }
    }
  }
  return out;
}

}  // namespace

const std::vector<ValidationCase>& validation_cases() {
  static const std::vector<ValidationCase> cases = {
      {"kernels", "kernel normalisation (1D/2D/3D) and Deptulski Table 2.1 corrected-gradient pair values",
       [](const ValidationContext&) { return operator_checks(); }},
      {"poiseuille_2d", "2D plane Poiseuille flow from rest against the transient series",
       [](const ValidationContext& ctx) { return channel_profile(ctx, "poiseuille_2d", {0.02, 0.1, 0.5}, 0.005); }},
      // Goal 0.5 % (issue), paper 0.4 %. Measured 0.48 / 0.12 / 0.05 / 0.38 % with the tensor
      // Laplacian the case file selects (VALIDATION.md).
      {"poiseuille_couette", "Pazdniakou 2018 §4.1 transient Poiseuille-Couette flow (paper: 0.4 %)",
       [](const ValidationContext& ctx) {
         return channel_profile(ctx, "poiseuille_couette", {0.01, 0.04, 0.08, 1.0}, 0.005);
       }},
      {"two_phase_poiseuille_2d",
       "Pazdniakou 2018 §4.3 gas-water layered Poiseuille flow, density ratio 1000, viscosity ratio 100 (paper: 1 %)",
       two_phase_poiseuille},
      {"sphere_permeability", "Pazdniakou 2018 §4.2 permeability of periodic sphere arrays (Tables 2-3)",
       sphere_permeability, 0.01},
      {"berea_permeability", "permeability of a Berea sandstone crop (micro-CT image) against a lattice-Boltzmann solve of the same voxels",
       berea_permeability_records, 0.01},
      {"ketton_permeability", "permeability of a Ketton limestone crop (micro-CT image) against a lattice-Boltzmann solve of the same voxels",
       ketton_permeability_records, 0.01},
      {"voxel_permeability", "permeability of voxel ducts, slits and sphere arrays against exact values and a lattice-Boltzmann reference",
       voxel_permeability_records, 0.01},
      {"berea_drainage", "gas drains water from a Berea sandstone crop: it percolates, Pc at breakthrough below Delta P",
       berea_drainage_records},
      {"claystone_drainage", "gas drains a claystone sample with a damaging clay matrix at 6 MPa: the monitors agree with each other (--full: Pazdniakou 2018 Table 5)",
       claystone_drainage_records},
      {"laplace_bubble_2d", "Pazdniakou 2018 §4.4 Laplace law, here a 2D bubble (paper: 2 % in 3D)",
       [](const ValidationContext& ctx) {
         return laplace(ctx, 2, ctx.full ? std::vector<double>{4, 6, 8, 12, 16} : std::vector<double>{8, 12});
       }},
      {"laplace_bubble_3d", "Pazdniakou 2018 §4.4 Laplace law for a 3D bubble (paper: 2 %)",
       [](const ValidationContext& ctx) {
         return laplace(ctx, 3, ctx.full ? std::vector<double>{4, 6, 8} : std::vector<double>{4});
       }},
      {"open_channel_2d", "2D channel flow driven by a pressure inlet and outlet (open boundaries)", open_channel},
      {"capillary_entry_2d", "gas entering a water-filled slit: Young-Laplace entry pressure within 10 % (ours)",
       capillary_entry},
      {"sessile_drop_2d", "static contact angle of a 2D drop on a flat wall, 30-150 degrees (ours: 5 degrees)",
       contact_angle_2d},
      {"vibrating_rod_1d", "Deptulski 2021 Ch. 3 longitudinal modes of a clamped-clamped and a clamped-free rod",
       vibrating_rod},
      {"oscillating_plate_2d", "cantilever plate: first bending frequency against Euler-Bernoulli (3 % with --full)",
       oscillating_plate},
      {"softening_bar_2d", "Deptulski 2021 §4.2 dynamic softening bar with PCW damage: plateau, onset, band width",
       softening_bar},
      {"plate_inclusion_2d", "Deptulski 2021 §4.3 plate with a rigid inclusion, AT-2 in tension and compression",
       plate_inclusion},
      {"pressurised_pore_2d", "water pressurised in a lens-shaped pore in clay: damage starts at the tips, later under confinement",
       pressurised_pore},
      {"elastic_cube_3d", "Pazdniakou 2018 §4.5 elastic cube compressed by fluid pressure: bulk modulus (0.5 %)",
       elastic_cube},
      {"lame_cylinder_2d", "thick-walled cylinder pressurised by fluid: radial and hoop stress against Lame (3 %)",
       lame_cylinder},
      {"rigid_top_3d", "rigid symmetric top in free fall: every particle against the analytical Newton-Euler motion",
       rigid_top},
      {"settling_cylinder_2d", "rigid cylinder settling through a periodic array: drag against Sangani & Acrivos (2 %)",
       settling_cylinder},
  };
  return cases;
}

}  // namespace psph
