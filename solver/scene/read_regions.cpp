// [[body_force_region]] and [open_boundary]: where a fluid is driven, and its pressure inlet and
// outlet.
#include <cmath>

#include "scene/case_tables.hpp"

namespace psph {

// Body forces on one fluid inside a box (e.g. the reservoir gas of a drainage).
void read_body_force_regions(CaseReader& top, CaseDraft& d) {
  top.each_table("body_force_region", kMaxForceRegions, "regions", [&](CaseReader& r) {
    SceneForceRegion f;
    f.material = d.material(r, "material", MaterialKind::Fluid, "a fluid");
    r.box(d.dimension(), f.lower, f.upper);
    f.acceleration = r.vec<double>("body_force", d.dimension());
    f.ramp_time = r.non_negative("ramp_time", 0.0);
    d.c.scene.force_regions.push_back(f);
  });
}

// Pressure inlet and outlet buffers across a periodic axis (boundary/open_boundary.hpp).
void read_open_boundary(CaseReader& top, CaseDraft& d) {
  if (!top.has("open_boundary")) return;
  Scene& sc = d.c.scene;
  const double R = sc.options.support_radius;
  CaseReader r(top.table("open_boundary", false), d.file, "open_boundary");
  SceneOpenBoundary& ob = sc.open_boundary;
  ob.axis = r.axis("axis", d.dimension());
  if (!sc.periodic[ob.axis])
    r.fail("axis", "expected an axis declared periodic under [domain]: the fluid leaving through the outlet "
                   "comes back through the inlet as the injected fluid");
  ob.lower = sc.lower[ob.axis], ob.upper = sc.upper[ob.axis];
  ob.inlet_at_lower = r.choice("inlet_side", {"lower", "upper"}, "lower") == "lower";
  ob.inlet_pressure = r.number("inlet_pressure");  // Pa; finite, as every number
  ob.outlet_pressure = r.number("outlet_pressure");
  ob.inlet_material = d.material(r, "inlet_material", MaterialKind::Fluid, "a fluid");
  ob.thickness = r.positive("thickness", R);
  if (ob.thickness < R * (1 - 1e-9))
    r.fail("thickness", "expected a buffer at least one support radius (" + CaseReader::fmt(R) + " m) thick, got " +
                            CaseReader::fmt(ob.thickness));
  if (2 * ob.thickness + 2 * R > ob.upper - ob.lower)
    r.fail("thickness", "expected the two buffers to leave at least two support radii of domain between them");
  r.finish();
}

}  // namespace psph
