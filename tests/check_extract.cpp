// Numbers behind the pictures: reruns a case to its end on the CPU (runs are deterministic) and
// checks that the run's last particle extract holds the pipelines' fields, every particle, and
// the solver's values (to float precision).
//   check_extract CASE.toml RUNDIR INTERVAL FIELD...
// INTERVAL: the run's output interval; the rerun stops at the same times, as the run's steps did.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <regex>
#include <fstream>

#include <vtkDataArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkXMLPolyDataReader.h>

#include "engine/engine.hpp"
#include "scene/case_file.hpp"
#include "scene/scene_builder.hpp"

int main(int argc, char** argv) {
  using namespace psph;
  if (argc < 5) return 2;
  const double interval = std::stod(argv[3]);
  Case c = load_case_file(argv[1]);
  build_particles(c);
  auto e = make_cpu_engine(c.scene);
  for (int k = 1; e->time() < c.end_time; ++k) e->run_until(std::min(c.end_time, k * interval));

  std::ifstream pvd(std::string(argv[2]) + "/extracts/particles.pvd");
  std::string line, last;
  const std::regex entry("file=\"([^\"]+)\"");
  std::smatch m;
  while (std::getline(pvd, line))
    if (std::regex_search(line, m, entry)) last = m[1].str();
  vtkNew<vtkXMLPolyDataReader> r;
  r->SetFileName((std::string(argv[2]) + "/extracts/" + last).c_str());
  r->Update();
  vtkPolyData* p = r->GetOutput();
  int bad = 0;
  if (p->GetNumberOfPoints() != e->particles()) {
    std::cout << last << ": " << p->GetNumberOfPoints() << " particles, the solver has " << e->particles() << "\n";
    return 1;
  }
  auto check = [&](const std::string& name, const std::vector<double>& want, int comps, vtkDataArray* a) {
    if (!a) {
      std::cout << last << ": no field '" << name << "'\n";
      ++bad;
      return;
    }
    double worst = 0, scale = 1e-30;
    for (double w : want) scale = std::max(scale, std::fabs(w));
    for (int i = 0; i < e->particles(); ++i)
      for (int k = 0; k < comps; ++k)
        worst = std::max(worst, std::fabs(a->GetComponent(i, k) - want[std::size_t(i) * comps + k]) / scale);
    std::cout << name << ": largest difference " << worst << " of the largest value\n";
    bad += worst > 1e-6;
  };
  const std::vector<double> x = e->field("position");
  check("position", x, e->dimension(), p->GetPoints()->GetData());
  for (int k = 4; k < argc; ++k)
    check(argv[k], e->field(argv[k]), int(e->field(argv[k]).size() / e->particles()), p->GetPointData()->GetArray(argv[k]));
  return bad ? 1 : 0;
}
