// Operated shading: see operated_shading.h for the rule and its source (IES LM-83-12 2.2.6).
#include "dayphoton/study/operated_shading.h"

#include <charconv>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "dayphoton/core/atomic_file.h"
#include "dayphoton/metrics/annual_metrics.h"
#include "dayphoton/metrics/occupancy.h"
#include "json_text.h"
#include "json_values.h"

namespace dayphoton::study {

namespace {

std::string shape(const metrics::IlluminanceTable& t) {
  return std::to_string(t.step_count()) + " steps x " + std::to_string(t.sensor_count()) + " sensors";
}

std::string number(double v, int decimals) {
  char buffer[64];
  const auto r = std::to_chars(buffer, buffer + sizeof buffer, v, std::chars_format::fixed, decimals);
  return std::string(buffer, r.ptr);
}

}  // namespace

bool step_is_shaded(std::size_t sunlit, std::size_t sensors, double sunlit_limit_percent) {
  // Integer counts times 100 and the limit times the count: exact in double for any real
  // grid, so the boundary (exactly the limit) is decided without rounding.
  return 100.0 * static_cast<double>(sunlit) > sunlit_limit_percent * static_cast<double>(sensors);
}

std::size_t ShadingSchedule::shaded_steps() const {
  std::size_t n = 0;
  for (char s : shaded) n += s ? 1 : 0;
  return n;
}

std::size_t ShadingSchedule::shaded_steps(const std::vector<char>& occupied) const {
  if (occupied.size() != shaded.size())
    throw std::invalid_argument("shading schedule: " + std::to_string(occupied.size()) + " occupancy flags for " +
                                std::to_string(shaded.size()) + " steps");
  std::size_t n = 0;
  for (std::size_t t = 0; t < shaded.size(); ++t) n += shaded[t] && occupied[t] ? 1 : 0;
  return n;
}

ShadingSchedule shading_schedule(const metrics::IlluminanceTable& open_direct_sun, const ShadingRule& rule) {
  ShadingSchedule schedule;
  schedule.sensors = open_direct_sun.sensor_count();
  schedule.sunlit.assign(open_direct_sun.step_count(), 0);
  schedule.shaded.assign(open_direct_sun.step_count(), 0);
  for (std::size_t t = 0; t < open_direct_sun.step_count(); ++t) {
    std::size_t n = 0;
    for (std::size_t s = 0; s < schedule.sensors; ++s)
      n += double(open_direct_sun.lux(t, s)) >= rule.direct_sun_threshold_lux ? 1 : 0;  // "1000 lux or more"
    schedule.sunlit[t] = n;
    schedule.shaded[t] = step_is_shaded(n, schedule.sensors, rule.sunlit_limit_percent) ? 1 : 0;
  }
  return schedule;
}

metrics::IlluminanceTable operated_illuminance(const metrics::IlluminanceTable& open,
                                               const metrics::IlluminanceTable& shaded,
                                               const ShadingSchedule& schedule) {
  if (open.step_count() != shaded.step_count() || open.sensor_count() != shaded.sensor_count())
    throw std::invalid_argument("operated shading: the open case's table has " + shape(open) +
                                ", the shaded case's " + shape(shaded));
  if (schedule.shaded.size() != open.step_count() || schedule.sensors != open.sensor_count())
    throw std::invalid_argument("operated shading: a schedule of " + std::to_string(schedule.shaded.size()) +
                                " steps x " + std::to_string(schedule.sensors) + " sensors for tables of " +
                                shape(open));
  metrics::IlluminanceTable result(open.steps(), open.sensor_count());
  for (std::size_t t = 0; t < open.step_count(); ++t) {
    const metrics::IlluminanceTable& source = schedule.shaded[t] ? shaded : open;
    for (std::size_t s = 0; s < open.sensor_count(); ++s) result.lux(t, s) = source.lux(t, s);
  }
  return result;
}

OperatedStudy compute_operated_study(const metrics::IlluminanceTable& open,
                                     const metrics::IlluminanceTable& shaded,
                                     const metrics::IlluminanceTable& open_direct_sun, const ShadingRule& rule,
                                     const AnnualStudySettings& settings,
                                     const std::vector<double>& daylight_hours_quantity,
                                     const std::string& daylight_hours_source, const std::string& description) {
  if (open_direct_sun.step_count() != open.step_count() || open_direct_sun.sensor_count() != open.sensor_count())
    throw std::invalid_argument("operated shading: the open case's direct-sun table has " + shape(open_direct_sun) +
                                ", its illuminance " + shape(open));
  const metrics::OccupancySchedule occupancy = occupancy_schedule(settings, open.steps());
  OperatedStudy result;
  result.schedule = shading_schedule(open_direct_sun, rule);
  AnnualStudy& study = result.study;
  study.illuminance = operated_illuminance(open, shaded, result.schedule);
  study.sky_description = description;
  study.occupied_hours = occupancy.occupied_count();
  result.occupied.resize(open.step_count());
  for (std::size_t t = 0; t < open.step_count(); ++t) result.occupied[t] = occupancy.occupied(t) ? 1 : 0;
  result.shaded_occupied_hours = result.schedule.shaded_steps(result.occupied);
  study.sensors = metrics::compute_sensor_metrics(study.illuminance, occupancy, settings.metrics);
  study.ase_hours = metrics::ase_hours_per_sensor(open_direct_sun, occupancy, settings.metrics);
  summarize_annual_study(study, settings, true, daylight_hours_quantity, daylight_hours_source);
  return result;
}

void write_shading_schedule_csv(const OperatedStudy& operated, const std::string& path) {
  const metrics::IlluminanceTable& table = operated.study.illuminance;
  const ShadingSchedule& sch = operated.schedule;
  if (sch.shaded.size() != table.step_count() || operated.occupied.size() != table.step_count())
    throw std::invalid_argument(path + ": schedule and table differ in steps");
  write_file_atomically(path, [&](std::ostream& out) {
    out << "month,day,hour,occupied,sunlit_sensors,sunlit_percent,shaded\n";
    for (std::size_t t = 0; t < table.step_count(); ++t) {
      const metrics::TimeStamp& ts = table.steps()[t];
      const double percent = sch.sensors ? 100.0 * double(sch.sunlit[t]) / double(sch.sensors) : 0.0;
      out << ts.month << ',' << ts.day << ',' << number(ts.hour, 1) << ',' << int(operated.occupied[t]) << ','
          << sch.sunlit[t] << ',' << number(percent, 3) << ',' << int(sch.shaded[t]) << '\n';
    }
  });
}

nlohmann::json operation_value(const OperatedStudy& operated, const ShadingRule& rule, const std::string& open_case,
                               const std::string& shaded_case) {
  nlohmann::json j = {{"open", open_case},
                      {"shaded", shaded_case},
                      {"direct_sun_threshold_lux", rule.direct_sun_threshold_lux},
                      {"sunlit_limit_percent", rule.sunlit_limit_percent},
                      {"rule", "shaded when more than sunlit_limit_percent of the sensors have direct-sun-only, "
                               "zero-bounce illuminance >= direct_sun_threshold_lux in the open case (IES LM-83-12 "
                               "2.2.6); ASE from the open case's direct sun"},
                      {"time_steps", operated.schedule.shaded.size()},
                      {"shaded_hours", operated.schedule.shaded_steps()},
                      {"occupied_hours", operated.study.occupied_hours},
                      {"shaded_occupied_hours", operated.shaded_occupied_hours}};
  return j;
}

std::string operation_json(const OperatedStudy& operated, const ShadingRule& rule, const std::string& open_case,
                           const std::string& shaded_case) {
  return json_text(operation_value(operated, rule, open_case, shaded_case));
}

}  // namespace dayphoton::study
