#include <cstring>
#include <vector>

#include "io/checkpoint_hdf5.hpp"
#include "io/hdf5_support.hpp"

namespace psph {
namespace {
using namespace hdf5;

// Reads one file on one process; every failure is a CheckpointError naming the file.
class Hdf5Reader {
 public:
  explicit Hdf5Reader(const std::string& path) : path_(path) {
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
    file_.reset(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT));
    if (!file_.valid()) fail("a damaged or truncated HDF5 file (" + hdf5_reason() + ")");
    if (!H5Aexists(file_, "format") || text(file_, "format") != kFormat)
      fail(std::string("not a poresph checkpoint (an HDF5 file without the attribute format = \"") + kFormat + "\")");
    const long long version = integer(file_, "format_version");
    if (version != kFormatVersion)
      fail("checkpoint format_version " + std::to_string(version) + ", this poresph reads version " +
           std::to_string(kFormatVersion) + " (written by poresph " + text(file_, "poresph_version") + ")");
  }
  Hdf5Reader(const Hdf5Reader&) = delete;
  Hdf5Reader& operator=(const Hdf5Reader&) = delete;
  hid_t file() const { return file_; }

  [[noreturn]] void fail(const std::string& what) const { throw CheckpointError(path_ + ": " + what); }

  std::string text(hid_t at, const char* name) const {
    const Id a(H5Aopen(at, name, H5P_DEFAULT), H5Aclose);
    const Id type(H5Aget_type(a), H5Tclose);
    if (!a.valid() || H5Tget_class(type) != H5T_STRING) fail(std::string("no text attribute '") + name + "'");
    std::string out(H5Tget_size(type), '\0');
    if (H5Aread(a, type, out.data()) < 0) fail(std::string("attribute '") + name + "' cannot be read");
    return out.substr(0, out.find('\0'));
  }
  template <class T>
  T number(hid_t at, const char* name, hid_t type) const {
    T v{};
    const Id a(H5Aopen(at, name, H5P_DEFAULT), H5Aclose);
    if (!a.valid() || H5Aread(a, type, &v) < 0) fail(std::string("no numeric attribute '") + name + "'");
    return v;
  }
  long long integer(hid_t at, const char* name) const { return number<long long>(at, name, H5T_NATIVE_LLONG); }
  double real(hid_t at, const char* name) const { return number<double>(at, name, H5T_NATIVE_DOUBLE); }

  // A dataset's rows (its first dimension) and the bytes of each, read whole as `type`.
  Bytes rows(hid_t at, const std::string& name, hid_t type, std::size_t& count, std::size_t& row_bytes) const {
    const Id set(H5Dopen2(at, name.c_str(), H5P_DEFAULT), H5Dclose);
    if (!set.valid()) fail("no dataset '" + name + "'");
    const Id space(H5Dget_space(set), H5Sclose);
    hsize_t dims[2] = {0, 1};
    const int rank = H5Sget_simple_extent_ndims(space);
    if (rank < 0 || rank > 2 || H5Sget_simple_extent_dims(space, dims, nullptr) < 0)
      fail("dataset '" + name + "' has " + std::to_string(rank) + " dimensions, expected 1 or 2");
    count = std::size_t(dims[0]), row_bytes = std::size_t(rank == 2 ? dims[1] : 1) * H5Tget_size(type);
    const Id stored(H5Dget_type(set), H5Tclose);
    const double stored_bytes = double(dims[0]) * double(rank == 2 ? dims[1] : 1) * double(H5Tget_size(stored));
    if (stored_bytes > double(H5Dget_storage_size(set)))  // sizes a damaged header claims, before any allocation
      fail("dataset '" + name + "' claims more bytes than the file holds for it (damaged)");
    Bytes out(count * row_bytes);
    if (!out.empty() && H5Dread(set, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, out.data()) < 0)
      fail("dataset '" + name + "' cannot be read (" + hdf5_reason() + ")");
    return out;
  }

 private:
  std::string path_;
  Id file_{-1, H5Fclose};  // closed also when the constructor throws
};

// The fields' names in the order they were written.
std::vector<std::string> names_in_order(hid_t group) {
  std::vector<std::string> names;
  H5G_info_t info{};
  if (H5Gget_info(group, &info) < 0) return names;
  for (hsize_t k = 0; k < info.nlinks; ++k) {
    const ssize_t len = H5Lget_name_by_idx(group, ".", H5_INDEX_CRT_ORDER, H5_ITER_INC, k, nullptr, 0, H5P_DEFAULT);
    if (len < 0) continue;
    std::string name(std::size_t(len) + 1, '\0');
    H5Lget_name_by_idx(group, ".", H5_INDEX_CRT_ORDER, H5_ITER_INC, k, name.data(), name.size(), H5P_DEFAULT);
    names.push_back(name.substr(0, std::size_t(len)));
  }
  return names;
}

CheckpointField read_field(const Hdf5Reader& r, hid_t group, const std::string& name, std::size_t particles) {
  CheckpointField f;
  f.name = name;
  const Id set(H5Dopen2(group, name.c_str(), H5P_DEFAULT), H5Dclose);
  if (!set.valid()) r.fail("field '" + name + "' cannot be opened");
  const std::string kind = r.text(set, "type");
  f.unit = r.text(set, "unit"), f.description = r.text(set, "description");
  const Id stored(H5Dget_type(set), H5Tclose);
  const Id type(H5Tget_native_type(stored, H5T_DIR_ASCEND), H5Tclose);
  std::size_t count = 0;
  f.bytes = r.rows(group, name, type, count, f.element_bytes);
  if (count != particles)
    r.fail("field '" + name + "' has " + std::to_string(count) + " particles, expected " + std::to_string(particles));
  const std::size_t scalar = H5Tget_size(type);
  f.components = kind == "bytes" ? 0 : int(f.element_bytes / scalar);
  f.type = kind == "real" ? FieldType::Real : kind == "int" ? FieldType::Int : FieldType::Byte;
  return f;
}

}  // namespace

Checkpoint read_hdf5_checkpoint(const std::string& path) {
  const Hdf5Reader r(path);
  const hid_t f = r.file();
  Checkpoint c;
  c.dimension = int(r.integer(f, "dimension"));
  c.particles = int(r.integer(f, "particles"));
  c.precision = r.text(f, "precision");
  c.time = r.real(f, "time"), c.last_dt = r.real(f, "last_dt"), c.first_dt = r.real(f, "first_dt");
  c.steps = long(r.integer(f, "steps"));
  const Id fields(H5Gopen2(f, "fields", H5P_DEFAULT), H5Gclose);
  if (!fields.valid()) r.fail("no group 'fields'");
  for (const std::string& name : names_in_order(fields)) c.fields.push_back(read_field(r, fields, name, c.particles));
  const Id energy(H5Dopen2(f, "extras/dissipated_energy", H5P_DEFAULT), H5Dclose);
  if (H5Dread(energy, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, &c.dissipated_energy) < 0)
    r.fail("extras/dissipated_energy cannot be read (" + hdf5_reason() + ")");
  std::size_t n = 0, bytes = 0;
  const Bytes b = r.rows(f, "extras/rigid_bodies", H5T_NATIVE_DOUBLE, n, bytes);
  c.rigid_bodies.resize(n);
  if (n) std::memcpy(c.rigid_bodies.data(), b.data(), n * sizeof(double));
  return c;
}

}  // namespace psph
