// Placement check: see placement_check.h.
#include "dayphoton/study/placement_check.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <sstream>

#include "dayphoton/core/diagnostics.h"
#include "dayphoton/core/polygon.h"
#include "dayphoton/engine/plane_cuts.h"
#include "dayphoton/study/daylight_openings.h"
#include "dayphoton/engine/port_facing.h"
#include "dayphoton/engine/port_view.h"
#include "dayphoton/engine/receiver_plane.h"
#include "dayphoton/engine/scene.h"
#include "dayphoton/engine/sensor_placement.h"
#include "dayphoton/project/length_units.h"
#include "dayphoton/project/north_rotation.h"
#include "dayphoton/study/simulation_plan.h"

namespace dayphoton::study {
namespace {

void report(Diagnostics& diag, const SourceLocation& where, const std::string& message) {
  std::string line;
  if (where.known() && !diag.at_cap()) line = read_source_line(where.file, where.line);
  diag.error(where, message, line);
}

std::string percent(double fraction) {
  std::ostringstream s;
  s << std::lround(100.0 * fraction) << " %";
  return s.str();
}

std::string point_text(const Vec3& p) {
  return "(" + format_coordinate(p.x) + ", " + format_coordinate(p.y) + ", " + format_coordinate(p.z) + ")";
}

/// Positions of the scene description as the project file writes them: back to world
/// coordinates (SceneDescription::world_origin_m), then to model coordinates (north rotation).
struct ModelFrame {
  const SceneDescription& description;
  double north_deg = 0;
  std::string text(const Vec3& position_m) const {
    return point_text(project::world_to_model(description.world_of(position_m), north_deg));
  }
};

std::string sky_fractions(const engine::Port& port) {
  return "sky seen by " + percent(port.sky_fraction_winding) + " of the test rays on the side its vertex order "
         "faces, " + percent(port.sky_fraction_opposite) + " on the other";
}

Diagnostic warning_at(const SourceLocation& where, const std::string& message) {
  Diagnostic d;
  d.severity = Severity::Warning;
  d.location = where;
  d.message = message;
  return d;
}

/// Probes along a receiver plane's outline (OutlineProbeInset_m inside it, about
/// OutlineProbeSpacing_m apart), facing as the grid's sensors.
std::vector<SensorPoint> outline_probes(const SensorGrid& grid) {
  std::vector<SensorPoint> probes;
  const std::vector<Vec3>& o = grid.outline;
  const std::size_t n = o.size();
  if (n < 3) return probes;
  double twice_area = 0;  // > 0: counter-clockwise seen from above
  for (std::size_t i = 0; i < n; ++i) twice_area += o[i].x * o[(i + 1) % n].y - o[(i + 1) % n].x * o[i].y;
  const double side = twice_area >= 0 ? 1.0 : -1.0;
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3 a = o[i], b = o[(i + 1) % n];
    const double dx = b.x - a.x, dy = b.y - a.y, length = std::hypot(dx, dy);
    if (!(length > 2 * OutlineProbeInset_m)) continue;
    const Vec3 inward{-dy / length * side, dx / length * side, 0};
    const int count = std::max(2, static_cast<int>(std::ceil(length / OutlineProbeSpacing_m)));
    for (int k = 0; k < count; ++k) {
      // Along the edge, OutlineProbeInset_m clear of its ends (the corners are the next edge's).
      const double s = OutlineProbeInset_m / length + (1 - 2 * OutlineProbeInset_m / length) * (k + 0.5) / count;
      probes.push_back({a + (b - a) * s + inward * OutlineProbeInset_m, grid.plane_normal});
    }
  }
  return probes;
}

/// The warning for sensors in a room that see the sky through a gap that is no port (header):
/// light enters only through ports, so what comes through the gap is not counted.
void check_sky_through_gaps(const SensorGrid& grid, const std::vector<engine::SensorPlacementTest>& tests,
                            const ModelFrame& frame, std::vector<Diagnostic>& warnings) {
  std::size_t count = 0, largest = tests.size();
  for (std::size_t i = 0; i < tests.size(); ++i) {
    const engine::SensorPlacementTest& t = tests[i];
    if (t.placement != engine::SensorPlacement::InRoom || t.sky_without_port == 0) continue;
    ++count;
    if (largest == tests.size() || t.sky_without_port * tests[largest].rays > tests[largest].sky_without_port * t.rays)
      largest = i;
  }
  if (count == 0) return;
  const engine::SensorPlacementTest& t = tests[largest];
  warnings.push_back(warning_at(
      grid.location,
      "sensor set '" + grid.name + "': " + std::to_string(count) + " of " + std::to_string(tests.size()) +
          " sensors see the sky through an opening that is no port (sensor " + std::to_string(largest) + " at " +
          frame.text(grid.points[largest].position) + " m in " +
          percent(double(t.sky_without_port) / t.rays) +
          " of its hemisphere): light enters only through ports, so the light through that gap is not counted "
          "and these sensors read low. Close the gap, or make the opening a port (a polygon with 'port: true' "
          "of an 'opening' material, a glass aperture in a Honeybee face, a RADIANCE glass or a modifier "
          "listed under 'ports')"));
}

/// The warning for a receiver-plane grid whose outline reaches outside every room (header).
void check_outline(const engine::Scene& scene, const SensorGrid& grid, const ModelFrame& frame,
                   std::vector<Diagnostic>& warnings) {
  if (!grid.planar) return;
  const std::vector<SensorPoint> probes = outline_probes(grid);
  const std::vector<engine::SensorPlacementTest> tests = engine::test_sensor_placements(scene, probes);
  std::size_t outside = 0, first = 0;
  for (std::size_t i = 0; i < tests.size(); ++i)
    if (tests[i].placement == engine::SensorPlacement::OutsideRooms && outside++ == 0) first = i;
  if (outside == 0) return;
  warnings.push_back(warning_at(
      grid.location,
      "sensor set '" + grid.name + "': its outline reaches outside every room (" + std::to_string(outside) + " of " +
          std::to_string(probes.size()) + " points " + format_number(OutlineProbeInset_m) +
          " m inside it, first at " + frame.text(probes[first].position) +
          " m, see the sky without a port); the work plane counts the light crossing it inside the outline, "
          "and none crosses beyond the walls, so the sensors near that part read low. Draw the outline along "
          "the room's inside faces"));
}

/// The warning for a receiver plane under glazing that is no port inside its outline: an
/// interior glazed partition drawn as polygons, boxes, a mesh or an imported scene, standing
/// more than 30 degrees from the plane's own orientation (a room's
/// interior windows lie on its grid's outline, and a room lit only through them is gathered:
/// project/scene_builder.cpp). The light the rooms' surfaces send through it reaches the plane
/// as photons alone, with the glazing's sharp footprint, which the plane's kernel blurs (docs/
/// validation.md, "A new user's rooms and materials": 0.5 m behind a clear pane over a
/// 1 m wall, 6-7 % low, z to -6.3).
void check_glazing_over_plane(const engine::Scene& scene, const std::vector<engine::Material>& materials,
                              const SensorGrid& grid, const ModelFrame& frame, std::vector<Diagnostic>& warnings) {
  if (!grid.planar || grid.outline.size() < 3) return;
  const engine::ReceiverPlane plane = engine::ReceiverPlane::from_grid(grid);
  const std::vector<Surface>& surfaces = scene.description().surfaces;
  const std::vector<engine::PlanePoint>& outline = plane.outline();
  for (std::size_t i = 0; i < surfaces.size(); ++i) {
    const Surface& s = surfaces[i];
    if (scene.is_port(static_cast<int>(i)) || s.outdoor_scatterer || s.vertices.size() < 3 ||
        !engine::transmits_straight(materials.at(static_cast<std::size_t>(s.material))))
      continue;
    // A pane lying over the plane (a light pipe's diffuser, a glass floor) sends its light
    // down as a smooth field (projects/light_pipe against a backward reference: RMS z 0.94).
    if (std::fabs(dot(polygon_normal(s.vertices), plane.normal())) > GlazingOverPlaneMaxCos) continue;
    Vec3 c{0, 0, 0};
    bool lit_side = false;  // some of it on the side of the plane its sensors face
    for (const Vec3& v : s.vertices) {
      c = c + v;
      lit_side = lit_side || dot(v, plane.normal()) > dot(Vec3{0, 0, plane.height_m()}, plane.normal()) + GlazingOverPlaneEdge_m;
    }
    c = c / double(s.vertices.size());
    if (!lit_side || !plane.contains(c.x, c.y)) continue;
    double edge_m = std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k < outline.size(); ++k) {
      const engine::PlanePoint& a = outline[k];
      const engine::PlanePoint& b = outline[(k + 1) % outline.size()];
      const double dx = b.x - a.x, dy = b.y - a.y, len2 = dx * dx + dy * dy;
      const double t = len2 > 0 ? std::clamp(((c.x - a.x) * dx + (c.y - a.y) * dy) / len2, 0.0, 1.0) : 0.0;
      edge_m = std::min(edge_m, std::hypot(c.x - a.x - t * dx, c.y - a.y - t * dy));
    }
    if (edge_m <= GlazingOverPlaneEdge_m) continue;  // on the outline: a room's own window
    warnings.push_back(warning_at(
        grid.location,
        "sensor set '" + grid.name + "': glazing '" + s.name + "' at " + frame.text(c) +
            " m is no port and stands inside the grid's outline (an interior glazed partition): the light that "
            "comes through it reaches the work plane as photons alone, and the plane's kernel blurs its footprint "
            "(measured 6-7 % low 0.5 m behind such a pane). Draw the spaces as rooms with an interior window (a "
            "room lit only through interior windows is estimated by final gather), or give the sensors behind it "
            "as a point set"));
    return;
  }
}

/// For a point set read from a .pts file with sensors outside the model's bounding box: the
/// hint to set `units` when the file's positions, scaled from another length unit
/// (project/length_units.h), would all lie inside it (a file in feet beside a model in metres
/// puts the sensors 3.3 times as far from the origin); empty otherwise.
std::string pts_units_hint(const engine::Scene& scene, const SensorGrid& grid, const project::Project& proj) {
  const project::PointsSpec* spec = nullptr;
  for (const project::PointsSpec& p : proj.sensors.points)
    if (p.name == grid.name && !p.file_as_written.empty()) spec = &p;
  if (!spec || grid.points.empty()) return {};
  const engine::Bounds3& b = scene.bounds();
  const double tolerance_m = 1e-6 * (1 + length(b.extent()));
  auto inside = [&](const Vec3& p) {
    for (int k = 0; k < 3; ++k)
      if (p[k] < b.lower[k] - tolerance_m || p[k] > b.upper[k] + tolerance_m) return false;
    return true;
  };
  auto all_inside = [&](double factor) {
    for (const SensorPoint& s : grid.points)
      if (!inside(s.position * factor)) return false;
    return true;
  };
  if (all_inside(1.0)) return {};
  // The unit nearest the one used that fits: shrunk enough, any set fits a model holding the
  // origin, so the smallest change of scale is the likely one.
  std::vector<std::string> names = project::length_unit_names();
  auto change = [&](const std::string& name) {
    return std::fabs(std::log(project::metres_per_length_unit(name) / spec->metres_per_unit));
  };
  std::stable_sort(names.begin(), names.end(),
                   [&](const std::string& x, const std::string& y) { return change(x) < change(y); });
  for (const std::string& name : names) {
    const double factor = project::metres_per_length_unit(name) / spec->metres_per_unit;
    if (name == spec->units || !all_inside(factor)) continue;
    std::string unit = name == "Meters" ? std::string("metres") : name;
    for (char& c : unit) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return "; scaled by " + format_number(factor) + " they all lie inside the model's bounding box: if '" +
           spec->file_as_written + "' is in " + unit + ", set 'units: " + name + "' on this entry";
  }
  return {};
}

/// The words for a sensor on a surface that crosses its work plane, and why it is refused
/// (header comment; measured at a 0.4 m column's faces: a final gather there reads the
/// column's inside through half its hemisphere, relative standard error about 21 %).
constexpr const char* OnCutWords = "on a surface that crosses the work plane";
constexpr const char* OnCutWhy =
    "a sensor on a surface has no illuminance of its own: part of what it sees is the surface's inside, and "
    "its final gather reads about 20 % relative standard error there";

/// The words for enclosed sensors (engine/sensor_placement.h): inside a closed volume drawn from
/// polygons, or in a room whose openings are all opaque.
constexpr const char* EnclosedWords =
    "in a closed volume no light enters (a column or solid drawn from polygons, or a room whose openings are "
    "opaque, missing or not ports)";

/// Per sensor of a planar set: whether it lies within engine::OnCut_m of an opaque surface
/// crossing its plane inside the outline (engine/plane_cuts.h); all false for other sets.
std::vector<bool> on_cut_flags(const engine::Scene& scene, const SensorGrid& grid) {
  std::vector<bool> out(grid.points.size(), false);
  if (!grid.planar || grid.points.empty()) return out;
  engine::ReceiverPlane plane = engine::ReceiverPlane::from_grid(grid);
  plane.set_interior_cuts(engine::interior_plane_cuts(scene, plane, true));
  for (std::size_t i : engine::sensors_on_cuts(plane, grid.points)) out[i] = true;
  return out;
}

/// A planar set's sensors within engine::NearCutGather_m of a surface crossing the plane
/// (header comment): how many, and the nearest.
struct NearCutSensors {
  std::size_t count = 0, nearest_sensor = 0;
  double nearest_m = 0;
  std::vector<std::size_t> sensors;  ///< their indices in the set
};
NearCutSensors near_cut_sensors_of(const engine::Scene& scene, const SensorGrid& grid) {
  NearCutSensors out;
  if (!grid.planar || grid.points.empty()) return out;
  engine::ReceiverPlane plane = engine::ReceiverPlane::from_grid(grid);
  plane.set_interior_cuts(engine::interior_plane_cuts(scene, plane));
  const std::vector<std::size_t> near = engine::sensors_near_cuts(plane, grid.points);
  if (near.empty()) return out;
  out.count = near.size();
  out.sensors = near;
  out.nearest_sensor = near.front();
  out.nearest_m = engine::NearCutGather_m;
  for (std::size_t i : near) {
    const Vec3& p = grid.points[i].position;
    const double d_m = engine::distance_to_interior_cut_m(plane, p.x, p.y);
    if (d_m < out.nearest_m) out.nearest_m = d_m, out.nearest_sensor = i;
  }
  return out;
}

/// One located message per set with sensors next to a cut (header comment): a note where
/// they are gathered, a warning where they keep the plane's estimate (near_cut_gathered).
void report_near_cuts(const SensorGrid& grid, const NearCutSensors& near, bool gathered, const ModelFrame& frame,
                      PlacementCheck& out) {
  if (near.count == 0) return;
  const std::string where =
      "sensor set '" + grid.name + "': " + std::to_string(near.count) + " of " + std::to_string(grid.points.size()) +
      " sensors lie within " + format_number(engine::NearCutGather_m) +
      " m of a surface that crosses the work plane (a column, a partition, furniture), the nearest, sensor " +
      std::to_string(near.nearest_sensor) + " at " +
      frame.text(grid.points[near.nearest_sensor].position) + " m, " +
      format_number(std::round(near.nearest_m * 1000) / 1000) +
      " m from it; there the light on the plane changes faster than the photon estimate's disc follows, so ";
  if (gathered) {
    Diagnostic d = warning_at(grid.location, where + "they are estimated by final gather from their own position, "
                                                     "as a point set is");
    d.severity = Severity::Note;
    out.notes.push_back(std::move(d));
    return;
  }
  out.warnings.push_back(warning_at(
      grid.location,
      where + "they read the plane's estimate, which can be 10-20 % off there (measured next to a 0.4 m column: "
              "-9 % in front, +19 % behind). They are fewer than " +
          format_number(100 * NearCutGatherMinShare) +
          " % of the set, too few to keep every surface photon of the case for their final gather (2-4 times "
          "the memory): keep the grid 0.3 m clear of such surfaces, or list those points as a point set, "
          "estimated by final gather"));
}

/// Cosine-distributed direction of the stratum (i, j) of a k x k lattice about `normal`
/// (Malley's method: a uniform point of the unit disc lifted onto the hemisphere).
Vec3 cosine_direction(const Vec3& normal, int i, int j, int k) {
  const double u = (i + 0.5) / k, v = (j + 0.5) / k;
  const double r = std::sqrt(u), phi = 2 * 3.14159265358979323846 * v;
  const Vec3 helper = std::fabs(normal.x) < 0.9 ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
  const Vec3 t = normalize(cross(helper, normal));
  const Vec3 b = cross(normal, t);
  return normalize(t * (r * std::cos(phi)) + b * (r * std::sin(phi)) + normal * std::sqrt(std::max(0.0, 1 - u)));
}

bool sends_light(const MaterialSpec& m) {
  const double rho = std::max({m.reflectance.x, m.reflectance.y, m.reflectance.z});
  switch (m.type) {
    case MaterialType::Lambertian:
    case MaterialType::Metal:
    case MaterialType::Mirror: return rho > 0;
    default: return true;
  }
}

/// What makes the light of `s` (an outdoor surface that only shades) traced, by its origin;
/// empty for a daylight system's part, whose `port` setting says how its light is traced.
std::string tracing_remedy(const Surface& s, const SceneDescription& description) {
  switch (s.origin) {
    case SurfaceOrigin::Polygon:
    case SurfaceOrigin::Box:
    case SurfaceOrigin::Mesh: return "To trace that light, give the polygon, box or mesh 'outdoor: true' (an outdoor scatterer)";
    case SurfaceOrigin::Radiance: {
      const std::string& material = description.materials[static_cast<std::size_t>(s.material)].name;
      const bool renamed = material.find('@') != std::string::npos;  // radiance_generator.cpp
      return "To trace that light, list its modifier" + (renamed ? std::string() : " '" + material + "'") +
             " under the RADIANCE scene's 'outdoor' (its surfaces become outdoor scatterers)";
    }
    case SurfaceOrigin::Room:
      return "The room generator's walls, floor and ceiling only shade from outside: to trace that light, draw "
             "that facade as a polygon or box with 'outdoor: true' just outside them (the wall's thickness)";
    case SurfaceOrigin::Honeybee:
      return "A Honeybee face, aperture, door or indoor shade only shades from outside: to trace that light, draw "
             "that facade as an outdoor shade of the model, or as a polygon with 'outdoor: true', just outside it";
    case SurfaceOrigin::Other: return "To trace that light, make it an outdoor scatterer";
    case SurfaceOrigin::System: return "";
  }
  return "";
}

/// Sensors of a gathered set tested by check_gather_outside_region (spread over the set) and
/// rays per sensor (a lattice of GatherProbeLattice^2 cosine-distributed directions).
constexpr std::size_t GatherProbeSensors = 64;
constexpr int GatherProbeLattice = 8;

/// The warning for sets estimated by final gather, and planar sets' gathered rows next to a
/// cut (`near_cut_rows[g]`: their indices, empty where the plane's estimate serves them), whose
/// rays reach surfaces outside simulation.region_of_interest (header comment).
void check_gather_outside_region(const engine::Scene& scene, const std::vector<SensorGrid>& grids,
                                 const std::vector<std::vector<std::size_t>>& near_cut_rows,
                                 const project::Project& proj, std::vector<Diagnostic>& warnings) {
  const auto& roi = proj.simulation.region_of_interest;
  if (!roi) return;
  const bool gather = proj.simulation.point_estimate == project::PointEstimate::Gather;
  const SceneDescription& description = scene.description();
  const double north_deg = proj.site.rotation_to_true_north_deg();
  constexpr double Tolerance_m = 1e-6;
  const Vec3 lo = roi->origin_m, hi = roi->origin_m + roi->size_m;
  auto outside_box = [&](const Vec3& world) {
    const Vec3 p = project::world_to_model(world, north_deg);
    for (int k = 0; k < 3; ++k)
      if (p[k] < lo[k] - Tolerance_m || p[k] > hi[k] + Tolerance_m) return true;
    return false;
  };
  for (std::size_t g = 0; g < grids.size(); ++g) {
    const SensorGrid& grid = grids[g];
    // The gathered sensors: a point or surface set's all (with point_estimate: gather), a
    // plane's rows next to a cut (whatever point_estimate says, CaseLayout::of).
    std::vector<std::size_t> gathered;
    if (!grid.planar && gather)
      for (std::size_t i = 0; i < grid.points.size(); ++i) gathered.push_back(i);
    else if (grid.planar && g < near_cut_rows.size())
      gathered = near_cut_rows[g];
    if (gathered.empty()) continue;
    const std::size_t stride = std::max<std::size_t>(1, gathered.size() / GatherProbeSensors);
    std::size_t rays = 0, outside = 0;
    for (std::size_t k = 0; k < gathered.size(); k += stride) {
      const SensorPoint& sensor = grid.points[gathered[k]];
      for (int a = 0; a < GatherProbeLattice; ++a)
        for (int b = 0; b < GatherProbeLattice; ++b) {
          ++rays;
          Vec3 origin = sensor.position, direction = cosine_direction(sensor.normal, a, b, GatherProbeLattice);
          // Straight on through ports (a clear pane: the gather reads the outdoor scatterers
          // behind it); photons on a diffusing port are stored whatever the box.
          bool through_port = false;
          for (int event = 0; event < 8; ++event) {
            const std::optional<engine::Hit> hit =
                scene.intersect(engine::Ray{origin, direction, 0.0, std::numeric_limits<double>::infinity()});
            if (!hit || (through_port && hit->scatterer < 0)) break;
            if (hit->port >= 0) {
              const MaterialSpec& m = description.materials[static_cast<std::size_t>(hit->material)];
              if (m.type == MaterialType::Translucent && m.transmissivity > 0 && m.transmitted_specular < 1) break;
              through_port = true;
              origin = scene.offset_ray_origin(hit->position, hit->normal, direction);
              continue;
            }
            if (outside_box(hit->position)) ++outside;
            break;
          }
        }
    }
    if (outside == 0) continue;
    const std::string who =
        grid.planar ? "sensor set '" + grid.name + "': its " + std::to_string(gathered.size()) +
                          " sensors next to a surface that crosses the work plane are estimated by final gather, and " +
                          percent(double(outside) / rays) + " of their gather rays reach surfaces outside the box, "
                          "where no photon is stored: they read low by the light from there"
                    : "sensor set '" + grid.name + "' is estimated by final gather, and " +
                          percent(double(outside) / rays) +
                          " of its gather rays reach surfaces outside the box, where no photon is stored: its sensors "
                          "read low by the light from there";
    warnings.push_back(warning_at(roi->location, "simulation.region_of_interest: " + who +
                                                     ". Make the box hold every surface the sensors see (the rooms "
                                                     "and the outdoor scatterers seen through their windows), or "
                                                     "remove it"));
  }
}

/// The warning for geometry outside the ports that only shades them (header comment).
void check_exterior_geometry(const engine::Scene& scene, std::vector<Diagnostic>& warnings) {
  const SceneDescription& description = scene.description();
  const engine::PortSet& ports = scene.ports();
  // An element: a box's or a room's faces and a RADIANCE primitive's or an HBJSON object's
  // triangles share its location; an OBJ face names its mesh before ':'.
  auto element_of = [](const Surface& s) {
    const std::size_t colon = s.name.find(':');
    if (s.origin == SurfaceOrigin::Mesh && colon != std::string::npos) return "mesh " + s.name.substr(0, colon);
    return s.location.known() ? s.location.to_string() : "surface " + s.name;
  };
  // An opening: the ports written as one element (a window; a light pipe's collector, whose
  // dome facets are ports of their own), its view the area-weighted mean of theirs.
  std::map<std::string, std::vector<std::size_t>> openings;
  for (std::size_t k = 0; k < ports.size(); ++k)
    openings[ports[k].location.known() ? ports[k].location.to_string() : "port " + ports[k].name].push_back(k);

  constexpr int Strata = 4, Directions = 16;
  static_assert(Strata * Strata == ExteriorViewPoints && Directions * Directions == ExteriorViewDirections,
                "square lattices of points and directions");
  const double rays = double(ExteriorViewPoints) * ExteriorViewDirections;
  struct Share {
    double fraction = 0;  ///< of the opening's outward view
    int surface = -1;     ///< the element's first surface seen
  };
  // Per port: element -> its share of the port's outward view.
  auto port_view = [&](std::size_t k) {
    std::map<std::string, Share> view;
    const Vec3 outward = ports[k].normal * -1.0;
    for (int i = 0; i < Strata; ++i)
      for (int j = 0; j < Strata; ++j) {
        const Vec3 p = ports.sample(k, (i + 0.5) / Strata, (j + 0.5) / Strata).position;
        for (int a = 0; a < Directions; ++a)
          for (int b = 0; b < Directions; ++b) {
            const Vec3 d = cosine_direction(outward, a, b, Directions);
            const std::optional<engine::Hit> hit = scene.intersect(engine::Ray{scene.offset_ray_origin(p, outward, d), d});
            if (!hit || hit->port >= 0 || hit->scatterer >= 0) continue;
            const Surface& s = description.surfaces[static_cast<std::size_t>(hit->surface)];
            if (s.origin == SurfaceOrigin::System) continue;
            if (!sends_light(description.materials[static_cast<std::size_t>(s.material)])) continue;
            Share& e = view[element_of(s)];
            e.fraction += 1 / rays;
            if (e.surface < 0 || hit->surface < e.surface) e.surface = hit->surface;
          }
      }
    return view;
  };
  // Per element: the largest share of an opening's view, that opening's first port.
  struct Seen {
    Share share;
    std::size_t port = 0, ports = 1;
  };
  std::map<std::string, Seen> seen;
  for (const auto& [opening, members] : openings) {
    double area_m2 = 0;
    for (std::size_t k : members) area_m2 += ports[k].area_m2;
    std::map<std::string, Share> view;
    for (std::size_t k : members)
      for (const auto& [element, share] : port_view(k)) {
        Share& e = view[element];
        e.fraction += share.fraction * ports[k].area_m2 / area_m2;
        if (e.surface < 0 || share.surface < e.surface) e.surface = share.surface;
      }
    for (const auto& [element, share] : view) {
      Seen& e = seen[element];
      if (share.fraction > e.share.fraction) e = {share, members.front(), members.size()};
    }
  }
  std::vector<Seen> named;
  for (const auto& [element, e] : seen)
    if (e.share.fraction >= ExteriorViewWarnFraction) named.push_back(e);
  std::sort(named.begin(), named.end(), [](const Seen& a, const Seen& b) { return a.share.surface < b.share.surface; });
  for (const Seen& e : named) {
    const Surface& s = description.surfaces[static_cast<std::size_t>(e.share.surface)];
    const std::string port = "port '" + ports[e.port].name + "'" +
                             (e.ports > 1 ? " and the " + std::to_string(e.ports - 1) + " others written with it" : "");
    warnings.push_back(warning_at(
        s.location, "'" + s.name + "' lies outside " + port + " and fills " + percent(e.share.fraction) + " of " +
                        (e.ports > 1 ? "their" : "its") + " outward view (cosine-weighted" +
                        (e.ports > 1 ? ", by area" : "") + "): its shadow is traced, but not the light it reflects "
                        "or transmits toward the port, so the sensors read low (a 0.4 m window reveal of reflectance "
                        "0.8: 13 % on the reference office). " + tracing_remedy(s, description)));
  }
}

}  // namespace

std::size_t PlacementCheck::dropped() const {
  std::size_t n = 0;
  for (const SensorSetPlacement& s : sets)
    if (s.dropped) n += s.outside + s.inside_solid + s.on_cut + s.enclosed;
  return n;
}

std::string describe_port_facing(const engine::Scene& scene, std::size_t index) {
  const engine::Port& port = scene.ports()[index];
  const std::string side = port.against_winding ? "against its vertex order" : "along its vertex order";
  switch (port.side_reason) {
    case engine::PortSideReason::Generated: return "into the room (generated)";
    case engine::PortSideReason::Sky:
      return "into the room " + side + " (facing: auto; " + sky_fractions(port) + ")";
    case engine::PortSideReason::Declared:
      return "into the room " + side + " (facing: " + (port.against_winding ? "out" : "in") + "; " +
             sky_fractions(port) + ")";
    case engine::PortSideReason::Ambiguous: return "undecided (" + sky_fractions(port) + ")";
    case engine::PortSideReason::Contradicted: return "contradicted (" + sky_fractions(port) + ")";
  }
  return "";
}

PlacementCheck check_placement(const engine::Scene& scene, std::vector<SensorGrid>& grids,
                               const project::Project& proj) {
  Diagnostics diag;
  const SourceLocation project{proj.path, 1, 1};
  const SceneDescription& description = scene.description();
  const ModelFrame frame{description, proj.site.rotation_to_true_north_deg()};
  const std::vector<engine::Material> materials = engine::materials_of(description.materials);
  if (scene.ports().empty())
    report(diag, project,
           "the project has no photon port: no light can enter (add a window to a room, a polygon or mesh with "
           "'port: true', or a daylight system with its own port)");
  for (std::size_t k = 0; k < scene.ports().size(); ++k) {
    const engine::Port& port = scene.ports()[k];
    const Surface& surface = description.surfaces[static_cast<std::size_t>(port.surface)];
    if (port.side_reason == engine::PortSideReason::Ambiguous) {
      const bool both = port.sky_fraction_winding > 0 && port.sky_fraction_opposite > 0;
      report(diag, surface.location,
             "port '" + surface.name + "': cannot tell which side is the room: " +
                 (both ? "both sides see the sky" : "neither side sees the sky") + " (" + sky_fractions(port) +
                 "); say 'facing: in' (its normal by the vertex order points into the room) or 'facing: out'");
    } else if (port.side_reason == engine::PortSideReason::Contradicted) {
      report(diag, surface.location,
             "port '" + surface.name + "': 'facing: " + (port.against_winding ? "out" : "in") +
                 "' puts the room on the side that sees the sky (" + sky_fractions(port) + "); use 'facing: " +
                 (port.against_winding ? "in" : "out") + "' or 'facing: auto'");
    }
  }

  PlacementCheck out;
  for (SensorGrid& grid : grids) {
    SensorSetPlacement set;
    set.name = grid.name;
    set.sensors = grid.points.size();
    const std::vector<engine::SensorPlacementTest> tests = engine::test_sensor_placements(scene, grid.points);
    const std::vector<bool> on_cut = on_cut_flags(scene, grid);
    std::vector<std::size_t> bad;
    for (std::size_t i = 0; i < tests.size(); ++i) {
      if (tests[i].placement == engine::SensorPlacement::InRoom) {
        if (!on_cut[i]) continue;
        ++set.on_cut;
      } else {
        const engine::SensorPlacement p = tests[i].placement;
        (p == engine::SensorPlacement::OutsideRooms  ? set.outside
         : p == engine::SensorPlacement::InsideSolid ? set.inside_solid
                                                     : set.enclosed)++;
      }
      bad.push_back(i);
    }
    if (!bad.empty()) {
      std::ostringstream m;
      m << "sensor set '" << grid.name << "': " << bad.size() << " of " << grid.points.size() << " sensors lie ";
      const std::vector<std::pair<std::size_t, std::string>> kinds = {
          {set.outside, "outside every room"},
          {set.inside_solid, "inside a solid"},
          {set.enclosed, EnclosedWords},
          {set.on_cut, OnCutWords}};
      const bool several = (set.outside > 0) + (set.inside_solid > 0) + (set.enclosed > 0) + (set.on_cut > 0) > 1;
      std::size_t named = 0;
      for (const auto& [count, words] : kinds)
        if (count > 0) m << (named++ > 0 ? " or " : "") << words << (several ? " (" + std::to_string(count) + ")" : "");
      m << " (";
      for (std::size_t j = 0; j < bad.size() && j < PlacementExamples; ++j) {
        const std::size_t i = bad[j];
        const engine::SensorPlacementTest& t = tests[i];
        if (j > 0) m << "; ";
        m << "sensor " << i << " at " << frame.text(grid.points[i].position)
          << " m ";
        if (t.placement == engine::SensorPlacement::InRoom) {
          m << "lies on a column's or a partition's face";
        } else if (t.placement == engine::SensorPlacement::OutsideRooms) {
          m << "sees the sky without a port in " << percent(double(t.sky_without_port) / t.rays) << " of its "
            << "hemisphere";
        } else if (t.placement == engine::SensorPlacement::Enclosed && t.same_volume_as >= 0) {
          m << "sees sensor " << t.same_volume_as << ", which reaches no port";
        } else if (t.placement == engine::SensorPlacement::Enclosed) {
          m << "reaches no port by " << t.enclosure_walks << " random paths of up to "
            << engine::SensorEnclosureBounces << " bounces";
        } else {
          m << "sees only the back of '" << description.surfaces[static_cast<std::size_t>(t.solid_surface)].name
            << "' and other solids' faces";
        }
      }
      if (bad.size() > PlacementExamples) m << "; ...";
      m << ")";
      if (set.outside > 0) m << pts_units_hint(scene, grid, proj);
      set.description = m.str();
      if (grid.drop_occluded) {
        set.dropped = true;
        set.description += ": dropped (drop_occluded)";
        // On a surface the placement rays call in a room: a located warning too (header comment).
        if (set.on_cut > 0)
          out.warnings.push_back(warning_at(grid.location, set.description + "; " + OnCutWhy));
        std::vector<SensorPoint> kept;
        std::vector<double> kept_area_m2;  // a dropped sensor's area leaves with it
        kept.reserve(grid.points.size() - bad.size());
        std::size_t j = 0;
        for (std::size_t i = 0; i < grid.points.size(); ++i) {
          if (j < bad.size() && bad[j] == i) {
            ++j;
            continue;
          }
          kept.push_back(grid.points[i]);
          if (!grid.area_m2.empty()) kept_area_m2.push_back(grid.area_m2[i]);
        }
        grid.points = std::move(kept);
        grid.area_m2 = std::move(kept_area_m2);
        grid.columns = grid.rows = 0;
        if (grid.points.empty())
          report(diag, grid.location,
                 set.description + "; no sensor is left: a set needs at least one sensor in a room");
      } else {
        report(diag, grid.location,
               set.description +
                   (set.on_cut == bad.size() ? "; " + std::string(OnCutWhy) + ". Move the grid (its inset or spacing) off "
                                               "the surface, or give the set 'drop_occluded: true' to leave them out"
                                             : std::string("; they would read (almost) no light") +
                                                   (set.on_cut > 0 ? std::string(", and ") + OnCutWhy : std::string()) +
                                                   ". Move them into a room, or give the set 'drop_occluded: true' "
                                                   "to leave them out"));
      }
    }
    check_sky_through_gaps(grid, tests, frame, out.warnings);
    check_outline(scene, grid, frame, out.warnings);
    check_glazing_over_plane(scene, materials, grid, frame, out.warnings);
    out.sets.push_back(std::move(set));
  }
  // Sensors next to a cut, gathered or not as the run decides (CaseLayout::of).
  std::vector<NearCutSensors> near;
  std::vector<std::size_t> near_count, planar_sensors;
  bool surface_photons_kept = false;
  for (const SensorGrid& grid : grids) {
    surface_photons_kept = surface_photons_kept || !grid.planar;
    near.push_back(near_cut_sensors_of(scene, grid));
    near_count.push_back(near.back().count);
    planar_sensors.push_back(grid.points.size());
  }
  const std::vector<bool> gathered = near_cut_gathered(near_count, planar_sensors, surface_photons_kept);
  std::vector<std::vector<std::size_t>> near_cut_rows(grids.size());
  for (std::size_t g = 0; g < grids.size(); ++g) {
    report_near_cuts(grids[g], near[g], gathered[g], frame, out);
    if (gathered[g]) near_cut_rows[g] = near[g].sensors;
  }
  check_exterior_geometry(scene, out.warnings);
  check_gather_outside_region(scene, grids, near_cut_rows, proj, out.warnings);
  if (proj.study == project::StudyKind::Annual && proj.outputs.metrics) {
    const DaylightOpenings model = daylight_openings(scene);
    out.openings = grid_daylight_openings(scene, engine::materials_of(description.materials), grids, model);
    daylight_openings_diagnostics(grids, model, out.openings, out.warnings, out.notes);
  }
  if (grids.empty())
    report(diag, project, "the project has no sensors: add a grid or a point set under 'sensors'");
  diag.throw_if_errors();
  return out;
}

void check_project_placement(const project::Project& project) {
  auto check_case = [](const project::Project& p) {
    SceneDescription description = project::build_scene_description(p);
    const engine::Scene scene = engine::Scene::build(description);
    check_placement(scene, description.grids, p);
  };
  check_case(project);
  for (const project::VariantSpec& v : project.variants) check_case(project::apply_variant(project, v));
}

}  // namespace dayphoton::study
