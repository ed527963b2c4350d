// Is an imported scene plausible in metres (scene_unit_check.h)?
#include "dayphoton/project/scene_unit_check.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "dayphoton/project/length_units.h"

namespace dayphoton::project {
namespace {

struct Box {
  Vec3 lo{std::numeric_limits<double>::max(), std::numeric_limits<double>::max(), std::numeric_limits<double>::max()};
  Vec3 hi{-std::numeric_limits<double>::max(), -std::numeric_limits<double>::max(), -std::numeric_limits<double>::max()};
  void add(const Vec3& p) {
    for (int k = 0; k < 3; ++k) {
      lo[k] = std::min(lo[k], p[k]);
      hi[k] = std::max(hi[k], p[k]);
    }
  }
};

struct Horizontal {
  std::vector<Vec3> vertices;
  double z = 0, area = 0;
  Box box;
};

/// Newell's normal: twice the area times the unit normal (M. E. Newell; Sutherland, Sproull
/// and Schumacker, "A Characterization of Ten Hidden-Surface Algorithms", 1974).
Vec3 newell(const std::vector<Vec3>& v) {
  Vec3 n{0, 0, 0};
  for (std::size_t i = 0; i < v.size(); ++i) {
    const Vec3& a = v[i];
    const Vec3& b = v[(i + 1) % v.size()];
    n.x += (a.y - b.y) * (a.z + b.z);
    n.y += (a.z - b.z) * (a.x + b.x);
    n.z += (a.x - b.x) * (a.y + b.y);
  }
  return n;
}

/// Even-odd point in polygon, in plan.
bool inside_plan(double x, double y, const std::vector<Vec3>& v) {
  bool in = false;
  for (std::size_t i = 0, j = v.size() - 1; i < v.size(); j = i++)
    if ((v[i].y > y) != (v[j].y > y) && x < (v[j].x - v[i].x) * (y - v[i].y) / (v[j].y - v[i].y) + v[i].x) in = !in;
  return in;
}

/// The area centroid in plan (shoelace), false for a degenerate outline.
bool centroid_plan(const std::vector<Vec3>& v, double& cx, double& cy) {
  double a2 = 0, sx = 0, sy = 0;
  for (std::size_t i = 0; i < v.size(); ++i) {
    const Vec3& p = v[i];
    const Vec3& q = v[(i + 1) % v.size()];
    const double c = p.x * q.y - q.x * p.y;
    a2 += c;
    sx += (p.x + q.x) * c;
    sy += (p.y + q.y) * c;
  }
  if (!(std::fabs(a2) > 0)) return false;
  cx = sx / (3 * a2);
  cy = sy / (3 * a2);
  return true;
}

}  // namespace

std::optional<SceneUnitSuggestion> suggest_scene_units(const std::vector<UnitCheckFacet>& facets) {
  std::vector<Horizontal> horizontal;
  std::vector<Box> glazing;
  for (const UnitCheckFacet& f : facets) {
    if (f.vertices.size() < 3) continue;
    if (f.glazed) {
      Box b;
      for (const Vec3& p : f.vertices) b.add(p);
      glazing.push_back(b);
    }
    const Vec3 n = newell(f.vertices);
    const double twice_area = length(n);
    if (!(twice_area > 0) || std::fabs(n.z) < UnitCheckHorizontalCos * twice_area) continue;
    Horizontal h;
    h.vertices = f.vertices;
    h.area = 0.5 * twice_area;
    for (const Vec3& p : f.vertices) {
      h.z += p.z / double(f.vertices.size());
      h.box.add(p);
    }
    horizontal.push_back(std::move(h));
  }
  if (glazing.empty() || horizontal.size() < 2) return std::nullopt;
  std::stable_sort(horizontal.begin(), horizontal.end(),
                   [](const Horizontal& a, const Horizontal& b) { return a.area > b.area; });
  if (horizontal.size() > UnitCheckMaxHorizontalFacets) horizontal.resize(UnitCheckMaxHorizontalFacets);

  struct Clearance {
    double height = 0, area = 0;
  };
  std::vector<Clearance> lit;
  double lit_area = 0;
  for (const Horizontal& h : horizontal) {
    double cx = 0, cy = 0;
    if (!centroid_plan(h.vertices, cx, cy) || !inside_plan(cx, cy, h.vertices)) continue;
    const double eps = 1e-9 * (1 + std::fabs(h.z));
    double above = std::numeric_limits<double>::infinity();
    for (const Horizontal& g : horizontal) {
      if (!(g.z > h.z + eps) || !(g.z < above)) continue;
      if (cx < g.box.lo.x || cx > g.box.hi.x || cy < g.box.lo.y || cy > g.box.hi.y) continue;
      if (inside_plan(cx, cy, g.vertices)) above = g.z;
    }
    if (!std::isfinite(above)) continue;
    const double c = above - h.z;
    const double margin = UnitCheckLitMargin * c;
    bool is_lit = false;
    for (const Box& b : glazing)
      is_lit = is_lit || (b.hi.x >= h.box.lo.x - margin && b.lo.x <= h.box.hi.x + margin &&
                          b.hi.y >= h.box.lo.y - margin && b.lo.y <= h.box.hi.y + margin &&
                          b.hi.z >= h.z - eps && b.lo.z <= above + eps);
    if (!is_lit) continue;
    lit.push_back({c, h.area});
    lit_area += h.area;
  }
  if (lit.empty()) return std::nullopt;

  auto plausible = [](double height_m) {
    return height_m >= PlausibleRoomHeightMin_m && height_m <= PlausibleRoomHeightMax_m;
  };
  double metre_area = 0;
  for (const Clearance& c : lit)
    if (plausible(c.height)) metre_area += c.area;
  std::optional<SceneUnitSuggestion> best;
  double best_area = 0;
  for (const std::string& name : length_unit_names()) {
    const double f = metres_per_length_unit(name);
    if (f == 1.0) continue;
    std::vector<Clearance> explained;
    double area = 0;
    for (const Clearance& c : lit)
      if (plausible(c.height * f)) {
        explained.push_back(c);
        area += c.area;
      }
    if (!(area > best_area) || !(area > UnitCheckDominance * metre_area)) continue;
    // The area-weighted median of the clearances this unit explains.
    std::sort(explained.begin(), explained.end(),
              [](const Clearance& a, const Clearance& b) { return a.height < b.height; });
    double acc = 0, median = explained.front().height;
    for (const Clearance& c : explained) {
      acc += c.area;
      median = c.height;
      if (acc >= 0.5 * area) break;
    }
    best_area = area;
    best = SceneUnitSuggestion{name, f, median, median * f, area / lit_area};
  }
  return best;
}

}  // namespace dayphoton::project
