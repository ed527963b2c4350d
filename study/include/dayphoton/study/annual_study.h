// AnnualStudy: from exported sky coefficients and an annual sky matrix to the annual
// illuminance table, the per-sensor and grid metrics, and their files (issue 5 items 4-6).
// Used by `dayphoton run` after the coefficients are estimated and by `dayphoton annual` on
// coefficients exported by an earlier run; both go through compute_annual_study so their
// results agree exactly for the same inputs.
//
// Conventions (docs/outputs.md, docs/metrics.md, DESIGN.md section 4):
//  - coefficients: sensors x bins x RGB, irradiance (W/m^2) per unit bin radiance, RADIANCE
//    row order (bin 0 = ground), i.e. what coefficients_sky.mtx and rfluxmtx hold;
//  - sky matrix: bins x steps x RGB radiance W/(sr m^2), one column per weather record, either
//    built from the EPW in the RADIANCE-compatible mode (gendaymtx -m MF: sun spread into the 4
//    nearest patches, patch-centre Perez values, RADIANCE's sun formulas, sky colour, 11 C dew
//    point) or read from a RADIANCE matrix file such as gendaymtx output;
//  - time stamps from the EPW via weather::SiteClock: mid-hour, local standard time, no DST;
//  - occupancy: a metrics::OccupancyPlan, default daily hours [8, 18) of the mid-hour stamp
//    (3650 h); weekly plans take the weekday of 1 January and the time zone from the EPW;
//  - ASE only from a direct-sun-only, zero-bounce table (LM-83); EN 17037 over the daylight
//    hours = the brightest half of the steps by the EPW's diffuse horizontal illuminance.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "dayphoton/core/radiance_matrix.h"
#include "dayphoton/core/scene_description.h"
#include "dayphoton/metrics/annual_metrics.h"
#include "dayphoton/metrics/illuminance_table.h"
#include "dayphoton/metrics/occupancy.h"
#include "dayphoton/metrics/occupancy_plan.h"
#include "dayphoton/sky/patch_basis.h"
#include "dayphoton/sky/sky_matrix.h"
#include "dayphoton/study/sub_patch_shares.h"
#include "dayphoton/weather/hourly_weather.h"

namespace dayphoton::study {

/// The sky side of an annual study: the matrix and what each of its columns stands for.
struct AnnualSky {
  RadianceMatrix matrix;                  ///< bins x steps x RGB radiance, W/(sr m^2)
  std::vector<metrics::TimeStamp> steps;  ///< one per column
  /// Per step, the quantity that ranks the EN 17037 daylight hours (diffuse horizontal
  /// illuminance of the weather file, lux); empty: EN 17037 is not computed.
  std::vector<double> daylight_hours_quantity;
  std::string daylight_hours_source;  ///< what that quantity is, for the summary
  std::string description;            ///< where the matrix came from, for the summary
  /// The sky's quadrant deltas (sky::SkyMatrix::quadrant_deltas) for the direct part's
  /// sub-patch correction (sub_patch_shares.h); empty for a matrix read from a file.
  RadianceMatrix quadrant_deltas;
};

/// Time stamps of the EPW records: month, day and mid-hour local standard time (SiteClock).
std::vector<metrics::TimeStamp> time_stamps(const weather::HourlyWeather& weather);

/// The EN 17037 ranking quantity of every record: the diffuse horizontal illuminance field
/// (lux) when every record has it; otherwise the diffuse horizontal irradiance (W/m^2, which
/// orders the hours nearly alike) when every record has that; otherwise empty. A record whose
/// illuminance reads 0 under a positive diffuse irradiance (a field a converter left at 0)
/// takes that irradiance times the file's mean diffuse efficacy (illuminance over irradiance
/// of the records with both), or the whole ranking is the irradiance's when no record has
/// both. `source` receives which one was used.
std::vector<double> daylight_hours_quantity(const weather::HourlyWeather& weather, std::string& source);

/// The RADIANCE-compatible sky options: SkyMatrixOptions::gendaymtx_compatible() with the sun
/// spread into patches (the mode in which sky coefficients alone give the annual result).
sky::SkyMatrixOptions radiance_compatible_sky_options(double ground_reflectance = 0.2);

/// AnnualSky::description of annual_sky_from_weather (the same text whether the matrix is built
/// or read from the cache, so a cached run writes the same files).
std::string annual_sky_description(const weather::HourlyWeather& weather, const sky::PatchBasis& basis,
                                   const sky::SkyMatrixOptions& options);

/// Sky matrix built from the EPW with build_sky_matrix for the sun of `site` (the project's,
/// study/sun_site.h; its time zone must be the file's), stamped with the EPW's time steps,
/// with its quadrant deltas.
AnnualSky annual_sky_from_weather(const weather::HourlyWeather& weather, const sky::SolarSite& site,
                              const sky::PatchBasis& basis, const sky::SkyMatrixOptions& options);

/// The quadrant deltas (sky::SkyMatrix::quadrant_deltas) of the sky annual_sky_from_weather
/// builds with `options`: for a matrix taken from the cache (they are not cached: a second of
/// Perez evaluations for a year).
RadianceMatrix annual_quadrant_deltas(const weather::HourlyWeather& weather, const sky::SolarSite& site,
                                      const sky::PatchBasis& basis, sky::SkyMatrixOptions options);

/// Sky matrix read from a RADIANCE matrix file (read_matrix_file), stamped with the EPW's
/// time steps. Throws InputError naming the matrix file if its column count differs from the
/// EPW's records.
AnnualSky annual_sky_from_matrix_file(const std::string& matrix_path, const weather::HourlyWeather& weather,
                                      const MatrixReadOptions& options = {},
                                      std::uint64_t max_decompressed_bytes = ResourceLimits{}.decompressed_bytes);

/// Read a RADIANCE matrix file (ascii/float/double) with RadianceMatrix::read's checks; a
/// name ending in ".gz" is decompressed by zlib as it is parsed, at most
/// max_decompressed_bytes (GzipInput). Errors are InputError naming the file.
RadianceMatrix read_matrix_file(const std::string& path, const MatrixReadOptions& options = {},
                                std::uint64_t max_decompressed_bytes = ResourceLimits{}.decompressed_bytes);

/// The calendar of an EPW for occupancy plans: the weekday of 1 January from the DATA
/// PERIODS start day and date, and the time zone.
metrics::WeatherCalendar weather_calendar(const weather::HourlyWeather& weather);

/// Settings of the metrics: thresholds and the occupancy (docs/metrics.md).
struct AnnualStudySettings {
  metrics::MetricSettings metrics;
  metrics::OccupancyPlan occupancy;    ///< default 08:00-18:00 every day, local standard time
  metrics::WeatherCalendar calendar;   ///< of the weather file (weather_calendar)
  /// The area each sensor stands for (m^2; SensorGrid::area_m2, sensors.csv's `area_m2`):
  /// every area share and grid mean is weighted by it; empty: equal shares.
  std::vector<double> sensor_area_m2;
};

/// The occupied steps of `settings` for `steps`. Throws std::invalid_argument for a daily
/// window outside 0 <= start < end <= 24, and InputError (at the plan's location) for a plan
/// that does not fit the weather file or leaves no occupied step.
metrics::OccupancySchedule occupancy_schedule(const AnnualStudySettings& settings,
                                              const std::vector<metrics::TimeStamp>& steps);

/// Everything computed for one grid.
struct AnnualStudy {
  metrics::IlluminanceTable illuminance;  ///< steps x sensors, lux; night steps 0
  std::size_t occupied_hours = 0;
  std::vector<metrics::SensorMetrics> sensors;
  std::vector<int> ase_hours;  ///< per sensor; empty unless a direct-sun table was given
  metrics::GridMetrics grid;   ///< ase_percent -1 and en17037 empty when not computed
  std::string sky_description;
  std::string daylight_hours_source;
};

/// Multiply and evaluate. `direct_sun` (optional): the direct-sun-only, zero-bounce
/// illuminance table for ASE (same steps and sensors). Throws std::invalid_argument on
/// shape mismatches (coefficient bins vs sky bins, steps, sensors). `shares` (optional): the
/// coefficients' sub-patch shares, applied with sky.quadrant_deltas (annual_illuminance).
AnnualStudy compute_annual_study(const RadianceMatrix& coefficients, const AnnualSky& sky,
                                 const AnnualStudySettings& settings,
                                 const metrics::IlluminanceTable* direct_sun = nullptr,
                                 const SubPatchShares* shares = nullptr);

/// The grid's metrics from `study.sensors` (and `study.ase_hours` when `with_ase`), and
/// EN 17037's from `study.illuminance` over the brightest half of `daylight_hours_quantity`
/// (none when it is empty), every share and mean weighted by settings.sensor_area_m2: the
/// one place the grid's shares are computed. Throws std::invalid_argument on a size mismatch.
void summarize_annual_study(AnnualStudy& study, const AnnualStudySettings& settings, bool with_ase,
                            const std::vector<double>& daylight_hours_quantity,
                            const std::string& daylight_hours_source);

/// The grid metrics as a JSON object (text), for summary.json: sensor and occupied-hour
/// counts, the settings, the means of every per-sensor metric, sDA, ASE (null if not
/// computed) and the EN 17037 levels (null if not computed). Keys carry units.
std::string grid_metrics_json(const AnnualStudy& study, const AnnualStudySettings& settings);

/// Which files write_annual_outputs writes.
struct AnnualOutputs {
  bool illuminance = true;  ///< illuminance.bin
  bool metrics = true;      ///< metrics.csv and grid_metrics.json
  bool illuminance_csv = false;  ///< with illuminance: illuminance.csv too
};

/// Write illuminance.csv (only with outputs.illuminance_csv), illuminance.bin, metrics.csv and
/// grid_metrics.json into `folder` (created if missing), each atomically. `sensors` gives the coordinates of the rows.
/// Returns the paths written, in that order.
std::vector<std::string> write_annual_outputs(const AnnualStudy& study, const std::vector<SensorPoint>& sensors,
                                              const AnnualStudySettings& settings, const std::string& folder,
                                              const AnnualOutputs& outputs = {});

/// write_annual_outputs while `alongside` runs (oneTBB's parallel_invoke; both must only read
/// the study): the writing, on one thread and mostly illuminance.bin, overlaps parallel work
/// such as the verdicts' uncertainty. Returns write_annual_outputs' paths once both are done;
/// an exception of either is rethrown then.
std::vector<std::string> write_annual_outputs_beside(const AnnualStudy& study, const std::vector<SensorPoint>& sensors,
                                                     const AnnualStudySettings& settings, const std::string& folder,
                                                     const AnnualOutputs& outputs,
                                                     const std::function<void()>& alongside);

}  // namespace dayphoton::study
