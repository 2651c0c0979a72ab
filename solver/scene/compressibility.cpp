#include "scene/compressibility.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "scene/pore_grid.hpp"

namespace psph {
namespace {

bool is_fluid(const Scene& sc, int m) { return sc.materials[m].props.kind == MaterialKind::Fluid; }

// The extent of material m's particles along axis k, one spacing wide at least.
double extent_of(const Scene& sc, int m, int k) {
  double lo = 1e300, hi = -1e300;
  const int D = sc.dimension;
  for (int i = 0; i < sc.count(); ++i)
    if (sc.material[i] == m)
      lo = std::min(lo, sc.x[i * D + k]), hi = std::max(hi, sc.x[i * D + k]);
  return hi >= lo ? hi - lo + sc.options.spacing : 0.0;
}

std::string key(const SceneMaterial& m, const char* k) { return "materials." + m.name + "." + k; }

std::string fixed(double v, int digits = 3) {
  std::ostringstream o;
  o.precision(digits);
  o << v;
  return o.str();
}

// Each fluid's terms.
class Terms {
 public:
  Terms(const Case& c, const PoreGrid& pores) : c_(c), sc_(c.scene), pores_(pores) {
    const int D = sc_.dimension;
    for (int i = 0; i < sc_.count(); ++i) {
      double s = 0;
      for (int k = 0; k < D; ++k) s += sc_.v[i * D + k] * sc_.v[i * D + k];
      v0_ = std::max(v0_, std::sqrt(s));
    }
  }

  void add(int f, std::vector<CompressibilityTerm>& out) const {
    const SceneMaterial& m = sc_.materials[f];
    const double cc = m.props.sound_speed, rc2 = m.props.rest_density * cc * cc;
    auto term = [&](const std::string& what, const std::string& keys, const std::string& detail, double dp, double value,
                    double power, double stiffness = 0, double sound_power = 2) {
      if (value > 0) out.push_back({m.name, what, keys, detail, dp, value, power, stiffness, sound_power});
    };
    body_force(f, rc2, term);
    drives(f, rc2, term);
    capillary(rc2, term);
    loads(f, rc2, term);
    speed(f, cc, term);
    impact(f, cc, term);
  }

 private:
  // Imposed pressures: the regions' body forces over their extent, the open boundaries' buffers.
  template <class Add>
  void drives(int f, double rc2, Add& term) const {
    const Material& m = sc_.materials[f].props;
    for (const auto& r : sc_.force_regions) {
      if (r.material != f) continue;
      const double dp = region_pressure(r);
      term("pressure drive", "body_force_region", "rho |a| over the region's extent", dp, dp / rc2, 1);
    }
    const SceneOpenBoundary& ob = sc_.open_boundary;
    if (ob.axis < 0) return;
    const double pb = m.background_pressure;
    const double dp = std::max(std::fabs(ob.inlet_pressure - pb), std::fabs(ob.outlet_pressure - pb));
    term("pressure drive", "open_boundary.inlet_pressure, open_boundary.outlet_pressure", "largest imposed |p - p_b|", dp,
         dp / rc2, 1);
  }

  // Loads on the solids that the pore fluid carries: tractions, and the background pressure that
  // the solids feel as p - p_ref (solid.reference_pressure, Terzaghi's effective stress) and give way
  // to by p / K, the fluid expanding as much, at most to p / (rho c^2).
  template <class Add>
  void loads(int f, double rc2, Add& term) const {
    double traction = 0, k_solid = 0;  // the largest traction, the softest elastic solid's bulk modulus
    for (const auto& l : sc_.solid_loads)
      if (!l.velocity)
        for (int k = 0; k < sc_.dimension; ++k) traction = std::max(traction, std::fabs(l.value[k]));
    term("confinement", "solid_load (traction)", "the largest traction on the solids, carried by the pore fluid",
         traction, traction / rc2, 0);
    for (const auto& mm : sc_.materials)
      if (mm.props.kind == MaterialKind::Elastic && (k_solid == 0 || mm.props.bulk_modulus < k_solid)) k_solid = mm.props.bulk_modulus;
    if (!(k_solid > 0)) return;
    const double pb = std::fabs(sc_.materials[f].props.background_pressure +
                                sc_.options.background_pressure_rate * c_.end_time - sc_.options.solid_reference_pressure);
    term("pressure on the solids", "solver.background_pressure, solver.background_pressure_rate, solid.reference_pressure",
         "the background pressure the elastic solids take (at the end of the run), over the stiffer of the fluid and "
         "the softest solid",
         pb, pb / std::max(rc2, k_solid), 0, k_solid);
  }

  // Along each axis with a force: a closed axis (or a fluid that does not span a periodic one) holds
  // a hydrostatic head rho g H; a periodic one the pressure field of Stokes flow through its sections.
  template <class Add>
  void body_force(int f, double rc2, Add& term) const {
    const SceneMaterial& m = sc_.materials[f];
    for (int k = 0; k < sc_.dimension; ++k) {
      const double g = std::fabs(m.body_force[k]);
      if (g == 0) continue;
      const double L = extent_of(sc_, f, k), rho = m.props.rest_density;
      const double H = sc_.periodic[k] ? pores_.periodic_head(k) : L;
      const std::string axis(1, "xyz"[k]);
      const std::string how = H < 0 ? "" : sc_.periodic[k] ? "Stokes flow through the sections along periodic " + axis +
                                                                  " (resistance ~ 1/A^2): head over " + fixed(H / L) + " of " + axis
                                                           : "hydrostatic head over the fluid's height along " + axis;
      const double h = H < 0 ? L : H;
      term("body force", key(m, "body_force"), H < 0 ? "head over " + axis + ": no open path along it" : how,
           rho * g * h, rho * g * h / rc2, 1);
    }
  }

  // Laplace pressure (D - 1) sigma / r at the smallest radius an interface takes: one support radius.
  template <class Add>
  void capillary(double rc2, Add& term) const {
    const double sigma = sc_.options.surface_tension;
    if (!(sigma > 0) || !c_.two_phase) return;
    const double r = sc_.options.support_radius, dp = (sc_.dimension - 1) * sigma / r;
    term("capillary pressure", "interface.surface_tension", "(D-1) sigma / r at r = the support radius", dp, dp / rc2, 0);
  }

  // (v/c)^2 at the largest speed the case implies: its initial and wall speeds, Stokes flow in its
  // widest pore along a periodic force, and, in a drop or bubble that no drive pushes, the flow that
  // surface tension drives at up to sigma / (2 mu_liquid) (within a factor of 2 on the Laplace
  // bubble and the sessile drop, VALIDATION.md).
  template <class Add>
  void speed(int f, double cc, Add& term) const {
    const SceneMaterial& m = sc_.materials[f];
    if (v0_ > 0) term("speed", "initial velocities", "the largest initial or wall speed " + fixed(v0_) + " m/s", 0, v0_ * v0_ / (cc * cc), 0);
    const double nu = m.props.viscosity / m.props.rest_density;
    for (int k = 0; k < sc_.dimension; ++k) {
      const double g = std::fabs(m.body_force[k]);
      if (g == 0 || !sc_.periodic[k] || !(nu > 0)) continue;
      const double w = pores_.widest(k), v = g * w * w / (8 * nu);  // plane Poiseuille peak
      term("speed", key(m, "body_force"), "Stokes flow g w^2 / (8 nu) in the widest pore, w = " + fixed(w) + " m: " + fixed(v) + " m/s",
           0, v * v / (cc * cc), 2);
    }
    const double mu = liquid_viscosity();
    if (!c_.two_phase || !(sc_.options.surface_tension > 0) || !(mu > 0) || drive_pressure() > 0) return;
    const double v = sc_.options.surface_tension / (2 * mu);
    term("speed", "interface.surface_tension", "capillary flow at sigma / (2 mu_liquid) = " + fixed(v) + " m/s", 0,
         v * v / (cc * cc), 0);
  }

  // Impacts: a fluid that moves is stopped at once and compressed by rho c v (Joukowsky), v/c of its
  // density, not (v/c)^2.
  //  - Free fall over a free surface's height onto a wall, sqrt(2 g H) (measured on dam_break_3d:
  //    4.3 % at c = 20 m/s, where (v/c)^2 gave 0.5 %).
  //  - Driven through pores, a Haines jump: the Laplace pressure 2 sigma / w drives the liquid
  //    through a throat about as long as wide at the mean Poiseuille speed sigma / (6 mu) (slit, 2D)
  //    or sigma / (8 mu) (pipe, 3D) until the meniscus stops against the next throat. Measured, 1/c
  //    rather than 1/c^2: drainage_2d 5.1 / 3.0 / 1.9 % at c = 1 / 2 / 3 m/s before the gas
  //    percolates (estimate 6.7 / 3.3 / 2.2 %), capillary_entry_2d 5.4 / 2.3 % at 1 / 2 m/s,
  //    berea_drainage 2.6 % at 2 m/s (estimate 2.5 %).
  //  - Once a driven gas percolates, it runs through the open path at up to sqrt(2 dp / rho) (the
  //    drive turned into speed) and stops against water and grains (drainage_2d: 22-30 % at c =
  //    1 m/s, 10.9 % at 2 m/s); a run that ends at percolation (time.after_percolation = 0) never
  //    sees it.
  template <class Add>
  void impact(int f, double cc, Add& term) const {
    const SceneMaterial& m = sc_.materials[f];
    const int D = sc_.dimension;
    for (int k = 0; k < D; ++k) {
      const double g = std::fabs(m.body_force[k]);
      if (g == 0 || sc_.periodic[k] || !pores_.free_surface()) continue;
      const double v = std::sqrt(2 * g * extent_of(sc_, f, k));
      term("impact", key(m, "body_force"), "free fall over the fluid's height at " + fixed(v) + " m/s onto a wall, rho c v: v/c",
           0, v / cc, 0.5, 0, 1);
    }
    const double dp = drive_pressure(), mu = liquid_viscosity(), rho = m.props.rest_density;
    if (!c_.two_phase || !(dp > 0)) return;
    if (sc_.options.surface_tension > 0 && mu > 0) {
      const double v = sc_.options.surface_tension / ((D == 3 ? 8 : 6) * mu);
      term("impact", "interface.surface_tension",
           "Haines jumps at sigma / (" + std::string(D == 3 ? "8" : "6") + " mu_liquid) = " + fixed(v) + " m/s stopped at rho c v, v/c",
           0, v / cc, 0, 0, 1);
    }
    if (c_.after_percolation == 0 || !(rho > 0)) return;
    const double v = std::sqrt(2 * dp / rho);
    const std::string keys = std::string(sc_.force_regions.empty() ? "" : "body_force_region") +
                             (sc_.open_boundary.axis < 0 ? "" : sc_.force_regions.empty() ? "open_boundary" : ", open_boundary");
    term("impact", keys, "once the gas percolates: its jet at sqrt(2 dp / rho) = " + fixed(v) + " m/s stopped at rho c v, v/c", 0,
         v / cc, 0.5, 0, 1);
  }

  // The most viscous liquid's viscosity (a fluid with a positive colour), 0 without one.
  double liquid_viscosity() const {
    double mu = 0;
    for (const auto& mm : sc_.materials)
      if (mm.props.kind == MaterialKind::Fluid && mm.props.colour > 0) mu = std::max(mu, double(mm.props.viscosity));
    return mu;
  }

  // A region's drive: rho |a| over its extent inside the domain (Pa).
  double region_pressure(const SceneForceRegion& r) const {
    double dp = 0;
    for (int k = 0; k < sc_.dimension; ++k)
      dp += sc_.materials[r.material].props.rest_density * std::fabs(r.acceleration[k]) *
            std::max(0.0, std::min(r.upper[k], sc_.upper[k]) - std::max(r.lower[k], sc_.lower[k]));
    return dp;
  }

  // The largest pressure the drives impose: a region's, an open boundary's |p - p_b| (Pa).
  double drive_pressure() const {
    double dp = 0;
    for (const auto& r : sc_.force_regions) dp = std::max(dp, region_pressure(r));
    const SceneOpenBoundary& ob = sc_.open_boundary;
    if (ob.axis >= 0)
      for (const auto& m : sc_.materials)
        if (m.props.kind == MaterialKind::Fluid)
          dp = std::max({dp, std::fabs(ob.inlet_pressure - m.props.background_pressure),
                         std::fabs(ob.outlet_pressure - m.props.background_pressure)});
    return dp;
  }

  const Case& c_;
  const Scene& sc_;
  const PoreGrid& pores_;
  double v0_ = 0;  // the largest initial speed of any particle (m/s)
};

// The fluid's terms at sound speed c (they were estimated at c0).
double total_at(const std::vector<CompressibilityTerm>& terms, const std::string& fluid, double rho, double c0, double c) {
  double sum = 0;
  for (const auto& t : terms)
    if (t.fluid == fluid)
      sum += t.stiffness > 0 ? t.pressure / std::max(rho * c * c, t.stiffness) : t.value * std::pow(c0 / c, t.sound_power);
  return sum;
}

// The sound speed that holds `limit` (bisection: the terms fall with c, some only down to a floor);
// 0 when none does.
double sound_speed_needed(const std::vector<CompressibilityTerm>& terms, const std::string& fluid, double rho, double c0,
                          double limit) {
  if (total_at(terms, fluid, rho, c0, c0) <= limit) return c0;
  double lo = c0, hi = c0;
  for (int k = 0; k < 60 && total_at(terms, fluid, rho, c0, hi) > limit; ++k) hi *= 2;
  if (total_at(terms, fluid, rho, c0, hi) > limit) return 0;
  for (int k = 0; k < 60; ++k) {
    const double mid = 0.5 * (lo + hi);
    (total_at(terms, fluid, rho, c0, mid) > limit ? lo : hi) = mid;
  }
  return hi;
}

// The factor f on every drive for which sum(value * f^drive_power) = limit (bisection: the sum
// grows with f); 0 when the terms that do not scale pass it alone.
double drive_factor(const std::vector<CompressibilityTerm>& terms, const std::string& fluid, double limit) {
  bool scales = false;
  auto at = [&](double f) {
    double sum = 0;
    for (const auto& t : terms)
      if (t.fluid == fluid) sum += t.value * std::pow(f, t.drive_power), scales = scales || t.drive_power > 0;
    return sum;
  };
  if (at(0) >= limit || !scales) return 0;
  double lo = 0, hi = 1;
  for (int k = 0; k < 60 && at(hi) < limit; ++k) hi *= 2;
  for (int k = 0; k < 100; ++k) {
    const double mid = 0.5 * (lo + hi);
    (at(mid) > limit ? hi : lo) = mid;
  }
  return 0.5 * (lo + hi);
}

// The longest settling time of a pressure field (CompressibilityEstimate::settle_time).
void settle_time(const Case& c, const PoreGrid& pores, CompressibilityEstimate& e) {
  const Scene& sc = c.scene;
  e.end_time = c.end_time;
  for (const auto& m : sc.materials) {
    if (m.props.kind != MaterialKind::Fluid || !(m.props.viscosity > 0)) continue;
    const double nu = m.props.viscosity / m.props.rest_density, cc = m.props.sound_speed;
    for (int k = 0; k < sc.dimension; ++k) {
      if (m.body_force[k] == 0 || !sc.periodic[k] || !(pores.periodic_head(k) > 0)) continue;  // no pressure field
      const double K = pores.periodic_permeability(k), L = sc.upper[k] - sc.lower[k];
      if (!(K > 0)) continue;
      const double t = L * L * nu / (M_PI * M_PI * cc * cc * K);
      if (t <= e.settle_time) continue;
      e.settle_time = t, e.settle_fluid = m.name, e.settle_sound_speed = cc;
      e.settle_sound_speed_needed = cc * std::sqrt(3 * t / e.end_time);
      e.settle_detail = "L^2 nu / (pi^2 c^2 K) over L = " + fixed(L) + " m along " + std::string(1, "xyz"[k]) +
                        ", K <= " + fixed(K) + " m^2 from the pores' sections";
    }
  }
}

}  // namespace

CompressibilityEstimate estimate_compressibility(const Case& c) {
  const Scene& sc = c.scene;
  const PoreGrid pores(sc);
  const Terms terms(c, pores);
  CompressibilityEstimate e;
  for (int f = 0; f < int(sc.materials.size()); ++f) {
    if (!is_fluid(sc, f)) continue;
    terms.add(f, e.terms);
    double sum = 0;
    for (const auto& t : e.terms)
      if (t.fluid == sc.materials[f].name) sum += t.value;
    if (e.fluid.empty() || sum > e.total) e.total = sum, e.fluid = sc.materials[f].name, e.sound_speed = sc.materials[f].props.sound_speed;
  }
  double rho = 0;
  for (const auto& m : sc.materials)
    if (m.name == e.fluid) rho = m.props.rest_density;
  e.sound_speed_needed = sound_speed_needed(e.terms, e.fluid, rho, e.sound_speed, e.limit);
  e.drive_factor = drive_factor(e.terms, e.fluid, e.limit);
  settle_time(c, pores, e);
  return e;
}

namespace {
std::string settle_text(const CompressibilityEstimate& e, const std::string& file) {
  if (!(e.settle_time > 0)) return "";
  std::ostringstream o;
  o.precision(3);
  o << "  " << e.settle_fluid << ": pressure field settles in ~" << e.settle_time << " s [materials." << e.settle_fluid
    << ".sound_speed, materials." << e.settle_fluid << ".body_force]: " << e.settle_detail << "\n";
  if (e.settles_late())
    o << "warning: " << file << ": the pressure field that turns the flow settles in ~" << e.settle_time
      << " s (or longer), more than a third of the run (time.end = " << e.end_time
      << " s): until it has, a flow rate is too high where the flow turns; raise materials." << e.settle_fluid
      << ".sound_speed from " << e.settle_sound_speed << " to " << e.settle_sound_speed_needed
      << " m/s (the time falls as 1/c^2)\n";
  return o.str();
}
}  // namespace

std::string compressibility_text(const CompressibilityEstimate& e, const std::string& file) {
  std::ostringstream o;
  o.precision(3);
  if (e.fluid.empty()) return "";
  o << "compressibility: estimated largest density variation " << 100 * e.total << " % (" << e.fluid;
  for (const auto& t : e.terms)
    if (t.fluid == e.fluid) o << "; " << t.what << " " << 100 * t.value << " %";
  o << ")" << (e.exceeds() ? "" : ", within the 1 % weak compressibility allows") << "\n";
  for (const auto& t : e.terms)
    o << "  " << t.fluid << ": " << t.what << " " << 100 * t.value << " % [" << t.keys << "]"
      << (t.pressure > 0 ? ", dp = " + fixed(t.pressure) + " Pa" : "") << ": " << t.detail << "\n";
  o << settle_text(e, file);
  if (!e.exceeds()) return o.str();
  std::string drives;
  for (const auto& t : e.terms)
    if (t.fluid == e.fluid && t.drive_power > 0 && drives.find(t.keys) == std::string::npos)
      drives += (drives.empty() ? "" : ", ") + t.keys;
  o << "warning: " << file << ": weak compressibility assumes about 1 %, this case implies " << 100 * e.total << " %: ";
  if (e.sound_speed_needed > 0)
    o << "raise materials." << e.fluid << ".sound_speed from " << e.sound_speed << " to " << e.sound_speed_needed
      << " m/s (the acoustic step shrinks by " << e.sound_speed_needed / e.sound_speed << "x: up to as many more steps)";
  else
    o << "no sound speed of materials." << e.fluid << " holds it (the solids' compliance alone passes it)";
  if (e.drive_factor > 0)
    o << ", or scale the drive (" << drives << ") by " << e.drive_factor
      << " (a permeability is linear in its drive in Stokes flow: the same answer)";
  o << "\n";
  return o.str();
}

nlohmann::json to_json(const CompressibilityEstimate& e) {
  nlohmann::json terms = nlohmann::json::array();
  for (const auto& t : e.terms)
    terms.push_back({{"fluid", t.fluid}, {"term", t.what}, {"keys", t.keys}, {"detail", t.detail},
                     {"pressure", t.pressure}, {"value", t.value}, {"drive_power", t.drive_power},
                     {"sound_power", t.sound_power}});
  return {{"estimate", e.total},
          {"limit", e.limit},
          {"exceeds", e.exceeds()},
          {"fluid", e.fluid},
          {"sound_speed", e.sound_speed},
          {"sound_speed_needed", e.sound_speed_needed},
          {"drive_factor", e.drive_factor},
          {"settle_time", e.settle_time},
          {"settles_late", e.settles_late()},
          {"settle_sound_speed_needed", e.settle_sound_speed_needed},
          {"terms", terms}};
}

}  // namespace psph
