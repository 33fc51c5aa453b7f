#pragma once
// Shared fixtures for the SPH tests: scenes from text or from the shipped files, lattices.
#include <string>
#include <vector>

#include "sph/initial_state.h"
#include "sph/scene.h"

namespace soilsph::sph::test {

/// A shipped scene (data/scenes/NAME.toml) with overrides.
inline Scene shipped_scene(const std::string& name, const std::vector<std::string>& overrides = {}) {
  return load_scene(SOILSPH_SOURCE_DIR "/data/scenes/" + name + ".toml", overrides);
}

/// A scene parsed from TOML text, with overrides.
inline Scene scene_from_text(const std::string& text, const std::vector<std::string>& overrides = {}) {
  toml::table root = toml::parse(text);
  for (const std::string& o : overrides) apply_override(root, o);
  return read_scene(root, "case.toml");
}

/// Soil particles only, on an n × n lattice of spacing dx starting at the origin, density rho.
inline Particles lattice(int n, double dx, double rho) {
  Particles p;
  p.resize(static_cast<std::size_t>(n * n), 0);
  for (int r = 0, i = 0; r < n; ++r)
    for (int c = 0; c < n; ++c, ++i) {
      p.x[i] = c * dx;
      p.y[i] = r * dx;
      p.density[i] = rho;
      p.mass[i] = rho * dx * dx;
    }
  return p;
}

}  // namespace soilsph::sph::test
