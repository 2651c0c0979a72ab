#include "monitors/pressure_probes.hpp"

#include <cmath>

#include "kernels/kernel.hpp"
#include "monitors/particle_volumes.hpp"

namespace psph {
namespace {

template <int D>
std::vector<double> shepard(const Scene& sc, const std::vector<Probe>& probes, const std::vector<double>& x,
                            const std::vector<double>& p, const std::vector<double>& volume,
                            const std::vector<double>& material) {
  const double R = sc.options.support_radius;
  const Kernel<D> kern = Kernel<D>::make(sc.options.kernel, Real(R));
  std::vector<double> num(probes.size(), 0.0), den(probes.size(), 0.0);
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (sc.materials[static_cast<int>(material[i])].props.kind != MaterialKind::Fluid) continue;
    for (std::size_t k = 0; k < probes.size(); ++k) {
      double r2 = 0;
      for (int d = 0; d < D; ++d) r2 += std::pow(x[i * D + d] - probes[k].position[d], 2);
      if (r2 >= R * R) continue;
      const double w = double(kern.W(Real(std::sqrt(r2)))) * volume[i];
      num[k] += w * p[i], den[k] += w;
    }
  }
  for (std::size_t k = 0; k < probes.size(); ++k) num[k] = den[k] > 0 ? num[k] / den[k] : 0.0;
  return num;
}

}  // namespace

std::vector<double> probe_pressures(const Scene& sc, const std::vector<Probe>& probes, const std::vector<double>& x,
                                    const std::vector<double>& p, const std::vector<double>& volume,
                                    const std::vector<double>& material) {
  switch (sc.dimension) {
    case 1: return shepard<1>(sc, probes, x, p, volume, material);
    case 2: return shepard<2>(sc, probes, x, p, volume, material);
    default: return shepard<3>(sc, probes, x, p, volume, material);
  }
}

std::vector<std::string> probe_columns(const std::vector<Probe>& probes) {
  std::vector<std::string> c;
  for (const Probe& pr : probes) c.push_back("pressure_" + pr.name);
  return c;
}

std::vector<double> sample_probes(Engine& e, const Scene& sc, const std::vector<Probe>& probes) {
  const std::vector<double> x = e.field("position"), p = e.field("pressure");
  return probe_pressures(sc, probes, x, p, particle_volumes(e), e.field("material"));
}

}  // namespace psph
