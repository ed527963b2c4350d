// The results model: what a run found, typed, written once by `dayphoton run` as results.json
// in its output folder (docs/outputs.md, "results.json") and read back by the report
// (report/) and anything else that presents a run. It is filled from the run's data in memory
// (study/results_model_builder.h), never from the run's own CSV text, and it carries
// everything a presentation needs that is not a per-sensor value: the project's name, per
// case (base, variants, operated shading) and grid the sensors with their lattice, the plan
// geometry, the metric settings and the summary values, and per quantity the file and column
// that hold its per-sensor values (read with read_quantity_values, one typed reader).
//
// The file has a schema version (ResultsSchemaVersion); a reader refuses another version and
// a results folder without results.json (a run of an older dayphoton) with a located error
// telling to run again. Results are deterministic: results.json holds no times, no cache
// history and no absolute output path, so a repeated run writes the same bytes.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "dayphoton/core/vec3.h"
#include "dayphoton/metrics/illuminance_table.h"

namespace dayphoton::study {

/// Version of results.json's layout; raised when a field changes meaning, is removed, or a
/// required one is added.
constexpr int ResultsSchemaVersion = 4;
/// The file's name in the output folder.
constexpr const char* ResultsFileName = "results.json";

using Polygon3 = std::vector<Vec3>;

/// How a grid's sensors face: up or down (horizontal plane), sideways (a wall), or otherwise.
enum class GridOrientation { Horizontal, Vertical, Tilted };
std::string orientation_name(GridOrientation o);

/// Where each sensor sits on the grid's picture: a lattice (one cell per sensor; columns along
/// the lattice axis closest to east, rows toward the south, or downward on a wall) or, when the
/// sensors are not on one, one row in sensor order.
struct SensorLattice {
  bool regular = false;        ///< false: one row in sensor order
  int columns = 0, rows = 0;
  double spacing_m = 0;        ///< regular only
  Vec3 origin_m;               ///< centre of cell (0, 0)
  Vec3 column_step_m;          ///< world step per column
  Vec3 row_step_m;             ///< world step per row
  std::vector<int> column_of, row_of;  ///< per sensor

  bool operator==(const SensorLattice& o) const;
};

/// How a quantity is coloured (the report's colour scales).
enum class QuantityScale { DaylightFactor, Percent, Illuminance };

/// One per-sensor quantity of a grid and where its values are: `column` of the per-sensor
/// table `file` (relative to the grid's folder; CSV with index,x,y,z first).
struct SensorQuantity {
  std::string stem;      ///< image file name without extension, e.g. "daylight_factor", "da300"
  std::string file;      ///< e.g. "daylight_factor.csv"
  std::string column;    ///< e.g. "df_percent"
  std::string kind;      ///< "daylight_factor", "da", "udi_achieved", "udi_autonomous", "mean_occupied_illuminance", "point_in_time"
  std::string quantity;  ///< words, e.g. "daylight autonomy (300 lx)"
  std::string unit;      ///< "%", "lx"
  QuantityScale scale = QuantityScale::Percent;
  std::string scale_label;  ///< the legend's name, e.g. "UDI achieved"

  bool operator==(const SensorQuantity& o) const;
};

struct DaylightFactorSummary {
  double mean_percent = 0, median_percent = 0, min_percent = 0, max_percent = 0;
  double uniformity = 0;  ///< min / mean
  std::vector<std::pair<double, double>> area_at_or_above_percent;  ///< (threshold %, area %)
  /// Monte Carlo standard error of DF relative to DF, over the sensors with daylight.
  double rms_relative_stderr_percent = 0, max_relative_stderr_percent = 0;
  std::size_t sensors_with_daylight = 0;

  /// What the accuracy target's rounds reached (docs/photon-tracing.md, "Accuracy target");
  /// absent when the project gives photon counts instead.
  struct AccuracyReached {
    double target_percent = 0;   ///< relative standard error of DF asked for, %
    double reached_percent = 0;  ///< its 95th percentile over the sensors after the last round, %
    std::size_t rounds = 0;
    std::uint64_t photons = 0;   ///< stored photons of all sky sources
    std::string stop_reason;     ///< "target met", "photon budget", ... (why the rounds of the case stopped)
    /// The grid's own: "met", "above target" (stop_reason says why) or "not reachable by
    /// photons" (a grid estimated by final gather above the target: accuracy_policy.h).
    std::string status;
    /// A grid estimated by final gather (docs/photon-tracing.md "Accuracy target"): the gather
    /// rays per sensor of its final estimate, its gather rounds after the photon rounds and
    /// their own stop ("target met", "gather photon part", "gather ray limit", "round limit",
    /// "time budget", "direct component"), which says why such a grid is above the target;
    /// gather_rays 0 for a grid the photons serve.
    int gather_rays = 0;
    std::size_t gather_rounds = 0;
    std::string gather_stop_reason{};
    /// The shadow rays per sky patch (direct samples per bin) of the grid's final estimate: the
    /// project's direct_samples_per_bin unless the rounds raised it (up to
    /// MaxDirectSamplesPerBin, plan_policy.h), which says where a "direct rays limit" stopped.
    int direct_samples_per_bin = 0;
    /// A receiver-plane grid's sensors next to a column or partition, estimated by final gather
    /// and left out of the measure (docs/photon-tracing.md "Accuracy target"): how many, their
    /// gather rays per sensor, their gather rounds and those rounds' stop (as gather_stop_reason)
    /// and their largest relative standard error, %; 0 sensors: none.
    std::size_t near_cut_sensors = 0;
    int near_cut_gather_rays = 0;
    double near_cut_largest_percent = 0;
    std::size_t near_cut_gather_rounds = 0;
    std::string near_cut_stop_reason{};

    bool operator==(const AccuracyReached& o) const;
  };
  std::optional<AccuracyReached> accuracy;

  bool operator==(const DaylightFactorSummary& o) const;
};

/// The occupancy the metrics use (docs/metrics.md "Occupancy schedules"): its words and its
/// whole definition, so that `dayphoton annual` rebuilds the same plan from results.json alone
/// (study/recorded_metric_settings.h).
struct OccupancySummary {
  std::string kind;           ///< "daily", "weekly", "hourly"
  double start_h = 8, end_h = 18;  ///< daily only
  std::string description;    ///< the plan's own words

  /// [start_h, end_h) windows of local clock time.
  using Windows = std::vector<std::pair<double, double>>;
  struct Holiday {
    int from_month = 1, from_day = 1, to_month = 1, to_day = 1;
    bool operator==(const Holiday& o) const {
      return from_month == o.from_month && from_day == o.from_day && to_month == o.to_month && to_day == o.to_day;
    }
  };
  // Weekly only (empty otherwise).
  std::array<Windows, 7> week;  ///< Monday .. Sunday; empty: closed
  Windows holiday_hours;
  std::vector<Holiday> holidays;
  std::string january_1;        ///< "Monday" .. "Sunday" as the plan gives it; "": the weather file's
  std::string daylight_saving = "none";  ///< "none", "eu", "us" (weekly and daily)
  // Hourly only.
  std::string hourly;           ///< one '0' or '1' per weather record
  std::string hourly_source;    ///< the CSV file the run read (informational)

  bool operator==(const OccupancySummary& o) const;
};

struct En17037Level {
  std::string level;  ///< "minimum", "medium", "high"
  double target_lux = 0, minimum_target_lux = 0;
  double target_area_percent = 0, minimum_target_area_percent = 0;
  bool passes = false;

  bool operator==(const En17037Level& o) const;
};

/// Grid means of the per-sensor annual metrics, with their settings.
struct AnnualSummary {
  std::size_t sensors = 0, time_steps = 0, occupied_hours = 0;
  // Settings.
  double da_threshold_lux = 300, udi_lower_lux = 100, udi_upper_original_lux = 2000, udi_upper_revised_lux = 3000;
  double sda_time_fraction = 0.5, ase_threshold_lux = 1000, ase_hours = 250;
  OccupancySummary occupancy;
  // Grid means (percent of occupied hours unless lux).
  double da_percent = 0, cda_percent = 0, da_max_percent = 0;
  double udi_below_percent = 0, udi_achieved_percent = 0, udi_above_original_percent = 0;
  double udi_supplementary_percent = 0, udi_autonomous_percent = 0, udi_above_revised_percent = 0;
  double mean_occupied_lux = 0;
  double sda_percent = 0;
  std::size_t sda_sensors = 0;
  std::optional<double> ase_percent;  ///< none: not computed (sun spread into patches)
  // EN 17037 daylight provision; empty levels: not computed.
  std::size_t en17037_daylight_hours = 0;
  std::string en17037_daylight_hours_source;
  /// The model's daylight openings (metrics::en17037_openings_name) and the area the target
  /// must reach for a level to pass (50 %, or 95 % under horizontal openings alone).
  std::string en17037_openings = "vertical or inclined";
  double en17037_target_area_required_percent = 50;
  std::vector<En17037Level> en17037;
  std::string sky;  ///< where the sky matrix came from
  /// Sensors whose DA verdict (DA >= sDA fraction) could flip within 2 standard errors.
  std::optional<std::size_t> da_verdicts_within_2_sigma;
  /// Their share of the area (percent), for a grid whose sensors stand for unequal areas
  /// (GridResult::area_m2); none (and not written) otherwise, where it is the count's share.
  std::optional<double> da_verdicts_within_2_sigma_area_percent;

  /// The highest EN 17037 level passed: "none", or "" when not computed.
  std::string en17037_level() const;
  bool operator==(const AnnualSummary& o) const;
};

/// Illuminance statistics of one point-in-time case on a grid.
struct PointInTimeSummary {
  std::string name, sky;
  double mean_lux = 0, median_lux = 0, min_lux = 0, max_lux = 0, uniformity = 0;
  /// The Monte Carlo uncertainty over the sensors with light (point_in_time.csv
  /// `<case>_stderr_lux` / `<case>_lux`): RMS and largest relative standard error, percent;
  /// absent from files of runs made before it was stated.
  std::optional<double> rms_relative_stderr_percent, max_relative_stderr_percent;
  /// Against the run's accuracy target (point_in_time_accuracy.h); absent without a target and
  /// in files of runs made before it was stated.
  struct AccuracyReached {
    double target_percent = 0;
    double reached_percent = 0;  ///< 95th percentile of the relative standard error
    std::string status;          ///< "met" or "above target"
    std::string stop_reason;     ///< "target met", or the stop of the part that keeps it above
    std::string limiting_part;   ///< "sky", "indirect sun", "direct sun" (above the target)
    bool operator==(const AccuracyReached& o) const;
  };
  std::optional<AccuracyReached> accuracy;

  bool operator==(const PointInTimeSummary& o) const;
};

/// One compliance criterion assessed on a grid by assess_compliance (compliance_verdicts.h):
/// its verdict, or why it was not assessed.
struct Verdict {
  std::string standard;     ///< e.g. "IES LM-83-12", "LEED v4.1 EQ Daylight option 1", "EN 17037", "BREEAM UK NC 2014 Hea 01"
  std::string criterion;    ///< e.g. "sDA300/50%"
  std::string requirement;  ///< in words, e.g. ">= 55 % of the area (nominally accepted)"
  std::optional<double> value;  ///< the grid's value the requirement is tested on; none if not assessed
  std::string unit;         ///< of value: "%", "level"
  /// "pass", "fail" or "not assessed".
  std::string outcome;
  std::string reason;       ///< not assessed: why; otherwise a remark (LEED points, the level reached) or empty

  bool operator==(const Verdict& o) const;
};

/// What the sun bins' accuracy rounds reached on a grid (`sun: bins` with an accuracy target;
/// docs/photon-tracing.md "Accuracy target", "The sun bins"). The measure is the 95th
/// percentile, over the sensors with sun-bin light, of the relative standard error of the
/// sensor's annual sun-bin illuminance (the year's indirect sun summed over every hour).
struct SunAccuracyReached {
  double target_percent = 0;   ///< asked for (the same target as the sky's), %
  double reached_percent = 0;  ///< the annual measure at the percentile after the last round, %
  double hourly_percent = 0;   ///< one hour's relative standard error at the percentile (reported, not targeted), %
  std::size_t rounds = 0;
  std::uint64_t photons = 0;   ///< stored photons of all sun bins of the case
  std::string stop_reason;     ///< "target met", "not reachable by photons", "photon budget", "round limit", "no light"
  std::string status;          ///< the grid's own: "met", "above target", "not reachable by photons"
  /// A grid estimated by final gather: its gather rounds on the annual measure, as the sky's
  /// (DaylightFactorSummary::AccuracyReached); gather_rays 0 for a grid the photons serve.
  int gather_rays = 0;
  std::size_t gather_rounds = 0;
  std::string gather_stop_reason{};
  /// Its sensors next to a cut, as the sky's (DaylightFactorSummary::AccuracyReached), on the
  /// annual measure.
  std::size_t near_cut_sensors = 0;
  int near_cut_gather_rays = 0;
  double near_cut_largest_percent = 0;
  std::size_t near_cut_gather_rounds = 0;
  std::string near_cut_stop_reason{};

  bool operator==(const SunAccuracyReached& o) const;
};

struct GridResult {
  std::string name;
  std::string folder;  ///< relative to the output folder, '/'-separated
  std::vector<Vec3> positions_m, normals;  ///< per sensor, world coordinates
  /// Per sensor, the area it stands for (m^2; SensorGrid::area_m2) when the sensors stand
  /// for unequal areas: every share and mean of the grid is weighted by it. Empty (and not
  /// written) otherwise.
  std::vector<double> area_m2;
  GridOrientation orientation = GridOrientation::Horizontal;
  bool plan = true;   ///< drawn as a plan (horizontal, or points); else an elevation in its plane
  SensorLattice lattice;
  Polygon3 outline;   ///< the room floor, polygon, wall or rectangle the grid covers (may be empty)
  std::vector<int> openings_drawn;  ///< indices into the case's openings drawn on this grid's picture
  std::size_t dropped_outside_rooms = 0, dropped_inside_solid = 0;
  /// On a surface crossing the work plane (placement_check.h; written only when some were).
  std::size_t dropped_on_cut_surface = 0;
  /// In a closed volume no light enters (placement_check.h; written only when some were).
  std::size_t dropped_enclosed = 0;
  std::vector<SensorQuantity> quantities;   ///< in the report's order
  std::optional<DaylightFactorSummary> daylight_factor;
  std::optional<AnnualSummary> annual;
  std::optional<SunAccuracyReached> sun_accuracy;  ///< none: no sun-bin accuracy rounds
  std::vector<PointInTimeSummary> points_in_time;
  bool has_illuminance_table = false;  ///< illuminance.bin in the folder (steps x sensors, lux)
  double spacing_m = 0;  ///< the grid's sensor spacing as generated; 0 for point sets
  std::vector<Verdict> verdicts;  ///< assess_compliance's, in its order

  const SensorQuantity* find_quantity(const std::string& kind) const;
  bool operator==(const GridResult& o) const;
};

/// A material of a case's scene as a report's materials table shows it (photometric values:
/// the RGB values weighted by RADIANCE's luminance weights, core/units.h).
struct MaterialSummary {
  std::string name, type;            ///< type as the project wrote it ("lambertian", "glazing", ...)
  std::optional<double> reflectance;  ///< diffuse + specular reflectance, photometric; none for glass and openings
  std::optional<double> transmittance;  ///< normal-incidence visible transmittance with the window's factors; none if opaque
  double specularity = 0;            ///< fraction of the reflection that is specular
  double area_m2 = 0;                ///< of the scene's surfaces with this material (one side)

  bool operator==(const MaterialSummary& o) const;
};

/// A material taken as operable shading in a case, and why (study/shading_materials.h).
struct ShadingMaterialInPlace {
  std::string material;
  std::string why;  ///< "`shading: operable`", or the BSDF file's DeviceType that names a shading device
  bool operator==(const ShadingMaterialInPlace& o) const { return material == o.material && why == o.why; }
};

/// A window or roof light of a room generator.
struct WindowSummary {
  std::string name;
  std::string wall;    ///< "south", "north", "east", "west" (model directions), or "roof"
  double width_m = 0, height_m = 0, sill_m = 0;  ///< roof lights: width along x, height = length along y, sill = well depth
  double area_m2 = 0;  ///< the opening, width x height
  std::string material;
  double frame_factor = 1, maintenance_factor = 1;

  bool operator==(const WindowSummary& o) const;
};

/// A room of the project's room generator (docs/project-format.md, `rooms`) with its openings.
struct RoomSummary {
  std::string name;
  double width_m = 0, depth_m = 0, height_m = 0;  ///< x, y and z extents (model axes)
  double floor_area_m2 = 0;
  double window_area_m2 = 0;      ///< windows in the walls
  double glazed_wall_area_m2 = 0; ///< gross area of the walls that hold a window
  double roof_light_area_m2 = 0;
  std::vector<WindowSummary> windows;

  /// Window-to-wall ratio of the walls with windows: window area / their gross area.
  double window_to_wall_ratio() const { return glazed_wall_area_m2 > 0 ? window_area_m2 / glazed_wall_area_m2 : 0; }
  /// Glazed openings (windows and roof lights) per floor area.
  double window_to_floor_ratio() const { return floor_area_m2 > 0 ? (window_area_m2 + roof_light_area_m2) / floor_area_m2 : 0; }
  bool operator==(const RoomSummary& o) const;
};

/// A spell of sunlight at a reference point: from start_h to end_h, local standard time of the
/// site's time zone (no daylight saving).
struct SunlightInterval {
  double start_h = 0, end_h = 0;
  bool operator==(const SunlightInterval& o) const { return start_h == o.start_h && end_h == o.end_h; }
};

/// EN 17037's exposure to sunlight at one window (study/sunlight_exposure.h).
struct WindowSunlight {
  std::string name;
  Vec3 reference_point_m;  ///< world coordinates
  std::vector<SunlightInterval> intervals;
  double hours = 0;
  /// Why the window was not assessed (its head below the reference point's height); "" if it was.
  std::string not_assessed;
  bool operator==(const WindowSunlight& o) const;
};

/// EN 17037's exposure to sunlight of one room: the union of its windows' spells.
struct RoomSunlight {
  std::string room;
  std::vector<WindowSunlight> windows;
  std::vector<SunlightInterval> intervals;
  double hours = 0;
  std::string level;  ///< "high", "medium", "minimum", "below minimum", or "not assessed" (no window could be)
  bool operator==(const RoomSunlight& o) const;
};

/// The settings of the sunlight exposure (`sunlight_exposure` of the project).
struct SunlightExposureSettings {
  int month = 3, day = 21, year = 2001;  ///< the date (the year of the sun's ephemeris)
  double min_altitude_deg = 0;
  double time_step_min = 1;
  bool operator==(const SunlightExposureSettings& o) const;
};

/// One case: the project as written ("base"), a variant, or the operated-shading result.
struct CaseResult {
  std::string kind;   ///< "base", "variant", "operated"
  std::string name;   ///< "" for the base; the variant's; "operated (open/shaded)"
  std::string folder; ///< relative to the output folder ("" for the base)
  std::vector<std::string> changes;  ///< a variant's changes, in words
  std::vector<Polygon3> openings;    ///< ports (windows, skylights), world coordinates
  std::vector<Polygon3> systems;     ///< outdoor daylight-system surfaces (shelves, louvres, ...)
  std::vector<MaterialSummary> materials;  ///< materials of the case's surfaces, in the scene's order
  std::vector<RoomSummary> rooms;    ///< the room generator's rooms (none for polygons, meshes, imports)
  double opening_area_m2 = 0;        ///< all openings (ports), one side
  /// Venetian blinds (`blinds` systems) in place in the case, by name; for the operated
  /// result, those of its open case. LM-83-12 computes ASE with every operable shading device
  /// retracted and sDA with the blinds operated hour by hour (section 2.2.6), so neither
  /// verdict is given for a case with blinds in place (compliance_verdicts.h). In results.json
  /// only when some are.
  std::vector<std::string> blinds_in_place;
  /// Materials of the case's surfaces taken as operable shading (study/shading_materials.h):
  /// a blind or a shade drawn as a material; for the operated result, those of its open case.
  /// Neither LM-83 verdict is given with one in place, as with blinds. In results.json only
  /// when some are.
  std::vector<ShadingMaterialInPlace> shading_materials_in_place;
  std::vector<GridResult> grids;
  /// EN 17037 exposure to sunlight, per room (empty: not assessed).
  std::vector<RoomSunlight> sunlight_exposure;

  bool operator==(const CaseResult& o) const;
};

/// A labelled setting of the run ("photons per bin" -> "20000"), in the run's order.
struct Setting {
  std::string name, value;
  bool operator==(const Setting& o) const { return name == o.name && value == o.value; }
};

struct ResultsModel {
  int schema_version = ResultsSchemaVersion;
  std::string project_name;   ///< the project file's name without folder, e.g. "project.yaml"
  /// The project's name for titles: the project file's folder name when the file is called
  /// project.yaml (projects/office/project.yaml -> "office"), else its name without extension.
  std::string title;
  std::string project_file;   ///< as given to the run (informational; never re-read)
  std::string dayphoton_version, compiler;
  std::string study;          ///< "annual" or "daylight_factor"
  // Site and sun.
  std::string site_name;
  double latitude_deg = 0, longitude_deg = 0, time_zone_h = 0, elevation_m = 0;
  bool sun_from_weather = false;
  /// The site the sun was computed for (the project's or the weather header's); set for annual studies.
  std::optional<std::array<double, 4>> sun_site;  ///< latitude, longitude, time zone h, elevation m
  std::string sun_sentence;   ///< sun_site_sentence()
  std::optional<double> station_distance_km;
  std::optional<std::size_t> below_horizon_hours;
  std::string below_horizon_their_sun;
  std::string weather_file;   ///< "" for a daylight-factor study
  // Simulation settings used by the sky images.
  std::string basis = "tregenza";  ///< "tregenza" or "reinhart"
  int reinhart_mf = 1;
  double ground_reflectance = 0.2;
  std::vector<Setting> settings;   ///< every simulation setting, labelled
  std::vector<std::string> notes;
  /// What the run did not assess, one sentence each (assess_compliance): criteria the report
  /// must name as not assessed, e.g. EN 17037's view out.
  std::vector<std::string> not_assessed;
  std::vector<CaseResult> cases;   ///< base first, then variants, then operated
  /// The project's `sunlight_exposure` settings; absent: not assessed.
  std::optional<SunlightExposureSettings> sunlight_exposure;

  bool operator==(const ResultsModel& o) const;
};

/// results.json's text (UTF-8 JSON, 2-space indent, keys as docs/outputs.md lists them).
std::string results_json(const ResultsModel& model);

/// Parse results.json's text; `path` names it in errors. InputError (located at the path,
/// naming the key) for text that is not JSON, a missing or mistyped field, or another schema
/// version.
ResultsModel parse_results_json(const std::string& text, const std::string& path);

/// Write <output_dir>/results.json atomically; returns its path.
std::string write_results_model(const ResultsModel& model, const std::string& output_dir);

/// Read <results_dir>/results.json. A folder without it (written by a dayphoton before
/// results.json existed, or not a results folder) is an InputError telling to run again.
ResultsModel read_results_model(const std::string& results_dir);

/// The per-sensor values of `quantity` of `grid` (the model's one typed reader of value
/// tables): column `quantity.column` of <results_dir>/<grid.folder>/<quantity.file>.
/// InputError (located) for a missing or malformed table, a missing column, or a row count
/// other than the grid's sensors.
std::vector<double> read_quantity_values(const std::string& results_dir, const GridResult& grid,
                                         const SensorQuantity& quantity);

/// The annual illuminance of `grid` (illuminance.bin in its folder: steps x sensors, lux; the
/// model's one typed reader of it). InputError (located at the file) if the model says the grid
/// has none (`illuminance_table` false), or the file is missing, malformed
/// (study/annual_illuminance.h) or holds another number of sensors than the grid.
metrics::IlluminanceTable read_illuminance_table(const std::string& results_dir, const GridResult& grid);

/// The folder of `grid` inside `results_dir`; InputError if the model's relative folder names
/// lead outside it (an edited results.json must not make a reader write elsewhere).
std::string grid_folder(const std::string& results_dir, const GridResult& grid);

}  // namespace dayphoton::study
