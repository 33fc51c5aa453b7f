#include "sph/read_measures.h"

#include <cmath>

#include "sph/geometry/read_layout.h"
#include "sph/scene.h"

namespace soilsph::sph {

namespace {
Vec2 vector_or(const TableReader& t, const toml::table& table, std::string_view key, Vec2 fallback,
               std::string_view unit) {
  t.accept({key});
  const toml::node* node = table.get(key);
  return node ? read_vector(*node, t.source() + ": [" + t.table_name() + "] " + std::string(key), unit) : fallback;
}
}  // namespace

DepositFrame read_deposit(const TableReader& t, const toml::table& table, bool given, const Geometry& g,
                          toml::table& resolved) {
  DepositFrame f;
  if (!given && !g.column) {
    f.defined = false;
    return f;
  }
  f.origin = vector_or(t, table, "origin", {g.soil_extent.largest_x, 0.0}, "m");
  // By default across gravity, a quarter turn clockwise from it: −x for gravity along −y.
  const Vec2 down = g.down();
  const Vec2 d = vector_or(t, table, "direction", {down.y, 0.0 - down.x}, "-");
  const double length = norm(d);
  if (!(length > 0.0)) t.fail("direction", "must not be [0, 0] (the direction in which the runout grows)");
  f.direction = (1.0 / length) * d;
  // up: the unit normal of the direction that points against gravity.
  const Vec2 normal{-f.direction.y, f.direction.x};
  const double against = -dot(normal, down);
  if (!(std::abs(against) > 1e-6))
    t.fail("direction", "is along gravity; it must cross it (the runout is measured across the pull of gravity)");
  f.up = against > 0.0 ? normal : Vec2{-normal.x, -normal.y};
  f.toe_thickness = t.number_or("toe_thickness", 0.1 * g.soil_extent.height, Range::non_negative(), "m");
  t.reject_unknown_keys();
  resolved = t.resolved();
  resolved.insert_or_assign("origin", toml::array{f.origin.x, f.origin.y});
  resolved.insert_or_assign("direction", toml::array{f.direction.x, f.direction.y});
  return f;
}

template <int dim>
std::vector<GaugeOf<dim>> read_gauges(const toml::table& root, const std::string& source, toml::array& resolved) {
  std::vector<GaugeOf<dim>> gauges;
  for (const auto& [table, label] : tables_of(root, source, "gauges")) {
    const TableReader t(*table, source, label);
    GaugeOf<dim> g;
    g.name = t.has("name") ? t.word("name") : "gauge_" + std::to_string(gauges.size() + 1);
    t.accept({"position"});
    const toml::node* position = table->get("position");
    if (!position) t.fail("position", dim == 2 ? "is missing ([x, y] in m)" : "is missing ([x, y, z] in m)");
    g.position = read_vector_of<dim>(*position, source + ": [" + label + "] position", "m");
    g.kind = t.choice_or("kind", "particle", {"particle", "point"}) == "particle" ? GaugeKind::Particle
                                                                                  : GaugeKind::Point;
    t.reject_unknown_keys();
    for (const GaugeOf<dim>& other : gauges)
      if (other.name == g.name)
        t.fail("name", "\"" + g.name + "\" names another gauge too (gauge names label gauges.csv rows)");
    toml::table r = t.resolved();
    r.insert_or_assign("name", g.name);
    if constexpr (dim == 2)
      r.insert_or_assign("position", toml::array{g.position.x, g.position.y});
    else
      r.insert_or_assign("position", toml::array{g.position.x, g.position.y, g.position.z});
    resolved.push_back(std::move(r));
    gauges.push_back(std::move(g));
  }
  return gauges;
}
template std::vector<GaugeOf<2>> read_gauges<2>(const toml::table&, const std::string&, toml::array&);
template std::vector<GaugeOf<3>> read_gauges<3>(const toml::table&, const std::string&, toml::array&);

}  // namespace soilsph::sph
