// sensor_areas: see sensor_areas.h.
#include "sensor_areas.h"

#include <algorithm>
#include <cmath>

namespace dayphoton::project::detail {

namespace {

struct Point2 {
  double x, y;
};

/// Twice the signed area (shoelace).
double twice_signed_area(const std::vector<Point2>& polygon) {
  double sum = 0;
  for (std::size_t i = 0, n = polygon.size(); i < n; ++i) {
    const Point2& a = polygon[i];
    const Point2& b = polygon[(i + 1) % n];
    sum += a.x * b.y - b.x * a.y;
  }
  return sum;
}

/// The part of `polygon` on the side of an axis-aligned line where keep(p) holds
/// (Sutherland-Hodgman). Clipped by the four sides of a convex square, a concave polygon may
/// come out with edges that run back over themselves; they enclose no area, so the
/// shoelace area of the result is the area of the intersection.
template <class Keep, class Cross>
std::vector<Point2> clip_side(const std::vector<Point2>& polygon, const Keep& keep, const Cross& cross) {
  std::vector<Point2> out;
  for (std::size_t i = 0, n = polygon.size(); i < n; ++i) {
    const Point2& a = polygon[(i + n - 1) % n];
    const Point2& b = polygon[i];
    if (keep(b)) {
      if (!keep(a)) out.push_back(cross(a, b));
      out.push_back(b);
    } else if (keep(a)) {
      out.push_back(cross(a, b));
    }
  }
  return out;
}

double clipped_area_m2(std::vector<Point2> polygon, double x0, double x1, double y0, double y1) {
  auto at_x = [](double x) {
    return [x](const Point2& a, const Point2& b) { return Point2{x, a.y + (b.y - a.y) * (x - a.x) / (b.x - a.x)}; };
  };
  auto at_y = [](double y) {
    return [y](const Point2& a, const Point2& b) { return Point2{a.x + (b.x - a.x) * (y - a.y) / (b.y - a.y), y}; };
  };
  polygon = clip_side(polygon, [x0](const Point2& p) { return p.x >= x0; }, at_x(x0));
  if (!polygon.empty()) polygon = clip_side(polygon, [x1](const Point2& p) { return p.x <= x1; }, at_x(x1));
  if (!polygon.empty()) polygon = clip_side(polygon, [y0](const Point2& p) { return p.y >= y0; }, at_y(y0));
  if (!polygon.empty()) polygon = clip_side(polygon, [y1](const Point2& p) { return p.y <= y1; }, at_y(y1));
  return polygon.size() < 3 ? 0.0 : 0.5 * std::fabs(twice_signed_area(polygon));
}

}  // namespace

std::vector<double> unequal_areas_m2(const std::vector<double>& areas_m2) {
  if (areas_m2.empty()) return {};
  const auto [lo, hi] = std::minmax_element(areas_m2.begin(), areas_m2.end());
  if (*hi - *lo <= EqualAreaRelativeTolerance * std::fabs(*hi)) return {};
  return areas_m2;
}

std::vector<double> lattice_cell_areas_m2(const std::vector<SensorPoint>& sensors, const std::vector<Vec3>& outline,
                                          double spacing_m) {
  std::vector<Point2> polygon;
  for (const Vec3& v : outline) polygon.push_back({v.x, v.y});
  const double half = 0.5 * spacing_m;
  std::vector<double> areas;
  areas.reserve(sensors.size());
  for (const SensorPoint& s : sensors) {
    const double x = s.position.x, y = s.position.y;
    areas.push_back(clipped_area_m2(polygon, x - half, x + half, y - half, y + half));
  }
  return unequal_areas_m2(areas);
}

}  // namespace dayphoton::project::detail
