// scatterer_lit_sides: closed solids among outdoor scatterers (method in scatterer_sides.h).
#include "dayphoton/engine/scatterer_sides.h"

#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <numeric>
#include <utility>

namespace dayphoton::engine {
namespace {

using VertexKey = std::array<std::int64_t, 3>;
using EdgeKey = std::pair<VertexKey, VertexKey>;

VertexKey key_of(const Vec3& v) {
  return {std::llround(v.x / ClosedSolidTolerance_m), std::llround(v.y / ClosedSolidTolerance_m),
          std::llround(v.z / ClosedSolidTolerance_m)};
}

int find_root(std::vector<int>& parent, int i) {
  while (parent[static_cast<std::size_t>(i)] != i) {
    parent[static_cast<std::size_t>(i)] = parent[static_cast<std::size_t>(parent[static_cast<std::size_t>(i)])];
    i = parent[static_cast<std::size_t>(i)];
  }
  return i;
}

}  // namespace

std::vector<LitSides> scatterer_lit_sides(const SceneDescription& description,
                                          const std::vector<int>& scatterers) {
  const std::size_t n = scatterers.size();
  // Directed edges: each polygon's edges in winding order, with the polygon that owns them.
  std::map<EdgeKey, std::vector<int>> edges;
  for (std::size_t i = 0; i < n; ++i) {
    const std::vector<Vec3>& v = description.surfaces[static_cast<std::size_t>(scatterers[i])].vertices;
    for (std::size_t a = 0; a < v.size(); ++a)
      edges[{key_of(v[a]), key_of(v[(a + 1) % v.size()])}].push_back(static_cast<int>(i));
  }
  std::vector<int> parent(n);
  std::iota(parent.begin(), parent.end(), 0);
  std::vector<char> open(n, 0);
  for (const auto& [edge, owners] : edges) {
    const auto twin = edges.find({edge.second, edge.first});
    if (owners.size() != 1 || twin == edges.end() || twin->second.size() != 1) {
      for (int o : owners) open[static_cast<std::size_t>(o)] = 1;
      continue;
    }
    const int a = find_root(parent, owners[0]), b = find_root(parent, twin->second[0]);
    if (a != b) parent[static_cast<std::size_t>(a)] = b;
  }
  // A component is closed if none of its polygons has an unmatched edge; its signed volume
  // says which side is outside.
  std::vector<char> component_open(n, 0);
  std::vector<double> volume(n, 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t root = static_cast<std::size_t>(find_root(parent, static_cast<int>(i)));
    if (open[i]) component_open[root] = 1;
    const std::vector<Vec3>& v = description.surfaces[static_cast<std::size_t>(scatterers[i])].vertices;
    for (std::size_t k = 1; k + 1 < v.size(); ++k) volume[root] += dot(v[0], cross(v[k], v[k + 1])) / 6.0;
  }
  std::vector<LitSides> sides(n, LitSides::Both);
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t root = static_cast<std::size_t>(find_root(parent, static_cast<int>(i)));
    if (component_open[root] || volume[root] == 0.0) continue;
    sides[i] = volume[root] > 0 ? LitSides::Front : LitSides::Back;
  }
  return sides;
}

}  // namespace dayphoton::engine
