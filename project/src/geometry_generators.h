// Internal interface of the geometry stage (Project -> SceneDescription, see project.h):
// one generator per kind of project geometry, all working in MODEL coordinates (the north
// rotation is applied once, by build_scene_description, afterwards). Generators report
// every problem located into a Diagnostics and skip what they cannot build.
#pragma once

#include <set>
#include <string>
#include <vector>

#include "dayphoton/core/diagnostics.h"
#include "dayphoton/core/scene_description.h"
#include "dayphoton/project/project.h"
#include "window_frame.h"

namespace dayphoton::project::detail {

/// Resolves project material names to indices into SceneDescription::materials, reporting
/// unknown names (with a "did you mean") at the referring location.
class MaterialLookup {
 public:
  MaterialLookup(std::vector<MaterialSpec>& materials, Diagnostics& diag);
  /// Index of `name`, or -1 after reporting an error naming `what` (e.g. "floor material of
  /// room 'office'").
  int resolve(const std::string& name, const SourceLocation& where, const std::string& what);
  /// The definition of material `index` (a valid index from resolve()).
  const MaterialSpec& spec(int index) const { return m_materials[static_cast<std::size_t>(index)]; }
  /// Index of material `index` with its transmitted light scaled by `factor`: `index` itself
  /// for a factor of 1, otherwise a copy named "<name> x <factor>" appended to the scene's
  /// materials once per (material, factor). Not resolvable by name from the project file.
  int with_transmittance_factor(int index, double factor);

 private:
  std::vector<MaterialSpec>& m_materials;
  std::vector<std::string> m_names;
  Diagnostics& m_diag;
};

/// Report an error, quoting the source line when the location names a readable file.
void report(Diagnostics& diag, const SourceLocation& where, const std::string& message);

/// An opening that an adjoining room's interior window cuts into a wall of this room, in
/// this room's wall frame (interior_windows.cpp).
struct WallHole {
  Wall wall = Wall::South;
  WallRect rect;
};

/// What daylight systems and adjoining rooms change in a room (system_generators.h,
/// interior_windows.cpp).
struct RoomCutouts {
  /// Convex polygons in the ceiling plane (light-pipe openings), each containing the
  /// centroid of its vertices; inside the ceiling and apart (the systems check).
  std::vector<std::vector<Vec3>> ceiling_holes;
  /// What cut each of ceiling_holes ("light_pipe 'pipe'"), for messages.
  std::vector<std::string> ceiling_hole_owners;
  /// Windows inside an exterior system's port enclosure, and interior windows: glazing,
  /// but not ports.
  std::set<std::string> windows_without_port;
  /// Interior windows of adjoining rooms: cut out of this room's walls too.
  std::vector<WallHole> wall_holes;
};

/// Room box (normals into the room) with its windows cut out of the named walls; each
/// window becomes a glazing Surface with port = true (unless `cutouts` says otherwise) and
/// its normal into the room; the walls also have the cutouts' wall holes, the ceiling the
/// cutouts' openings and the roof lights' (generate_roof_lights).
void generate_room(const RoomSpec& room, const RoomCutouts& cutouts, MaterialLookup& materials,
                   Diagnostics& diag, std::vector<Surface>& out);

/// The material of room window `w`: its glazing with the window's frame factor times its
/// maintenance factor applied (MaterialLookup::with_transmittance_factor), or -1 after
/// reporting an error: an unknown material, or factors on a material that does not transmit
/// straight through (only glass, glazing and opening do). `what` names the window.
int window_material(const WindowSpec& w, const std::string& what, MaterialLookup& materials,
                    Diagnostics& diag);

/// A rectangle of a room's ceiling: x in [x0, x1], y in [y0, y1], room coordinates (from
/// the room's origin corner).
struct CeilingRect {
  double x0 = 0, x1 = 0, y0 = 0, y1 = 0;
};

/// The roof lights of `room` (roof_light_generator.cpp): each valid one (inside the ceiling,
/// apart from the others and from the light-pipe openings in `cutouts`) adds its glazing (a
/// port, normal down) and the walls of its light well to `out`, and its opening to the
/// returned list; each invalid one is reported at the offending key and left out.
std::vector<CeilingRect> generate_roof_lights(const RoomSpec& room, const RoomCutouts& cutouts,
                                              MaterialLookup& materials, Diagnostics& diag,
                                              std::vector<Surface>& out);

/// An interior window (interior_windows.cpp): a window of `room` whose rectangle lies in the
/// wall of `adjoining` that coincides with its own wall (same plane, `adjoining` on the far
/// side).
struct InteriorOpening {
  const RoomSpec* room = nullptr;
  const WindowSpec* window = nullptr;
  const RoomSpec* adjoining = nullptr;
  Wall adjoining_wall = Wall::North;
  WallRect rect_in_adjoining;  ///< the window in the adjoining room's wall frame
};

/// Every interior window of `rooms`, in file order. With `diag`, reports (at the window) a
/// window that lies partly in another room's wall, and two interior windows that overlap
/// (the same opening defined from both rooms). Windows that do not fit their own wall are
/// left to generate_room.
std::vector<InteriorOpening> find_interior_windows(const std::vector<RoomSpec>& rooms, Diagnostics* diag);

/// The rooms whose daylight all comes through interior windows: each has at least one
/// interior window (its own or another room's into it) and no photon port of its own (no
/// exterior window, roof light, light pipe, nor a port polygon whose centroid lies inside
/// it). Their light on a work plane is the borrowed windows' footprint, made of photons
/// alone and sparse, which a receiver plane's kernel blurs (docs/photon-map.md, "Rooms lit
/// only through interior windows").
std::set<std::string> rooms_lit_only_through_interior_windows(const Geometry& geometry);

/// The room of `borrowed` that planar grid `grid` (made from `spec`) lies in: a room grid's
/// room, or the first of them holding a sensor of a polygon grid; "" if none.
std::string borrowed_light_room_of(const GridSpec& spec, const SensorGrid& grid, const std::vector<RoomSpec>& rooms,
                                   const std::set<std::string>& borrowed);

/// Axis-aligned box rotated about +Z (counter-clockwise for positive rotation_deg) around
/// its origin corner; six faces with outward normals.
void generate_box(const BoxSpec& box, MaterialLookup& materials, Diagnostics& diag,
                  std::vector<Surface>& out);

/// One Surface per OBJ face, transformed by scale, rotation about +Z and translation.
void generate_mesh(const MeshSpec& mesh, MaterialLookup& materials, Diagnostics& diag,
                   std::vector<Surface>& out);

/// The surfaces of a RADIANCE scene (radiance_scene.h; radiance_generator.cpp): its files
/// read in order, its materials appended to `scene_materials` (a project material of the
/// same name among the first `project_material_count` is used instead), its glazing made
/// port candidates (`ports: auto`) or the surfaces of the listed modifiers made ports.
void generate_radiance(const RadianceSceneSpec& spec, std::size_t project_material_count,
                       std::vector<MaterialSpec>& scene_materials, Diagnostics& diag,
                       std::vector<Surface>& out);

/// Check one surface: at least 3 finite vertices, non-zero area, planar within
/// 1e-3 m x max(1, size), simple enough to triangulate.
void validate_surface(const Surface& surface, Diagnostics& diag);

/// Sensor grid over a room's floor rectangle, a polygon, a room surface or a rectangle
/// (model coordinates). Returns false (after reporting) when the spec is invalid, yields no
/// point, or would yield more than `max_points` (limits.sensors_per_grid; reported at
/// `spacing` before any point is made).
bool generate_grid(const GridSpec& spec, const std::vector<RoomSpec>& rooms, std::uint64_t max_points,
                   Diagnostics& diag, SensorGrid& out);

/// The wall and rectangle grids of generate_grid (surface_grid.cpp), with the same limit.
bool generate_surface_grid(const GridSpec& spec, const std::vector<RoomSpec>& rooms, std::uint64_t max_points,
                           Diagnostics& diag, SensorGrid& out);

/// Number of lattice points over `span_m` at `spacing_m` (0 if the span is negative) and,
/// in `first_m`, the first point's distance from the span's start, so that the lattice is
/// centred in the span (sensor_grid.cpp). A double: a tiny spacing over a huge span gives more
/// points than any integer type holds, so callers check it against their limit before
/// converting it.
double lattice(double span_m, double spacing_m, double& first_m);

/// "<what> would have N sensors, more than limits.sensors_per_grid (...)".
std::string limit_message(const std::string& what, double count, std::uint64_t max_points);

/// Reports a spacing that is not positive and finite, or an inset that is negative or not
/// finite, at their keys; false if it reported.
bool check_spacing_and_inset(const GridSpec& spec, const std::string& what, Diagnostics& diag);

/// The room named `name`, or nullptr after reporting "<what>: unknown room" with a hint.
const RoomSpec* find_grid_room(const std::string& name, const std::vector<RoomSpec>& rooms, Diagnostics& diag,
                               const SourceLocation& where, const std::string& what);

/// Sensor points given inline and/or in a .pts file, at most `max_points` of them.
bool generate_points(const PointsSpec& spec, std::uint64_t max_points, Diagnostics& diag, SensorGrid& out);

}  // namespace dayphoton::project::detail
