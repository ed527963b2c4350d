// build_scene_description: Project -> SceneDescription (the geometry stage of project.h).
//
// Order: materials are copied; daylight systems are generated (system_generators.h; an
// `opening` material is appended for port enclosures), interior windows are found
// (interior_windows.cpp; a system outside one is an error), then rooms (windows cut out,
// glazing as ports unless an enclosure took over or the window is interior, interior windows
// of adjoining rooms cut out too, light-pipe and roof-light openings in ceilings), free
// polygons, boxes, OBJ meshes, RADIANCE scenes (radiance_generator.cpp) and the systems' surfaces,
// all in model coordinates and validated (finite vertices,
// non-zero area, planarity within 1e-3 m x max(1, size) where size is the largest extent of
// the polygon's bounding box, triangulable); sensor grids and point sets are generated;
// finally every position and direction is rotated to world coordinates by the site's
// rotation_to_true_north_deg (convention: north_rotation.h). All problems are collected and
// thrown together as one InputError.
#include "dayphoton/core/diagnostics.h"
#include "dayphoton/project/project.h"

#include <algorithm>
#include <cmath>
#include <set>
#include <stdexcept>

#include "dayphoton/core/polygon.h"
#include "dayphoton/engine/bsdf_material.h"
#include "dayphoton/project/local_origin.h"
#include "dayphoton/project/north_rotation.h"
#include "geometry_generators.h"
#include "system_generators.h"

namespace dayphoton::project {

namespace detail {

void report(Diagnostics& diag, const SourceLocation& where, const std::string& message) {
  std::string line;
  if (where.known() && !diag.at_cap()) line = read_source_line(where.file, where.line);
  diag.error(where, message, line);
}

MaterialLookup::MaterialLookup(std::vector<MaterialSpec>& materials, Diagnostics& diag)
    : m_materials(materials), m_diag(diag) {
  for (const MaterialSpec& m : materials) m_names.push_back(m.name);
}

int MaterialLookup::resolve(const std::string& name, const SourceLocation& where,
                            const std::string& what) {
  for (std::size_t i = 0; i < m_materials.size(); ++i)
    if (m_materials[i].name == name) return static_cast<int>(i);
  std::string message = name.empty() ? "no material given for " + what
                                     : "unknown material '" + name + "' for " + what;
  const std::string hint = name.empty() ? std::string() : closest_match(name, m_names);
  if (!hint.empty()) message += " (did you mean '" + hint + "'?)";
  report(m_diag, where, message);
  return -1;
}

void validate_surface(const Surface& surface, Diagnostics& diag) {
  const std::string what = "surface '" + surface.name + "'";
  if (surface.vertices.size() < 3) {
    report(diag, surface.location,
           what + " has " + std::to_string(surface.vertices.size()) + " vertices; a polygon needs at least 3");
    return;
  }
  for (std::size_t i = 0; i < surface.vertices.size(); ++i)
    if (!is_finite(surface.vertices[i])) {
      report(diag, surface.location, what + ": vertex " + std::to_string(i + 1) + " is not finite (NaN or Inf)");
      return;
    }
  Vec3 lo = surface.vertices[0], hi = surface.vertices[0];
  for (const Vec3& p : surface.vertices)
    for (int k = 0; k < 3; ++k) {
      lo[k] = std::min(lo[k], p[k]);
      hi[k] = std::max(hi[k], p[k]);
    }
  const double size_m = std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z});
  const double area_m2 = polygon_area_m2(surface.vertices);
  if (polygon_normal(surface.vertices) == Vec3{0, 0, 0} || area_m2 < 1e-10) {
    report(diag, surface.location, what + " is degenerate (zero area)");
    return;
  }
  const double deviation_m = planarity_deviation_m(surface.vertices);
  const double tolerance_m = 1e-3 * std::max(1.0, size_m);
  if (deviation_m > tolerance_m) {
    report(diag, surface.location,
           what + " is not planar: a vertex is " + format_number(deviation_m) +
               " m from the mean plane (tolerance " + format_number(tolerance_m) + " m)");
    return;
  }
  try {
    (void)triangulate_polygon(surface.vertices);
  } catch (const std::invalid_argument& e) {
    report(diag, surface.location, what + " cannot be triangulated: " + e.what());
  }
}

}  // namespace detail

namespace {

void generate_polygon(const PolygonSpec& spec, detail::MaterialLookup& materials,
                      std::vector<Surface>& out) {
  Surface s;
  s.name = spec.name;
  s.material = materials.resolve(spec.material, spec.location, "polygon '" + spec.name + "'");
  s.vertices = spec.vertices;
  s.port = spec.port;
  s.facing = spec.facing;
  s.outdoor_scatterer = spec.outdoor;
  s.location = spec.location;
  out.push_back(std::move(s));
}

/// The surfaces of an imported Honeybee model (honeybee_model.h): apertures in Outdoors faces
/// are ports whose normal points out of the room (Honeybee's faces point outward), tested
/// against the scene like a polygon declared `facing: out` (orphaned ones: `facing: auto`);
/// outdoor shades are outdoor scatterers, like the parts of exterior systems with
/// `port: system`. A project `bsdf` material that a variant puts in an opening's modifier's
/// place turns the opening round as the model's own BSDF modifier does (its front outdoors:
/// honeybee_bsdf_refusal, turn_for_bsdf), and is refused where that one would be.
void generate_honeybee(const HoneybeeImport& hb, detail::MaterialLookup& materials, std::vector<Surface>& out,
                       Diagnostics& diag) {
  for (const HoneybeeSurface& hs : hb.model.surfaces) {
    Surface s;
    s.name = hs.name;
    s.material = materials.resolve(hs.material, hs.location, hs.path + " ('" + hs.name + "')");
    s.vertices = hs.vertices;
    s.location = hs.location;
    s.port = hs.role == HoneybeeRole::Port;
    PortFacing facing = hs.facing;
    if (s.material >= 0 && engine::bsdf_parameters(materials.spec(s.material))) {
      if (const char* why = honeybee_bsdf_refusal(hs.role, hs.facing)) {
        detail::report(diag, hs.location,
                       hs.path + " ('" + hs.name + "') has BSDF material '" + hs.material + "': " + why);
        continue;
      }
      turn_for_bsdf(s.vertices, facing);
    }
    if (s.port) s.facing = facing;
    s.outdoor_scatterer = hs.role == HoneybeeRole::OutdoorShade;
    out.push_back(std::move(s));
  }
}

bool written(const SystemSpec& sys, const std::string& key) {
  for (const auto& kv : sys.key_locations)
    if (kv.first == key) return true;
  return false;
}

void rotate_scene(SceneDescription& scene, double north_deg) {
  if (north_deg == 0) return;
  for (Surface& s : scene.surfaces)
    for (Vec3& v : s.vertices) v = model_to_world(v, north_deg);
  for (SensorGrid& g : scene.grids) {
    for (SensorPoint& p : g.points) {
      p.position = model_to_world(p.position, north_deg);
      p.normal = model_to_world(p.normal, north_deg);
    }
    for (Vec3& v : g.outline) v = model_to_world(v, north_deg);
    g.plane_normal = model_to_world(g.plane_normal, north_deg);
    // A rotation about the origin keeps the plane's distance along its (rotated) normal.
  }
  // A measured BSDF's up vector is a direction of the model, turned with its geometry.
  for (MaterialSpec& m : scene.materials)
    if (const engine::BsdfMaterialParameters* bsdf = engine::bsdf_parameters(m)) {
      auto turned = std::make_shared<engine::BsdfMaterialParameters>(*bsdf);
      turned->up = model_to_world(bsdf->up, north_deg);
      m.parameters = std::move(turned);
    }
}

}  // namespace

SceneDescription build_scene_description(const Project& project) {
  Diagnostics diag;
  SceneDescription scene;
  scene.materials = project.materials;
  detail::MaterialLookup materials(scene.materials, diag);

  const double north_deg = project.site.rotation_to_true_north_deg();
  if (!std::isfinite(north_deg))
    detail::report(diag, project.site.location, "site north angle is not finite");

  const Geometry& g = project.geometry;
  // Systems first: they decide what rooms look like (ceiling openings, windows that stop
  // being ports inside an enclosure); their surfaces come after the meshes.
  detail::SystemOutput systems;
  detail::generate_systems(project, materials, scene.materials, diag, systems);
  // Interior windows: glazing, not ports, cut out of the adjoining room's wall too. A system
  // outside such a window would stand in the adjoining room (and an enclosure's ports there).
  for (const detail::InteriorOpening& i : detail::find_interior_windows(g.rooms, &diag)) {
    systems.rooms[i.room->name].windows_without_port.insert(i.window->name);
    systems.rooms[i.adjoining->name].wall_holes.push_back({i.adjoining_wall, i.rect_in_adjoining});
    for (const SystemSpec& sys : g.systems)
      if (sys.enabled && sys.mount.window == i.window->name && sys.mount.side == MountSide::Exterior &&
          !std::holds_alternative<LightPipeSpec>(sys.params))
        detail::report(diag, sys.location_of(written(sys, "side") ? "side" : "window"),
                       std::string(sys.type_name()) + " '" + sys.name + "' is outside window '" + i.window->name +
                           "', an interior window: outside is room '" + i.adjoining->name +
                           "'; mount it inside (side: interior) or model it in that room");
  }
  std::vector<Surface> surfaces;
  // Each generator's surfaces are marked with their origin once they are all made.
  std::size_t marked = 0;
  auto mark = [&](SurfaceOrigin origin) {
    for (; marked < surfaces.size(); ++marked) surfaces[marked].origin = origin;
  };
  static const detail::RoomCutouts unchanged;
  for (const RoomSpec& room : g.rooms) {
    const auto cut = systems.rooms.find(room.name);
    detail::generate_room(room, cut == systems.rooms.end() ? unchanged : cut->second, materials,
                          diag, surfaces);
  }
  mark(SurfaceOrigin::Room);
  for (const PolygonSpec& poly : g.polygons) generate_polygon(poly, materials, surfaces);
  mark(SurfaceOrigin::Polygon);
  for (const BoxSpec& box : g.boxes) detail::generate_box(box, materials, diag, surfaces);
  mark(SurfaceOrigin::Box);
  for (const MeshSpec& mesh : g.meshes) detail::generate_mesh(mesh, materials, diag, surfaces);
  mark(SurfaceOrigin::Mesh);
  for (const RadianceSceneSpec& rad : g.radiance)
    detail::generate_radiance(rad, project.materials.size(), scene.materials, diag, surfaces);
  mark(SurfaceOrigin::Radiance);
  std::vector<Diagnostic> model_notes;  // the model's notes, which are no warnings (a grid's weighting mesh)
  if (g.honeybee) {
    generate_honeybee(*g.honeybee, materials, surfaces, diag);
    for (const Diagnostic& w : g.honeybee->model.warnings) {
      if (w.severity == Severity::Note) model_notes.push_back(w);
      else diag.warning(w.location, w.message, w.source_line);
    }
  }
  mark(SurfaceOrigin::Honeybee);
  surfaces.insert(surfaces.end(), systems.surfaces.begin(), systems.surfaces.end());
  mark(SurfaceOrigin::System);
  for (const Surface& s : surfaces) detail::validate_surface(s, diag);
  scene.surfaces = std::move(surfaces);

  std::set<std::string> sensor_names;
  auto check_name = [&](const std::string& name, const SourceLocation& where) {
    if (!sensor_names.insert(name).second)
      detail::report(diag, where, "sensor set name '" + name + "' is used twice (names must be unique: each gets its own output folder)");
  };
  // All sensor sets together: at most limits.sensors, reported at the set that passes it.
  std::uint64_t sensor_count = 0;
  bool over_total = false;
  auto add_sensors = [&](SensorGrid&& grid) {
    sensor_count += grid.points.size();
    if (sensor_count > project.limits.sensors && !over_total) {
      over_total = true;
      detail::report(diag, grid.location,
                     "sensor set '" + grid.name + "' brings the project to " + std::to_string(sensor_count) +
                         " sensors, " + over_limit_text(project.limits.sensors, "limits.sensors"));
    }
    if (!over_total) scene.grids.push_back(std::move(grid));
  };
  // A work plane over a room whose light all comes through interior windows is estimated by
  // final gather at its sensors, not as a receiver plane: the windows' footprint there is
  // photons alone, sparse, and the kernel's disc blurred it (the shipped corridor read -11 to
  // +6 % against a backward reference; docs/photon-map.md, "Rooms lit only through interior
  // windows"): a room grid over such a room, or a polygon grid with a sensor in one. With
  // point_estimate: surface it cannot be (its sensors lie in mid air): a warning.
  const std::set<std::string> borrowed = detail::rooms_lit_only_through_interior_windows(g);
  for (const GridSpec& spec : project.sensors.grids) {
    check_name(spec.name, spec.location);
    SensorGrid grid;
    if (!detail::generate_grid(spec, g.rooms, project.limits.sensors_per_grid, diag, grid)) continue;
    const std::string room = grid.planar ? detail::borrowed_light_room_of(spec, grid, g.rooms, borrowed) : "";
    if (!room.empty()) {
      const std::string key = spec.room.empty() ? "polygon" : "room";
      const std::string what = "grid '" + spec.name + "' " + (spec.room.empty() ? "has sensors in" : "covers") +
                               " room '" + room + "', whose daylight all comes through interior windows";
      if (project.simulation.point_estimate == PointEstimate::Gather) {
        grid.planar = false;
        grid.plane_height_m = 0;
        model_notes.push_back({Severity::Note, spec.location_of(key),
                               what + ": its sensors are estimated by final gather, not as a receiver plane (a plane's "
                                      "kernel blurs those windows' light)",
                               {}});
      } else {
        diag.warning(spec.location_of(key),
                     what + ": with simulation.point_estimate: surface it stays a receiver plane, whose kernel blurs "
                            "those windows' light (measured up to 11 % low beside them); remove point_estimate: surface "
                            "to estimate it by final gather");
      }
    }
    add_sensors(std::move(grid));
  }
  for (const PointsSpec& spec : project.sensors.points) {
    check_name(spec.name, spec.location);
    SensorGrid grid;
    if (detail::generate_points(spec, project.limits.sensors_per_grid, diag, grid)) add_sensors(std::move(grid));
  }

  if (const auto& roi = project.simulation.region_of_interest) {
    // Photons are stored only inside the box: a sensor outside it would get none.
    const Vec3 lo = roi->origin_m, hi = roi->origin_m + roi->size_m;
    constexpr double Tolerance_m = 1e-9;
    for (const SensorGrid& grid : scene.grids)
      for (std::size_t i = 0; i < grid.points.size(); ++i) {
        const Vec3& p = grid.points[i].position;
        bool inside = true;
        for (int k = 0; k < 3; ++k) inside = inside && p[k] >= lo[k] - Tolerance_m && p[k] <= hi[k] + Tolerance_m;
        if (inside) continue;
        detail::report(diag, roi->location,
                       "simulation.region_of_interest: sensor " + std::to_string(i) + " of '" + grid.name + "' at (" +
                           format_coordinate(p.x) + ", " + format_coordinate(p.y) + ", " + format_coordinate(p.z) +
                           ") m lies outside the box; no photon would be stored for its estimates");
        break;  // one message per grid
      }
  }
  diag.throw_if_errors();
  for (const Diagnostic& d : diag.entries())
    if (d.severity == Severity::Warning) scene.warnings.push_back(d);
  scene.warnings.insert(scene.warnings.end(), model_notes.begin(), model_notes.end());
  rotate_scene(scene, north_deg);
  // Survey coordinates near (0, 0, 0) before anything becomes a float (local_origin.h).
  move_to_local_origin(scene);
  return scene;
}

}  // namespace dayphoton::project
