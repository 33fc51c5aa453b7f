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
#include <sstream>
#include <string>
#include <vector>

#include "sph_output_fixtures.h"

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

std::string read_text(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

std::filesystem::path fresh_directory(const std::string& name) {
  const auto dir =
      std::filesystem::temp_directory_path() / ("soilsph_test_" + name + "_" + std::to_string(getpid()));
  std::filesystem::remove_all(dir);
  return dir;
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
  CHECK(items == 2 * 13);  // topology, geometry and 11 attributes per frame
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
