// Project: the typed content of a project file (docs/project-format.md), every value with
// the location it came from. Loading is staged (STYLE.md A.3):
//   YAML text --parse--> located node tree --validate against the schema--> Project
//   Project --generate geometry (rooms, windows, boxes, meshes, grids)--> SceneDescription
// Both stages report every problem as a located error (file:line:col) and throw InputError
// with all of them (up to a cap); neither writes anything.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "dayphoton/core/resource_limits.h"
#include "dayphoton/core/scene_description.h"
#include "dayphoton/core/source_location.h"
#include "dayphoton/core/vec3.h"
#include "dayphoton/project/honeybee_model.h"

namespace dayphoton::project {

/// A value together with where it was written (location unknown for defaults).
template <typename T>
struct Located {
  T value{};
  SourceLocation location;
};

struct Site {
  std::string name;
  /// `from_weather: true`: the sun and the sky are computed for the weather file header's site,
  /// as RADIANCE's gendaymtx does; latitude, longitude, time_zone, elevation and utm_zone are
  /// then not written (the fields below stay 0: use study::resolve_sun_site for the values).
  /// false: the sun is computed for this site, with the weather station's irradiance.
  bool from_weather = false;
  double latitude_deg = 0;    ///< north positive
  double longitude_deg = 0;   ///< east positive (as EPW; RADIANCE's -o uses west positive)
  double time_zone_h = 0;     ///< standard time offset from UTC, east positive (EPW convention)
  double elevation_m = 0;
  /// Where time_zone was written (the check that it is the weather file's clock points here).
  SourceLocation time_zone_location;
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

/// What `run` computes (`study`, docs/project-format.md): the annual study (daylight factors,
/// the weather file's annual skies and sun, annual illuminance and metrics), or daylight
/// factors only (the CIE overcast sky: no weather file is read and no sun is traced).
enum class StudyKind { Annual, DaylightFactor };
/// The `study` value of the project file ("annual", "daylight_factor").
const char* study_kind_name(StudyKind kind);

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
  /// Glazed fraction of the opening, (0, 1]: the frame absorbs the rest. Multiplies the
  /// glazing's transmittance (docs/materials.md, "Frame and maintenance factors").
  double frame_factor = 1.0;
  /// Transmittance left by dirt on the glazing, (0, 1]. Multiplies it too.
  double maintenance_factor = 1.0;
  SourceLocation location;
};

/// A roof light (skylight): a rectangular opening in a room's ceiling, its glazing either
/// flush with the ceiling (well_depth_m = 0) or at the top of a light well of that depth
/// whose four walls rise from the ceiling opening (docs/daylight-systems.md, "Roof lights").
/// The glazing is a photon port facing down into the room. Placed in room coordinates: x
/// from the room's west wall (min x) over width_m, y from its south wall (min y) over
/// length_m; centred along an axis whose offset is absent.
struct RoofLightSpec {
  std::string name;
  double width_m = 0;   ///< along x
  double length_m = 0;  ///< along y
  std::optional<double> offset_x_m, offset_y_m;  ///< to the near edges; centred if absent
  double well_depth_m = 0;     ///< ceiling to glazing; 0 = flush
  std::string well_material;   ///< walls of the well; empty = the room's ceiling material
  std::string material;        ///< glazing material
  SourceLocation location;
  /// Where each key was written, for located errors; see location_of().
  std::vector<std::pair<std::string, SourceLocation>> key_locations;

  /// Location of `key` as written, else of the roof light.
  SourceLocation location_of(const std::string& key) const;
};

struct RoomSpec {
  std::string name;
  Vec3 origin{0, 0, 0};   ///< the room's (min x, min y, floor) corner, metres
  Vec3 size_m{0, 0, 0};   ///< x, y, z extents
  std::string floor_material, ceiling_material;
  std::string wall_material[4];  ///< indexed by Wall
  /// Windows in the walls. A window in a wall that another room shares (same plane, the
  /// other room on the far side) is an INTERIOR window when its rectangle lies inside that
  /// room's wall: both walls are cut and its glazing is ordinary glazing, not a port
  /// (interior_windows(); docs/daylight-systems.md, "Interior windows").
  std::vector<WindowSpec> windows;
  std::vector<RoofLightSpec> roof_lights;
  SourceLocation location;
};

struct PolygonSpec {
  std::string name;
  std::vector<Vec3> vertices;
  std::string material;
  bool port = false;
  /// Ports: which side is the room (`facing`: auto, in = the winding normal points into it, out).
  PortFacing facing = PortFacing::Auto;
  /// `outdoor`: an outdoor scatterer (Surface::outdoor_scatterer): sky and sun photons also
  /// land on it and the light it sends toward the ports is traced; otherwise it only shades.
  bool outdoor = false;
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
  /// `outdoor`: an outdoor scatterer (Surface::outdoor_scatterer): sky and sun photons also
  /// land on it and the light it sends toward the ports is traced; otherwise it only shades.
  bool outdoor = false;
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
  /// Ports: which side of every face is the room (`facing`: auto, in, out), as for polygons.
  PortFacing facing = PortFacing::Auto;
  /// `outdoor`: an outdoor scatterer (Surface::outdoor_scatterer): sky and sun photons also
  /// land on it and the light it sends toward the ports is traced; otherwise it only shades.
  bool outdoor = false;
  SourceLocation location;
};

// ---- daylight systems (docs/daylight-systems.md) -----------------------------------------
// Each system is a generator: a few parameters that build_scene_description turns into
// surfaces in model coordinates. Systems mounted on a window are placed in the window's
// frame (u along the wall, to the right as seen from outside; v up, measured from the room
// floor; w along the wall's outward normal, 0 in the wall plane, > 0 outside).

/// Which side of the wall a window-mounted system is on.
enum class MountSide { Interior, Exterior };

/// Where photons enter for a window-mounted system (docs/daylight-systems.md, "Ports").
/// System (the default): the window stays the photon port and the exterior parts are
/// outdoor scatterers (Surface::outdoor_scatterer): photons also land on them straight from
/// the sources, so the light they reflect or transmit toward the window is traced. Window:
/// the window alone is the port; exterior parts only shade it (the path from the port toward
/// the source is tested; light they reflect is not modelled), an explicit approximation.
/// Enclosure: an invisible box of `opening` ports encloses the exterior parts and the
/// window, which is then no longer a port, so light reflected or refracted outside is traced.
enum class PortMode { System, Window, Enclosure };
/// The `port` value of the project file ("system", "window", "enclosure").
const char* port_mode_name(PortMode mode);

struct SystemSpec;
/// How the light of a system is modelled, one sentence for `check`, the run log and the
/// report: "light_shelf 'outer' outside window 'w', port: system: what it reflects and
/// transmits toward the window is traced", and for `port: window` that it only shades (an
/// approximation).
std::string describe_system_light(const SystemSpec& system);

struct WindowMount {
  std::string window;                  ///< name of the window the system belongs to
  MountSide side = MountSide::Interior;
  PortMode port = PortMode::System;    ///< resolved: interior systems always Window
};

/// Light shelf: a flat shelf (or a closed slab) along the wall at `height_m` above the floor,
/// `depth_m` from the wall to its free edge, the free edge raised by `tilt_deg`.
struct LightShelfSpec {
  double height_m = 0;
  double depth_m = 0;
  double tilt_deg = 0;
  double thickness_m = 0;     ///< 0: one two-sided polygon; > 0: a closed slab
  double extension_m = 0;     ///< beyond each window jamb
  std::string material;       ///< top face (and every face of a thin shelf)
  std::string underside_material;  ///< slab faces other than the top; empty = material
};

/// Venetian blinds: horizontal slats of chord `slat_width_m`, `spacing_m` apart, rotated by
/// `angle_deg` about their long axes, optionally curved (crown) as `facets` flat facets.
struct BlindsSpec {
  double slat_width_m = 0;
  double spacing_m = 0;
  double angle_deg = 0;       ///< 0 horizontal; > 0 the window-side edge down (see docs)
  double crown_m = 0;         ///< rise of the slat's middle above its chord
  int facets = 4;             ///< flat facets across a curved slat (1 if crown_m == 0)
  std::optional<double> offset_m;  ///< glass to slat axes; default slat_width / 2 + 0.02
  std::optional<double> bottom_m, top_m;  ///< covered heights; default the window's
  double extension_m = 0;
  std::string material;
};

/// Prismatic panel: horizontal dielectric prisms with isosceles cross-section (apex angle,
/// base = pitch in the panel plane), stacked over the panel, optionally on a backing plate.
struct PrismaticPanelSpec {
  double apex_angle_deg = 90;
  double pitch_m = 0;
  bool apex_outward = false;  ///< apexes point outside (true) or into the room
  double backing_m = 0;       ///< plate thickness behind the prisms; 0 = separate prisms
  double offset_m = 0.01;     ///< glass to the panel
  std::optional<double> bottom_m, top_m;
  std::string material;       ///< a dielectric
};

/// Lamella panel (Y-glass, seeds/000 section 4.2.1): a dielectric panel cut by thin air
/// lamellae inclined by `lamella_angle_deg` (inner edge lower), `spacing_m` apart.
struct LamellaPanelSpec {
  double thickness_m = 0;
  double spacing_m = 0;
  double lamella_angle_deg = 7;
  double gap_m = 0.0005;      ///< air gap of a lamella
  double offset_m = 0.01;
  std::optional<double> bottom_m, top_m;
  std::string material;       ///< a dielectric
};

/// Compound parabolic concentrators (seeds/000 section 4.2.2): `count` horizontal 2-D CPC
/// troughs stacked over the panel, faceted parabolic walls extruded along the window.
struct CpcSpec {
  double acceptance_angle_deg = 0;  ///< half angle theta
  int count = 1;
  bool dielectric = false;    ///< solid dielectric troughs (sun shading) or mirror walls
  int facets = 8;             ///< straight facets per parabolic wall
  double tilt_deg = 0;        ///< troughs' axes raised toward the sky by this angle
  double offset_m = 0.01;
  std::optional<double> bottom_m, top_m;
  std::string material;       ///< wall material (reflective) or the dielectric
  std::string exit_material;  ///< dielectric: opaque coating of the exit aperture
};

/// Light pipe (seeds/000 section 4.2.3): a vertical specular tube of `sides` facets from a
/// room's ceiling up `length_m`, a collector (dome or flat, a photon port) on top and a
/// diffuser filling the hole it cuts in the ceiling.
struct LightPipeSpec {
  std::string room;
  double x_m = 0, y_m = 0;    ///< axis, model coordinates
  double diameter_m = 0;      ///< of the circle the tube's polygon is inscribed in
  double length_m = 0;        ///< ceiling to collector
  int sides = 16;
  bool dome = true;           ///< hemispherical collector (else a flat one)
  int dome_rings = 4;
  std::string tube_material, diffuser_material, collector_material;
};

/// Overhang: a horizontal (or tilted) projection above a window.
struct OverhangSpec {
  std::optional<double> height_m;  ///< above the floor; default the window head
  double depth_m = 0;
  double tilt_deg = 0;
  double thickness_m = 0;
  double extension_m = 0;
  std::string material;
};

/// Fins: vertical projections beside a window.
struct FinsSpec {
  double depth_m = 0;
  bool left = true, right = true;  ///< as seen from outside
  double offset_m = 0;        ///< from the jamb, away from the window
  double extension_m = 0;     ///< above the head and below the sill
  double angle_deg = 0;       ///< free edges turned toward the window's centre line
  double thickness_m = 0;
  std::string material;
};

using SystemParams = std::variant<LightShelfSpec, BlindsSpec, PrismaticPanelSpec,
                                  LamellaPanelSpec, CpcSpec, LightPipeSpec, OverhangSpec,
                                  FinsSpec>;

struct SystemSpec {
  std::string name;
  bool enabled = true;        ///< false: the system is absent (e.g. blinds raised)
  WindowMount mount;          ///< every type but light_pipe
  SystemParams params;
  SourceLocation location;
  /// Where each key was written (for located geometry errors); see location_of().
  std::vector<std::pair<std::string, SourceLocation>> key_locations;

  /// The `type` value of the project file ("light_shelf", "blinds", ...).
  const char* type_name() const;
  /// Location of `key` as written, else of the system.
  SourceLocation location_of(const std::string& key) const;
};

/// A RADIANCE scene read in place (`geometry.radiance`, docs/radiance-import.md): its files
/// are read in order when the scene is built (radiance_scene.h), their materials mapped by
/// radiance_material.h and added to the scene's under their RADIANCE names (a project
/// material of the same name is used instead: a way to give imported glazing a `glazing`).
struct RadianceSceneSpec {
  std::vector<Located<std::string>> files;  ///< resolved paths, each where it was written
  std::vector<std::string> files_as_written;
  /// `ports: auto`: the surfaces of transmitting materials (glass, dielectric, trans with
  /// transmission, glazing, opening) are ports if exactly one side sees the sky
  /// (Surface::port_if_outdoors). Otherwise the surfaces of the modifiers in port_modifiers
  /// are ports (facing auto); an empty list makes no port.
  bool ports_auto = true;
  std::vector<Located<std::string>> port_modifiers;
  /// `outdoor`: the surfaces of these modifiers (matched as port_modifiers) are outdoor
  /// scatterers (Surface::outdoor_scatterer): context whose reflected light is traced.
  /// Never also ports: such a surface is no port candidate, and a modifier in both lists
  /// is an error.
  std::vector<Located<std::string>> outdoor_modifiers;
  bool skip_unsupported = false;  ///< `unsupported: skip` (else `error`)
  /// `units` (project/length_units.h): the unit of the files' numbers, metres per unit; the
  /// reader scales every coordinate and length to metres. units_written: the key was given
  /// (else the metre is assumed, and an implausible scene is warned about:
  /// scene_unit_check.h).
  std::string units = "Meters";
  double metres_per_unit = 1.0;
  bool units_written = false;
  SourceLocation location;
};

/// `geometry.honeybee`: a Honeybee model (HBJSON) read at load time (honeybee_model.h). Its
/// modifiers are appended to Project::materials under their identifiers; its surfaces are
/// generated by build_scene_description after the meshes.
struct HoneybeeImport {
  std::string path;             ///< resolved against the project file's folder
  std::string path_as_written;
  SourceLocation location;      ///< of the `honeybee` value
  HoneybeeModel model;
};

struct Geometry {
  std::vector<RoomSpec> rooms;
  std::vector<PolygonSpec> polygons;
  std::vector<BoxSpec> boxes;
  std::vector<MeshSpec> meshes;
  std::vector<SystemSpec> systems;  ///< daylight systems, in file order
  std::vector<RadianceSceneSpec> radiance;  ///< RADIANCE scenes, in file order
  std::optional<HoneybeeImport> honeybee;
};

/// A surface of a room generator that a sensor grid can cover: one of its four walls
/// (named as Wall), its floor or its ceiling.
enum class RoomSurface { South, North, East, West, Floor, Ceiling };
const char* room_surface_name(RoomSurface surface);

/// `metrics.occupancy` (docs/metrics.md, "Occupancy schedules"): the occupied hours per
/// kind of day, holidays, the weekday of 1 January and daylight saving time, or a CSV file of
/// one 0/1 value per weather record. Plain data mirroring metrics::OccupancyPlan (this library
/// does not depend on it). Not given: MetricsSettings' daily window.
struct OccupancySpec {
  /// [start_h, end_h) of local clock time, 0 <= start < end <= 24, in order, not overlapping.
  using Windows = std::vector<std::pair<double, double>>;
  struct Holiday {
    int from_month = 1, from_day = 1, to_month = 1, to_day = 1;  ///< both included; may wrap the year end
  };
  bool given = false;
  std::array<Windows, 7> week;  ///< Monday .. Sunday; empty: closed
  Windows holiday_hours;        ///< empty: closed (the default)
  std::vector<Holiday> holidays;
  int january_1 = -1;           ///< 0 = Monday .. 6 = Sunday; -1: the weather file's DATA PERIODS
  std::string daylight_saving = "none";  ///< none, eu, us
  std::string file;             ///< resolved CSV path; "" unless the schedule is a file
  std::vector<bool> hourly;     ///< the file's values, one per weather record
  SourceLocation location;      ///< of the `occupancy` key's value
};

/// A regular sensor grid (docs/project-format.md, `sensors.grids`). Exactly one of `room`,
/// `polygon`, `wall` and `rectangle` says what it covers:
///   - room: the room's floor rectangle, sensors at height_m above the floor facing `normal`;
///   - polygon: the outline seen from above, sensors at z = height_m facing `normal`;
///   - wall: the rectangle of a room's wall, floor or ceiling, sensors facing into the room
///     offset_m in front of the surface (the frames are listed in sensor_grid.cpp);
///   - rectangle: the parallelogram origin + s u + t v (s, t in [0, 1]), sensors facing
///     normalize(u x v) (right-hand rule), offset_m along that normal.
struct GridSpec {
  std::string name;
  std::string room;                 ///< room name, or empty if another outline is given
  std::vector<Vec3> polygon;        ///< outline (z ignored, height from height_m)
  struct WallReference {
    std::string room;
    RoomSurface surface = RoomSurface::North;
  };
  std::optional<WallReference> wall;
  struct Rectangle {
    Vec3 origin{0, 0, 0};  ///< metres, model coordinates
    Vec3 u{0, 0, 0}, v{0, 0, 0};  ///< edge vectors, metres; the lattice runs along u (inner) and v
  };
  std::optional<Rectangle> rectangle;
  double height_m = 0.8;            ///< room and polygon grids
  double spacing_m = 0.5;
  double inset_m = 0.5;
  double offset_m = 0;              ///< wall and rectangle grids: in front of the surface
  Vec3 normal{0, 0, 1};             ///< room and polygon grids
  bool drop_occluded = false;       ///< drop sensors outside every room or inside a solid
  OccupancySpec occupancy;          ///< this grid's own schedule, if given (else the project's)
  SourceLocation location;
  SourceLocation spacing_location;  ///< of `spacing` if written, else of the grid

  /// Where each key was written ("wall.room", "rectangle.u", ...), for located errors found
  /// when the grid is generated; see location_of().
  std::vector<std::pair<std::string, SourceLocation>> key_locations;

  /// Location of `key` as written, else of the grid.
  SourceLocation location_of(const std::string& key) const;
};

struct PointsSpec {
  std::string name;
  std::vector<SensorPoint> points;  ///< inline points
  /// The area each inline point stands for (m^2; SensorGrid::area_m2): a Honeybee grid's
  /// unequal mesh faces; empty: equal shares.
  std::vector<double> area_m2;
  std::string file;                 ///< resolved .pts path (x y z nx ny nz per line), or empty
  std::string file_as_written;
  /// `units` of the .pts file (project/length_units.h), metres per unit: its positions are
  /// scaled to metres (directions are not lengths). Inline `points` are in metres.
  std::string units = "Meters";
  double metres_per_unit = 1.0;
  bool drop_occluded = false;  ///< drop sensors outside every room or inside a solid
  OccupancySpec occupancy;     ///< this set's own schedule, if given (else the project's)
  SourceLocation location;
};

struct Sensors {
  std::vector<GridSpec> grids;
  std::vector<PointsSpec> points;
};

enum class SkyBasis { Tregenza, Reinhart };
enum class SunMode { Bins, Spread };
/// The density estimator on receiver planes and surfaces (engine::PhotonEstimator).
enum class Estimator { PerSource, Contribution };
/// How sensors off a receiver plane are estimated (engine/final_gather.h).
enum class PointEstimate { Gather, Surface };

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
  /// Stored caustic photons per bin (sky and sun bins alike), a target of their own; 0: caustic
  /// photons are stored like global ones (engine::TracingOptions::caustic_photons_per_source).
  long long caustic_photons_per_bin = 0;
  /// Photons per caustic estimate, among caustic photons only (the caustic map); 0: `bandwidth`
  /// if caustic_photons_per_bin > 0, else caustic and global photons share one disc
  /// (engine::CoefficientOptions::caustic_bandwidth).
  int caustic_bandwidth = 0;
  /// Photons are stored only inside this box (model coordinates), and the photon targets count
  /// only those (engine::TracingOptions::region_of_interest). Every sensor must lie inside.
  struct RegionOfInterest {
    Vec3 origin_m;  ///< min corner
    Vec3 size_m;
    SourceLocation location;
  };
  std::optional<RegionOfInterest> region_of_interest;
  /// Low-yield cap: main-pass attempts per target photon of a source, 0 = none
  /// (engine::TracingOptions::max_mainpass_attempts_per_target).
  long long max_attempts_per_photon = 256;
  /// Sensors that are not on a receiver plane: a final gather from each (the default), or
  /// the surface photons where the sensor lies (it must lie on a surface that stores them).
  PointEstimate point_estimate = PointEstimate::Gather;
  /// Receiver-plane and surface estimates: each source from its own N nearest photons (the
  /// default), or the contribution estimate (R. Schregle, "Development and Integration of
  /// the RADIANCE Photon Map Extension", 2015: the N nearest of all sources, binned).
  Estimator estimator = Estimator::PerSource;
  /// `accuracy`: trace the sky sources in rounds until the daylight factors reach a relative
  /// standard error (study/accuracy_rounds.h) instead of photons_per_bin photons each.
  struct Accuracy {
    std::string preset;  ///< "draft", "standard", "final" or "" (target given or defaulted)
    double target_df_relative_stderr_percent = 1.0;
    long long max_photons = 0;  ///< stored photons of all sky sources; 0: limits.photons
    double max_seconds = 0;     ///< 0: no time budget
    bool defaulted = false;     ///< not written: the project gives no photon count (the final preset)
    SourceLocation location;
    SourceLocation max_photons_location;
  };
  std::optional<Accuracy> accuracy;
  int gather_rays = 1024;        ///< final-gather rays per sensor (engine::GatherOptions)
  int gather_bandwidth = 32;     ///< photons per lookup at a gather hit
  SourceLocation location;
  SourceLocation photons_per_bin_location;  ///< of `photons_per_bin` if written, else of the section
};

struct Outputs {
  std::string folder;            ///< resolved; default "results" beside the project file
  std::string folder_as_written;
  /// `folder_outside_project`: the user allows `folder` outside the project's folder.
  bool folder_outside_project = false;
  bool daylight_factor = true;
  bool annual_illuminance = true;
  /// `illuminance_csv`: illuminance.csv beside illuminance.bin (off by default: the same table
  /// written twice; docs/outputs.md "Defaults: binary first").
  bool illuminance_csv = false;
  bool metrics = true;
  bool coefficients = true;
  /// `radiance_sun_matrix`: coefficients_sun_mf<N>.mtx for gendaymtx -d (with coefficients).
  bool radiance_sun_matrix = false;
  bool images = true;
  bool report = true;
  std::string matrix_format = "float";  ///< "ascii" or "float"
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
  /// A schedule beyond the daily window (`occupancy`); then the two keys above are unused.
  OccupancySpec occupancy;
  double udi_lower_lux = 100;            ///< below: "fell short"
  double udi_upper_original_lux = 2000;  ///< Nabil & Mardaljevic 2005
  double udi_upper_revised_lux = 3000;   ///< Mardaljevic's revision
  double sda_time_fraction = 0.5;        ///< sDA300/50%: fraction of occupied hours, (0, 1]
  double ase_threshold_lux = 1000;       ///< ASE1000,250: direct-sun illuminance threshold
  double ase_hours = 250;                ///< a sensor fails with more than this many hours
  SourceLocation location;
};

/// What a variant removes from the base project: names of base elements, each where the
/// variant wrote it (docs/project-format.md, `variants`).
struct VariantRemovals {
  std::vector<Located<std::string>> polygons, boxes, meshes, systems;
  std::vector<Located<std::string>> windows;  ///< windows of room generators (photon ports)
  bool empty() const;
};

/// A window a variant adds to a room of the base project.
struct AddedWindow {
  Located<std::string> room;
  WindowSpec window;
};

/// What a variant adds: full definitions, read and validated like the base's, after the
/// base's elements of the same kind (windows after their room's own).
struct VariantAdditions {
  std::vector<PolygonSpec> polygons;
  std::vector<BoxSpec> boxes;
  std::vector<MeshSpec> meshes;
  std::vector<SystemSpec> systems;
  std::vector<AddedWindow> windows;
  bool empty() const;
};

/// A study variant: the whole project with some materials and/or daylight systems replaced
/// (alternative glazing, blinds modelled as a translucent material, blinds tilted or
/// closed, ...), and polygons, boxes, meshes, systems and windows removed or added. Rooms,
/// sensors and settings are the base's (every case has the same sensors);
/// apply_variant() builds the variant's Project.
struct VariantSpec {
  std::string name;                    ///< unique, a portable folder name
  std::vector<MaterialSpec> materials; ///< full definitions, each named after a base material
  /// Full definitions, each named after a base system: the base system's keys with the
  /// variant's `systems: {name: {key: value}}` overrides applied (docs/project-format.md).
  std::vector<SystemSpec> systems;
  SourceLocation location;
  VariantRemovals remove;              ///< `remove`: base elements left out
  VariantAdditions add;                ///< `add`: elements the base does not have
};

/// The name that `operation` uses for the project as written (the base case).
constexpr const char* BaseCaseName = "base";

/// Operated shading (IES LM-83-12 section 2.2.6; docs/metrics.md, "Operated shading"): per
/// grid and hour, the `shaded` case's illuminance when more than `sunlit_limit_percent` of
/// the grid's sensors see direct sun (direct-sun-only, zero-bounce illuminance of the `open`
/// case >= `direct_sun_threshold_lux`), else the `open` case's. Needs `sun: bins`.
struct OperationSpec {
  Located<std::string> open;    ///< a variant's name, or BaseCaseName
  Located<std::string> shaded;  ///< a variant's name, or BaseCaseName; not `open`
  double direct_sun_threshold_lux = 1000;  ///< LM-83 "direct sun": 1000 lx or more
  double sunlit_limit_percent = 2;         ///< LM-83: shade when MORE than 2 % of the points
  SourceLocation location;
};

/// EN 17037's exposure to sunlight (`sunlight_exposure`, docs/metrics.md "EN 17037 exposure
/// to sunlight"): the hours of possible sunlight, on one date, at the reference point of each
/// window of the room generator's rooms (study/sunlight_exposure.h).
/// EN 17037:2018's dates for the sunlight exposure: a date between 1 February and 21 March
/// (docs/metrics.md "EN 17037 exposure to sunlight"); the default date is the last of them.
constexpr int SunlightFirstMonth = 2, SunlightFirstDay = 1;
constexpr int SunlightLastMonth = 3, SunlightLastDay = 21;
struct SunlightExposureSpec {
  int month = SunlightLastMonth, day = SunlightLastDay;  ///< the date, in [02-01, 03-21]
  SourceLocation date_location;   ///< of `date`, or of the section
  /// The sun counts only at or above this altitude (degrees, the geometric altitude of the
  /// disc's centre). No default: EN 17037 makes it depend on the site.
  double min_altitude_deg = 0;
  double time_step_min = 1;       ///< the sun is sampled every time_step_min minutes
  /// The windows assessed (names of windows of `geometry.rooms`); empty: every window in an
  /// outside wall.
  std::vector<Located<std::string>> windows;
  SourceLocation location;
};

/// The sky of a point-in-time case (`points_in_time[].sky`).
enum class PointSky {
  CieOvercast,  ///< CIE standard overcast sky (Moon & Spencer), no sun
  CieGeneral,   ///< CIE standard general sky of type 1..15 (ISO 15469 / CIE S 011) with its sun
  Weather,      ///< the weather file's hour that contains the time (the annual study's sky and sun)
};
/// The `sky` value of the project file ("cie_overcast", "cie", "weather").
const char* point_sky_name(PointSky sky);

/// A point-in-time case (`points_in_time`): the illuminance at every sensor at one date and
/// local standard time under one sky, with its sun.
struct PointInTimeSpec {
  std::string name;
  int month = 1, day = 1;
  double hour_lst = 12;  ///< local standard time, [0, 24]
  PointSky sky = PointSky::CieOvercast;
  int cie_type = 0;      ///< CieGeneral: 1..15
  /// CIE skies: the sky's (diffuse) horizontal illuminance, lux.
  double diffuse_horizontal_illuminance_lux = 10000;
  /// CieGeneral: the sun's direct normal illuminance, lux (0: no sun).
  double direct_normal_illuminance_lux = 0;
  SourceLocation location;       ///< of the case
  SourceLocation time_location;  ///< of `time` (a sun below the horizon is located there)
};

struct Project {
  int format_version = 1; ///< `version` key of the file (only 1 exists)
  std::string path;       ///< the project file as given
  std::string directory;  ///< its folder, for resolving relative paths
  Site site;
  /// Annual unless the file says `study: daylight_factor`, or has no weather file and asks
  /// for no annual output (the form before the `study` key existed).
  StudyKind study = StudyKind::Annual;
  SourceLocation study_location;  ///< of `study` if written, else of the file's top level
  Weather weather;
  std::vector<MaterialSpec> materials;
  Geometry geometry;
  Sensors sensors;
  Simulation simulation;
  Outputs outputs;
  MetricsSettings metrics;
  std::vector<VariantSpec> variants;  ///< in file order; empty if the file has none
  std::optional<OperationSpec> operation;  ///< absent: no operated result
  std::vector<PointInTimeSpec> points_in_time;  ///< in file order; empty if the file has none
  std::optional<SunlightExposureSpec> sunlight_exposure;  ///< absent: not assessed
  /// `limits`: the largest study this project may make (sensors, photons), each checked
  /// before anything of that size is allocated; defaults in core/resource_limits.h.
  ResourceLimits limits;
};

/// How the caller will use the project it loads.
struct LoadOptions {
  /// The results go elsewhere (`run --output`, `render -o`): outputs.folder is not used, so
  /// it need not lie inside the project folder. Otherwise a folder outside it (absolute, or
  /// leaving it with ..) is an error unless outputs.folder_outside_project is true.
  bool output_folder_overridden = false;
};

/// Parse and validate a project file. Throws InputError with every problem found (located,
/// up to a cap); throws nothing else for bad input.
Project load_project(const std::string& path, const LoadOptions& options = {});

/// Same, from text already in memory (`path` is used in messages and to resolve relative paths).
Project load_project_from_string(const std::string& text, const std::string& path,
                                 const LoadOptions& options = {});

/// The project of one variant: `base` with every material of `variant` put in place of the
/// base material of the same name (same position in `materials`, so material indices do not
/// change) and every system of `variant` in place of the base system of the same name; then
/// the removed elements left out (the others keep their order) and the added ones appended
/// after the base's of their kind (an added window after its room's windows); everything
/// else, `variants` included, is equal to `base`. Throws std::invalid_argument if the
/// variant replaces or removes something `base` does not have, or adds a window to a room it
/// does not have (the loader reports these as input errors, so this only happens with
/// hand-made variants).
Project apply_variant(const Project& base, const VariantSpec& variant);

/// What `variant` changes, one short phrase each, in this order: replaced materials, changed
/// systems, removed then added elements by kind ("material glazing replaced", "system
/// venetian changed", "polygon skylight removed", "window west added to room office"); for
/// the run log and summary.json.
std::vector<std::string> variant_changes(const VariantSpec& variant);

/// A window between two rooms (see RoomSpec::windows): it belongs to `room` and opens into
/// `adjoining_room`.
struct InteriorWindow {
  std::string room, window, adjoining_room;
};

/// The interior windows of `geometry`, in file order. Reports nothing: windows that do not
/// fit, or lie partly in another room's wall, are errors of build_scene_description and are
/// left out here.
std::vector<InteriorWindow> interior_windows(const Geometry& geometry);

/// Generate the scene: rooms with their windows cut out (windows become glazing ports,
/// interior windows are cut out of both rooms' walls and stay ordinary glazing; roof lights
/// cut the ceiling, their glazing a port at the top of their well),
/// polygons, boxes, OBJ meshes, daylight systems (docs/daylight-systems.md; systems may cut
/// the ceiling, add `opening` port enclosures and then make their window an ordinary
/// surface), sensor grids and point files, all rotated by the site's
/// rotation_to_true_north_deg about +Z, then held relative to a local origin when drawn in
/// survey coordinates (SceneDescription::world_origin_m, local_origin.h). Validates the geometry (non-planar polygons,
/// windows outside their wall, overlapping or lying partly in another room's wall, roof
/// lights outside the ceiling or overlapping each other or a light pipe, unknown materials,
/// degenerate faces, NaN/Inf) and throws InputError with located messages.
SceneDescription build_scene_description(const Project& project);

}  // namespace dayphoton::project
