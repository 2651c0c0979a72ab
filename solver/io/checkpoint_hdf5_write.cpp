#include "io/checkpoint_hdf5.hpp"

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <sys/statvfs.h>
#include <unistd.h>

#include "io/durable_file.hpp"
#include "io/hdf5_support.hpp"

namespace psph {
namespace {
using namespace hdf5;

// How a field's bytes are stored: its scalars' HDF5 type and components per particle; opaque
// bytes where the field's declared type does not account for its size.
struct StoredType {
  hid_t type;
  int components;
  bool opaque;
};
StoredType stored_type(const CheckpointField& f) {
  const int comps = f.components;
  if (comps > 0 && f.element_bytes % std::size_t(comps) == 0) {
    const std::size_t s = f.element_bytes / std::size_t(comps);
    if (f.type == FieldType::Real && s == 8) return {H5T_NATIVE_DOUBLE, comps, false};
    if (f.type == FieldType::Real && s == 4) return {H5T_NATIVE_FLOAT, comps, false};
    if (f.type == FieldType::Int && s == 4) return {H5T_NATIVE_INT32, comps, false};
    if (f.type == FieldType::Byte && s == 1) return {H5T_NATIVE_UINT8, comps, false};
  }
  return {H5T_NATIVE_UINT8, int(f.element_bytes), true};
}

const char* type_name(FieldType t, bool opaque) {
  return opaque ? "bytes" : t == FieldType::Real ? "real" : t == FieldType::Int ? "int" : "byte";
}

// Writes one file on every process: the first failure on this process is kept, and every
// collective call is still made, so that no process waits for one that gave up.
class Hdf5Writer {
 public:
  // One process makes the file in memory (HDF5's core driver), several write it through MPI-IO.
  Hdf5Writer(const std::string& file, Communicator& comm) : comm_(comm) {
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
    const Id fapl(H5Pcreate(H5P_FILE_ACCESS), H5Pclose);
    if (!comm.mpi_comm()) H5Pset_fapl_core(fapl, std::size_t(1) << 20, false);
#ifdef H5_HAVE_PARALLEL
    if (comm.mpi_comm()) H5Pset_fapl_mpio(fapl, *static_cast<const MPI_Comm*>(comm.mpi_comm()), MPI_INFO_NULL);
    if (comm.mpi_comm()) H5Pset_dxpl_mpio(xfer_, H5FD_MPIO_COLLECTIVE);
#endif
    file_.reset(checked(H5Fcreate(file.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, fapl), "cannot create the file"));
    // Same bytes whoever writes them: no times in object headers, space allocated at creation.
    H5Pset_obj_track_times(dcpl_, false);
    H5Pset_alloc_time(dcpl_, H5D_ALLOC_TIME_EARLY);
    H5Pset_fill_time(dcpl_, H5D_FILL_TIME_NEVER);
    H5Pset_obj_track_times(gcpl_, false);
    H5Pset_link_creation_order(gcpl_, H5P_CRT_ORDER_TRACKED | H5P_CRT_ORDER_INDEXED);
  }
  hid_t file() const { return file_; }
  bool ok() const { return why_.empty(); }
  const std::string& why() const { return why_; }

  template <class T>
  T checked(T r, const char* what) {
    if (r < 0 && why_.empty()) why_ = std::string(what) + ": " + hdf5_reason();
    return r;
  }

  hid_t group(hid_t at, const char* name) {
    return checked(H5Gcreate2(at, name, H5P_DEFAULT, gcpl_, H5P_DEFAULT), "cannot create a group");
  }

  void attribute(hid_t at, const char* name, const std::string& value) {
    const Id type(H5Tcopy(H5T_C_S1), H5Tclose);
    H5Tset_size(type, std::max<std::size_t>(value.size(), 1));
    write_attribute(at, name, type, value.c_str());
  }
  void attribute(hid_t at, const char* name, double value) { write_attribute(at, name, H5T_NATIVE_DOUBLE, &value); }
  void attribute(hid_t at, const char* name, long long value) { write_attribute(at, name, H5T_NATIVE_LLONG, &value); }

  // A dataset of `rows` x `comps` (comps 1: one dimension) of which this process writes the rows
  // first .. first + count - 1 from `data`.
  hid_t rows(hid_t at, const char* name, hid_t type, long long rows, int comps, long long first, long long count,
             const void* data) {
    const hsize_t dims[2] = {hsize_t(rows), hsize_t(comps)};
    const int rank = comps == 1 ? 1 : 2;
    const Id space(checked(H5Screate_simple(rank, dims, nullptr), "cannot describe a dataset"), H5Sclose);
    const hid_t set = checked(H5Dcreate2(at, name, type, space, H5P_DEFAULT, dcpl_, H5P_DEFAULT), "cannot create a dataset");
    const hsize_t start[2] = {hsize_t(first), 0}, block[2] = {hsize_t(count), hsize_t(comps)};
    const hsize_t one = 1;
    const Id mem(H5Screate_simple(count > 0 ? rank : 1, count > 0 ? block : &one, nullptr), H5Sclose);
    if (count > 0) {
      H5Sselect_hyperslab(space, H5S_SELECT_SET, start, nullptr, block, nullptr);
    } else {
      H5Sselect_none(space), H5Sselect_none(mem);
    }
    const unsigned char dummy = 0;  // an empty dataset has no storage to write (every process sees it empty)
    if (rows > 0) checked(H5Dwrite(set, type, mem, space, xfer_, data ? data : &dummy), "writing failed");
    return set;
  }
  // The first process writes a dataset that every process creates.
  hid_t by_first(hid_t at, const char* name, hid_t type, long long n, const void* data) {
    return rows(at, name, type, n, 1, 0, comm_.rank() == 0 ? n : 0, data);
  }
  // The same for one value (a scalar dataset).
  void scalar(hid_t at, const char* name, hid_t type, const void* data) {
    const Id space(H5Screate(H5S_SCALAR), H5Sclose), mem(H5Screate(H5S_SCALAR), H5Sclose);
    const Id set(checked(H5Dcreate2(at, name, type, space, H5P_DEFAULT, dcpl_, H5P_DEFAULT), "cannot create a dataset"),
                 H5Dclose);
    if (comm_.rank() != 0) H5Sselect_none(space), H5Sselect_none(mem);
    checked(H5Dwrite(set, type, mem, space, xfer_, data), "writing failed");
  }
  void close(hid_t id, herr_t (*closer)(hid_t)) { checked(id >= 0 ? closer(id) : 0, "closing failed"); }
  void close_file() { checked(file_.release(), "closing failed"); }
  // The finished file's bytes (one process: made in memory).
  Bytes image() {
    checked(H5Fflush(file_, H5F_SCOPE_GLOBAL), "flushing failed");
    const ssize_t n = checked(H5Fget_file_image(file_, nullptr, 0), "no file image");
    Bytes out(std::size_t(std::max<ssize_t>(n, 0)));
    if (n > 0) checked(H5Fget_file_image(file_, out.data(), out.size()), "no file image");
    return out;
  }

 private:
  void write_attribute(hid_t at, const char* name, hid_t type, const void* value) {
    const Id space(H5Screate(H5S_SCALAR), H5Sclose);
    const Id a(checked(H5Acreate2(at, name, type, space, H5P_DEFAULT, H5P_DEFAULT), "cannot create an attribute"),
               H5Aclose);
    checked(H5Awrite(a, type, value), "writing failed");
  }

  Communicator& comm_;
  Id xfer_{H5Pcreate(H5P_DATASET_XFER), H5Pclose};
  Id dcpl_{H5Pcreate(H5P_DATASET_CREATE), H5Pclose};
  Id gcpl_{H5Pcreate(H5P_GROUP_CREATE), H5Pclose};
  Id file_{-1, H5Fclose};
  std::string why_;
};

void write_all(Hdf5Writer& w, const Checkpoint& c, const CheckpointOrigin& o) {
  const hid_t f = w.file();
  w.attribute(f, "format", std::string(kFormat));
  w.attribute(f, "format_version", static_cast<long long>(kFormatVersion));
  w.attribute(f, "poresph_version", std::string(PORESPH_VERSION));
  w.attribute(f, "case", o.case_name);
  w.attribute(f, "dimension", static_cast<long long>(c.dimension));
  w.attribute(f, "particles", static_cast<long long>(c.particles));
  w.attribute(f, "precision", c.precision);
  w.attribute(f, "time", c.time);
  w.attribute(f, "last_dt", c.last_dt);
  w.attribute(f, "first_dt", c.first_dt);
  w.attribute(f, "steps", static_cast<long long>(c.steps));
  const Id text(H5Tcopy(H5T_C_S1), H5Tclose);
  H5Tset_size(text, std::max<std::size_t>(o.resolved_case.size(), 1));
  w.scalar(f, "case", text, o.resolved_case.c_str());
  const hid_t fields = w.group(f, "fields");
  for (const CheckpointField& cf : c.fields) {
    const StoredType st = stored_type(cf);
    const long long count = cf.element_bytes ? static_cast<long long>(cf.bytes.size() / cf.element_bytes) : 0;
    const hid_t set = w.rows(fields, cf.name.c_str(), st.type, c.particles, st.components, c.first, count, cf.bytes.data());
    w.attribute(set, "unit", cf.unit);
    w.attribute(set, "description", cf.description);
    w.attribute(set, "type", std::string(type_name(cf.type, st.opaque)));
    w.close(set, H5Dclose);
  }
  w.close(fields, H5Gclose);
  const hid_t extras = w.group(f, "extras");
  w.scalar(extras, "dissipated_energy", H5T_NATIVE_DOUBLE, &c.dissipated_energy);
  w.close(w.by_first(extras, "rigid_bodies", H5T_NATIVE_DOUBLE, static_cast<long long>(c.rigid_bodies.size()),
                     c.rigid_bodies.data()),
          H5Dclose);
  w.close(extras, H5Gclose);
}

// One process: the file made in memory, then written whole like every durable file, so that a full
// disk fails a plain write. (HDF5 1.10 that fails to write its own file leaves objects open and
// crashes at exit.)
void write_in_memory(const std::string& path, const Checkpoint& c, const CheckpointOrigin& o, Communicator& comm) {
  Bytes image;
  std::string why;
  {
    Hdf5Writer w(path, comm);
    write_all(w, c, o);
    image = w.image();
    w.close_file();
    why = w.why();
  }
  if (!why.empty()) throw WriteError(path + ": " + why);
  DurableFile out(path);
  out.write(image.data(), image.size());
  out.commit();
}

// At most the bytes of the checkpoint's file: its data, and more than HDF5's own records need.
long long file_bound(const Checkpoint& c, const CheckpointOrigin& o) {
  long long bytes = (1LL << 15) + static_cast<long long>(o.resolved_case.size() + 8 * c.rigid_bodies.size());
  for (const CheckpointField& f : c.fields) bytes += (1LL << 10) + static_cast<long long>(f.element_bytes) * c.particles;
  return bytes;
}

// The file's room taken on the disk before HDF5 writes in it, and given back when HDF5 creates
// the file (MPI-IO truncates it): a disk without room is said here, not in the middle of HDF5's
// writes; one that another writer fills in between is not. Empty, or why not.
std::string reserve(const std::string& file, long long bytes) {
  const int fd = ::open(file.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) return std::string("cannot create the file: ") + std::strerror(errno);
  int err = ::fallocate(fd, 0, 0, bytes) == 0 ? 0 : errno;
  struct statvfs fs {};
  if (err == EOPNOTSUPP)  // a file system without it: its free space, counted
    err = ::fstatvfs(fd, &fs) == 0 && static_cast<long long>(fs.f_bavail) * static_cast<long long>(fs.f_frsize) < bytes ? ENOSPC : 0;
  ::close(fd);
  if (err == 0) return "";
  ::unlink(file.c_str());
  return "no room for the checkpoint (" + std::to_string(bytes) + " bytes): " + std::strerror(err);
}

// Several processes: each writes its slice through MPI-IO into the file the first one reserved.
void write_together(const std::string& path, const Checkpoint& c, const CheckpointOrigin& o, Communicator& comm) {
  const std::string partial = path + ".partial";
  Bytes room;
  if (comm.rank() == 0) {
    const std::string why = reserve(partial, file_bound(c, o));
    room.assign(why.begin(), why.end());
  }
  comm.broadcast(room, 0);
  if (!room.empty()) throw WriteError(path + ": " + std::string(room.begin(), room.end()));
  std::string why;
  {
    Hdf5Writer w(partial, comm);
    write_all(w, c, o);
    w.close_file();
    why = w.why();
  }
  // Every process's outcome: the first failure, with the process that had it.
  int from = -1;
  const std::string first = first_message(comm, why, &from);
  std::string verdict = first.empty() ? "" : path + ": " + first + " (process " + std::to_string(from) + ")";
  if (comm.rank() == 0) {
    if (!verdict.empty()) {
      ::unlink(partial.c_str());
    } else {
      try {
        publish_durably(partial, path);
      } catch (const WriteError& e) {
        verdict = e.what();
      }
    }
  }
  Bytes b(verdict.begin(), verdict.end());
  comm.broadcast(b, 0);
  if (!b.empty()) throw WriteError(std::string(b.begin(), b.end()));
}

}  // namespace

void write_hdf5_checkpoint(const std::string& path, const Checkpoint& c, const CheckpointOrigin& o, Communicator& comm) {
  if (comm.mpi_comm()) write_together(path, c, o, comm);
  else write_in_memory(path, c, o, comm);
}

}  // namespace psph
