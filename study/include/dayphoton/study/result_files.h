// The per-grid result files of DESIGN.md section 6, written atomically. CSV tables have one
// header row and start with index,x,y,z; value columns carry their unit in the name.
#pragma once

#include <string>
#include <vector>

#include "dayphoton/core/scene_description.h"
#include "dayphoton/metrics/annual_metrics.h"
#include "dayphoton/metrics/illuminance_table.h"

namespace dayphoton::study {

/// sensors.csv: index,x,y,z,nx,ny,nz (metres, world coordinates; micrometre resolution),
/// then `area_m2` (SensorGrid::area_m2, the shortest text of each double) when `area_m2` is
/// not empty: the grid's sensors stand for unequal areas.
void write_sensors_csv(const std::vector<SensorPoint>& sensors, const std::vector<double>& area_m2,
                       const std::string& path);
/// Read a sensors.csv back (`dayphoton annual` takes the coordinates from it, and the areas
/// into `area_m2` when given: empty without the column). Throws InputError located
/// file:line:field on a wrong header, a non-number, a negative area or an index out of
/// sequence.
std::vector<SensorPoint> read_sensors_csv(const std::string& path, std::vector<double>* area_m2 = nullptr);
/// daylight_factor.csv: index,x,y,z,df_percent (4 decimals), and df_stderr_percent (the
/// Monte Carlo standard error of df_percent, 4 decimals) when `stderr_percent` is not empty.
void write_daylight_factor_csv(const std::vector<SensorPoint>& sensors,
                               const std::vector<double>& df_percent, const std::string& path,
                               const std::vector<double>& stderr_percent = {});
/// point_in_time.csv: index,x,y,z then one `<case>_lux` column per point-in-time case
/// (`case_names`, in file order), lux with 1 decimal, each followed by `<case>_stderr_lux`
/// (its Monte Carlo standard error, lux with 1 decimal; point_in_time_uncertainty.h) when
/// `stderr_lux` (per case, per sensor) is not empty. `table` has one step per case.
void write_point_in_time_csv(const std::vector<SensorPoint>& sensors, const std::vector<std::string>& case_names,
                             const metrics::IlluminanceTable& table, const std::string& path,
                             const std::vector<std::vector<double>>& stderr_lux = {});
/// metrics.csv: index,x,y,z then da<X>_percent, cda<X>_percent, damax_percent,
/// udi_below<L>_percent, udi<L>_<U1>_percent, udi_above<U1>_percent,
/// udi_supplementary<L>_<X>_percent, udi_autonomous<X>_<U2>_percent, udi_above<U2>_percent,
/// mean_occupied_lux, and ase_hours if `ase_hours` is non-empty. X = da_threshold_lux,
/// L = udi_lower_lux, U1 = udi_upper_original_lux, U2 = udi_upper_revised_lux, written in
/// their shortest form (defaults: 300, 100, 2000, 3000). Percentages with 3 decimals, lux 1.
/// Throws std::invalid_argument if the counts of sensors, metrics and ASE hours differ.
void write_metrics_csv(const std::vector<SensorPoint>& sensors,
                       const std::vector<metrics::SensorMetrics>& metrics,
                       const metrics::MetricSettings& settings, const std::vector<int>& ase_hours,
                       const std::string& path);
/// The header of metrics.csv for these settings, in order.
std::vector<std::string> metrics_csv_columns(const metrics::MetricSettings& settings, bool with_ase);

}  // namespace dayphoton::study
