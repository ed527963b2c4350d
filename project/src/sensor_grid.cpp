// Sensor grids and point sets (model coordinates; build_scene_description rotates them).
//
// Room grid: over the room's floor rectangle at height_m above the floor, inset_m from the
// walls, spacing_m apart. Along each axis the number of points is
//   n = floor((extent - 2 inset) / spacing + 1e-9) + 1
// (the 1e-9 keeps floating error, e.g. 4.9999999/0.5, from dropping the last row) and the
// lattice is centred in the inset rectangle, so when (extent - 2 inset) is a multiple of the
// spacing the first and last points lie exactly at the inset. Order: rows in y outer,
// x inner, both ascending: index = columns * iy + ix, as the reference office's
// grid_0p8m.pts (../shared/refdata/sensors/README.md: 11 x 15 = 165 points,
// x = 0.5..5.5, y = 0.5..7.5 at z = 0.8).
//
// Polygon grid: the outline's x, y (its z is ignored) at z = height_m (absolute); the same
// centred lattice over the outline's bounding box shrunk by the inset, keeping the points
// inside the outline whose distance to its boundary is >= inset_m. Same order.
//
// A grid is a planar virtual receiver (SensorGrid::planar) when its sensors face straight
// up or down; the outline is the floor rectangle (room grids) or the polygon at the grid's
// height.
//
// Wall and rectangle grids: surface_grid.cpp (never receiver planes).
//
// Point sets: inline points followed by the points of a .pts file (pts_reader.h), normals
// normalised.
//
// Sensor areas (sensor_areas.h): a room or polygon grid whose outline cuts the lattice cells
// of its sensors (an inset below spacing / sqrt(2)) gives each sensor its cell clipped to the
// outline; a Honeybee grid's point set its mesh faces (PointsSpec::area_m2).
//
// Limits (core/resource_limits.h): a grid or point set holds at most limits.sensors_per_grid
// sensors. The count is computed in floating point from the spans and the spacing and
// checked before any point is made (a spacing of 1e-6 m, or a room of 1e6 m, gives a count
// no integer holds); the error is placed at `spacing`.
#include "dayphoton/core/diagnostics.h"
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "dayphoton/core/polygon.h"
#include "dayphoton/project/pts_reader.h"
#include "geometry_generators.h"
#include "sensor_areas.h"

namespace dayphoton::project::detail {

namespace {

constexpr double CountEpsilon = 1e-9;

// A polygon grid tests every point of the lattice over the polygon's bounding box against
// the outline: that lattice may hold at most this many times limits.sensors_per_grid points
// (a thin diagonal strip has a huge box and few points inside).
constexpr double PolygonLatticeFactor = 100;

void set_plane(SensorGrid& out, const Vec3& normal, double height_m) {
  out.planar = std::fabs(normal.z) > 1 - 1e-12;
  out.plane_normal = out.planar ? Vec3{0, 0, normal.z > 0 ? 1.0 : -1.0} : normal;
  out.plane_height_m = out.planar ? out.plane_normal.z * height_m : 0;
}

}  // namespace

/// Number of lattice points over `span_m` (0 if the span is negative beyond rounding), and
/// the first point's offset (centred). A double: a tiny spacing over a huge span gives more
/// points than any integer type holds (5e300), so it is checked against the limit before
/// it is converted.
double lattice(double span_m, double spacing_m, double& first_m) {
  if (span_m < -CountEpsilon * std::max(1.0, spacing_m)) return 0;
  span_m = std::max(0.0, span_m);
  const double n = std::floor(span_m / spacing_m + CountEpsilon) + 1;
  first_m = 0.5 * (span_m - (n - 1) * spacing_m);
  return n;
}

std::string limit_message(const std::string& what, double count, std::uint64_t max_points) {
  return what + " would have " + format_number(count) + " sensors, " +
         over_limit_text(max_points, "limits.sensors_per_grid");
}

bool check_spacing_and_inset(const GridSpec& spec, const std::string& what, Diagnostics& diag) {
  bool ok = true;
  if (!std::isfinite(spec.spacing_m) || spec.spacing_m <= 0) {
    report(diag, spec.location_of("spacing"), what + ": spacing must be positive");
    ok = false;
  }
  if (!std::isfinite(spec.inset_m) || spec.inset_m < 0) {
    report(diag, spec.location_of("inset"), what + ": inset must be >= 0");
    ok = false;
  }
  return ok;
}

const RoomSpec* find_grid_room(const std::string& name, const std::vector<RoomSpec>& rooms, Diagnostics& diag,
                               const SourceLocation& where, const std::string& what) {
  std::vector<std::string> names;
  for (const RoomSpec& r : rooms) {
    if (r.name == name) return &r;
    names.push_back(r.name);
  }
  std::string message = what + ": unknown room '" + name + "'";
  const std::string hint = closest_match(name, names);
  if (!hint.empty()) message += " (did you mean '" + hint + "'?)";
  report(diag, where, message);
  return nullptr;
}

bool generate_grid(const GridSpec& spec, const std::vector<RoomSpec>& rooms, std::uint64_t max_points,
                   Diagnostics& diag, SensorGrid& out) {
  const std::string what = "grid '" + spec.name + "'";
  const int outlines = int(!spec.room.empty()) + int(!spec.polygon.empty()) + int(spec.wall.has_value()) +
                       int(spec.rectangle.has_value());
  if (outlines != 1) {
    report(diag, spec.location, what + ": give exactly one of room, polygon, wall and rectangle");
    return false;
  }
  if (spec.wall || spec.rectangle) return generate_surface_grid(spec, rooms, max_points, diag, out);
  const SourceLocation& at_spacing = spec.spacing_location.known() ? spec.spacing_location : spec.location;
  bool ok = true;
  if (!check_spacing_and_inset(spec, what, diag)) ok = false;
  if (!std::isfinite(spec.height_m)) {
    report(diag, spec.location_of("height"), what + ": height is not finite");
    ok = false;
  }
  const double normal_length = length(spec.normal);
  if (!is_finite(spec.normal) || !(normal_length > 1e-12)) {
    report(diag, spec.location_of("normal"), what + ": sensor normal must be a non-zero vector");
    ok = false;
  }
  if (!ok) return false;
  const Vec3 normal = spec.normal / normal_length;

  out = SensorGrid{};
  out.name = spec.name;
  out.location = spec.location;
  out.drop_occluded = spec.drop_occluded;
  out.spacing_m = spec.spacing_m;

  if (!spec.room.empty()) {
    const RoomSpec* room = find_grid_room(spec.room, rooms, diag, spec.location_of("room"), what);
    if (!room) return false;
    if (!is_finite(room->origin) || !is_finite(room->size_m)) return false;  // reported by the room
    // Above the ceiling or below the floor the sensors lie outside the room (the ceiling and
    // the floor themselves are legitimate sensor planes).
    if (spec.height_m < 0 || spec.height_m > room->size_m.z) {
      report(diag, spec.location_of("height"),
             what + ": height " + format_number(spec.height_m) + " m puts the sensors " +
                 (spec.height_m < 0 ? "below the floor" : "above the ceiling") + " of room '" + room->name +
                 "' (" + format_number(room->size_m.z) + " m high); a room grid's height is measured from "
                 "the floor and must lie in [0, " + format_number(room->size_m.z) + "] m");
      return false;
    }
    const double z = room->origin.z + spec.height_m;
    double x_first = 0, y_first = 0;
    const double nx = lattice(room->size_m.x - 2 * spec.inset_m, spec.spacing_m, x_first);
    const double ny = lattice(room->size_m.y - 2 * spec.inset_m, spec.spacing_m, y_first);
    if (!(nx * ny <= static_cast<double>(max_points))) {
      report(diag, at_spacing,
             limit_message(what + " (" + format_number(nx) + " x " + format_number(ny) + " at spacing " +
                               format_number(spec.spacing_m) + " m over room '" + room->name + "', " +
                               format_number(room->size_m.x) + " x " + format_number(room->size_m.y) + " m)",
                           nx * ny, max_points));
      return false;
    }
    if (nx <= 0 || ny <= 0) {
      report(diag, spec.location,
             what + " has no points: the inset (" + format_number(spec.inset_m) + " m) leaves nothing of room '" +
                 room->name + "' (" + format_number(room->size_m.x) + " x " + format_number(room->size_m.y) + " m)");
      return false;
    }
    const double x0 = room->origin.x + spec.inset_m + x_first;
    const double y0 = room->origin.y + spec.inset_m + y_first;
    const std::size_t columns = static_cast<std::size_t>(nx), rows = static_cast<std::size_t>(ny);
    out.points.reserve(columns * rows);
    for (std::size_t iy = 0; iy < rows; ++iy)
      for (std::size_t ix = 0; ix < columns; ++ix)
        out.points.push_back({{x0 + double(ix) * spec.spacing_m, y0 + double(iy) * spec.spacing_m, z}, normal});
    out.columns = static_cast<int>(columns);
    out.rows = static_cast<int>(rows);
    const Vec3 o{room->origin.x, room->origin.y, z};
    out.outline = {o, o + Vec3{room->size_m.x, 0, 0}, o + Vec3{room->size_m.x, room->size_m.y, 0},
                   o + Vec3{0, room->size_m.y, 0}};
    out.area_m2 = lattice_cell_areas_m2(out.points, out.outline, spec.spacing_m);  // the walls' cut cells
    set_plane(out, normal, z);
    return true;
  }

  // Polygon outline at the grid height.
  std::vector<Vec3> outline;
  for (const Vec3& p : spec.polygon) {
    if (!std::isfinite(p.x) || !std::isfinite(p.y)) {
      report(diag, spec.location, what + ": polygon vertex is not finite");
      return false;
    }
    outline.push_back({p.x, p.y, spec.height_m});
  }
  if (outline.size() < 3 || polygon_area_m2(outline) < 1e-10) {
    report(diag, spec.location, what + ": polygon needs at least 3 vertices enclosing an area (seen from above)");
    return false;
  }
  try {
    (void)triangulate_polygon(outline);
  } catch (const std::invalid_argument& e) {
    report(diag, spec.location, what + ": polygon is not simple: " + e.what());
    return false;
  }
  Vec3 lo = outline[0], hi = outline[0];
  for (const Vec3& p : outline) {
    lo.x = std::min(lo.x, p.x);
    lo.y = std::min(lo.y, p.y);
    hi.x = std::max(hi.x, p.x);
    hi.y = std::max(hi.y, p.y);
  }
  double x_first = 0, y_first = 0;
  const double nx = lattice(hi.x - lo.x - 2 * spec.inset_m, spec.spacing_m, x_first);
  const double ny = lattice(hi.y - lo.y - 2 * spec.inset_m, spec.spacing_m, y_first);
  // Before the lattice is walked: the points the polygon's area holds, and the lattice itself.
  const double about = polygon_area_m2(outline) / (spec.spacing_m * spec.spacing_m);
  if (!(about <= static_cast<double>(max_points))) {
    report(diag, at_spacing,
           limit_message(what + " (a polygon of " + format_number(polygon_area_m2(outline)) + " m2 at spacing " +
                             format_number(spec.spacing_m) + " m)",
                         about, max_points));
    return false;
  }
  if (!(nx * ny <= PolygonLatticeFactor * static_cast<double>(max_points))) {
    report(diag, at_spacing,
           what + ": the lattice over the polygon's bounding box would have " + format_number(nx * ny) +
               " points to test, more than " + format_number(PolygonLatticeFactor) +
               " x limits.sensors_per_grid (" + std::to_string(max_points) +
               "); use a larger spacing, or raise limits.sensors_per_grid if you mean it");
    return false;
  }
  const double boundary_tolerance_m = 1e-9 * std::max(1.0, std::max(hi.x - lo.x, hi.y - lo.y));
  const std::size_t columns = static_cast<std::size_t>(nx), rows = static_cast<std::size_t>(ny);
  for (std::size_t iy = 0; iy < rows; ++iy)
    for (std::size_t ix = 0; ix < columns; ++ix) {
      const Vec3 p{lo.x + spec.inset_m + x_first + double(ix) * spec.spacing_m,
                   lo.y + spec.inset_m + y_first + double(iy) * spec.spacing_m, spec.height_m};
      const double d = distance_to_polygon_boundary_m(outline, p);
      const bool on_boundary = d <= boundary_tolerance_m;
      if (d < spec.inset_m - boundary_tolerance_m) continue;
      if (!on_boundary && !polygon_contains(outline, p)) continue;
      if (out.points.size() == max_points) {
        report(diag, at_spacing, limit_message(what, double(max_points) + 1, max_points) + " (or more)");
        return false;
      }
      out.points.push_back({p, normal});
    }
  if (out.points.empty()) {
    report(diag, spec.location,
           what + " has no points: no lattice point of spacing " + format_number(spec.spacing_m) +
               " m lies inside the polygon at least " + format_number(spec.inset_m) + " m from its edges");
    return false;
  }
  out.outline = outline;
  out.area_m2 = lattice_cell_areas_m2(out.points, out.outline, spec.spacing_m);  // the outline's cut cells
  set_plane(out, normal, spec.height_m);
  return true;
}

bool generate_points(const PointsSpec& spec, std::uint64_t max_points, Diagnostics& diag, SensorGrid& out) {
  const std::string what = "sensor points '" + spec.name + "'";
  out = SensorGrid{};
  out.name = spec.name;
  out.location = spec.location;
  out.drop_occluded = spec.drop_occluded;
  bool ok = true;
  if (spec.points.size() > max_points) {
    report(diag, spec.location, limit_message(what, double(spec.points.size()), max_points));
    return false;
  }
  for (std::size_t i = 0; i < spec.points.size(); ++i) {
    const SensorPoint& p = spec.points[i];
    const double len = length(p.normal);
    if (!is_finite(p.position) || !is_finite(p.normal) || !(len > 1e-12)) {
      report(diag, spec.location,
             what + ": point " + std::to_string(i + 1) + " needs a finite position and a non-zero direction");
      ok = false;
      continue;
    }
    out.points.push_back({p.position, p.normal / len});
  }
  if (ok && !spec.area_m2.empty()) {
    if (spec.area_m2.size() != spec.points.size() || !spec.file.empty() || !spec.file_as_written.empty())
      throw std::logic_error("sensor points: areas given for another count of points");
    out.area_m2 = spec.area_m2;
  }
  const std::string path = spec.file.empty() ? spec.file_as_written : spec.file;
  if (!path.empty()) {
    const std::size_t errors_before = diag.error_count();
    const std::uint64_t room_left = max_points > out.points.size() ? max_points - out.points.size() : 0;
    std::vector<SensorPoint> from_file = read_pts(path, diag, spec.location, room_left);
    if (diag.error_count() != errors_before) ok = false;
    for (SensorPoint& p : from_file) p.position = p.position * spec.metres_per_unit;  // `units`
    out.points.insert(out.points.end(), from_file.begin(), from_file.end());
  }
  if (ok && out.points.empty()) {
    report(diag, spec.location, what + " has no points");
    return false;
  }
  return ok;
}

}  // namespace dayphoton::project::detail
