// FrameWriter: HDF5 1.10 C API frames and the XDMF index that points into them.
#include "sph/output/frame_writer.h"

#include "sph/output/atomic_file.h"
#include "sph/output/disk_space.h"
#include "sph/output/hdf5_file.h"

#include <algorithm>
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
constexpr const char* kConventions3 =
    "SI units; y vertical (up), x and z horizontal (3D); stress components sxx, syy, szz, sxy, sxz, "
    "syz tension-positive; p = -tr(sigma)/3 and q = sqrt(3/2 s:s) compression-positive";

const char* conventions(int dimension) { return dimension == 3 ? kConventions3 : kConventions; }

using hdf5::check;
using hdf5::Handle;
using hdf5::write_dataset;
using hdf5::write_double_attribute;
using hdf5::write_string_attribute;

/// Bytes of HDF5 metadata (superblock, object headers of a dozen datasets) allowed for per file
/// besides its data, and per link of the index.
constexpr std::uintmax_t kFileOverhead = 16 * 1024, kLinkBytes = 256;

std::string frame_name(std::size_t index) {
  char name[32];
  std::snprintf(name, sizeof name, "frame_%06zu", index);
  return name;
}

/// Interleaves two components with z = 0, or three, into an N×3 array (XDMF XYZ geometry and vectors).
std::vector<double> xyz(std::span<const double> a, std::span<const double> b, std::span<const double> c = {}) {
  std::vector<double> out(3 * a.size(), 0.0);
  for (std::size_t i = 0; i < a.size(); ++i) {
    out[3 * i] = a[i];
    out[3 * i + 1] = b[i];
    if (!c.empty()) out[3 * i + 2] = c[i];
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
  bool space_only = false;  ///< written in 3D frames only
};
constexpr std::array<XdmfField, 14> kFields{
    {{Field::velocity, "velocity", "Vector", "Float", 8, 3},
     {Field::stress, "sxx", "Scalar", "Float", 8, 1},
     {Field::stress, "syy", "Scalar", "Float", 8, 1},
     {Field::stress, "szz", "Scalar", "Float", 8, 1},
     {Field::stress, "sxy", "Scalar", "Float", 8, 1},
     {Field::stress, "sxz", "Scalar", "Float", 8, 1, true},
     {Field::stress, "syz", "Scalar", "Float", 8, 1, true},
     {Field::p, "p", "Scalar", "Float", 8, 1},
     {Field::q, "q", "Scalar", "Float", 8, 1},
     {Field::plastic_strain, "plastic_strain", "Scalar", "Float", 8, 1},
     {Field::density, "density", "Scalar", "Float", 8, 1},
     {Field::layer, "layer", "Scalar", "Int", 4, 1},
     {Field::material, "material", "Scalar", "Int", 4, 1},
     {Field::speed, "speed", "Scalar", "Float", 8, 1}}};

/// Whether the writer of frames of `dimension` writes `field`'s dataset when its Field is selected.
bool written_in(const XdmfField& field, int dimension) { return dimension == 3 || !field.space_only; }

/// Root dataset of the vertex indices 0..n−1 that make each of n particles a Polyvertex cell: without
/// explicit connectivity the Xdmf3 library (ParaView's Xdmf3 readers) reads a grid of points but no
/// cells. One dataset per distinct particle count, shared by all frames with that count.
std::string vertices_name(std::size_t particles) {
  return "vertices_" + std::to_string(particles);
}

/// The dataset of a UMAT's STATEV(k), k from 1.
std::string statev_name(int k) {
  return "statev_" + std::to_string(k);
}

std::string dimensions(std::size_t particles, int components) {
  return components == 1 ? std::to_string(particles)
                         : std::to_string(particles) + " " + std::to_string(components);
}

}  // namespace

namespace {
/// A new HDF5 file written whole by `fill(file)` to PATH.tmp and renamed to PATH: a reader, a crash
/// or kill -9 finds either the complete file or none, never a torn one.
template <class Fill>
void write_file_atomically(const std::filesystem::path& path, Fill&& fill) {
  std::filesystem::path temporary = path;
  temporary += ".tmp";
  try {
    const Handle access(hdf5::unlocked_file_access(), H5Pclose, "create a file-access property list");
    Handle file(H5Fcreate(temporary.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, access), H5Fclose,
                "create " + temporary.string());
    fill(file);
    file.close("close " + temporary.string());
  } catch (...) {
    std::error_code ignored;
    std::filesystem::remove(temporary, ignored);
    throw;
  }
  std::error_code error;
  std::filesystem::rename(temporary, path, error);
  if (error) throw std::runtime_error("cannot rename " + temporary.string() + ": " + error.message());
}

/// frames/ inside the run folder, relative: the index's external links and the XDMF are relative
/// too, so a run folder can be moved or copied whole.
constexpr const char* kFrameFolder = "frames";
}  // namespace

FrameWriter::FrameWriter(const std::filesystem::path& dir, FieldSet fields, int dimension)
    : h5_path_(dir / "frames.h5"), xdmf_path_(dir / "frames.xdmf"), fields_(fields), dimension_(dimension) {
  if (dimension != 2 && dimension != 3) throw std::invalid_argument("FrameWriter: dimension must be 2 or 3");
  std::filesystem::create_directories(dir);
  std::filesystem::remove_all(dir / kFrameFolder);  // an earlier run's frames
  std::filesystem::create_directories(dir / kFrameFolder);
  write_index();
  write_xdmf();
}

FrameWriter::FrameWriter(const std::filesystem::path& dir, FieldSet fields, int dimension, Continuing)
    : h5_path_(dir / "frames.h5"), xdmf_path_(dir / "frames.xdmf"), fields_(fields), dimension_(dimension) {
  if (dimension != 2 && dimension != 3) throw std::invalid_argument("FrameWriter: dimension must be 2 or 3");
}

FrameWriter FrameWriter::continuing(const std::filesystem::path& dir, FieldSet fields, double last_kept,
                                    int dimension) {
  FrameWriter writer(dir, fields, dimension, Continuing{});
  std::error_code ignored;
  for (const auto& entry : std::filesystem::directory_iterator(dir / kFrameFolder, ignored))
    if (entry.path().extension() == ".tmp") std::filesystem::remove(entry.path(), ignored);  // a killed write
  // The frame files are the record; the index and the XDMF are rebuilt from them, so an index that a
  // kill left one frame behind is repaired here.
  for (std::size_t index = 0;; ++index) {
    const std::filesystem::path path = writer.frame_path(index);
    if (!std::filesystem::exists(path)) break;
    double time = 0.0;
    std::size_t particles = 0;
    int state_variables = 0;
    bool ids = false;
    {
      const Handle access(hdf5::unlocked_file_access(), H5Pclose, "create a file-access property list");
      const Handle file(H5Fopen(path.c_str(), H5F_ACC_RDONLY, access), H5Fclose, "open " + path.string());
      time = hdf5::read_double_attribute(file, "time");
      while (H5Lexists(file, statev_name(state_variables + 1).c_str(), H5P_DEFAULT) > 0) ++state_variables;
      const Handle set(H5Dopen2(file, "position", H5P_DEFAULT), H5Dclose, "open " + path.string() + ":/position");
      const Handle space(H5Dget_space(set), H5Sclose, "read the dataspace of " + path.string() + ":/position");
      std::array<hsize_t, 2> dims{};
      H5Sget_simple_extent_dims(space, dims.data(), nullptr);
      particles = static_cast<std::size_t>(dims[0]);
      ids = H5Lexists(file, "id", H5P_DEFAULT) > 0;
    }
    if (time > last_kept) {  // written after the checkpoint: this frame and every later one go
      for (std::size_t later = index; std::filesystem::remove(writer.frame_path(later)); ++later) {
      }
      break;
    }
    writer.frames_.push_back({time, particles, state_variables, ids});
  }
  writer.write_index();
  writer.write_xdmf();
  return writer;
}

std::filesystem::path FrameWriter::frame_path(std::size_t index) const {
  return h5_path_.parent_path() / kFrameFolder / (frame_name(index) + ".h5");
}

void FrameWriter::write_index() const {
  ensure_room(h5_path_, kFileOverhead + kLinkBytes * frames_.size());
  write_file_atomically(h5_path_, [&](hid_t file) {
    write_string_attribute(file, "conventions", conventions(dimension_));
    std::vector<std::size_t> counts;
    for (std::size_t index = 0; index < frames_.size(); ++index) {
      const std::string name = frame_name(index), target = std::string(kFrameFolder) + "/" + name + ".h5";
      check(H5Lcreate_external(target.c_str(), "/", file, name.c_str(), H5P_DEFAULT, H5P_DEFAULT),
            "link " + name + " in " + h5_path_.string());
      const std::size_t n = frames_[index].particles;
      if (std::find(counts.begin(), counts.end(), n) != counts.end()) continue;
      counts.push_back(n);
      const std::string vertices = vertices_name(n), vertex_file = std::string(kFrameFolder) + "/" + vertices + ".h5";
      check(H5Lcreate_external(vertex_file.c_str(), "/vertices", file, vertices.c_str(), H5P_DEFAULT, H5P_DEFAULT),
            "link " + vertices + " in " + h5_path_.string());
    }
  });
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
  if (frame.dimension != dimension_)
    throw std::invalid_argument("FrameWriter: the frame at t = " + exact(frame.time) + " is " +
                                std::to_string(frame.dimension) + "D, the writer's frames " +
                                std::to_string(dimension_) + "D");
  const bool space = dimension_ == 3;
  const auto has = [&](Field f) { return fields_.contains(f); };
  check_size(frame.y.size());
  if (space) check_size(frame.z.size());
  if (has(Field::velocity) || has(Field::speed)) {
    check_size(frame.vx.size());
    check_size(frame.vy.size());
    if (space) check_size(frame.vz.size());
  }
  if (has(Field::stress)) {
    for (const auto& s : {frame.sxx, frame.syy, frame.szz, frame.sxy}) check_size(s.size());
    if (space) check_size(frame.sxz.size()), check_size(frame.syz.size());
  }
  if (has(Field::p)) check_size(frame.p.size());
  if (has(Field::q)) check_size(frame.q.size());
  if (has(Field::plastic_strain)) check_size(frame.plastic_strain.size());
  if (has(Field::density)) check_size(frame.density.size());
  if (has(Field::layer)) check_size(frame.layer.size());
  if (has(Field::material)) check_size(frame.material.size());
  const auto statev_count = static_cast<std::size_t>(std::max(frame.state_variable_count, 0));
  if (frame.state_variables.size() != statev_count * n)
    throw std::invalid_argument("FrameWriter: the frame at t = " + exact(frame.time) + " has " +
                                std::to_string(frame.state_variables.size()) + " state-variable values for " +
                                std::to_string(statev_count) + " variables of " + std::to_string(n) +
                                " particles");
  const bool ids = !frame.id.empty();
  if (ids) check_size(frame.id.size());
  const std::filesystem::path path = frame_path(frames_.size());
  const std::string where = path.string() + ":/";
  // Room first, so that a full disk is one clear message rather than HDF5's failure half-way.
  std::uintmax_t values = (ids ? 4 : 3) * n + statev_count * n;
  for (const XdmfField& f : kFields) values += fields_.contains(f.field) && written_in(f, dimension_) ? f.components * n : 0;
  ensure_room(path, 8 * values + kFileOverhead);
  write_file_atomically(path, [&](hid_t file) {
    write_double_attribute(file, "time", frame.time);
    const std::vector<double> position = xyz(frame.x, frame.y, frame.z);
    write_dataset(file, "position", H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, n, 3, position.data(), where);
    if (ids) write_dataset(file, "id", H5T_STD_U64LE, H5T_NATIVE_UINT64, n, 1, frame.id.data(), where);
    if (has(Field::velocity)) {
      const std::vector<double> velocity = xyz(frame.vx, frame.vy, frame.vz);
      write_dataset(file, "velocity", H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, n, 3, velocity.data(), where);
    }
    if (has(Field::speed)) {
      std::vector<double> speed(n);
      if (space)
        for (std::size_t i = 0; i < n; ++i) speed[i] = std::hypot(frame.vx[i], frame.vy[i], frame.vz[i]);
      else
        for (std::size_t i = 0; i < n; ++i) speed[i] = std::hypot(frame.vx[i], frame.vy[i]);
      hdf5::write_doubles(file, "speed", speed, where);
    }
    if (has(Field::stress)) {
      hdf5::write_doubles(file, "sxx", frame.sxx, where);
      hdf5::write_doubles(file, "syy", frame.syy, where);
      hdf5::write_doubles(file, "szz", frame.szz, where);
      hdf5::write_doubles(file, "sxy", frame.sxy, where);
      if (space) {
        hdf5::write_doubles(file, "sxz", frame.sxz, where);
        hdf5::write_doubles(file, "syz", frame.syz, where);
      }
    }
    if (has(Field::p)) hdf5::write_doubles(file, "p", frame.p, where);
    if (has(Field::q)) hdf5::write_doubles(file, "q", frame.q, where);
    if (has(Field::plastic_strain)) hdf5::write_doubles(file, "plastic_strain", frame.plastic_strain, where);
    if (has(Field::density)) hdf5::write_doubles(file, "density", frame.density, where);
    if (has(Field::layer))
      write_dataset(file, "layer", H5T_STD_I32LE, H5T_NATIVE_INT, n, 1, frame.layer.data(), where);
    if (has(Field::material))
      write_dataset(file, "material", H5T_STD_I32LE, H5T_NATIVE_INT, n, 1, frame.material.data(), where);
    for (std::size_t k = 0; k < statev_count; ++k)
      hdf5::write_doubles(file, statev_name(static_cast<int>(k) + 1), frame.state_variables.subspan(k * n, n),
                          where);
  });
  const std::filesystem::path vertices = h5_path_.parent_path() / kFrameFolder / (vertices_name(n) + ".h5");
  if (!std::filesystem::exists(vertices)) {
    std::vector<long long> index(n);
    std::iota(index.begin(), index.end(), 0LL);
    write_file_atomically(vertices, [&](hid_t file) {
      write_dataset(file, "vertices", H5T_STD_I64LE, H5T_NATIVE_LLONG, n, 1, index.data(), vertices.string() + ":/");
    });
  }
  // The frame's file is complete on disk before the index and the XDMF point at it.
  frames_.push_back({frame.time, n, static_cast<int>(statev_count), ids});
  write_index();
  write_xdmf();
}

void FrameWriter::write_xdmf() const {
  const std::string h5_name = h5_path_.filename().string();
  std::ostringstream out;
  out << "<?xml version=\"1.0\" ?>\n"
      << "<!-- soilsph SPH frames (data in " << h5_name << "). " << conventions(dimension_) << " -->\n"
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
    if (frames_[index].ids) {
      out << "        <Attribute Name=\"id\" AttributeType=\"Scalar\" Center=\"Node\">\n";
      data_item("id", "UInt", 8, 1);
      out << "        </Attribute>\n";
    }
    for (const XdmfField& field : kFields) {
      if (!fields_.contains(field.field) || !written_in(field, dimension_)) continue;
      out << "        <Attribute Name=\"" << field.name << "\" AttributeType=\"" << field.attribute_type
          << "\" Center=\"Node\">\n";
      data_item(field.name, field.number_type, field.precision, field.components);
      out << "        </Attribute>\n";
    }
    for (int k = 1; k <= frames_[index].state_variables; ++k) {
      out << "        <Attribute Name=\"" << statev_name(k)
          << "\" AttributeType=\"Scalar\" Center=\"Node\">\n";
      data_item(statev_name(k).c_str(), "Float", 8, 1);
      out << "        </Attribute>\n";
    }
    out << "      </Grid>\n";
  }
  out << "    </Grid>\n  </Domain>\n</Xdmf>\n";
  // Replaced atomically: a reader (ParaView on a running simulation) never sees a half-written index.
  replace_file(xdmf_path_, out.str());
}

}  // namespace soilsph::sph
