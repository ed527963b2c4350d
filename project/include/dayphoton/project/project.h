// Project: the typed content of a project file (docs/project-format.md), every value with
// the location it came from. Loading is staged (STYLE.md A.3):
//   YAML text --parse--> located node tree --validate against the schema--> Project
//   Project --generate geometry (rooms, windows, boxes, meshes, grids)--> SceneDescription
// Both stages report every problem as a located error (file:line:col) and throw InputError
// with all of them (up to a cap); neither writes anything.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "dayphoton/core/scene_description.h"
#include "dayphoton/core/source_location.h"
#include "dayphoton/core/vec3.h"

namespace dayphoton::project {

/// A value together with where it was written (location unknown for defaults).
template <typename T>
struct Located {
  T value{};
  SourceLocation location;
};

struct Site {
  std::string name;
  double latitude_deg = 0;    ///< north positive
  double longitude_deg = 0;   ///< east positive (as EPW; RADIANCE's -o uses west positive)
  double time_zone_h = 0;     ///< standard time offset from UTC, east positive (EPW convention)
  double elevation_m = 0;
  /// Angle (degrees, clockwise seen from above) from model +Y to true north (Honeybee
  /// convention): the model is rotated by this angle about +Z to world coordinates.
  double north_deg = 0;
  /// If the model is drawn in a UTM grid, its zone (1..60) and hemisphere; the meridian
  /// convergence at the site then corrects north_deg (see rotation_to_true_north_deg).
  std::optional<int> utm_zone;
  bool utm_north = true;
  /// Meridian convergence gamma (degrees) at the site, from GeographicLib::UTMUPS::Forward;
  /// 0 without a UTM zone. GeographicLib's sign: the bearing of grid north measured clockwise
  /// from true north (positive east of the zone's central meridian in the northern
  /// hemisphere). See dayphoton/project/site_geodesy.h and docs/project-format.md.
  double meridian_convergence_deg = 0;
  SourceLocation location;

  /// Total clockwise rotation from model +Y to true north. With a UTM zone, north_deg is
  /// measured from model +Y to grid north, and true north lies gamma counter-clockwise of
  /// grid north: north_deg - meridian_convergence_deg.
  double rotation_to_true_north_deg() const { return north_deg - meridian_convergence_deg; }
};

struct Weather {
  std::string path;           ///< resolved against the project file's folder
  std::string path_as_written;
  SourceLocation location;
};

/// Model walls of a room generator, named by the compass direction they face *outward* in
/// model coordinates (south = the wall at the room's minimum y).
enum class Wall { South, North, East, West };
const char* wall_name(Wall wall);

struct WindowSpec {
  std::string name;
  Wall wall = Wall::South;
  double width_m = 0;
  double height_m = 0;
  double sill_m = 0;   ///< height of the window's bottom edge above the floor
  /// Distance along the wall from its lower-coordinate end (min x for south/north walls,
  /// min y for east/west walls) to the window's near edge; centred if absent.
  std::optional<double> offset_m;
  std::string material;  ///< glazing material name
  SourceLocation location;
};

struct RoomSpec {
  std::string name;
  Vec3 origin{0, 0, 0};   ///< the room's (min x, min y, floor) corner, metres
  Vec3 size_m{0, 0, 0};   ///< x, y, z extents
  std::string floor_material, ceiling_material;
  std::string wall_material[4];  ///< indexed by Wall
  std::vector<WindowSpec> windows;
  SourceLocation location;
};

struct PolygonSpec {
  std::string name;
  std::vector<Vec3> vertices;
  std::string material;
  bool port = false;
  SourceLocation location;
};

/// Axis-aligned box (before the site rotation), outward normals, optional rotation about +Z
/// around its origin corner.
struct BoxSpec {
  std::string name;
  Vec3 origin{0, 0, 0};
  Vec3 size_m{0, 0, 0};
  double rotation_deg = 0;
  std::string material;
  SourceLocation location;
};

struct MeshSpec {
  std::string name;
  std::string path;             ///< resolved OBJ path
  std::string path_as_written;
  /// OBJ `usemtl` name -> project material name; faces without a mapping take default_material.
  std::vector<std::pair<std::string, std::string>> material_map;
  std::string default_material;  ///< may be empty if every usemtl is mapped
  Vec3 translate{0, 0, 0};
  double scale = 1;
  double rotation_deg = 0;  ///< about +Z, applied after scale, before translate
  bool port = false;
  SourceLocation location;
};

struct Geometry {
  std::vector<RoomSpec> rooms;
  std::vector<PolygonSpec> polygons;
  std::vector<BoxSpec> boxes;
  std::vector<MeshSpec> meshes;
};

struct GridSpec {
  std::string name;
  std::string room;                 ///< room name, or empty if `polygon` is given
  std::vector<Vec3> polygon;        ///< outline (z ignored, height from height_m)
  double height_m = 0.8;
  double spacing_m = 0.5;
  double inset_m = 0.5;
  Vec3 normal{0, 0, 1};
  SourceLocation location;
};

struct PointsSpec {
  std::string name;
  std::vector<SensorPoint> points;  ///< inline points
  std::string file;                 ///< resolved .pts path (x y z nx ny nz per line), or empty
  std::string file_as_written;
  SourceLocation location;
};

struct Sensors {
  std::vector<GridSpec> grids;
  std::vector<PointsSpec> points;
};

enum class SkyBasis { Tregenza, Reinhart };
enum class SunMode { Bins, Spread };

struct Simulation {
  SkyBasis basis = SkyBasis::Tregenza;
  int reinhart_mf = 1;           ///< subdivision for Reinhart (1 = Tregenza)
  long long photons_per_bin = 20000;   ///< stored photons per sky/sun bin
  int bandwidth = 50;            ///< nearest photons per density estimate
  unsigned long long seed = 1;
  double ground_reflectance = 0.2;
  SunMode sun = SunMode::Bins;
  int sun_mf = 6;                ///< Reinhart subdivision whose patch centres are sun bins
  int direct_samples_per_bin = 16;  ///< shadow rays per bin for the direct component
  SourceLocation location;
};

struct Outputs {
  std::string folder;            ///< resolved; default "results" beside the project file
  std::string folder_as_written;
  bool daylight_factor = true;
  bool annual_illuminance = true;
  bool metrics = true;
  bool coefficients = true;
  bool images = true;
  bool report = true;
  std::string matrix_format = "ascii";  ///< "ascii" or "float"
  SourceLocation location;
};

/// Settings of the results (docs/project-format.md, section `metrics`). Plain numbers that
/// mirror metrics::MetricSettings and the occupancy schedule of the metrics library (this
/// library does not depend on it); defaults are those of LM-83 / the issue 5 conventions
/// and equal the schema defaults (a test checks both agree).
struct MetricsSettings {
  /// Daylight factor: the grid statistics report the area (percent of sensors) with
  /// DF >= each threshold, in the order written. Each in (0, 100], no duplicates.
  std::vector<double> daylight_factor_thresholds_percent = {2.0};
  double da_threshold_lux = 300;         ///< DA, cDA, sDA; also the revised-UDI split
  /// Occupied hours: start_h <= mid-hour stamp < end_h in local standard time (no DST),
  /// every day; 0 <= start_h < end_h <= 24.
  double occupancy_start_h = 8;
  double occupancy_end_h = 18;
  double udi_lower_lux = 100;            ///< below: "fell short"
  double udi_upper_original_lux = 2000;  ///< Nabil & Mardaljevic 2005
  double udi_upper_revised_lux = 3000;   ///< Mardaljevic's revision
  double sda_time_fraction = 0.5;        ///< sDA300/50%: fraction of occupied hours, (0, 1]
  double ase_threshold_lux = 1000;       ///< ASE1000,250: direct-sun illuminance threshold
  double ase_hours = 250;                ///< a sensor fails with more than this many hours
  SourceLocation location;
};

/// A study variant: the whole project with some materials replaced (alternative glazing,
/// blinds modelled as a translucent material, ...). Only replaces materials that exist in
/// Project::materials; apply_variant() builds the variant's Project.
struct VariantSpec {
  std::string name;                    ///< unique, a portable folder name
  std::vector<MaterialSpec> materials; ///< full definitions, each named after a base material
  SourceLocation location;
};

struct Project {
  int format_version = 1; ///< `version` key of the file (only 1 exists)
  std::string path;       ///< the project file as given
  std::string directory;  ///< its folder, for resolving relative paths
  Site site;
  Weather weather;
  std::vector<MaterialSpec> materials;
  Geometry geometry;
  Sensors sensors;
  Simulation simulation;
  Outputs outputs;
  MetricsSettings metrics;
  std::vector<VariantSpec> variants;  ///< in file order; empty if the file has none
};

/// Parse and validate a project file. Throws InputError with every problem found (located,
/// up to a cap); throws nothing else for bad input.
Project load_project(const std::string& path);

/// Same, from text already in memory (`path` is used in messages and to resolve relative paths).
Project load_project_from_string(const std::string& text, const std::string& path);

/// The project of one variant: `base` with every material of `variant` put in place of the
/// base material of the same name (same position in `materials`, so material indices do not
/// change); everything else, `variants` included, is equal to `base`. Throws
/// std::invalid_argument if the variant names a material `base` does not have (the loader
/// reports that as an input error, so this only happens with hand-made variants).
Project apply_variant(const Project& base, const VariantSpec& variant);

/// True if `name` can be used as a folder name on every common file system: 1 to 64
/// characters from [A-Za-z0-9_.-], not starting with '.' or '-', not ending with '.', and
/// not a Windows device name (con, nul, com1, ... with any extension).
bool is_portable_folder_name(const std::string& name);

/// Generate the scene: rooms with their windows cut out (windows become glazing ports),
/// polygons, boxes, OBJ meshes, sensor grids and point files, all rotated by the site's
/// rotation_to_true_north_deg about +Z. Validates the geometry (non-planar polygons,
/// windows outside their wall or overlapping, unknown materials, degenerate faces, NaN/Inf)
/// and throws InputError with located messages.
SceneDescription build_scene_description(const Project& project);

}  // namespace dayphoton::project
