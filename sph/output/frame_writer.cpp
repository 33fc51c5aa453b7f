// FrameWriter: HDF5 1.10 C API frames and the XDMF index that points into them.
#include "sph/output/frame_writer.h"

#include "sph/output/atomic_file.h"

#include <hdf5.h>

#include <array>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <numeric>
#include <sstream>
#include <stdexcept>
#include <string>
#include <system_error>
#include <vector>

namespace soilsph::sph {
namespace {

constexpr const char* kConventions =
    "SI units; x horizontal, y vertical (up), z = 0 (2D plane strain); stress components sxx, syy, "
    "szz, sxy tension-positive; p = -tr(sigma)/3 and q = sqrt(3/2 s:s) compression-positive";

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

void check(herr_t status, const std::string& what) {
  if (status < 0) throw std::runtime_error("HDF5: cannot " + what);
}

/// The writer takes no HDF5 file lock (HDF5 ≥ 1.10.7): a viewer that keeps frames.h5 open (h5py,
/// ParaView) holds a shared lock, and a locking writer could then not reopen the file for the next
/// frame and the run would fail. The lock would only guard against a second run writing into the
/// same folder at the same time, which is a user error either way.
void allow_concurrent_readers(hid_t file_access) {
#if H5_VERSION_GE(1, 10, 7)
  check(H5Pset_file_locking(file_access, false, true), "disable HDF5 file locking");
#else
  (void)file_access;
#endif
}

std::string frame_name(std::size_t index) {
  char name[32];
  std::snprintf(name, sizeof name, "frame_%06zu", index);
  return name;
}

/// Writes a contiguous dataset of `rows` × `columns` (columns = 1: a 1-D dataset).
void write_dataset(hid_t group, const std::string& name, hid_t file_type, hid_t memory_type, std::size_t rows,
                   std::size_t columns, const void* data, const std::string& where) {
  const std::array<hsize_t, 2> dims{rows, columns};
  const Handle space(H5Screate_simple(columns == 1 ? 1 : 2, dims.data(), nullptr), H5Sclose,
                     "create the dataspace of " + where + name);
  const Handle set(H5Dcreate2(group, name.c_str(), file_type, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
                   H5Dclose, "create dataset " + where + name);
  if (rows > 0)
    check(H5Dwrite(set, memory_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data), "write " + where + name);
}

void write_double(hid_t group, const std::string& name, std::span<const double> values,
                  const std::string& where) {
  write_dataset(group, name, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, values.size(), 1, values.data(), where);
}

/// Interleaves two components with z = 0 into an N×3 array (XDMF XYZ geometry and vectors).
std::vector<double> xyz(std::span<const double> a, std::span<const double> b) {
  std::vector<double> out(3 * a.size(), 0.0);
  for (std::size_t i = 0; i < a.size(); ++i) {
    out[3 * i] = a[i];
    out[3 * i + 1] = b[i];
  }
  return out;
}

void write_string_attribute(hid_t object, const char* name, const std::string& value) {
  const Handle type(H5Tcopy(H5T_C_S1), H5Tclose, "copy the string type");
  check(H5Tset_size(type, value.size() + 1), "size a string attribute");
  const Handle space(H5Screate(H5S_SCALAR), H5Sclose, "create a scalar dataspace");
  const Handle attribute(H5Acreate2(object, name, type, space, H5P_DEFAULT, H5P_DEFAULT), H5Aclose,
                         std::string("create attribute ") + name);
  check(H5Awrite(attribute, type, value.c_str()), std::string("write attribute ") + name);
}

void write_double_attribute(hid_t object, const char* name, double value) {
  const Handle space(H5Screate(H5S_SCALAR), H5Sclose, "create a scalar dataspace");
  const Handle attribute(H5Acreate2(object, name, H5T_IEEE_F64LE, space, H5P_DEFAULT, H5P_DEFAULT), H5Aclose,
                         std::string("create attribute ") + name);
  check(H5Awrite(attribute, H5T_NATIVE_DOUBLE, &value), std::string("write attribute ") + name);
}

/// Shortest text that reads back to the same double (XDMF Time values).
std::string exact(double value) {
  char text[32];
  const auto result = std::to_chars(text, text + sizeof text, value);
  return std::string(text, result.ptr);
}

/// One scalar or vector attribute of the XDMF grid: the field it belongs to, name (= HDF5 dataset),
/// XDMF type, components.
struct XdmfField {
  Field field;
  const char* name;
  const char* attribute_type;  ///< "Scalar" or "Vector"
  const char* number_type;     ///< "Float" or "Int"
  int precision;               ///< bytes
  int components;
};
constexpr std::array<XdmfField, 11> kFields{
    {{Field::velocity, "velocity", "Vector", "Float", 8, 3},
     {Field::stress, "sxx", "Scalar", "Float", 8, 1},
     {Field::stress, "syy", "Scalar", "Float", 8, 1},
     {Field::stress, "szz", "Scalar", "Float", 8, 1},
     {Field::stress, "sxy", "Scalar", "Float", 8, 1},
     {Field::p, "p", "Scalar", "Float", 8, 1},
     {Field::q, "q", "Scalar", "Float", 8, 1},
     {Field::plastic_strain, "plastic_strain", "Scalar", "Float", 8, 1},
     {Field::density, "density", "Scalar", "Float", 8, 1},
     {Field::layer, "layer", "Scalar", "Int", 4, 1},
     {Field::speed, "speed", "Scalar", "Float", 8, 1}}};

/// Root dataset of the vertex indices 0..n−1 that make each of n particles a Polyvertex cell: without
/// explicit connectivity the Xdmf3 library (ParaView's Xdmf3 readers) reads a grid of points but no
/// cells. One dataset per distinct particle count, shared by all frames with that count.
std::string vertices_name(std::size_t particles) {
  return "vertices_" + std::to_string(particles);
}

std::string dimensions(std::size_t particles, int components) {
  return components == 1 ? std::to_string(particles)
                         : std::to_string(particles) + " " + std::to_string(components);
}

}  // namespace

FrameWriter::FrameWriter(const std::filesystem::path& dir, FieldSet fields)
    : h5_path_(dir / "frames.h5"), xdmf_path_(dir / "frames.xdmf"), fields_(fields) {
  std::filesystem::create_directories(dir);
  const Handle access(H5Pcreate(H5P_FILE_ACCESS), H5Pclose, "create a file-access property list");
  allow_concurrent_readers(access);
  Handle file(H5Fcreate(h5_path_.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, access), H5Fclose,
              "create " + h5_path_.string());
  write_string_attribute(file, "conventions", kConventions);
  file.close("close " + h5_path_.string());
  write_xdmf();
}

void FrameWriter::write(const Frame& frame) {
  const std::size_t n = frame.x.size();
  const auto check_size = [&](std::size_t size) {
    if (size != n) {
      throw std::invalid_argument("FrameWriter: the fields of the frame at t = " + exact(frame.time) +
                                  " have different lengths (" + std::to_string(size) + " vs " +
                                  std::to_string(n) + " particles)");
    }
  };
  const auto has = [&](Field f) { return fields_.contains(f); };
  check_size(frame.y.size());
  if (has(Field::velocity) || has(Field::speed)) {
    check_size(frame.vx.size());
    check_size(frame.vy.size());
  }
  if (has(Field::stress)) {
    for (const auto& s : {frame.sxx, frame.syy, frame.szz, frame.sxy}) check_size(s.size());
  }
  if (has(Field::p)) check_size(frame.p.size());
  if (has(Field::q)) check_size(frame.q.size());
  if (has(Field::plastic_strain)) check_size(frame.plastic_strain.size());
  if (has(Field::density)) check_size(frame.density.size());
  if (has(Field::layer)) check_size(frame.layer.size());
  const std::string name = frame_name(frames_.size());
  const std::string where = h5_path_.string() + ":/" + name + "/";
  // The file is open only while a frame is written: a reader that opens it between writes finds
  // it complete and consistent (closing writes all metadata).
  const Handle access(H5Pcreate(H5P_FILE_ACCESS), H5Pclose, "create a file-access property list");
  allow_concurrent_readers(access);
  Handle file(H5Fopen(h5_path_.c_str(), H5F_ACC_RDWR, access), H5Fclose, "open " + h5_path_.string());
  {
    const Handle group(H5Gcreate2(file, name.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose,
                       "create group " + where);
    write_double_attribute(group, "time", frame.time);
    const std::vector<double> position = xyz(frame.x, frame.y);
    write_dataset(group, "position", H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, n, 3, position.data(), where);
    if (has(Field::velocity)) {
      const std::vector<double> velocity = xyz(frame.vx, frame.vy);
      write_dataset(group, "velocity", H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, n, 3, velocity.data(), where);
    }
    if (has(Field::speed)) {
      std::vector<double> speed(n);
      for (std::size_t i = 0; i < n; ++i) speed[i] = std::hypot(frame.vx[i], frame.vy[i]);
      write_double(group, "speed", speed, where);
    }
    if (has(Field::stress)) {
      write_double(group, "sxx", frame.sxx, where);
      write_double(group, "syy", frame.syy, where);
      write_double(group, "szz", frame.szz, where);
      write_double(group, "sxy", frame.sxy, where);
    }
    if (has(Field::p)) write_double(group, "p", frame.p, where);
    if (has(Field::q)) write_double(group, "q", frame.q, where);
    if (has(Field::plastic_strain)) write_double(group, "plastic_strain", frame.plastic_strain, where);
    if (has(Field::density)) write_double(group, "density", frame.density, where);
    if (has(Field::layer))
      write_dataset(group, "layer", H5T_STD_I32LE, H5T_NATIVE_INT, n, 1, frame.layer.data(), where);
  }
  const std::string vertices = vertices_name(n);
  if (H5Lexists(file, vertices.c_str(), H5P_DEFAULT) <= 0) {
    std::vector<long long> index(n);
    std::iota(index.begin(), index.end(), 0LL);
    write_dataset(file, vertices, H5T_STD_I64LE, H5T_NATIVE_LLONG, n, 1, index.data(),
                  h5_path_.string() + ":/");
  }
  // Close (and so flush) before indexing the frame: the XDMF never points at data not on disk.
  file.close("close " + h5_path_.string());
  frames_.push_back({frame.time, n});
  write_xdmf();
}

void FrameWriter::write_xdmf() const {
  const std::string h5_name = h5_path_.filename().string();
  std::ostringstream out;
  out << "<?xml version=\"1.0\" ?>\n"
      << "<!-- soilsph SPH frames (data in " << h5_name << "). " << kConventions << " -->\n"
      << "<Xdmf Version=\"2.0\">\n  <Domain>\n"
      << "    <Grid Name=\"soil\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
  for (std::size_t index = 0; index < frames_.size(); ++index) {
    const std::string name = frame_name(index);
    const std::size_t n = frames_[index].particles;
    const auto data_item = [&](const char* dataset, const char* number_type, int precision,
                               int components) {
      out << "          <DataItem Dimensions=\"" << dimensions(n, components) << "\" NumberType=\""
          << number_type << "\" Precision=\"" << precision << "\" Format=\"HDF\">" << h5_name << ":/"
          << name << "/" << dataset << "</DataItem>\n";
    };
    out << "      <Grid Name=\"" << name << "\" GridType=\"Uniform\">\n"
        << "        <Time Value=\"" << exact(frames_[index].time) << "\" />\n"
        << "        <Topology TopologyType=\"Polyvertex\" NumberOfElements=\"" << n
        << "\" NodesPerElement=\"1\">\n"
        << "          <DataItem Dimensions=\"" << n
        << "\" NumberType=\"Int\" Precision=\"8\" Format=\"HDF\">" << h5_name << ":/" << vertices_name(n)
        << "</DataItem>\n"
        << "        </Topology>\n"
        << "        <Geometry GeometryType=\"XYZ\">\n";
    data_item("position", "Float", 8, 3);
    out << "        </Geometry>\n";
    for (const XdmfField& field : kFields) {
      if (!fields_.contains(field.field)) continue;
      out << "        <Attribute Name=\"" << field.name << "\" AttributeType=\"" << field.attribute_type
          << "\" Center=\"Node\">\n";
      data_item(field.name, field.number_type, field.precision, field.components);
      out << "        </Attribute>\n";
    }
    out << "      </Grid>\n";
  }
  out << "    </Grid>\n  </Domain>\n</Xdmf>\n";
  // Replaced atomically: a reader (ParaView on a running simulation) never sees a half-written index.
  replace_file(xdmf_path_, out.str());
}

}  // namespace soilsph::sph
