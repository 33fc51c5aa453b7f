// The checkpoint as one HDF5 file: arrays as datasets, the loop state as attributes of the root.
#include "sph/output/checkpoint.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <system_error>

#include "sph/output/disk_space.h"
#include "sph/output/hdf5_file.h"

namespace soilsph::sph {

namespace {
using hdf5::Handle;

/// Format 2 dropped format 1's accumulated plastic strain tensor (no longer part of State); format 3
/// added the plastic dilation (the dilatancy cut-off's state); format 4 the volumetric strain (MCC's
/// current specific volume).
constexpr const char* kFormat = "soilsph checkpoint 4";
constexpr std::size_t kStateValues = 14;  ///< per soil particle: σ (9), p_c, ε^p_s, Δλ, ε^p_v, ε_v

void pack(const State& s, double* out) {
  for (int k = 0; k < 9; ++k) out[k] = s.stress(k / 3, k % 3);
  out[9] = s.pc, out[10] = s.plastic_shear_strain, out[11] = s.plastic_multiplier,
  out[12] = s.plastic_dilation;
  out[13] = s.volumetric_strain;
}

State unpack(const double* in) {
  State s;
  for (int k = 0; k < 9; ++k) s.stress(k / 3, k % 3) = in[k];
  s.pc = in[9], s.plastic_shear_strain = in[10], s.plastic_multiplier = in[11], s.plastic_dilation = in[12];
  s.volumetric_strain = in[13];
  return s;
}

/// A UMAT plug-in's variables (State::umat) per soil particle, in the optional dataset "umat_state",
/// written only when a UMAT has been called: STATEV (kMaxStateVariables), STRAN (6), TIME, KINC.
constexpr std::size_t kUmatValues = kMaxStateVariables + 8;

void pack_umat(const UmatVariables& u, double* out) {
  std::copy(u.statev.begin(), u.statev.end(), out);
  std::copy(u.strain.begin(), u.strain.end(), out + kMaxStateVariables);
  out[kMaxStateVariables + 6] = u.time, out[kMaxStateVariables + 7] = u.increment;
}

void unpack_umat(const double* in, UmatVariables& u) {
  std::copy(in, in + kMaxStateVariables, u.statev.begin());
  std::copy(in + kMaxStateVariables, in + kMaxStateVariables + 6, u.strain.begin());
  u.time = in[kMaxStateVariables + 6], u.increment = static_cast<int>(in[kMaxStateVariables + 7]);
}

/// The loop state's numbers by name, so that writing and reading list them once.
template <class Loop, class F>
void for_each_number(Loop& l, F&& f) {
  f("time", l.stats.end_time), f("wall_seconds", l.stats.wall_seconds);
  f("smallest_time_step", l.stats.smallest_time_step), f("largest_time_step", l.stats.largest_time_step);
  f("next_frame", l.next_frame), f("previous_dt", l.previous_dt), f("sound_speed", l.sound_speed);
  f("max_speed", l.max_speed), f("rest_since", l.rest.since);
}
template <class Loop, class F>
void for_each_count(Loop& l, F&& f) {
  f("steps", l.stats.steps), f("guard_corrections", l.stats.guard_corrections);
  f("fallback_stress_updates", l.stats.fallback_stress_updates), f("moving", l.moving);
}
}  // namespace

template <int dim>
void write_checkpoint(const std::filesystem::path& file, const ParticlesOf<dim>& p, const LoopState& loop,
                      const std::string& scene_toml) {
  std::filesystem::path temporary = file;
  temporary += ".tmp";
  const std::size_t n = p.size(), soil = p.soil_count;
  constexpr std::size_t soil_arrays = dim == 2 ? 8 : 16;  // about: a, ρ rate, L, x0
  ensure_room(temporary,
              8 * (ParticlesOf<dim>::kParticleArrays * n + (kStateValues + kUmatValues + soil_arrays) * soil +
                   dim * n) +
                  scene_toml.size() + 64 * 1024);
  try {
    const Handle access(hdf5::unlocked_file_access(), H5Pclose, "create a file-access property list");
    Handle h5(H5Fcreate(temporary.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, access), H5Fclose,
              "create " + temporary.string());
    const std::string where = file.string() + ":/";
    hdf5::write_string_attribute(h5, "format", kFormat);
    hdf5::write_string_attribute(h5, "scene", scene_toml);
    if constexpr (dim == 3) hdf5::write_double_attribute(h5, "dimension", 3.0);  // absent: the plane
    hdf5::write_double_attribute(h5, "soil_count", static_cast<double>(soil));
    hdf5::write_double_attribute(h5, "rest_moved", loop.rest.moved ? 1.0 : 0.0);
    for_each_number(loop, [&](const char* name, double v) { hdf5::write_double_attribute(h5, name, v); });
    for_each_count(loop, [&](const char* name, std::size_t v) {
      hdf5::write_double_attribute(h5, name, static_cast<double>(v));  // exact below 2^53
    });
    p.for_each_array(
        [&](const char* name, const std::vector<double>& a) { hdf5::write_doubles(h5, name, a, where); });
    std::vector<double> states(kStateValues * soil);
    for (std::size_t i = 0; i < soil; ++i) pack(p.state[i], &states[kStateValues * i]);
    hdf5::write_dataset(h5, "state", H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, soil, kStateValues, states.data(),
                        where);
    if (std::any_of(p.state.begin(), p.state.end(), [](const State& s) { return s.umat.increment > 0; })) {
      std::vector<double> umat(kUmatValues * soil);
      for (std::size_t i = 0; i < soil; ++i) pack_umat(p.state[i].umat, &umat[kUmatValues * i]);
      hdf5::write_dataset(h5, "umat_state", H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, soil, kUmatValues, umat.data(),
                          where);
    }
    hdf5::write_dataset(h5, "layer", H5T_STD_I32LE, H5T_NATIVE_INT, soil, 1, p.layer.data(), where);
    hdf5::write_dataset(h5, "id", H5T_STD_U64LE, H5T_NATIVE_UINT64, soil, 1, p.id.data(), where);
    hdf5::write_dataset(h5, "boundary_kind", H5T_STD_U8LE, H5T_NATIVE_UINT8, p.boundary_kind.size(), 1,
                        p.boundary_kind.data(), where);
    hdf5::write_doubles(h5, "search_x", loop.search_x, where);
    hdf5::write_doubles(h5, "search_y", loop.search_y, where);
    if constexpr (dim == 3) hdf5::write_doubles(h5, "search_z", loop.search_z, where);
    h5.close("close " + temporary.string());
  } catch (...) {
    std::error_code ignored;
    std::filesystem::remove(temporary, ignored);  // the previous checkpoint stays
    throw;
  }
  std::error_code error;
  std::filesystem::rename(temporary, file, error);
  if (error) throw std::runtime_error("cannot replace " + file.string() + ": " + error.message());
}

namespace {
/// The checkpoint FILE opened for reading (check_format next).
Handle open_checkpoint(const std::filesystem::path& file) {
  if (!std::filesystem::exists(file))
    throw std::runtime_error(file.string() +
                             " does not exist: nothing to resume (a run writes it every "
                             "[output] checkpoint_interval, at rest, on a signal and before its end)");
  const Handle access(hdf5::unlocked_file_access(), H5Pclose, "create a file-access property list");
  return Handle(H5Fopen(file.c_str(), H5F_ACC_RDONLY, access), H5Fclose, "open " + file.string());
}

void check_format(hid_t h5, const std::filesystem::path& file) {
  const std::string format = H5Aexists(h5, "format") > 0 ? hdf5::read_string_attribute(h5, "format") : "";
  if (format != kFormat)
    throw std::runtime_error(
        file.string() + " is not a soilsph checkpoint of this version (format \"" + kFormat + "\"" +
        (format.empty() ? std::string() : ", the file's is \"" + format + "\"") + "): rerun the scene");
}
}  // namespace

std::string read_checkpoint_scene(const std::filesystem::path& file) {
  const Handle h5 = open_checkpoint(file);
  check_format(h5, file);
  return hdf5::read_string_attribute(h5, "scene");
}

template <int dim>
CheckpointOf<dim> read_checkpoint(const std::filesystem::path& file) {
  const Handle h5 = open_checkpoint(file);
  check_format(h5, file);
  const std::string where = file.string() + ":/";
  const int saved = H5Aexists(h5, "dimension") > 0 ? static_cast<int>(hdf5::read_double_attribute(h5, "dimension")) : 2;
  if (saved != dim)
    throw std::runtime_error(file.string() + " is the checkpoint of a " + std::to_string(saved) +
                             "D run, not of a " + std::to_string(dim) + "D one");
  CheckpointOf<dim> c;
  c.scene_toml = hdf5::read_string_attribute(h5, "scene");
  const auto soil = static_cast<std::size_t>(hdf5::read_double_attribute(h5, "soil_count"));
  {
    const Handle set(H5Dopen2(h5, "x", H5P_DEFAULT), H5Dclose, "open " + where + "x");
    const Handle space(H5Dget_space(set), H5Sclose, "read the dataspace of " + where + "x");
    const auto n = static_cast<std::size_t>(H5Sget_simple_extent_npoints(space));
    if (n < soil) throw std::runtime_error(where + "x holds fewer particles than soil_count");
    c.particles.resize(soil, n - soil);
  }
  c.loop.rest.moved = hdf5::read_double_attribute(h5, "rest_moved") != 0.0;
  for_each_number(c.loop, [&](const char* name, double& v) { v = hdf5::read_double_attribute(h5, name); });
  for_each_count(c.loop, [&](const char* name, std::size_t& v) {
    v = static_cast<std::size_t>(hdf5::read_double_attribute(h5, name));
  });
  c.particles.for_each_array([&](const char* name, std::vector<double>& a) {
    hdf5::read_dataset(h5, name, H5T_NATIVE_DOUBLE, a.size(), a.data(), where);
  });
  std::vector<double> states(kStateValues * soil);
  hdf5::read_dataset(h5, "state", H5T_NATIVE_DOUBLE, states.size(), states.data(), where);
  for (std::size_t i = 0; i < soil; ++i) c.particles.state[i] = unpack(&states[kStateValues * i]);
  if (H5Lexists(h5, "umat_state", H5P_DEFAULT) > 0) {
    std::vector<double> umat(kUmatValues * soil);
    hdf5::read_dataset(h5, "umat_state", H5T_NATIVE_DOUBLE, umat.size(), umat.data(), where);
    for (std::size_t i = 0; i < soil; ++i) unpack_umat(&umat[kUmatValues * i], c.particles.state[i].umat);
  }
  hdf5::read_dataset(h5, "layer", H5T_NATIVE_INT, soil, c.particles.layer.data(), where);
  if (H5Lexists(h5, "id", H5P_DEFAULT) > 0)  // else the ids as built (a checkpoint written before ids)
    hdf5::read_dataset(h5, "id", H5T_NATIVE_UINT64, soil, c.particles.id.data(), where);
  hdf5::read_dataset(h5, "boundary_kind", H5T_NATIVE_UINT8, c.particles.boundary_kind.size(),
                     c.particles.boundary_kind.data(), where);
  c.loop.search_x.resize(c.particles.size());
  c.loop.search_y.resize(c.particles.size());
  hdf5::read_dataset(h5, "search_x", H5T_NATIVE_DOUBLE, c.loop.search_x.size(), c.loop.search_x.data(),
                     where);
  hdf5::read_dataset(h5, "search_y", H5T_NATIVE_DOUBLE, c.loop.search_y.size(), c.loop.search_y.data(),
                     where);
  if constexpr (dim == 3) {
    c.loop.search_z.resize(c.particles.size());
    hdf5::read_dataset(h5, "search_z", H5T_NATIVE_DOUBLE, c.loop.search_z.size(), c.loop.search_z.data(),
                       where);
  }
  return c;
}

template void write_checkpoint<2>(const std::filesystem::path&, const ParticlesOf<2>&, const LoopState&,
                                  const std::string&);
template void write_checkpoint<3>(const std::filesystem::path&, const ParticlesOf<3>&, const LoopState&,
                                  const std::string&);
template CheckpointOf<2> read_checkpoint<2>(const std::filesystem::path&);
template CheckpointOf<3> read_checkpoint<3>(const std::filesystem::path&);

}  // namespace soilsph::sph
