// The report of a segmented image (image/image_report.hpp).
#include "image/image_report.hpp"

#include <cstdio>

namespace psph {
namespace {


std::string fmt(const char* f, double v) {
  char b[64];
  std::snprintf(b, sizeof b, f, v);
  return b;
}

}  // namespace

nlohmann::json image_report(const ImageReportInput& in) {
  const PhaseVolume& v = *in.volume;
  nlohmann::json r;
  r["file"] = in.file, r["format"] = in.format;
  r["voxels"] = {v.file_size[0], v.file_size[1], v.file_size[2]};
  double cropped = 0;
  for (const auto& [label, n] : v.label_voxels) cropped += double(n);
  nlohmann::json labels = nlohmann::json::array();
  for (const auto& [label, n] : v.label_voxels)
    labels.push_back({{"label", label}, {"voxels", n}, {"fraction", double(n) / cropped}});
  r["labels"] = labels;
  r["porosity"] = porosity(v, in.pore_phases, false);
  r["coarsen"] = {in.coarsen[0], in.coarsen[1], in.coarsen[2]};
  r["coarse_voxels"] = {v.size[0], v.size[1], v.size[2]};
  r["coarse_porosity"] = porosity(v, in.pore_phases, true);
  const PoreComponents& c = *in.pores;
  long pore = 0;
  std::array<int, 3> percolating{0, 0, 0};
  for (const PoreComponent& p : c.components) {
    pore += p.voxels;
    for (int k = 0; k < in.dimension; ++k) percolating[k] += p.percolates[k];
  }
  r["connectivity"] = in.connectivity;
  r["components"] = c.components.size();
  r["percolating_components"] = {{"x", percolating[0]}, {"y", percolating[1]}};
  if (in.dimension == 3) r["percolating_components"]["z"] = percolating[2];
  nlohmann::json largest = nlohmann::json::array();
  for (std::size_t k = 0; k < c.components.size() && int(k) < in.largest_listed; ++k) {
    const PoreComponent& p = c.components[k];
    nlohmann::json along = nlohmann::json::array();
    for (int a = 0; a < in.dimension; ++a)
      if (p.percolates[a]) along.push_back(std::string(1, "xyz"[a]));
    largest.push_back({{"index", k}, {"voxels", p.voxels}, {"pore_fraction", pore ? double(p.voxels) / double(pore) : 0.0},
                       {"percolates", along}});
  }
  r["largest_components"] = largest;
  return r;
}

std::string image_report_text(const nlohmann::json& r) {
  std::string s = r["file"].get<std::string>() + " (" + r["format"].get<std::string>() + "): " +
                  std::to_string(r["voxels"][0].get<long>()) + " x " + std::to_string(r["voxels"][1].get<long>()) + " x " +
                  std::to_string(r["voxels"][2].get<long>()) + " voxels\n  labels:";
  for (const auto& l : r["labels"])
    s += " " + std::to_string(l["label"].get<long>()) + " (" + fmt("%.2f %%", 100 * l["fraction"].get<double>()) + ")";
  s += "\n  porosity " + fmt("%.4f", r["porosity"].get<double>());
  const auto& f = r["coarsen"];
  if (f[0] != 1 || f[1] != 1 || f[2] != 1)
    s += ", coarsened " + std::to_string(f[0].get<int>()) + " x " + std::to_string(f[1].get<int>()) + " x " +
         std::to_string(f[2].get<int>()) + " (majority) to " + std::to_string(r["coarse_voxels"][0].get<long>()) +
         " x " + std::to_string(r["coarse_voxels"][1].get<long>()) + " x " +
         std::to_string(r["coarse_voxels"][2].get<long>()) + ": " + fmt("%.4f", r["coarse_porosity"].get<double>());
  s += "\n  pore components (" + std::to_string(r["connectivity"].get<int>()) + "-connected): " +
       std::to_string(r["components"].get<long>()) + "; percolating along";
  for (const auto& [axis, n] : r["percolating_components"].items()) s += " " + axis + ": " + std::to_string(n.get<int>());
  for (const auto& c : r["largest_components"]) {
    std::string along;
    for (const auto& a : c["percolates"]) along += (along.empty() ? "" : ", ") + a.get<std::string>();
    s += "\n    #" + std::to_string(c["index"].get<long>()) + ": " + std::to_string(c["voxels"].get<long>()) + " voxels (" +
         fmt("%.1f %% of the pore space", 100 * c["pore_fraction"].get<double>()) + ")" +
         (along.empty() ? "" : ", percolates along " + along);
  }
  return s + "\n";
}

}  // namespace psph
