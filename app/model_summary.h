// ModelSummary: what `check` (and the head of `run`) prints about a project: site, weather,
// surfaces and areas per material, ports with orientation, roof lights, interior windows,
// sensor grids. Building it performs
// every validation (weather header, geometry, Embree scene), so a summary exists only for a
// valid model.
#pragma once

#include <iosfwd>
#include <string>
#include <vector>

#include "dayphoton/core/scene_description.h"
#include "dayphoton/project/project.h"

namespace dayphoton::app {

struct MaterialArea {
  std::string name;
  std::string type;  ///< as the project file wrote it ("plastic", not the model "lambertian")
  int surfaces = 0;
  double area_m2 = 0;
  /// Glass, glazing and glazed openings: "glass", "glazing, 2 panes", ... and the mean-RGB
  /// transmittance for light from outside at each of TransmittanceAnglesDeg (empty otherwise).
  std::string glazing;
  std::vector<double> transmittance;
  /// Glazing: one line per pane (thickness, normal transmittance or absorption, index, coating).
  std::vector<std::string> panes;
  /// A registered material model's summary line (its registry entry's `summary`), or empty.
  std::string description;
};

/// Angles of incidence at which `check` lists each glazing's transmittance.
inline constexpr double TransmittanceAnglesDeg[] = {0, 30, 45, 60, 75};

struct PortInfo {
  std::string name;
  double area_m2 = 0;
  double azimuth_deg = 0;  ///< of the outward normal, clockwise from true north
  double tilt_deg = 0;     ///< of the outward normal from the zenith (90 = vertical window)
  std::string room_side;   ///< which side is the room, and why (study::describe_port_facing)
};

/// A roof light of the room generator (its glazing is also listed among the ports).
struct RoofLightInfo {
  std::string name;          ///< "<room>.<roof light>", the glazing's surface name
  double area_m2 = 0;
  double well_depth_m = 0;   ///< 0: flush with the ceiling
};

/// A window between two rooms: glazing, not a port (project::interior_windows).
struct InteriorWindowInfo {
  std::string name;          ///< "<room>.<window>", the glazing's surface name
  std::string adjoining_room;
  double area_m2 = 0;
};

struct GridInfo {
  std::string name;
  std::size_t sensors = 0;
  int columns = 0, rows = 0;
  double spacing_m = 0;
  bool planar = false;
  double plane_z_m = 0;      ///< planar grids: the plane's height z (world coordinates)
  bool facing_down = false;  ///< planar grids: the sensors face down (a ceiling grid)
  /// How the photon part is estimated: "receiver plane", "final gather" or "surface photons",
  /// with its parameters, and how many sensors lie in mid air / on a surface (gather only).
  std::string estimate;
};

struct ModelSummary {
  std::string project_path;
  project::Site site;
  std::vector<std::string> weather_lines;  ///< human-readable weather header
  /// Which site the sun is computed for, the station's distance, the hours with direct light
  /// and the sun below the horizon (the run log's words, study/sun_site.h).
  std::vector<std::string> sun_lines;
  /// One line per point-in-time case (study::check_points_in_time).
  std::vector<std::string> point_in_time_lines;
  std::vector<MaterialArea> materials;
  std::size_t surface_count = 0;
  std::size_t triangle_count = 0;
  std::vector<PortInfo> ports;
  std::vector<RoofLightInfo> roof_lights;
  std::vector<InteriorWindowInfo> interior_windows;
  /// One line per daylight system: how its light is modelled (project::describe_system_light).
  std::vector<std::string> system_lines;
  /// The imported Honeybee model (docs/honeybee-import.md): what it brought, then its notes
  /// (faces left out: the far sides of shared walls, air boundaries).
  std::vector<std::string> honeybee_lines;
  /// One line per `geometry.radiance` entry: its files and the unit their numbers are read in
  /// (docs/radiance-import.md, "Units"), said to be assumed when the entry has no `units`.
  std::vector<std::string> radiance_lines;
  std::vector<GridInfo> grids;
  std::vector<std::string> placement_lines;  ///< sensor sets that dropped sensors (drop_occluded)
  SceneDescription scene;
};

/// Validate everything the project refers to and gather the summary; throws InputError
/// (also for the placement checks of study/placement_check.h, and for a surface estimate, simulation.point_estimate: surface, of a sensor that does not
/// lie on a surface storing photons: it would silently read no photon light).
ModelSummary summarize_model(const project::Project& proj);

void print_model_summary(const ModelSummary& summary, std::ostream& out);

/// Compass point (N, NNE, ..., NNW) of an azimuth in degrees clockwise from north.
std::string compass_point(double azimuth_deg);

}  // namespace dayphoton::app
