// FrameWriter: HDF5 1.10 C API frames and the XDMF index that points into them.
#include "sph/output/frame_writer.h"

#include "sph/output/atomic_file.h"
#include "sph/output/disk_space.h"
#include "sph/output/hdf5_file.h"

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

using hdf5::check;
using hdf5::Handle;
using hdf5::write_dataset;
using hdf5::write_double_attribute;
using hdf5::write_string_attribute;

/// Bytes of HDF5 metadata (superblock, group, dataset headers) allowed for besides the data.
constexpr std::uintmax_t kFileOverhead = 64 * 1024;

std::string frame_name(std::size_t index) {
  char name[32];
  std::snprintf(name, sizeof name, "frame_%06zu", index);
  return name;
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
  ensure_room(h5_path_, kFileOverhead);
  const Handle access(hdf5::unlocked_file_access(), H5Pclose, "create a file-access property list");
  Handle file(H5Fcreate(h5_path_.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, access), H5Fclose,
              "create " + h5_path_.string());
  write_string_attribute(file, "conventions", kConventions);
  file.close("close " + h5_path_.string());
  write_xdmf();
}

FrameWriter::FrameWriter(const std::filesystem::path& dir, FieldSet fields, Continuing)
    : h5_path_(dir / "frames.h5"), xdmf_path_(dir / "frames.xdmf"), fields_(fields) {}

FrameWriter FrameWriter::continuing(const std::filesystem::path& dir, FieldSet fields, double last_kept) {
  FrameWriter writer(dir, fields, Continuing{});
  const Handle access(hdf5::unlocked_file_access(), H5Pclose, "create a file-access property list");
  Handle file(H5Fopen(writer.h5_path_.c_str(), H5F_ACC_RDWR, access), H5Fclose,
              "open " + writer.h5_path_.string());
  for (std::size_t index = 0;; ++index) {
    const std::string name = frame_name(index);
    if (H5Lexists(file, name.c_str(), H5P_DEFAULT) <= 0) break;
    const Handle group(H5Gopen2(file, name.c_str(), H5P_DEFAULT), H5Gclose, "open group " + name);
    const double time = hdf5::read_double_attribute(group, "time");
    if (time > last_kept) {
      check(H5Ldelete(file, name.c_str(), H5P_DEFAULT), "delete " + name + ", written after the checkpoint");
      continue;
    }
    const Handle set(H5Dopen2(group, "position", H5P_DEFAULT), H5Dclose, "open " + name + "/position");
    const Handle space(H5Dget_space(set), H5Sclose, "read the dataspace of " + name + "/position");
    std::array<hsize_t, 2> dims{};
    H5Sget_simple_extent_dims(space, dims.data(), nullptr);
    writer.frames_.push_back({time, static_cast<std::size_t>(dims[0])});
  }
  file.close("close " + writer.h5_path_.string());
  writer.write_xdmf();
  return writer;
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
  // Room first: a write that fails half-way can leave the file unreadable, earlier frames included.
  std::uintmax_t values = 3 * n;
  for (const XdmfField& f : kFields) values += fields_.contains(f.field) ? f.components * n : 0;
  ensure_room(h5_path_, 8 * values + (frames_.empty() ? 8 * n : 0) + kFileOverhead);
  // The file is open only while a frame is written: a reader that opens it between writes finds
  // it complete and consistent (closing writes all metadata).
  const Handle access(hdf5::unlocked_file_access(), H5Pclose, "create a file-access property list");
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
      hdf5::write_doubles(group, "speed", speed, where);
    }
    if (has(Field::stress)) {
      hdf5::write_doubles(group, "sxx", frame.sxx, where);
      hdf5::write_doubles(group, "syy", frame.syy, where);
      hdf5::write_doubles(group, "szz", frame.szz, where);
      hdf5::write_doubles(group, "sxy", frame.sxy, where);
    }
    if (has(Field::p)) hdf5::write_doubles(group, "p", frame.p, where);
    if (has(Field::q)) hdf5::write_doubles(group, "q", frame.q, where);
    if (has(Field::plastic_strain)) hdf5::write_doubles(group, "plastic_strain", frame.plastic_strain, where);
    if (has(Field::density)) hdf5::write_doubles(group, "density", frame.density, where);
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
