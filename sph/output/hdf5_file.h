#pragma once
/// @file
/// The few HDF5 1.10 C API pieces the frame writer and the checkpoint share: identifiers that close
/// themselves, datasets and attributes written and read whole, and one-line errors. Internal to
/// sph/output (it includes hdf5.h).
#include <hdf5.h>

#include <array>
#include <cstddef>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

namespace soilsph::sph::hdf5 {

/// HDF5 prints its own error stack on stderr (14–165 lines for a full disk), which buries the
/// reason; every failure here becomes one exception with one line instead. Called before any use.
inline void silence_diagnostics() {
  static const bool silenced = [] { return H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr) >= 0; }();
  (void)silenced;
}

/// Owns one HDF5 identifier and closes it with the matching H5?close.
class Handle {
 public:
  Handle(hid_t id, herr_t (*close)(hid_t), const std::string& what) : id_(id), close_(close) {
    if (id_ < 0) throw std::runtime_error("HDF5: cannot " + what);
  }
  ~Handle() {
    if (id_ >= 0) close_(id_);
  }
  /// Closes now and reports failure (a file's close writes its metadata).
  void close(const std::string& what) {
    const herr_t status = close_(id_);
    id_ = -1;
    if (status < 0) throw std::runtime_error("HDF5: cannot " + what);
  }
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;
  operator hid_t() const { return id_; }

 private:
  hid_t id_;
  herr_t (*close_)(hid_t);
};

inline void check(herr_t status, const std::string& what) {
  if (status < 0) throw std::runtime_error("HDF5: cannot " + what);
}

/// A file-access property list without HDF5's file lock (HDF5 ≥ 1.10.7): a viewer that keeps a file
/// open (h5py, ParaView) holds a shared lock, and a locking writer could then not reopen the file
/// for the next frame and the run would fail. The lock would only guard against a second run
/// writing into the same folder at the same time, which is a user error either way.
inline hid_t unlocked_file_access() {
  silence_diagnostics();
  const hid_t access = H5Pcreate(H5P_FILE_ACCESS);
  if (access < 0) throw std::runtime_error("HDF5: cannot create a file-access property list");
#if H5_VERSION_GE(1, 10, 7)
  if (H5Pset_file_locking(access, false, true) < 0) {
    H5Pclose(access);
    throw std::runtime_error("HDF5: cannot disable HDF5 file locking");
  }
#endif
  return access;
}

/// Writes a contiguous dataset of `rows` × `columns` (columns = 1: a 1-D dataset).
inline void write_dataset(hid_t group, const std::string& name, hid_t file_type, hid_t memory_type,
                          std::size_t rows, std::size_t columns, const void* data, const std::string& where) {
  const std::array<hsize_t, 2> dims{rows, columns};
  const Handle space(H5Screate_simple(columns == 1 ? 1 : 2, dims.data(), nullptr), H5Sclose,
                     "create the dataspace of " + where + name);
  const Handle set(H5Dcreate2(group, name.c_str(), file_type, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
                   H5Dclose, "create dataset " + where + name);
  if (rows > 0)
    check(H5Dwrite(set, memory_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data), "write " + where + name);
}

inline void write_doubles(hid_t group, const std::string& name, std::span<const double> values,
                          const std::string& where) {
  write_dataset(group, name, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, values.size(), 1, values.data(), where);
}

/// Reads a whole dataset of `count` values of `memory_type` into `data`; throws if its size differs.
inline void read_dataset(hid_t group, const std::string& name, hid_t memory_type, std::size_t count, void* data,
                         const std::string& where) {
  const Handle set(H5Dopen2(group, name.c_str(), H5P_DEFAULT), H5Dclose, "open dataset " + where + name);
  const Handle space(H5Dget_space(set), H5Sclose, "read the dataspace of " + where + name);
  const hssize_t points = H5Sget_simple_extent_npoints(space);
  if (points < 0 || static_cast<std::size_t>(points) != count)
    throw std::runtime_error(where + name + " holds " + std::to_string(points) + " values, expected " +
                             std::to_string(count));
  if (count > 0) check(H5Dread(set, memory_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data), "read " + where + name);
}

inline void write_string_attribute(hid_t object, const char* name, const std::string& value) {
  const Handle type(H5Tcopy(H5T_C_S1), H5Tclose, "copy the string type");
  check(H5Tset_size(type, value.size() + 1), "size a string attribute");
  const Handle space(H5Screate(H5S_SCALAR), H5Sclose, "create a scalar dataspace");
  const Handle attribute(H5Acreate2(object, name, type, space, H5P_DEFAULT, H5P_DEFAULT), H5Aclose,
                         std::string("create attribute ") + name);
  check(H5Awrite(attribute, type, value.c_str()), std::string("write attribute ") + name);
}

inline void write_double_attribute(hid_t object, const char* name, double value) {
  const Handle space(H5Screate(H5S_SCALAR), H5Sclose, "create a scalar dataspace");
  const Handle attribute(H5Acreate2(object, name, H5T_IEEE_F64LE, space, H5P_DEFAULT, H5P_DEFAULT), H5Aclose,
                         std::string("create attribute ") + name);
  check(H5Awrite(attribute, H5T_NATIVE_DOUBLE, &value), std::string("write attribute ") + name);
}

inline double read_double_attribute(hid_t object, const char* name) {
  const Handle attribute(H5Aopen(object, name, H5P_DEFAULT), H5Aclose, std::string("open attribute ") + name);
  double value = 0.0;
  check(H5Aread(attribute, H5T_NATIVE_DOUBLE, &value), std::string("read attribute ") + name);
  return value;
}

inline std::string read_string_attribute(hid_t object, const char* name) {
  const Handle attribute(H5Aopen(object, name, H5P_DEFAULT), H5Aclose, std::string("open attribute ") + name);
  const Handle type(H5Aget_type(attribute), H5Tclose, std::string("read the type of attribute ") + name);
  std::vector<char> text(H5Tget_size(type) + 1, '\0');
  check(H5Aread(attribute, type, text.data()), std::string("read attribute ") + name);
  return text.data();
}

}  // namespace soilsph::sph::hdf5
