#include "io/field_staging.hpp"

#include <algorithm>

namespace psph {
namespace {

// Interleaved doubles with `comps` per particle into float with `out_comps` per particle.
void to_float(const std::vector<double>& in, int n, int comps, int out_comps, std::vector<float>& out) {
  out.resize(static_cast<std::size_t>(n) * out_comps);
#pragma omp parallel for schedule(static)
  for (int i = 0; i < n; ++i)
    for (int k = 0; k < out_comps; ++k)
      out[static_cast<std::size_t>(i) * out_comps + k] =
          k < comps ? static_cast<float>(in[static_cast<std::size_t>(i) * comps + k]) : 0.f;
}

}  // namespace

std::vector<std::string> stage_frame(Engine& e, const std::vector<std::string>& fields, ParticleFrame& frame,
                                     bool slice) {
  auto get = [&](const std::string& name) { return slice ? e.field_slice(name) : e.field(name); };
  const int D = e.dimension();
  const std::vector<double> x = get("position");
  const int n = static_cast<int>(x.size() / D);
  frame.dimension = D;
  frame.n = n;
  to_float(x, n, D, 3, frame.position);
  const std::vector<std::string> have = e.field_names();
  std::vector<std::string> missing;
  for (const std::string& name : fields) {
    if (std::find(have.begin(), have.end(), name) == have.end()) {
      missing.push_back(name);
      continue;
    }
    const std::vector<double> v = get(name);
    const int comps = n > 0 ? static_cast<int>(v.size() / n) : 1;
    StagedField& s = frame.slot(name);
    s.components = comps == D && D > 1 ? 3 : comps;  // vectors as 3 components, as ParaView expects
    to_float(v, n, comps, s.components, s.data);
  }
  return missing;
}

void agree_components(ParticleFrame& frame, Communicator& comm) {
  for (StagedField& f : frame.fields) {
    const long long comps = comm.max(static_cast<long long>(frame.n > 0 ? f.components : 0));
    if (frame.n == 0 && comps > 0) f.components = int(comps);
  }
}

}  // namespace psph
