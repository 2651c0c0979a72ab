// Image-diff test of one Catalyst pipeline on a small deterministic particle scene, in the VTK
// style: renders through the real adaptor and pipeline script, then compares each view with its
// baseline tests/baselines/<pipeline>_<view>.png using vtkTesting's image difference (threshold
// 0.15, VTK 9.2's default). On failure the rendered image and a difference image are written to
// OUTDIR. UPDATE_BASELINES=1 copies the rendered images over the baselines.
//   render_pipeline PIPELINE OUTDIR [--wrong-range | --wrong-camera]
// The two --wrong modes render deliberately off (colour range, camera) and pass only if the
// comparison fails: they show that the check bites.
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <set>
#include <sstream>

#include <nlohmann/json.hpp>
#include <vtkDataArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkTesting.h>
#include <vtkXMLPPolyDataReader.h>

#include "catalyst/insitu.hpp"
#include "catalyst/pipeline_scripts.hpp"

namespace fs = std::filesystem;
using namespace psph;

namespace {

constexpr double kThreshold = 0.15;

// A 16 x 10 x 8 block of particles: a wall layer around it, water and gas halves, a solid slab
// with a rigid inclusion; smooth analytic fields with every value class each pipeline colours.
ParticleFrame scene() {
  ParticleFrame f;
  const int nx = 16, ny = 10, nz = 8;
  f.dimension = 3;
  f.n = nx * ny * nz;
  f.fields.reserve(7);  // the references below stay valid
  auto& phase = f.slot("phase");
  auto& pressure = f.slot("pressure");
  auto& damage = f.slot("damage");
  auto& colour = f.slot("colour");
  auto& sigma = f.slot("principal_stress");
  auto& dir = f.slot("principal_direction");
  auto& disp = f.slot("displacement");
  sigma.components = dir.components = disp.components = 3;
  for (int i = 0; i < nx; ++i)
    for (int j = 0; j < ny; ++j)
      for (int k = 0; k < nz; ++k) {
        const double x = (i + 0.5) * 0.1, y = (j + 0.5) * 0.1, z = (k + 0.5) * 0.1;
        f.position.insert(f.position.end(), {float(x), float(y), float(z)});
        const bool wall = i == 0 || j == 0 || i == nx - 1 || k == 0 || k == nz - 1;
        const bool rigid = std::hypot(x - 1.2, y - 0.5) < 0.2;
        const int ph = wall ? 0 : i < 7 ? (y < 0.55 ? 1 : 2) : rigid ? 4 : 3;
        phase.data.push_back(float(ph));
        pressure.data.push_back(float(1000 * (1.0 - y)));
        damage.data.push_back(i < 8 ? 0.f : float(std::min(1.0, (x - 0.8) * 2.0)));
        colour.data.push_back(float(0.5 + 0.5 * std::tanh((0.55 - y) * 12)));
        const double s1 = 200 * std::sin(2.5 * x) * std::cos(2 * y);
        sigma.data.insert(sigma.data.end(), {float(s1), float(s1 - 50), float(s1 - 120)});
        dir.data.insert(dir.data.end(), {1.f, 0.f, 0.f});
        disp.data.insert(disp.data.end(), {float(0.01 * std::sin(4 * x) * std::cos(3 * y)), 0.f, 0.f});
      }
  return f;
}

nlohmann::json settings(const fs::path& out, const std::string& mode) {
  nlohmann::json cam = {{"position", {0.8, 2.2, 3.6}}, {"focal_point", {0.8, 0.5, 0.4}}, {"view_up", {0, 1, 0}}};
  if (mode == "--wrong-camera") cam["position"] = {2.8, 1.2, 2.6};
  nlohmann::json ranges = {{"pressure", {0, 1000}}, {"damage", {0, 0.999}}, {"colour", {0, 1}},
                           {"principal_stress", {-250, 250}}, {"displacement", {-0.01, 0.01}}};
  if (mode == "--wrong-range") ranges = {{"pressure", {0, 3000}}, {"damage", {0, 3}}, {"colour", {0, 4}},
                                         {"principal_stress", {0, 1000}}, {"displacement", {0, 0.05}}};
  return {{"dimension", 3},
          {"image_size", {320, 240}},
          {"images_dir", (out / "images").string()},
          {"extracts_dir", (out / "extracts").string()},
          {"point_radius", 0.05},
          {"scalar_bar", false},  // no text: FreeType output is not part of what is compared
          {"live_url", ""},
          {"camera", cam},
          {"slab",
           {{"origin", {0.8, 0.5, 0.4}},
            {"normal", {0, 0, 1}},
            {"half_thickness", 0.06},
            {"camera", {{"position", {0.8, 0.5, 3}}, {"focal_point", {0.8, 0.5, 0.4}}, {"view_up", {0, 1, 0}},
                        {"parallel_scale", 0.6}}}}},
          {"ranges", ranges},
          {"colour_maps",
           {{"pressure", "Viridis (matplotlib)"},
            {"damage", "Inferno (matplotlib)"},
            {"principal_stress", "Cool to Warm"},
            {"displacement", "Cool to Warm"},
            {"colour", "Blue Orange (divergent)"}}}};
}

// 0 when `image` matches tests/baselines/<name>.png. `may_update`: UPDATE_BASELINES applies
// (never to the deliberately wrong renders).
int compare(const fs::path& image, const std::string& name, const fs::path& out, bool may_update) {
  const fs::path baseline = fs::path(PORESPH_BASELINE_DIR) / (name + ".png");
  if (may_update && std::getenv("UPDATE_BASELINES")) {
    fs::copy_file(image, baseline, fs::copy_options::overwrite_existing);
    std::cout << "updated " << baseline << "\n";
    return 0;
  }
  if (!fs::exists(baseline)) {
    std::cout << "no baseline " << baseline << "; the rendered image is " << image
              << " (UPDATE_BASELINES=1 accepts it)\n";
    return 1;
  }
  vtkNew<vtkTesting> t;
  t->AddArgument("-T");
  t->AddArgument(out.c_str());
  t->AddArgument("-V");
  t->AddArgument(baseline.c_str());
  std::ostringstream msg;
  const int r = t->RegressionTest(image.string(), kThreshold, msg);
  std::cout << name << ": image difference " << t->GetImageDifference() << " (threshold " << kThreshold << ")"
            << (r == vtkTesting::PASSED ? ", passed\n" : ", FAILED; actual and difference images in " + out.string() + "\n");
  return r == vtkTesting::PASSED ? 0 : 1;
}

// The phases in the slab extract (extracts/slab_000000.pvtp): every particle of the slab, whichever
// pipeline took it (a solid field's pipeline colours only the solid, but extracts them all).
std::set<int> slab_extract_phases(const fs::path& out) {
  vtkNew<vtkXMLPPolyDataReader> r;
  r->SetFileName((out / "extracts" / "slab_000000.pvtp").c_str());
  r->Update();
  std::set<int> phases;
  vtkDataArray* a = r->GetOutput()->GetPointData()->GetArray("phase");
  for (vtkIdType k = 0; a && k < a->GetNumberOfTuples(); ++k) phases.insert(int(std::lround(a->GetTuple1(k))));
  return phases;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) {
    std::cerr << "usage: render_pipeline PIPELINE OUTDIR [--wrong-range | --wrong-camera]\n";
    return 2;
  }
  const std::string name = argv[1], mode = argc > 3 ? argv[3] : "";
  const fs::path out = fs::absolute(argv[2]);
  fs::remove_all(out);
  fs::create_directories(out / "extracts");
  std::ofstream(out / "settings.json") << settings(out, mode).dump(2);
  {
    const std::unique_ptr<InSitu> insitu = make_insitu({{find_pipeline(name).path}, (out / "settings.json").string(), ""});
    insitu->execute(scene(), 0, 0.0);
    insitu->finalise();
  }
  int failed = 0, rendered = 0;
  for (const char* view : {"3d", "slab"}) {
    const fs::path img = out / "images" / name / (std::string(view) + "_000000.png");
    if (!fs::exists(img)) {
      std::cout << "not rendered: " << img << "\n";
      return 1;
    }
    ++rendered;
    failed += compare(img, name + "_" + view, out, mode.empty()) != 0;
  }
  if (mode.empty()) {
    const std::size_t phases = slab_extract_phases(out).size();
    if (phases < 4)
      std::cout << "the slab extract holds " << phases << " phase(s), expected at least 4 (wall, water, gas, solid)\n";
    return failed || phases < 4 ? 1 : 0;
  }
  // A deliberately wrong render must fail the comparison in at least one view.
  std::cout << (failed ? "the comparison caught the wrong " : "the comparison did NOT catch the wrong ") << mode.substr(8)
            << "\n";
  return rendered == 2 && failed > 0 ? 0 : 1;
}
