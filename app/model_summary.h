// ModelSummary: what `check` (and the head of `run`) prints about a project: site, weather,
// surfaces and areas per material, ports with orientation, sensor grids. Building it performs
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
  std::string type;
  int surfaces = 0;
  double area_m2 = 0;
};

struct PortInfo {
  std::string name;
  double area_m2 = 0;
  double azimuth_deg = 0;  ///< of the outward normal, clockwise from true north
  double tilt_deg = 0;     ///< of the outward normal from the zenith (90 = vertical window)
  std::string room_side;   ///< which side is the room, and why (study::describe_port_facing)
};

struct GridInfo {
  std::string name;
  std::size_t sensors = 0;
  int columns = 0, rows = 0;
  double spacing_m = 0;
  bool planar = false;
  double plane_height_m = 0;
  /// How the photon part is estimated: "receiver plane", "final gather" or "surface photons",
  /// with its parameters, and how many sensors lie in mid air / on a surface (gather only).
  std::string estimate;
};

struct ModelSummary {
  std::string project_path;
  project::Site site;
  std::vector<std::string> weather_lines;  ///< human-readable weather header
  std::vector<MaterialArea> materials;
  std::size_t surface_count = 0;
  std::size_t triangle_count = 0;
  std::vector<PortInfo> ports;
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
