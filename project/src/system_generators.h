// Internal interface of the daylight-system generators (docs/daylight-systems.md): each
// system of Project::geometry.systems becomes surfaces in MODEL coordinates (the north
// rotation is applied afterwards, with everything else, by build_scene_description).
//
// generate_systems (system_generators.cpp) dispatches to one generator per type (one file
// each group: projection_generators.cpp for light shelves, overhangs and fins,
// blinds_generator.cpp, prism_panel_generator.cpp for prismatic and lamella panels,
// cpc_generator.cpp, light_pipe_generator.cpp), then checks that a window-mounted system
// stays on its side of the wall (inside the room, or outside it) and builds the port
// enclosures of exterior systems with `port: enclosure`. What the systems change in rooms
// (ceiling openings, windows that stop being ports) is returned per room for the room
// generator.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "dayphoton/core/diagnostics.h"
#include "dayphoton/core/scene_description.h"
#include "dayphoton/project/project.h"
#include "geometry_generators.h"
#include "system_geometry.h"
#include "window_frame.h"

namespace dayphoton::project::detail {

/// Name of the `opening` material appended to the scene's materials for port enclosures.
constexpr const char* EnclosureMaterialName = "system port opening";

/// Margin between an enclosure and what it encloses, m: keeps its faces off the system's
/// and the window's own faces (coplanar surfaces are ambiguous to a ray tracer).
constexpr double EnclosureMargin_m = 0.01;

/// Gap between a slab's wall-side face and the wall plane, m (a closed slab must not share
/// a plane with the wall or the glazing).
constexpr double WallStandoff_m = 0.001;

struct SystemOutput {
  std::vector<Surface> surfaces;
  std::map<std::string, RoomCutouts> rooms;  ///< by room name
};

/// Every enabled system of `project`. `scene_materials` is the scene's material list (the
/// one `materials` resolves into): the enclosure material is appended to it when needed.
void generate_systems(const Project& project, MaterialLookup& materials,
                      std::vector<MaterialSpec>& scene_materials, Diagnostics& diag,
                      SystemOutput& out);

/// What a window-mounted generator works with: the system, its window's frame, materials,
/// diagnostics and where its surfaces go.
struct MountedBuild {
  const SystemSpec& spec;
  const WindowFrame& frame;
  MaterialLookup& materials;
  Diagnostics& diag;
  std::vector<Surface>& out;

  /// "blinds 'venetian'": how messages name the system.
  std::string what() const;
  /// Report `message` (prefixed with what()) at the value of `key` (or the system).
  void error(const std::string& key, const std::string& message) const;
  /// Index of material `name` given under `key`, or -1 after reporting it.
  int material(const std::string& key, const std::string& name) const;
  /// Report unless material `index` may be used on open (non-closed) surfaces: a
  /// dielectric is an interface between outside and inside and needs a closed solid.
  bool check_not_dielectric(const std::string& key, int index, const std::string& use) const;
  /// Report unless material `index` is a dielectric.
  bool check_dielectric(const std::string& key, int index) const;
  /// Direction of the room from the wall plane along w: -1 interior, +1 exterior side of a
  /// system's parts (where it is mounted).
  double side_sign() const { return spec.mount.side == MountSide::Interior ? -1.0 : 1.0; }
  /// Heights covered by a panel-like system: its bottom/top keys or the window's sill/head;
  /// false after reporting bottom >= top.
  bool covered_heights(const std::optional<double>& bottom, const std::optional<double>& top,
                       double& v0, double& v1) const;
  /// Profiles in the vertical plane across the wall: x = w, y = v, extruded along u.
  ProfilePlane wv_plane() const { return {frame.origin, frame.e_w, frame.e_v, frame.e_u}; }
  /// Profiles in the horizontal plane: x = u, y = w, extruded along v.
  ProfilePlane uw_plane() const { return {frame.origin, frame.e_u, frame.e_w, frame.e_v}; }
};

// One generator per type; each returns false after reporting what makes it impossible.
bool generate_light_shelf(const MountedBuild& b, const LightShelfSpec& p);
bool generate_overhang(const MountedBuild& b, const OverhangSpec& p);
bool generate_fins(const MountedBuild& b, const FinsSpec& p);
bool generate_blinds(const MountedBuild& b, const BlindsSpec& p);
bool generate_prismatic_panel(const MountedBuild& b, const PrismaticPanelSpec& p);
bool generate_lamella_panel(const MountedBuild& b, const LamellaPanelSpec& p);
bool generate_cpc(const MountedBuild& b, const CpcSpec& p);

/// A light pipe through the ceiling of `room`: tube, diffuser and collector surfaces into
/// `out`, and the ceiling opening into `cutouts`.
bool generate_light_pipe(const SystemSpec& spec, const LightPipeSpec& p, const RoomSpec& room,
                         MaterialLookup& materials, Diagnostics& diag, std::vector<Surface>& out,
                         RoomCutouts& cutouts);

/// The regular polygon of a light pipe (its tube's cross-section) at height z_m:
/// counter-clockwise seen from above, first vertex at angle pi / sides from +x (so that
/// four sides make an axis-aligned square).
std::vector<Vec3> light_pipe_polygon(const LightPipeSpec& p, double z_m);

/// The 2-D profile of one compound parabolic concentrator (Welford & Winston): exit
/// aperture of half width exit_half_m at y = 0, entrance of half width
/// exit_half_m / sin(theta) at y = L = (a + a') cot(theta), axis +y; the right wall is the
/// parabola with focus at the exit's left edge and axis tilted by theta, sampled at
/// `facets` + 1 points from the exit edge to the entrance edge. Returned: the right wall's
/// points, exit to entrance (the left wall is its mirror image x -> -x).
std::vector<P2> cpc_right_wall(double acceptance_angle_rad, double exit_half_m, int facets);

}  // namespace dayphoton::project::detail
