// The per-grid result files of DESIGN.md section 6, written atomically. CSV tables have one
// header row and start with index,x,y,z; value columns carry their unit in the name.
#pragma once

#include <string>
#include <vector>

#include "dayphoton/core/scene_description.h"
#include "dayphoton/metrics/annual_metrics.h"

namespace dayphoton::study {

/// sensors.csv: index,x,y,z,nx,ny,nz (metres, world coordinates).
void write_sensors_csv(const std::vector<SensorPoint>& sensors, const std::string& path);
/// daylight_factor.csv: index,x,y,z,df_percent.
void write_daylight_factor_csv(const std::vector<SensorPoint>& sensors,
                               const std::vector<double>& df_percent, const std::string& path);
/// metrics.csv: index,x,y,z then da<X>_percent, cda<X>_percent, damax_percent,
/// udi_below100_percent, udi100_2000_percent, udi_above2000_percent,
/// udi_supplementary100_<X>_percent, udi_autonomous<X>_3000_percent, udi_above3000_percent,
/// mean_occupied_lux, and ase_hours if `ase_hours` is non-empty (X = the DA threshold).
void write_metrics_csv(const std::vector<SensorPoint>& sensors,
                       const std::vector<metrics::SensorMetrics>& metrics,
                       const metrics::MetricSettings& settings, const std::vector<int>& ase_hours,
                       const std::string& path);

}  // namespace dayphoton::study
