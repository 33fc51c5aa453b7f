// FrameWriter round trip: what is read back with the HDF5 C API is what was written, the XDMF index
// names every frame and dataset, and frames written before a crash survive it.
#include <catch2/catch.hpp>

#include <hdf5.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "sph_output_fixtures.h"
#include "sph/frame_buffers.h"
#include "../common/temp_dir.h"

using namespace soilsph::sph;
using soilsph::test::SyntheticParticles;

namespace {

struct H5File {
  hid_t id;
  explicit H5File(const std::filesystem::path& path)
      : id(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT)) {
    REQUIRE(id >= 0);
  }
  ~H5File() { H5Fclose(id); }
};

/// The shape of dataset `path` and its contents converted to `memory_type`.
template <class T>
std::vector<T> read_dataset(hid_t file, const std::string& path, hid_t memory_type,
                            std::vector<hsize_t>& dims) {
  const hid_t set = H5Dopen2(file, path.c_str(), H5P_DEFAULT);
  REQUIRE(set >= 0);
  const hid_t space = H5Dget_space(set);
  dims.assign(static_cast<std::size_t>(H5Sget_simple_extent_ndims(space)), 0);
  H5Sget_simple_extent_dims(space, dims.data(), nullptr);
  std::vector<T> values(static_cast<std::size_t>(H5Sget_simple_extent_npoints(space)));
  if (!values.empty()) REQUIRE(H5Dread(set, memory_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()) >= 0);
  H5Sclose(space);
  H5Dclose(set);
  return values;
}

double read_time(hid_t file, const std::string& group) {
  double time = -1;
  const hid_t attribute = H5Aopen_by_name(file, group.c_str(), "time", H5P_DEFAULT, H5P_DEFAULT);
  REQUIRE(attribute >= 0);
  REQUIRE(H5Aread(attribute, H5T_NATIVE_DOUBLE, &time) >= 0);
  H5Aclose(attribute);
  return time;
}

hsize_t link_count(hid_t file) {
  H5G_info_t info;
  REQUIRE(H5Gget_info(file, &info) >= 0);
  return info.nlinks;
}

/// The names of the links in group `path`.
std::set<std::string> group_members(hid_t file, const std::string& path) {
  const hid_t group = H5Gopen2(file, path.c_str(), H5P_DEFAULT);
  REQUIRE(group >= 0);
  H5G_info_t info;
  REQUIRE(H5Gget_info(group, &info) >= 0);
  std::set<std::string> names;
  for (hsize_t i = 0; i < info.nlinks; ++i) {
    char name[256] = {};
    REQUIRE(H5Lget_name_by_idx(group, ".", H5_INDEX_NAME, H5_ITER_INC, i, name, sizeof name, H5P_DEFAULT) >
            0);
    names.insert(name);
  }
  H5Gclose(group);
  return names;
}

std::string read_text(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

/// A directory not yet made, inside this test process's own temporary directory.
std::filesystem::path fresh_directory(const std::string& name) {
  static const soilsph::testing::TempDir scratch("soilsph-frames");
  return scratch / name;
}

}  // namespace

TEST_CASE("frames read back with the shapes and values written", "[frame_writer]") {
  const auto dir = fresh_directory("roundtrip");
  const SyntheticParticles a(7, 0.0), b(12, 0.125);  // particle counts may change between frames
  {
    FrameWriter writer(dir);
    writer.write(a.frame());
    writer.write(b.frame());
    CHECK(writer.frames() == 2);
  }
  const H5File file(dir / "frames.h5");
  CHECK(link_count(file.id) == 4);  // frame_000000, frame_000001, vertices_7, vertices_12
  const SyntheticParticles* expected[] = {&a, &b};
  for (int f = 0; f < 2; ++f) {
    const SyntheticParticles& s = *expected[f];
    const std::string group = f == 0 ? "/frame_000000" : "/frame_000001";
    const std::size_t n = s.x.size();
    CHECK(read_time(file.id, group) == s.time);

    std::vector<hsize_t> dims;
    const auto position = read_dataset<double>(file.id, group + "/position", H5T_NATIVE_DOUBLE, dims);
    CHECK(dims == std::vector<hsize_t>{n, 3});
    const auto velocity = read_dataset<double>(file.id, group + "/velocity", H5T_NATIVE_DOUBLE, dims);
    CHECK(dims == std::vector<hsize_t>{n, 3});
    const auto speed = read_dataset<double>(file.id, group + "/speed", H5T_NATIVE_DOUBLE, dims);
    CHECK(dims == std::vector<hsize_t>{n});
    for (std::size_t i = 0; i < n; ++i) {
      CHECK(position[3 * i] == s.x[i]);
      CHECK(position[3 * i + 1] == s.y[i]);
      CHECK(position[3 * i + 2] == 0.0);
      CHECK(velocity[3 * i] == s.vx[i]);
      CHECK(velocity[3 * i + 1] == s.vy[i]);
      CHECK(velocity[3 * i + 2] == 0.0);
      CHECK(speed[i] == Approx(std::sqrt(s.vx[i] * s.vx[i] + s.vy[i] * s.vy[i])).epsilon(1e-15));
    }
    const std::pair<const char*, const std::vector<double>*> scalars[] = {{"sxx", &s.sxx},
                                                                          {"syy", &s.syy},
                                                                          {"szz", &s.szz},
                                                                          {"sxy", &s.sxy},
                                                                          {"p", &s.p},
                                                                          {"q", &s.q},
                                                                          {"plastic_strain", &s.eps},
                                                                          {"density", &s.density}};
    for (const auto& [name, values] : scalars) {
      INFO(group << "/" << name);
      CHECK(read_dataset<double>(file.id, group + "/" + name, H5T_NATIVE_DOUBLE, dims) == *values);
      CHECK(dims == std::vector<hsize_t>{n});
    }
    CHECK(read_dataset<int>(file.id, group + "/layer", H5T_NATIVE_INT, dims) == s.layer);
    // The Polyvertex connectivity: particle i is vertex i.
    const auto vertices =
        read_dataset<long long>(file.id, "/vertices_" + std::to_string(n), H5T_NATIVE_LLONG, dims);
    CHECK(dims == std::vector<hsize_t>{n});
    for (std::size_t i = 0; i < vertices.size(); ++i) CHECK(vertices[i] == static_cast<long long>(i));
  }
  std::filesystem::remove_all(dir);
}

TEST_CASE("the XDMF index lists every frame with its time and every dataset with its size",
          "[frame_writer]") {
  const auto dir = fresh_directory("xdmf");
  const SyntheticParticles a(5, 0.0), b(9, 0.05);
  FrameWriter writer(dir);
  CHECK(read_text(writer.xdmf_path()).find("<Grid Name=\"frame_") == std::string::npos);
  writer.write(a.frame());
  writer.write(b.frame());
  const std::string xdmf = read_text(writer.xdmf_path());

  const std::regex grid(R"re(<Grid Name="(frame_\d{6})" GridType="Uniform">\s*<Time Value="([^"]+)" />)re");
  std::vector<std::pair<std::string, double>> grids;
  for (auto it = std::sregex_iterator(xdmf.begin(), xdmf.end(), grid); it != std::sregex_iterator(); ++it) {
    grids.emplace_back((*it)[1], std::stod((*it)[2]));
  }
  REQUIRE(grids.size() == 2);
  CHECK(grids[0] == std::pair<std::string, double>{"frame_000000", 0.0});
  CHECK(grids[1] == std::pair<std::string, double>{"frame_000001", 0.05});

  // Every DataItem points at an existing dataset of frames.h5 whose size matches its Dimensions.
  const std::regex item(R"re(<DataItem Dimensions="(\d+)( 3)?"[^>]*>frames\.h5:(/[\w/]+)</DataItem>)re");
  std::size_t items = 0;
  const H5File file(dir / "frames.h5");  // shares the writer's open file (HDF5 allows read-only reopening)
  for (auto it = std::sregex_iterator(xdmf.begin(), xdmf.end(), item); it != std::sregex_iterator(); ++it) {
    ++items;
    const std::string path = (*it)[3];
    INFO(path);
    const hid_t set = H5Dopen2(file.id, path.c_str(), H5P_DEFAULT);
    REQUIRE(set >= 0);
    const hid_t space = H5Dget_space(set);
    const auto expected = std::stoull((*it)[1]) * ((*it)[2].matched ? 3 : 1);
    CHECK(static_cast<unsigned long long>(H5Sget_simple_extent_npoints(space)) == expected);
    H5Sclose(space);
    H5Dclose(set);
  }
  CHECK(items == 2 * 14);  // topology, geometry and 12 attributes per frame
  CHECK(xdmf.find("NumberOfElements=\"5\"") != std::string::npos);
  CHECK(xdmf.find("NumberOfElements=\"9\"") != std::string::npos);
  std::filesystem::remove_all(dir);
}

TEST_CASE("a frame whose fields differ in length is rejected", "[frame_writer]") {
  const auto dir = fresh_directory("mismatch");
  SyntheticParticles s(6, 0.0);
  Frame frame = s.frame();
  frame.q = frame.q.first(5);
  FrameWriter writer(dir);
  CHECK_THROWS_AS(writer.write(frame), std::invalid_argument);
  CHECK(writer.frames() == 0);
  std::filesystem::remove_all(dir);
}

TEST_CASE("only the selected fields are written to frames.h5 and listed in frames.xdmf", "[frame_writer]") {
  using Names = std::set<std::string>;
  struct Case {
    FieldSet fields;
    Names datasets;  ///< besides position
  };
  const Names all{"velocity", "speed",          "sxx",     "syy",  "szz", "sxy", "p",
                  "q",        "plastic_strain", "density", "layer", "material"};
  const std::vector<Case> cases{
      {FieldSet::all(), all},
      {FieldSet().insert(Field::p).insert(Field::q), {"p", "q"}},
      {FieldSet().insert(Field::stress).insert(Field::layer), {"sxx", "syy", "szz", "sxy", "layer"}},
      {FieldSet().insert(Field::material), {"material"}},
      {FieldSet().insert(Field::speed).insert(Field::plastic_strain).insert(Field::density),
       {"speed", "plastic_strain", "density"}},
      {FieldSet().insert(Field::velocity), {"velocity"}},
      {FieldSet(), {}},
  };
  const std::regex attribute(
      R"re(<Attribute Name="(\w+)"[^>]*>\s*<DataItem Dimensions="(\d+)( 3)?"[^>]*>frames\.h5:(/[\w/]+)</DataItem>)re");
  for (std::size_t c = 0; c < cases.size(); ++c) {
    const Case& test = cases[c];
    INFO("case " << c);
    const auto dir = fresh_directory("fields_" + std::to_string(c));
    const SyntheticParticles a(4, 0.0), b(6, 0.25);
    FrameWriter writer(dir, test.fields);
    CHECK(writer.fields() == test.fields);
    // The spans of unselected fields are not read: a frame may leave them empty.
    Frame sparse = b.frame();
    if (!test.fields.contains(Field::stress)) sparse.sxx = sparse.syy = sparse.szz = sparse.sxy = {};
    if (!test.fields.contains(Field::p)) sparse.p = {};
    if (!test.fields.contains(Field::q)) sparse.q = {};
    if (!test.fields.contains(Field::plastic_strain)) sparse.plastic_strain = {};
    if (!test.fields.contains(Field::density)) sparse.density = {};
    if (!test.fields.contains(Field::layer)) sparse.layer = {};
    if (!test.fields.contains(Field::material)) sparse.material = {};
    if (!test.fields.contains(Field::velocity) && !test.fields.contains(Field::speed))
      sparse.vx = sparse.vy = {};
    writer.write(a.frame());
    writer.write(sparse);

    const H5File file(dir / "frames.h5");
    Names expected = test.datasets;
    expected.insert("position");
    CHECK(group_members(file.id, "/frame_000000") == expected);
    CHECK(group_members(file.id, "/frame_000001") == expected);
    std::vector<hsize_t> dims;
    if (test.fields.contains(Field::p))
      CHECK(read_dataset<double>(file.id, "/frame_000001/p", H5T_NATIVE_DOUBLE, dims) == b.p);
    if (test.fields.contains(Field::layer))
      CHECK(read_dataset<int>(file.id, "/frame_000001/layer", H5T_NATIVE_INT, dims) == b.layer);
    if (test.fields.contains(Field::material))
      CHECK(read_dataset<int>(file.id, "/frame_000001/material", H5T_NATIVE_INT, dims) == b.material);
    if (test.fields.contains(Field::speed)) {
      const auto speed = read_dataset<double>(file.id, "/frame_000001/speed", H5T_NATIVE_DOUBLE, dims);
      for (std::size_t i = 0; i < speed.size(); ++i) CHECK(speed[i] == Approx(std::hypot(b.vx[i], b.vy[i])));
    }

    // The index lists exactly the selected datasets of each frame, each pointing at its own dataset.
    const std::string xdmf = read_text(writer.xdmf_path());
    std::vector<Names> listed(2);
    for (auto it = std::sregex_iterator(xdmf.begin(), xdmf.end(), attribute); it != std::sregex_iterator();
         ++it) {
      const std::string name = (*it)[1], path = (*it)[4];
      const int frame = path.rfind("/frame_000000/", 0) == 0 ? 0 : 1;
      CHECK(path == "/frame_00000" + std::to_string(frame) + "/" + name);
      CHECK(std::stoull((*it)[2]) == (frame == 0 ? 4u : 6u));
      listed[static_cast<std::size_t>(frame)].insert(name);
    }
    CHECK(listed[0] == test.datasets);
    CHECK(listed[1] == test.datasets);
    CHECK(xdmf.find("frames.h5:/frame_000001/position") != std::string::npos);  // geometry always
    std::filesystem::remove_all(dir);
  }
}

TEST_CASE("the particles' ids go into every frame that has them, whatever the fields, and into the index",
          "[frame_writer]") {
  const auto dir = fresh_directory("ids");
  const SyntheticParticles a(4, 0.0), b(4, 0.25);
  // Ids that are not the indices: a frame records who each particle is, not where it sits.
  const std::vector<std::uint64_t> ids{7, 3, 11, 0};
  Frame with_ids = b.frame();
  with_ids.id = ids;
  FrameWriter writer(dir, FieldSet().insert(Field::p));
  writer.write(a.frame());  // without ids (a frame written before a resume from an older run)
  writer.write(with_ids);
  const H5File file(dir / "frames.h5");
  std::vector<hsize_t> dims;
  CHECK(group_members(file.id, "/frame_000000") == std::set<std::string>{"position", "p"});
  CHECK(read_dataset<std::uint64_t>(file.id, "/frame_000001/id", H5T_NATIVE_UINT64, dims) == ids);
  const std::string xdmf = read_text(writer.xdmf_path());
  CHECK(xdmf.find("frames.h5:/frame_000000/id") == std::string::npos);
  CHECK(xdmf.find(R"(<Attribute Name="id" AttributeType="Scalar" Center="Node">)") != std::string::npos);
  CHECK(xdmf.find(R"(NumberType="UInt" Precision="8" Format="HDF">frames.h5:/frame_000001/id<)") !=
        std::string::npos);
  // A frame whose ids do not match its particle count is refused.
  with_ids.id = std::span(ids).first(3);
  CHECK_THROWS_AS(writer.write(with_ids), std::invalid_argument);
  std::filesystem::remove_all(dir);
}

TEST_CASE("a frame missing a selected field is rejected", "[frame_writer]") {
  const auto dir = fresh_directory("missing_field");
  SyntheticParticles s(6, 0.0);
  Frame frame = s.frame();
  frame.density = {};
  FrameWriter writer(dir, FieldSet().insert(Field::density));
  CHECK_THROWS_AS(writer.write(frame), std::invalid_argument);
  frame = s.frame();
  frame.vy = frame.vy.first(2);
  FrameWriter speed_only(fresh_directory("missing_velocity"), FieldSet().insert(Field::speed));
  CHECK_THROWS_AS(speed_only.write(frame), std::invalid_argument);
  std::filesystem::remove_all(dir);
  std::filesystem::remove_all(fresh_directory("missing_velocity"));
}

TEST_CASE("the field names are the dataset names", "[frame_writer]") {
  for (std::size_t i = 0; i < kFieldNames.size(); ++i) {
    const auto field = field_named(kFieldNames[i]);
    REQUIRE(field.has_value());
    CHECK(static_cast<std::size_t>(*field) == i);
    CHECK(FieldSet::all().contains(*field));
    CHECK_FALSE(FieldSet().contains(*field));
  }
  CHECK_FALSE(field_named("sxx").has_value());  // the stress components come as one field, "stress"
  CHECK_FALSE(field_named("").has_value());
}

TEST_CASE("frames written before a crash survive it", "[frame_writer]") {
  const auto dir = fresh_directory("crash");
  const pid_t child = fork();
  REQUIRE(child >= 0);
  if (child == 0) {
    // The child writes two frames and dies without closing anything (no destructors, no atexit).
    try {
      FrameWriter writer(dir);
      writer.write(SyntheticParticles(4, 0.0).frame());
      writer.write(SyntheticParticles(4, 0.01).frame());
      _exit(0);  // before the writer's destructor could close the file
    } catch (...) {
      _exit(1);
    }
  }
  int status = 0;
  REQUIRE(waitpid(child, &status, 0) == child);
  REQUIRE(WIFEXITED(status));
  const H5File file(dir / "frames.h5");
  CHECK(link_count(file.id) == 3);  // two frames and vertices_4
  CHECK(read_time(file.id, "/frame_000001") == 0.01);
  std::vector<hsize_t> dims;
  CHECK(read_dataset<double>(file.id, "/frame_000001/p", H5T_NATIVE_DOUBLE, dims) ==
        SyntheticParticles(4, 0.01).p);
  CHECK(read_text(dir / "frames.xdmf").find("frame_000001/p<") != std::string::npos);
  std::filesystem::remove_all(dir);
}

TEST_CASE("another process can read the frames while the writer is alive", "[frame_writer]") {
  // A fresh process (this test program re-executed) opens frames.h5 as a viewer would: a file left
  // open by the writer is locked by HDF5 and could not be opened.
  const auto dir = fresh_directory("concurrent");
  FrameWriter writer(dir);
  writer.write(SyntheticParticles(8, 0.0).frame());
  const pid_t child = fork();
  REQUIRE(child >= 0);
  if (child == 0) {
    setenv("SOILSPH_TEST_FRAMES", writer.h5_path().c_str(), 1);
    execl("/proc/self/exe", "test_sph_output", "[open_frames]", "--out", "/dev/null",
          static_cast<char*>(nullptr));
    _exit(127);
  }
  int status = 0;
  REQUIRE(waitpid(child, &status, 0) == child);
  CHECK(WIFEXITED(status));
  CHECK(WEXITSTATUS(status) == 0);
  writer.write(SyntheticParticles(8, 0.01).frame());  // and the writer goes on afterwards
  CHECK(writer.frames() == 2);
  std::filesystem::remove_all(dir);
}

TEST_CASE("open the frames named by SOILSPH_TEST_FRAMES (run by the test above)", "[.][open_frames]") {
  const char* path = std::getenv("SOILSPH_TEST_FRAMES");
  REQUIRE(path != nullptr);
  const H5File file(path);
  std::vector<hsize_t> dims;
  CHECK(read_dataset<double>(file.id, "/frame_000000/p", H5T_NATIVE_DOUBLE, dims) ==
        SyntheticParticles(8, 0.0).p);
}

TEST_CASE("a reader keeping the file open does not stop the writer", "[frame_writer]") {
  // Another process opens frames.h5 read-only (taking HDF5's shared lock, as h5py or ParaView do)
  // and keeps it open while this process writes the next frame. Two pipes order the steps.
  const auto dir = fresh_directory("held");
  FrameWriter writer(dir);
  writer.write(SyntheticParticles(8, 0.0).frame());
  int ready[2], done[2];
  REQUIRE(pipe(ready) == 0);
  REQUIRE(pipe(done) == 0);
  const pid_t child = fork();
  REQUIRE(child >= 0);
  if (child == 0) {
    close(ready[0]);  // keep only the ends the child uses, so a parent that stops ends the child
    close(done[1]);
    setenv("SOILSPH_TEST_FRAMES", writer.h5_path().c_str(), 1);
    setenv("SOILSPH_TEST_READY_FD", std::to_string(ready[1]).c_str(), 1);
    setenv("SOILSPH_TEST_DONE_FD", std::to_string(done[0]).c_str(), 1);
    execl("/proc/self/exe", "test_sph_output", "[hold_frames]", "--out", "/dev/null",
          static_cast<char*>(nullptr));
    _exit(127);
  }
  close(ready[1]);
  close(done[0]);
  char byte = 0;
  REQUIRE(read(ready[0], &byte, 1) == 1);  // the child has the file open
  CHECK_NOTHROW(writer.write(SyntheticParticles(8, 0.01).frame()));
  REQUIRE(write(done[1], "x", 1) == 1);  // let the child close it and exit
  int status = 0;
  REQUIRE(waitpid(child, &status, 0) == child);
  CHECK((WIFEXITED(status) && WEXITSTATUS(status) == 0));
  close(ready[0]);
  close(done[1]);
  const H5File file(dir / "frames.h5");
  CHECK(link_count(file.id) == 3);  // two frames and vertices_8
  std::filesystem::remove_all(dir);
}

TEST_CASE("hold the frames open until told (run by the test above)", "[.][hold_frames]") {
  const char *path = std::getenv("SOILSPH_TEST_FRAMES"), *ready = std::getenv("SOILSPH_TEST_READY_FD"),
             *done = std::getenv("SOILSPH_TEST_DONE_FD");
  REQUIRE((path && ready && done));
  const H5File file(path);
  REQUIRE(write(std::atoi(ready), "x", 1) == 1);
  char byte = 0;
  REQUIRE(read(std::atoi(done), &byte, 1) == 1);
}

TEST_CASE("a 3D frame writes positions and velocities (x, y, z) and the six stress components", "[frame_writer]") {
  // Four soil particles and one ghost (not written) with distinct values in every component.
  ParticlesOf<3> p;
  p.resize(4, 1);
  for (std::size_t i = 0; i < 4; ++i) {
    const double k = static_cast<double>(i + 1);
    p.x[i] = 0.1 * k, p.y[i] = 0.2 * k, p.z[i] = 0.3 * k;
    p.vx[i] = -1.0 * k, p.vy[i] = 2.0 * k, p.vz[i] = -3.0 * k;
    p.density[i] = 2600.0 + k;
    p.layer[i] = static_cast<int>(i);
    soilsph::Mat3 s;
    s << -10 * k, 4 * k, 5 * k, 4 * k, -20 * k, 6 * k, 5 * k, 6 * k, -30 * k;
    p.state[i].stress = s;
  }
  const auto dir = fresh_directory("space");
  FrameBuffers buffers;
  const Frame frame = buffers.view(p, 0.25);
  CHECK(frame.dimension == 3);
  {
    FrameWriter writer(dir, FieldSet::all(), 3);
    writer.write(frame);
    SyntheticParticles plane(4, 0.5);
    CHECK_THROWS_AS(writer.write(plane.frame()), std::invalid_argument);  // a 2D frame to a 3D writer
  }
  const H5File file(dir / "frames.h5");
  std::vector<hsize_t> dims;
  const auto position = read_dataset<double>(file.id, "/frame_000000/position", H5T_NATIVE_DOUBLE, dims);
  CHECK(dims == std::vector<hsize_t>{4, 3});
  const auto velocity = read_dataset<double>(file.id, "/frame_000000/velocity", H5T_NATIVE_DOUBLE, dims);
  const auto speed = read_dataset<double>(file.id, "/frame_000000/speed", H5T_NATIVE_DOUBLE, dims);
  for (std::size_t i = 0; i < 4; ++i) {
    const double k = static_cast<double>(i + 1);
    CHECK(position[3 * i] == p.x[i]);
    CHECK(position[3 * i + 1] == p.y[i]);
    CHECK(position[3 * i + 2] == p.z[i]);
    CHECK(velocity[3 * i] == p.vx[i]);
    CHECK(velocity[3 * i + 1] == p.vy[i]);
    CHECK(velocity[3 * i + 2] == p.vz[i]);
    CHECK(speed[i] == Approx(k * std::sqrt(14.0)).epsilon(1e-15));  // |(−1, 2, −3)| k
  }
  const std::pair<const char*, double> components[] = {{"sxx", -10}, {"syy", -20}, {"szz", -30},
                                                       {"sxy", 4},   {"sxz", 5},   {"syz", 6}};
  for (const auto& [name, per_k] : components) {
    const auto values = read_dataset<double>(file.id, std::string("/frame_000000/") + name, H5T_NATIVE_DOUBLE, dims);
    CHECK(dims == std::vector<hsize_t>{4});
    for (std::size_t i = 0; i < 4; ++i) CHECK(values[i] == per_k * static_cast<double>(i + 1));
  }
  const std::string xdmf = read_text(dir / "frames.xdmf");
  CHECK(xdmf.find("TopologyType=\"Polyvertex\"") != std::string::npos);
  CHECK(xdmf.find("GeometryType=\"XYZ\"") != std::string::npos);
  for (const char* name : {"sxz", "syz"}) CHECK(xdmf.find(std::string("Attribute Name=\"") + name + "\"") != std::string::npos);
  CHECK(xdmf.find("x and z horizontal (3D)") != std::string::npos);
}

TEST_CASE("a 2D frame writer lists no sxz or syz", "[frame_writer]") {
  const auto dir = fresh_directory("plane-no-shear-z");
  FrameWriter writer(dir);
  writer.write(SyntheticParticles(3, 0.0).frame());
  const std::string xdmf = read_text(dir / "frames.xdmf");
  CHECK(xdmf.find("sxz") == std::string::npos);
  CHECK(xdmf.find("syz") == std::string::npos);
  const H5File file(dir / "frames.h5");
  CHECK(group_members(file.id, "/frame_000000").count("sxz") == 0);
}
