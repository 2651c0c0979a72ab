#include "io/checkpoint_file.hpp"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "io/durable_file.hpp"
#ifdef PORESPH_HAVE_HDF5
#include "io/checkpoint_hdf5.hpp"
#endif

namespace psph {
namespace fs = std::filesystem;
namespace {
constexpr const char* kMagic = "PORESPH-CHECKPOINT 1";
constexpr char kHdf5Signature[8] = {'\x89', 'H', 'D', 'F', '\r', '\n', '\x1a', '\n'};

Checkpoint read_raw_checkpoint_file(const std::string& path);
}  // namespace

const char* checkpoint_extension() {
#ifdef PORESPH_HAVE_HDF5
  return ".h5";
#else
  return ".ckpt";
#endif
}

void write_checkpoint_file(const std::string& path, const Checkpoint& c, const CheckpointOrigin& o, Communicator& comm) {
#ifdef PORESPH_HAVE_HDF5
  write_hdf5_checkpoint(path, c, o, comm);
#else
  if (comm.parallel()) throw std::logic_error("a checkpoint over several processes needs HDF5");
  write_raw_checkpoint_file(path, c, o.case_name);
#endif
}

void write_checkpoint_file(const std::string& path, const Checkpoint& c, const std::string& case_name) {
  Communicator one;
  write_checkpoint_file(path, c, CheckpointOrigin{case_name, ""}, one);
}

void write_raw_checkpoint_file(const std::string& path, const Checkpoint& c, const std::string& case_name) {
  if (!c.whole()) throw std::logic_error("the raw checkpoint format holds whole checkpoints only");
  nlohmann::json head = {{"case", case_name},   {"dimension", c.dimension}, {"particles", c.particles},
                         {"precision", c.precision}, {"time", c.time},      {"last_dt", c.last_dt},
                         {"first_dt", c.first_dt},   {"steps", c.steps},     {"dissipated_energy", c.dissipated_energy},
                         {"rigid_bodies", c.rigid_bodies}, {"fields", nlohmann::json::array()}};
  for (const auto& f : c.fields)
    head["fields"].push_back({{"name", f.name},
                              {"element_bytes", f.element_bytes},
                              {"bytes", f.bytes.size()},
                              {"type", int(f.type)},
                              {"components", f.components},
                              {"unit", f.unit}});
  DurableFile out(path);
  out.write(std::string(kMagic) + '\n' + head.dump() + '\n');
  for (const auto& f : c.fields) out.write(f.bytes.data(), f.bytes.size());
  out.commit();
}

Checkpoint read_checkpoint_file(const std::string& path) {
  char head[sizeof kHdf5Signature] = {};
  std::ifstream(path, std::ios::binary).read(head, sizeof head);
  if (std::equal(head, head + sizeof head, kHdf5Signature)) {
#ifdef PORESPH_HAVE_HDF5
    return read_hdf5_checkpoint(path);
#else
    throw CheckpointError(path + ": an HDF5 checkpoint, and this poresph was built without HDF5 (scripts/install-deps.sh)");
#endif
  }
  return read_raw_checkpoint_file(path);
}

namespace {

Checkpoint read_raw_checkpoint_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw CheckpointError(path + ": cannot open the checkpoint file");
  std::string magic, line;
  std::getline(in, magic);
  if (magic != kMagic)
    throw CheckpointError(path + ": not a poresph checkpoint (expected an HDF5 file or a first line '" + kMagic + "')");
  std::getline(in, line);
  Checkpoint c;
  nlohmann::json head;
  try {
    head = nlohmann::json::parse(line);
    c.dimension = head.at("dimension").get<int>();
    c.particles = head.at("particles").get<int>();
    c.precision = head.at("precision").get<std::string>();
    c.time = head.at("time").get<double>();
    c.last_dt = head.at("last_dt").get<double>();
    c.first_dt = head.at("first_dt").get<double>();
    c.steps = head.at("steps").get<long>();
    c.dissipated_energy = head.value("dissipated_energy", 0.0);
    c.rigid_bodies = head.value("rigid_bodies", std::vector<double>{});
    for (const auto& f : head.at("fields")) {
      CheckpointField cf;
      cf.name = f.at("name").get<std::string>();
      cf.element_bytes = f.at("element_bytes").get<std::size_t>();
      cf.bytes.resize(f.at("bytes").get<std::size_t>());
      // Earlier files say no type, components or unit: opaque bytes.
      const int type = f.value("type", int(FieldType::Byte));
      if (type < int(FieldType::Real) || type > int(FieldType::Byte))
        throw CheckpointError(path + ": field '" + cf.name + "' has the type " + std::to_string(type) + ", expected 0 to 2");
      cf.type = FieldType(type);
      cf.components = f.value("components", 0);
      cf.unit = f.value("unit", std::string());
      c.fields.push_back(std::move(cf));
    }
  } catch (const nlohmann::json::exception& e) {
    throw CheckpointError(path + ": damaged checkpoint header: " + e.what());
  }
  for (auto& f : c.fields) {
    in.read(reinterpret_cast<char*>(f.bytes.data()), std::streamsize(f.bytes.size()));
    if (!in) throw CheckpointError(path + ": the checkpoint is truncated in field '" + f.name + "'");
  }
  if (in.peek() != std::char_traits<char>::eof())
    throw CheckpointError(path + ": unexpected bytes after the last field");
  return c;
}

fs::path checkpoint_folder(const std::string& dir) {
  fs::path d(dir);
  return fs::is_directory(d / "checkpoints") ? d / "checkpoints" : d;
}

// step_<zero-padded step>.h5 or .ckpt, newest (highest step) first.
std::vector<std::string> checkpoints_newest_first(const fs::path& d) {
  std::vector<std::pair<std::string, std::string>> all;  // stem, path
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(d, ec)) {
    const std::string name = e.path().filename().string(), ext = e.path().extension().string();
    if (e.is_regular_file() && name.rfind("step_", 0) == 0 && (ext == ".h5" || ext == ".ckpt"))
      all.emplace_back(e.path().stem().string(), e.path().string());
  }
  std::sort(all.rbegin(), all.rend());
  std::vector<std::string> out;
  for (const auto& a : all) out.push_back(a.second);
  return out;
}

}  // namespace

RestartCheckpoint newest_intact_checkpoint(const std::string& dir) {
  RestartCheckpoint r;
  const fs::path d = checkpoint_folder(dir);
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(d, ec))
    if (e.path().extension() == ".partial" && fs::remove(e.path(), ec)) r.removed.push_back(e.path().string());
  for (const std::string& f : checkpoints_newest_first(d)) {
    try {
      r.data = read_checkpoint_file(f);
      r.path = f;
      return r;
    } catch (const CheckpointError& x) {
      r.skipped.push_back(x.what());
    }
  }
  return r;
}

}  // namespace psph
