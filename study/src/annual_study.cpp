// AnnualStudy: coefficients x sky matrix -> illuminance table -> metrics -> files. The
// conventions are stated in annual_study.h and docs/outputs.md; the metric definitions are
// docs/metrics.md (metrics/). This file only wires the pieces and checks that their shapes
// agree, naming the file at fault where there is one.
#include "dayphoton/study/annual_study.h"

#include <cstdio>
#include <iterator>
#include <filesystem>
#include <sstream>
#include <stdexcept>

#include <nlohmann/json.hpp>
#include <tbb/parallel_invoke.h>

#include "dayphoton/core/atomic_file.h"
#include "dayphoton/core/diagnostics.h"
#include "dayphoton/core/gzip_input.h"
#include "dayphoton/study/annual_illuminance.h"
#include "dayphoton/study/result_files.h"
#include "dayphoton/weather/site_clock.h"
#include "json_text.h"
#include "json_values.h"

namespace dayphoton::study {

namespace {

std::string describe_options(const sky::SkyMatrixOptions& o, const sky::PatchBasis& basis) {
  std::ostringstream d;
  d << "Perez sky matrix, " << (basis.multiplication_factor() == 1 ? std::string("Tregenza")
                                                                   : "Reinhart MF " + std::to_string(basis.multiplication_factor()))
    << " basis (" << basis.bin_count() << " bins), "
    << (o.patch_value == sky::PatchValue::Centre ? "patch-centre values" : "patch-mean values") << ", sun "
    << (o.sun == sky::SunInMatrix::Spread ? "spread into 4 patches" : o.sun == sky::SunInMatrix::None ? "left out" : "only")
    << ", " << (o.solar.algorithm == sky::SolarPositionAlgorithm::Spa ? "NREL SPA" : "RADIANCE") << " sun positions, "
    << "ground reflectance " << format_number(o.ground_reflectance);
  return d.str();
}

}  // namespace

std::vector<metrics::TimeStamp> time_stamps(const weather::HourlyWeather& weather) {
  const weather::SiteClock clock = weather::SiteClock::for_weather(weather);
  std::vector<metrics::TimeStamp> stamps;
  stamps.reserve(weather.records.size());
  for (const weather::TimeStep& step : clock.steps(weather.records))
    stamps.push_back(metrics::TimeStamp{step.month, step.day, step.hour_lst});
  return stamps;
}

metrics::WeatherCalendar weather_calendar(const weather::HourlyWeather& weather) {
  metrics::WeatherCalendar calendar;
  calendar.time_zone_h = weather.site.time_zone_h;
  if (weather.format == weather::WeatherFormat::Wea) {
    calendar.january_1_source = weather.source_name + " (a .wea file names no weekday)";
    return calendar;
  }
  const std::string date = std::to_string(weather.start_month) + "/" + std::to_string(weather.start_day);
  if (const auto start = metrics::parse_weekday(weather.start_weekday)) {
    calendar.january_1 =
        metrics::january_1_from(*start, weather.start_month, weather.start_day, weather.leap_day_present);
    calendar.january_1_source = "the DATA PERIODS of " + weather.source_name + ": " + metrics::weekday_name(*start) + " " + date;
  } else {
    calendar.january_1_source = "the DATA PERIODS of " + weather.source_name + " start " + date + " on '" +
                                weather.start_weekday + "', not a weekday";
  }
  return calendar;
}

metrics::OccupancySchedule occupancy_schedule(const AnnualStudySettings& settings,
                                              const std::vector<metrics::TimeStamp>& steps) {
  const metrics::OccupancyPlan& plan = settings.occupancy;
  if (plan.kind == metrics::OccupancyPlan::Kind::Daily &&
      !(plan.daily.start_h >= 0 && plan.daily.start_h < plan.daily.end_h && plan.daily.end_h <= 24))
    throw std::invalid_argument("occupancy window must satisfy 0 <= start < end <= 24 hours");
  metrics::OccupancySchedule schedule = plan.schedule(steps, settings.calendar);
  if (schedule.occupied_count() == 0 && !steps.empty())
    throw InputError(plan.location, "the occupancy (" + plan.description() + ") leaves no occupied hour in the " +
                                        std::to_string(steps.size()) + " records of the weather file");
  return schedule;
}

std::vector<double> daylight_hours_quantity(const weather::HourlyWeather& weather, std::string& source) {
  std::vector<double> lux, w_m2;
  for (const weather::WeatherRecord& r : weather.records) {
    if (r.diffuse_horizontal_lux) lux.push_back(*r.diffuse_horizontal_lux);
    if (r.diffuse_horizontal_w_m2) w_m2.push_back(*r.diffuse_horizontal_w_m2);
  }
  const bool all_irradiance = !weather.records.empty() && w_m2.size() == weather.records.size();
  if (!weather.records.empty() && lux.size() == weather.records.size()) {
    if (!all_irradiance) {
      source = "diffuse horizontal illuminance of " + weather.source_name;
      return lux;
    }
    // 0 lx of diffuse illuminance under a positive diffuse irradiance is no measurement: a
    // converter that does not compute the illuminance fields writes 0 in every record, others
    // write 0 where their own sun is below the horizon. Ranked as 0 lx such hours tie with
    // the nights, and the ties (broken by the earlier hour) would put nights of January into
    // the daylight hours: with a field of zeros, the first 4380 records of the year. They
    // take their irradiance times the file's own mean diffuse efficacy instead (the
    // illuminance over the irradiance of the records that have both), or, in a file with
    // no such record, the ranking is the irradiance's.
    double lux_sum = 0, w_m2_sum = 0;
    std::size_t unmeasured = 0;
    for (std::size_t t = 0; t < lux.size(); ++t) {
      if (lux[t] > 0 && w_m2[t] > 0) {
        lux_sum += lux[t];
        w_m2_sum += w_m2[t];
      } else if (!(lux[t] > 0) && w_m2[t] > 0) {
        ++unmeasured;
      }
    }
    if (unmeasured == 0) {
      source = "diffuse horizontal illuminance of " + weather.source_name;
      return lux;
    }
    if (!(w_m2_sum > 0)) {
      source = "diffuse horizontal irradiance of " + weather.source_name +
               " (its illuminance field reads 0 lx in every record with diffuse irradiance)";
      return w_m2;
    }
    const double efficacy_lm_W = lux_sum / w_m2_sum;
    for (std::size_t t = 0; t < lux.size(); ++t)
      if (!(lux[t] > 0) && w_m2[t] > 0) lux[t] = w_m2[t] * efficacy_lm_W;
    char note[160];
    std::snprintf(note, sizeof note, " (%zu records reading 0 lx under diffuse irradiance ranked by it times the file's mean diffuse efficacy, %.1f lm/W)",
                  unmeasured, efficacy_lm_W);
    source = "diffuse horizontal illuminance of " + weather.source_name + note;
    return lux;
  }
  if (all_irradiance) {
    source = "diffuse horizontal irradiance of " + weather.source_name +
             (weather.format == weather::WeatherFormat::Wea ? " (a .wea file has no illuminance)"
                                                             : " (its illuminance field has missing values)");
    return w_m2;
  }
  source = "none: " + weather.source_name + " lacks diffuse horizontal values";
  return {};
}

sky::SkyMatrixOptions radiance_compatible_sky_options(double ground_reflectance) {
  sky::SkyMatrixOptions o = sky::SkyMatrixOptions::gendaymtx_compatible();
  o.sun = sky::SunInMatrix::Spread;
  o.ground_reflectance = ground_reflectance;
  return o;
}

std::string annual_sky_description(const weather::HourlyWeather& weather, const sky::PatchBasis& basis,
                                   const sky::SkyMatrixOptions& options) {
  return describe_options(options, basis) + ", from " + weather.source_name;
}

AnnualSky annual_sky_from_weather(const weather::HourlyWeather& weather, const sky::SolarSite& site,
                              const sky::PatchBasis& basis, const sky::SkyMatrixOptions& options) {
  AnnualSky result;
  sky::SkyMatrixOptions with_deltas = options;
  with_deltas.quadrant_deltas = true;
  sky::SkyMatrix built = sky::build_sky_matrix(weather, site, basis, with_deltas);
  result.matrix = std::move(built.matrix);
  result.quadrant_deltas = std::move(built.quadrant_deltas);
  result.steps = time_stamps(weather);
  result.daylight_hours_quantity = daylight_hours_quantity(weather, result.daylight_hours_source);
  result.description = annual_sky_description(weather, basis, options);
  return result;
}

RadianceMatrix annual_quadrant_deltas(const weather::HourlyWeather& weather, const sky::SolarSite& site,
                                      const sky::PatchBasis& basis, sky::SkyMatrixOptions options) {
  options.quadrant_deltas = true;
  return sky::build_sky_matrix(weather, site, basis, options).quadrant_deltas;
}

RadianceMatrix read_matrix_file(const std::string& path, const MatrixReadOptions& options,
                                std::uint64_t max_decompressed_bytes) {
  if (!has_gzip_extension(path)) return RadianceMatrix::read_file(path, options);
  // Decompressed as it is parsed: the parser's size checks stop a bad header early, and the
  // decompressed-size limit stops a stream of padding.
  GzipInput in(path, max_decompressed_bytes, "matrix file", "--max-decompressed-bytes");
  return RadianceMatrix::read(in, path, options);
}

AnnualSky annual_sky_from_matrix_file(const std::string& matrix_path, const weather::HourlyWeather& weather,
                                      const MatrixReadOptions& options, std::uint64_t max_decompressed_bytes) {
  AnnualSky result;
  result.matrix = read_matrix_file(matrix_path, options, max_decompressed_bytes);
  result.steps = time_stamps(weather);
  if (result.matrix.columns() != result.steps.size())
    throw InputError(SourceLocation{matrix_path, 0, 0},
                     "the sky matrix has " + std::to_string(result.matrix.columns()) +
                         " columns (time steps) but the weather file " + weather.source_name + " has " +
                         std::to_string(result.steps.size()) + " records");
  result.daylight_hours_quantity = daylight_hours_quantity(weather, result.daylight_hours_source);
  result.description = "RADIANCE matrix " + matrix_path + " (" + std::to_string(result.matrix.rows()) +
                       " bins), time steps of " + weather.source_name;
  return result;
}

AnnualStudy compute_annual_study(const RadianceMatrix& coefficients, const AnnualSky& sky,
                                 const AnnualStudySettings& settings, const metrics::IlluminanceTable* direct_sun,
                                 const SubPatchShares* shares) {
  const metrics::OccupancySchedule occupancy = occupancy_schedule(settings, sky.steps);
  AnnualStudy study;
  study.illuminance = annual_illuminance(coefficients, sky.matrix, sky.steps, 0, shares, &sky.quadrant_deltas);
  study.sky_description = sky.description;
  study.occupied_hours = occupancy.occupied_count();
  study.sensors = metrics::compute_sensor_metrics(study.illuminance, occupancy, settings.metrics);
  if (direct_sun) {
    if (direct_sun->step_count() != sky.steps.size() || direct_sun->sensor_count() != coefficients.rows())
      throw std::invalid_argument("the direct-sun table has " + std::to_string(direct_sun->step_count()) +
                                  " steps x " + std::to_string(direct_sun->sensor_count()) +
                                  " sensors, the study " + std::to_string(sky.steps.size()) + " x " +
                                  std::to_string(coefficients.rows()));
    study.ase_hours = metrics::ase_hours_per_sensor(*direct_sun, occupancy, settings.metrics);
  }
  summarize_annual_study(study, settings, direct_sun != nullptr, sky.daylight_hours_quantity,
                         sky.daylight_hours_source);
  return study;
}

void summarize_annual_study(AnnualStudy& study, const AnnualStudySettings& settings, bool with_ase,
                            const std::vector<double>& daylight_hours_quantity,
                            const std::string& daylight_hours_source) {
  const std::vector<double>& area_m2 = settings.sensor_area_m2;
  if (!area_m2.empty() && area_m2.size() != study.sensors.size())
    throw std::invalid_argument("the grid has " + std::to_string(area_m2.size()) + " sensor areas for " +
                                std::to_string(study.sensors.size()) + " sensors");
  study.grid = metrics::summarize_grid(study.sensors, settings.metrics, area_m2, with_ase ? &study.ase_hours : nullptr);
  if (daylight_hours_quantity.empty()) return;
  if (daylight_hours_quantity.size() != study.illuminance.step_count())
    throw std::invalid_argument("daylight-hours quantity has " + std::to_string(daylight_hours_quantity.size()) +
                                " values for " + std::to_string(study.illuminance.step_count()) + " steps");
  study.grid.en17037 = metrics::en17037_daylight_provision(
      study.illuminance, metrics::OccupancySchedule::brightest_half(daylight_hours_quantity), area_m2, settings.metrics);
  study.daylight_hours_source = daylight_hours_source;
}

static nlohmann::json occupancy_json(const AnnualStudySettings& settings) {
  using nlohmann::json;
  const metrics::OccupancyPlan& plan = settings.occupancy;
  switch (plan.kind) {
    case metrics::OccupancyPlan::Kind::Daily:
      return {{"start_h", plan.daily.start_h},
              {"end_h", plan.daily.end_h},
              {"time", "local standard time, mid-hour stamps, every day"}};
    case metrics::OccupancyPlan::Kind::Hourly:
      return {{"schedule", plan.description()}, {"file", plan.hourly_source},
              {"time", "one value per weather record, in file order"}};
    case metrics::OccupancyPlan::Kind::Weekly: break;
  }
  json j = {{"schedule", plan.description()},
            {"daylight_saving", metrics::describe_daylight_saving(plan.daylight_saving)},
            {"time", "local clock time at the mid-hour stamps"}};
  if (const auto first = plan.january_1_of(settings.calendar))
    j["january_1"] = {{"weekday", metrics::weekday_name(first->first)}, {"from", first->second}};
  return j;
}

nlohmann::json grid_metrics_value(const AnnualStudy& study, const AnnualStudySettings& settings) {
  using nlohmann::json;
  const metrics::MetricSettings& m = settings.metrics;
  json j;
  j["sensors"] = study.sensors.size();
  j["time_steps"] = study.illuminance.step_count();
  j["occupied_hours"] = study.occupied_hours;
  j["occupancy"] = occupancy_json(settings);
  j["thresholds"] = {{"da_lux", m.da_threshold_lux},
                     {"udi_lower_lux", m.udi_lower_lux},
                     {"udi_upper_original_lux", m.udi_upper_original_lux},
                     {"udi_upper_revised_lux", m.udi_upper_revised_lux},
                     {"sda_time_fraction", m.sda_time_fraction},
                     {"ase_threshold_lux", m.ase_threshold_lux},
                     {"ase_hours", m.ase_hours}};
  // Means under the names of the metrics.csv columns (after index,x,y,z).
  const std::vector<std::string> names = metrics_csv_columns(m, false);
  const metrics::SensorMetrics& mean = study.grid.mean;
  const double values[] = {mean.da_percent,
                           mean.cda_percent,
                           mean.da_max_percent,
                           mean.udi_below_percent,
                           mean.udi_original_percent,
                           mean.udi_above_original_percent,
                           mean.udi_supplementary_percent,
                           mean.udi_autonomous_percent,
                           mean.udi_above_revised_percent,
                           mean.mean_occupied_lux};
  json means = json::object();
  for (std::size_t i = 0; i < std::size(values); ++i) means[names[4 + i]] = values[i];
  j["mean"] = means;
  std::size_t sda_sensors = 0;
  for (const metrics::SensorMetrics& s : study.sensors) sda_sensors += s.da_percent >= 100.0 * m.sda_time_fraction;
  j["sda_percent"] = study.grid.sda_percent;
  j["sda_sensors"] = sda_sensors;
  j["ase_percent"] = study.grid.ase_percent >= 0 ? json(study.grid.ase_percent) : json(nullptr);
  if (study.grid.en17037.empty()) {
    j["en17037"] = nullptr;
  } else {
    json levels = json::array();
    for (std::size_t i = 0; i < study.grid.en17037.size(); ++i) {
      const metrics::En17037Result& r = study.grid.en17037[i];
      levels.push_back({{"level", r.level},
                        {"target_lux", metrics::En17037Levels[i].target_lux},
                        {"minimum_target_lux", metrics::En17037Levels[i].minimum_target_lux},
                        {"target_area_percent", r.target_area_percent},
                        {"minimum_target_area_percent", r.minimum_target_area_percent},
                        {"passes", r.passes}});
    }
    j["en17037"] = {{"daylight_hours", study.illuminance.step_count() / 2},
                    {"daylight_hours_source", study.daylight_hours_source},
                    {"openings", metrics::en17037_openings_name(m.en17037_openings)},
                    {"target_area_required_percent", metrics::en17037_target_area_required_percent(m)},
                    {"levels", levels}};
  }
  j["sky"] = study.sky_description;
  return j;
}

std::string grid_metrics_json(const AnnualStudy& study, const AnnualStudySettings& settings) {
  return json_text(grid_metrics_value(study, settings));
}

std::vector<std::string> write_annual_outputs(const AnnualStudy& study, const std::vector<SensorPoint>& sensors,
                                              const AnnualStudySettings& settings, const std::string& folder,
                                              const AnnualOutputs& outputs) {
  if (sensors.size() != study.illuminance.sensor_count())
    throw std::invalid_argument(folder + ": " + std::to_string(sensors.size()) + " sensor positions for " +
                                std::to_string(study.illuminance.sensor_count()) + " sensors");
  std::filesystem::create_directories(folder);
  const std::filesystem::path dir(folder);
  std::vector<std::string> written;
  if (outputs.illuminance) {
    if (outputs.illuminance_csv) {
      written.push_back((dir / "illuminance.csv").string());
      write_illuminance_csv(study.illuminance, written.back());
    }
    written.push_back((dir / "illuminance.bin").string());
    write_illuminance_binary(study.illuminance, written.back());
  }
  if (outputs.metrics) {
    written.push_back((dir / "metrics.csv").string());
    write_metrics_csv(sensors, study.sensors, settings.metrics, study.ase_hours, written.back());
    written.push_back((dir / "grid_metrics.json").string());
    write_file_atomically(written.back(), grid_metrics_json(study, settings) + "\n");
  }
  return written;
}

std::vector<std::string> write_annual_outputs_beside(const AnnualStudy& study, const std::vector<SensorPoint>& sensors,
                                                     const AnnualStudySettings& settings, const std::string& folder,
                                                     const AnnualOutputs& outputs,
                                                     const std::function<void()>& alongside) {
  std::vector<std::string> written;
  tbb::parallel_invoke([&] { written = write_annual_outputs(study, sensors, settings, folder, outputs); }, alongside);
  return written;
}

}  // namespace dayphoton::study
