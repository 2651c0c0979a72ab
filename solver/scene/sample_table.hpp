#pragma once
// [sample]: the drainage cell of the references in one table (Pazdniakou 2018 §5.2, Fig. 8b;
// Deptulski 2021 §5.2, Fig. 5.3a): "this image, these materials, this confinement, this pressure
// drop". Before the other tables are read it is replaced by the tables it stands for, which then
// go through the ordinary readers and checks and appear in case.resolved.toml:
//
//   [domain]      the sample between two gas reservoirs, periodic along the flow axis only, with a
//                 lateral layer of lateral_thickness on the other axes' faces and, beyond it, two
//                 support radii (at least 4 spacings) of empty space for those faces to move into;
//   [[geometry]]  the reservoir walls (plate_material) around everything, the lateral layer
//                 (lateral_material) beside the sample, the reservoirs' gas, the image (with
//                 end_plates: its solid voxels within plate_thickness of the two faces along the
//                 flow axis are plate_material, the pores open; its elastic voxels within
//                 plate_guard_thickness beyond them are lateral_material: an undamaged guard);
//   [[body_force_region]]  on the reservoir gas only, rho_g |F| (2 H_r) = pressure_drop
//                 (Pazdniakou §5.2: p_g = rho_g F H_r with H_r the reservoirs' total height);
//   [[solid_load]] the confinement as a traction -sigma n_out on the lateral layer's outermost
//                 particles (the digests' choice; the papers do not say how);
//   [monitors]    the sample's box, the flow axis.
#include <string>

#include <toml++/toml.h>

namespace psph {

// Replaces `tbl`'s [sample] by the tables it stands for (moving its image table and the file's own
// geometries into place, so that they keep their lines); false when there is none. Throws CaseError
// naming `file` and the key on a bad value, or when the file also sets a table the sample makes.
bool expand_sample(toml::table& tbl, const std::string& file);

}  // namespace psph
