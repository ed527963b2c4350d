// Annual climate-based daylight metrics per sensor and per grid. Definitions, threshold
// operators and sources are in docs/metrics.md (from ../shared/facts/sky-and-metrics.md
// section 5); every percentage is of the occupied steps, night steps included as 0 lux.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "dayphoton/metrics/illuminance_table.h"
#include "dayphoton/metrics/occupancy.h"

namespace dayphoton::metrics {

struct MetricSettings {
  double da_threshold_lux = 300;         ///< DA, cDA, sDA threshold
  double udi_lower_lux = 100;            ///< below: "fell short"
  double udi_upper_original_lux = 2000;  ///< Nabil & Mardaljevic 2005
  double udi_upper_revised_lux = 3000;   ///< Mardaljevic's revision, split at da_threshold_lux
  double sda_time_fraction = 0.5;        ///< sDA300/50%
  double ase_threshold_lux = 1000;       ///< ASE1000,250 (direct sun only)
  double ase_hours = 250;                ///< more than this many occupied hours fails a sensor
  /// EN 17037:2018 daylight provision: the daylight openings of the model. Under horizontal
  /// openings alone (roof lights) the standard asks the target illuminance over 95 % of the
  /// reference plane instead of 50 % (en17037_target_area_required_percent); a model with
  /// both kinds is assessed with the rule for vertical and inclined openings (and warned
  /// about where the run finds it).
  enum class Openings { VerticalOrInclined, Horizontal, Both };
  Openings en17037_openings = Openings::VerticalOrInclined;
};

/// "vertical or inclined", "horizontal", "vertical or inclined, and horizontal" (results.json),
/// and back (nullopt for any other text).
const char* en17037_openings_name(MetricSettings::Openings openings);
std::optional<MetricSettings::Openings> parse_en17037_openings(const std::string& name);

/// Per-sensor metrics (percent of occupied steps unless the name says otherwise).
struct SensorMetrics {
  double da_percent = 0;          ///< E >= X
  double cda_percent = 0;         ///< mean of min(1, E/X)
  double da_max_percent = 0;      ///< E > 10 X (Rogers 2006)
  double udi_below_percent = 0;   ///< E < 100
  double udi_original_percent = 0;  ///< 100 <= E <= 2000
  double udi_above_original_percent = 0;  ///< E > 2000
  double udi_supplementary_percent = 0;   ///< 100 <= E < 300 (revised UDI)
  double udi_autonomous_percent = 0;      ///< 300 <= E <= 3000 (revised UDI)
  double udi_above_revised_percent = 0;   ///< E > 3000
  double mean_occupied_lux = 0;
};

std::vector<SensorMetrics> compute_sensor_metrics(const IlluminanceTable& table,
                                                  const OccupancySchedule& occupancy,
                                                  const MetricSettings& settings = {});

/// Hours (occupied steps) per sensor with direct-sun illuminance >= the ASE threshold.
/// `direct_sun` is the zero-bounce, direct-sun-only table (blinds open) per LM-83.
std::vector<int> ase_hours_per_sensor(const IlluminanceTable& direct_sun,
                                      const OccupancySchedule& occupancy,
                                      const MetricSettings& settings = {});

/// EN 17037:2018 daylight provision (climate-based method) for one level.
struct En17037Level {
  const char* name;
  double target_lux;          ///< over 50 % of the plane (95 % under horizontal openings)
  double minimum_target_lux;  ///< over 95 % of the plane
};
/// The share of the reference plane (percent) that must reach the minimum target, and the
/// target under daylight openings in vertical and inclined surfaces and under horizontal
/// ones (EN 17037:2018, Annex A, Table A.1 and its rule for horizontal openings).
constexpr double En17037MinimumTargetAreaPercent = 95.0;
constexpr double En17037TargetAreaPercentVertical = 50.0;
constexpr double En17037TargetAreaPercentHorizontal = 95.0;
double en17037_target_area_required_percent(const MetricSettings& settings);
constexpr En17037Level En17037Levels[3] = {
    {"minimum", 300, 100}, {"medium", 500, 300}, {"high", 750, 500}};

struct En17037Result {
  const char* level = "";
  double target_area_percent = 0;          ///< sensors with E >= target for >= 50 % of daylight hours
  double minimum_target_area_percent = 0;  ///< same for the minimum target
  bool passes = false;  ///< target area >= target_area_required_percent and minimum area >= 95 %
  /// The area the target must reach: 50 %, or 95 % under horizontal openings.
  double target_area_required_percent = En17037TargetAreaPercentVertical;
};

/// Grid summary: area-weighted means (equal weights when `area_weights` is empty).
struct GridMetrics {
  SensorMetrics mean;              ///< weighted mean of every per-sensor value
  double sda_percent = 0;          ///< area with DA >= sda_time_fraction
  double ase_percent = -1;         ///< area with more than ase_hours; -1 if not computed
  std::vector<En17037Result> en17037;  ///< empty if not computed
};

GridMetrics summarize_grid(const std::vector<SensorMetrics>& sensors, const MetricSettings& settings,
                           const std::vector<double>& area_weights = {},
                           const std::vector<int>* ase_hours = nullptr);

/// EN 17037 levels from the table over the given daylight-hours schedule.
std::vector<En17037Result> en17037_daylight_provision(const IlluminanceTable& table,
                                                      const OccupancySchedule& daylight_hours,
                                                      const std::vector<double>& area_weights = {},
                                                      const MetricSettings& settings = {});

}  // namespace dayphoton::metrics
